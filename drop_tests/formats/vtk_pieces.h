#pragma once
// The things touchdown shows in ParaView, as VTK pieces in world coordinates (vtk_writer.h): a pad's
// surface with its per-element soil stresses and forces, a square of the soil's surface, and the
// craters the pads press into it. The free drop
// (drop_tests/drop/drop_vtk.h), the lander (drop_tests/scenario/lander_vtk.h) and `touchdown force`
// build their files from these, so a pad looks and is named alike in all three.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "drop_tests/formats/vtk_writer.h"
#include "rft/element_stresses.h"
#include "rft/ground.h"
#include "rft/surface_elements.h"
#include "rft/units.h"

namespace touchdown::io {

// A pad's surface elements as an indexed triangle mesh in the pad frame: the elements' corners
// merged where they are equal (the contact keeps them as separate triangles), built once per pad.
// Triangle i is surface element i.
struct PadSurfaceMesh {
  Eigen::Matrix3Xd points_B;
  std::vector<std::vector<int>> triangles;
  Eigen::VectorXd area_m2;  // of element i (the traction is its force per this area)
};
PadSurfaceMesh MakePadSurfaceMesh(const rft::SurfaceElements& elements);

// The cell fields of a pad piece, in this order, with their units (docs/paraview.md):
// normal_stress_Pa, shear_stress_Pa, depth_m, leading (0/1), and two vectors in the world frame
// (3 components, ready for ParaView's Glyph filter): traction_Pa, the soil's force on the element per
// its area [N/m^2], and element_force_N, that force [N]. The element forces of a pad sum to its RFT
// soil force.
inline constexpr const char* kPadFieldNames[] = {"normal_stress_Pa", "shear_stress_Pa", "depth_m",
                                                 "leading",          "traction_Pa",     "element_force_N"};

// The pad at pose (R_WB, p_WB) with the stresses and forces of rft::ComputeElementStresses at that
// pose (all its fields from that one evaluation: stress times area is the force).
VtkPolyData PadSurfacePiece(const PadSurfaceMesh& mesh, const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& p_WB,
                            const rft::ElementStresses& stresses);

// The ground as a square of side 2 half_width_m centred on (x, y), `cells` quads a side, at the
// surface's height at each corner (a slope shows as one). Cell field `soil`: soil_at(x, y) at
// each quad's centre (the index of the soil in the terrain; all 0 on a uniform bed).
VtkPolyData SoilSurfacePiece(const rft::GroundSurface& ground, const Eigen::Vector2d& centre_W, double half_width_m,
                             int cells, const std::function<int(double, double)>& soil_at);

// The soil's surface as pads deform it, for one pad's path: a grid over the rectangle [lo, hi] (x, y)
// of the ground's height, each grid point pressed down to the pad's lowest surface point above or
// below it whenever that is lower. Pressed at every frame, it keeps the deepest imprint of every pose
// so far: the crater, and for a sliding pad the furrow. What it leaves out: the soil that the pad
// pushes aside (no rim or heave) and any spring-back; it is the pad's swept volume cut out of the
// ground, not a soil deformation model.
//
// Grid coordinates are whole multiples of step_mm millimetres, computed as integer / 1000, so that
// they are written as short decimals ("0.124"), and the flat part of a level ground as "0".
class CraterSurface {
 public:
  CraterSurface(const rft::GroundSurface& ground, const Eigen::Vector2d& lo_W, const Eigen::Vector2d& hi_W, int step_mm);
  // Presses the pad's surface (mesh at pose R_WB, p_WB) into the grid.
  void Press(const PadSurfaceMesh& mesh, const Eigen::Matrix3d& R_WB, const Eigen::Vector3d& p_WB);
  // Quads, counter-clockwise seen from above; point field crater_depth_m: how far the point is
  // pressed below the ground's surface [m] (0 outside the imprint).
  VtkPolyData Piece() const;

  // A grid step for a pad of this radius: about 14 steps a radius, whole millimetres, at least 1.
  static int StepFor(double pad_radius_m);

 private:
  double X(int i) const { return (i0_ + i) * step_mm_ / units::kMmPerM; }
  double Y(int j) const { return (j0_ + j) * step_mm_ / units::kMmPerM; }
  int Index(int i, int j) const { return j * (nx_ + 1) + i; }
  int step_mm_, i0_, j0_, nx_, ny_;
  std::vector<double> surface_z_, z_;
};

}  // namespace touchdown::io
