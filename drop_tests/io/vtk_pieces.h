#pragma once
// The things touchdown shows in ParaView, as VTK pieces in world coordinates (vtk_writer.h): a pad's
// surface with its per-element soil stresses, and a square of the soil's surface. The free drop
// (drop_tests/drop/drop_vtk.h), the lander (drop_tests/scenario/lander_vtk.h) and `touchdown force`
// build their files from these, so a pad looks and is named alike in all three.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "drop_tests/io/vtk_writer.h"
#include "rft/element_stresses.h"
#include "rft/ground.h"
#include "rft/surface_elements.h"

namespace touchdown::io {

// A pad's surface elements as an indexed triangle mesh in the pad frame: the elements' corners
// merged where they are equal (the contact keeps them as separate triangles), built once per pad.
// Triangle i is surface element i.
struct PadSurfaceMesh {
  Eigen::Matrix3Xd points_B;
  std::vector<std::vector<int>> triangles;
};
PadSurfaceMesh MakePadSurfaceMesh(const rft::SurfaceElements& elements);

// The cell fields of a pad piece, in this order, with their units (docs/paraview.md):
// normal_stress_Pa, shear_stress_Pa, depth_m, leading (0/1).
inline constexpr const char* kPadFieldNames[] = {"normal_stress_Pa", "shear_stress_Pa", "depth_m", "leading"};

// The pad at pose (R_WB, p_WB) with the stresses of rft::ComputeElementStresses at that pose.
VtkPolyData PadSurfacePiece(const PadSurfaceMesh& mesh, const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& p_WB,
                            const rft::ElementStresses& stresses);

// The ground as a square of side 2 half_width_m centred on (x, y), `cells` quads a side, at the
// surface's height at each corner (a slope shows as one). Cell field `soil`: soil_at(x, y) at
// each quad's centre (the index of the soil in the terrain; all 0 on a uniform bed).
VtkPolyData SoilSurfacePiece(const rft::GroundSurface& ground, const Eigen::Vector2d& centre_W, double half_width_m,
                             int cells, const std::function<int(double, double)>& soil_at);

}  // namespace touchdown::io
