#pragma once
// A ground surface given as heights on a regular grid (a terrain raster, a generated crater field).
//
// Grid: node (i, j), 0 <= i < nx, 0 <= j < ny, lies at (x0 + i c, y0 + j c) with height
// heights[j * nx + i] (rows from south to north, x east, y north). Nodes are the heights' sample
// points (an ESRI grid's cell centres).
//
// Interpolation: bicubic cubic convolution (Keys 1981, IEEE Trans. ASSP 29(6):1153, with a = -1/2,
// i.e. the tensor product of Catmull-Rom splines through the nodes). It interpolates the nodes,
// is C1 (the height and both slopes are continuous everywhere inside the grid; the curvature jumps
// across cell edges), and reproduces any quadratic along each axis, hence any plane exactly (up to
// rounding): a tilted plane sampled on the grid is that plane again. C1 keeps the integrator's
// right-hand side free of slope jumps where a pad crosses a cell edge; bilinear (C0) would put one
// at every edge. At the grid's edges the stencil takes Keys' boundary nodes,
// f(-1) = 3 f(0) - 3 f(1) + f(2) (his eq. 25), which keep the cubic's accuracy and planes exact.
//
// Outside the grid the point is clamped to the grid's rectangle: the edge heights continue
// outwards, continuous but with a slope jump at the edge. Clamping rather than failing, because a
// right-hand side must not throw on a pad that slides a little past the edge during a step;
// the scenario loader instead refuses a terrain whose grid does not hold the lander's pads at
// release (a landing that starts outside would run on made-up ground).
//
// Nothing allocates in Height(): the padded node array is built once here.
#include <string>
#include <vector>

#include "rft/ground.h"

namespace touchdown::rft {

struct HeightGrid {
  double x0_m = 0.0, y0_m = 0.0;  // node (0, 0), the south-west corner node
  double cell_m = 1.0;            // node spacing, both axes
  int nx = 0, ny = 0;
  std::vector<double> heights_m;  // row by row: heights_m[j * nx + i]

  double x_max_m() const { return x0_m + (nx - 1) * cell_m; }
  double y_max_m() const { return y0_m + (ny - 1) * cell_m; }
  double At(int i, int j) const { return heights_m[static_cast<size_t>(j) * nx + i]; }
};

// "" when `grid` can be interpolated: nx, ny >= 3 (Keys' boundary nodes need three), a positive
// finite cell size and origin, nx * ny heights, all finite; otherwise why not.
std::string HeightGridProblem(const HeightGrid& grid);

class HeightFieldGround final : public GroundSurface {
 public:
  // Throws std::invalid_argument with HeightGridProblem's reason (a loader checks first and
  // words it for its file).
  explicit HeightFieldGround(HeightGrid grid);

  double Height(double x_m, double y_m) const override;
  // The surface is one plane everywhere only when every node has the same height; then the
  // contact takes the plane's exact path (and a flat grid lands bit-identically to level ground).
  const PlaneGround* ExactPlane() const override { return flat_ ? &plane_ : nullptr; }

  const HeightGrid& grid() const { return grid_; }
  // True when (x, y) lies in the grid's rectangle (where Height interpolates rather than clamps).
  bool Contains(double x_m, double y_m) const;

 private:
  HeightGrid grid_;
  int stride_ = 0;              // nx + 2
  std::vector<double> padded_;  // (nx + 2) x (ny + 2): the nodes with one ring of boundary nodes
  bool flat_ = false;
  PlaneGround plane_;
};

}  // namespace touchdown::rft
