#pragma once
// Isotropic remeshing (CGAL PMP::isotropic_remeshing), so a coarse CAD export of a pad becomes an
// even surface mesh: every element then samples the depth field alike. Sharp edges (normals
// more than 30 degrees apart, e.g. the rim of a flat pad or a chamfer) are kept as feature
// lines: they are split and collapsed along themselves but never smoothed away, so flat faces
// stay flat and the volume is kept. The input must be a prepared mesh (mesh_io.h).
#include "footpad_geom/triangle_mesh.h"

namespace touchdown::geom {

// Returns the remeshed surface (not yet re-validated: pass it to PrepareTriangleMesh).
// target_edge_m > 0; iterations >= 1.
TriangleMesh RemeshIsotropic(const TriangleMesh& mesh, double target_edge_m, int iterations = 3);

}  // namespace touchdown::geom
