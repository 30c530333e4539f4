#pragma once
// Pad meshes from files: STL (ASCII and binary), OFF, OBJ and PLY, read through CGAL's IO and
// validated before any physics sees them. A mesh is accepted when, after merging coincident
// points:
//   - every face has three or more distinct vertices (faces with more are triangulated:
//     CAD exports of flat pads often carry quads or n-gons; triangulating them changes nothing
//     of the surface, so refusing them would only be a nuisance);
//   - every edge joins exactly two faces (no non-manifold edge, no border edge: closed);
//   - the faces can be oriented consistently (a Moebius-like band cannot) and no vertex joins
//     two otherwise separate sheets;
//   - no triangle has zero area and no two triangles intersect (other than along a shared
//     edge or vertex);
//   - the mesh is one closed shell: no shell inside another (a box inside a box), no second
//     solid beside the first (one pad is one solid), and it is at most limits::kPadSize_m
//     (10 m) across;
// and it is then oriented so that it bounds a volume with outward normals: an inverted mesh
// (all normals inward, as some exporters write) is reversed and reported, not refused.
// Every defect throws InputError with one line: "<file>: <count> <defect>", e.g.
// "pad.stl: 12 border edges, mesh is not closed".
#include <string>

#include "footpad_geom/triangle_mesh.h"

namespace touchdown::geom {

struct PreparedMesh {
  TriangleMesh mesh;                  // closed, oriented outward, triangles only
  int merged_points = 0;              // coincident input points merged into one vertex
  int triangulated_faces = 0;         // input faces with more than three vertices
  bool reoriented = false;            // the input was inside out (or had inverted pieces)
};

// Validates and orients a soup (see above). `source` names the file in error messages.
PreparedMesh PrepareTriangleMesh(PolygonSoup soup, const std::string& source);

struct MeshLoadOptions {
  LengthUnit unit = LengthUnit::kMillimetre;
  // > 0: isotropic remeshing to this edge length [m] after validation (mesh_remesh.h); the
  // result is validated again.
  double remesh_edge_m = 0.0;
};

// Reads `path` (format from its extension: .stl, .off, .obj, .ply, any case), converts the
// coordinates to metres and prepares it. Throws InputError for a missing or unreadable file
// (rft/input_file.h says which),
// an unknown format or any defect above.
PreparedMesh LoadTriangleMesh(const std::string& path, const MeshLoadOptions& options = {});

// Writes `mesh` in the format of the extension of `path` (.stl, .off, .obj, .ply), scaled by
// `scale` (e.g. 1000 to write millimetres). STL and PLY are binary unless `ascii`. Throws
// InputError if the file cannot be written.
void WriteTriangleMesh(const TriangleMesh& mesh, const std::string& path, double scale = 1.0, bool ascii = false);

}  // namespace touchdown::geom
