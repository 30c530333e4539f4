#include "rft/height_field_ground.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace touchdown::rft {

namespace {

// Catmull-Rom weights of the nodes at -1, 0, 1, 2 for a point at t in [0, 1] between nodes 0
// and 1 (Keys' kernel with a = -1/2). They sum to 1 and reproduce t itself: planes are exact.
struct CubicWeights {
  double w[4];
  explicit CubicWeights(double t) {
    const double t2 = t * t, t3 = t2 * t;
    w[0] = 0.5 * (-t3 + 2.0 * t2 - t);
    w[1] = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
    w[2] = 0.5 * (-3.0 * t3 + 4.0 * t2 + t);
    w[3] = 0.5 * (t3 - t2);
  }
};

// The cell holding coordinate u (in node spacings from node 0, clamped to [0, n - 1]) and the
// position in it: the last cell takes u = n - 1 at t = 1, so every index stays inside.
inline void Locate(double u, int n, int* cell, double* t) {
  u = std::clamp(u, 0.0, double(n - 1));
  const int i = std::min(static_cast<int>(u), n - 2);
  *cell = i;
  *t = u - i;
}

}  // namespace

std::string HeightGridProblem(const HeightGrid& g) {
  if (g.nx < 3 || g.ny < 3)
    return "needs at least 3 x 3 nodes for its cubic interpolation, got " + std::to_string(g.nx) + " x " +
           std::to_string(g.ny);
  if (!(std::isfinite(g.cell_m) && g.cell_m > 0.0))
    return "cell size must be positive, got " + std::to_string(g.cell_m);
  if (!std::isfinite(g.x0_m) || !std::isfinite(g.y0_m)) return "origin must be finite";
  if (g.heights_m.size() != static_cast<size_t>(g.nx) * static_cast<size_t>(g.ny))
    return "holds " + std::to_string(g.heights_m.size()) + " heights for " + std::to_string(g.nx) + " x " +
           std::to_string(g.ny) + " nodes";
  for (size_t k = 0; k < g.heights_m.size(); ++k)
    if (!std::isfinite(g.heights_m[k]))
      return "height at node (" + std::to_string(k % g.nx) + ", " + std::to_string(k / g.nx) + ") is not finite";
  return "";
}

HeightFieldGround::HeightFieldGround(HeightGrid grid) : grid_(std::move(grid)) {
  if (const std::string problem = HeightGridProblem(grid_); !problem.empty())
    throw std::invalid_argument("height grid: " + problem);
  const int nx = grid_.nx, ny = grid_.ny;
  stride_ = nx + 2;
  padded_.assign(static_cast<size_t>(stride_) * (ny + 2), 0.0);
  auto P = [&](int i, int j) -> double& { return padded_[static_cast<size_t>(j + 1) * stride_ + (i + 1)]; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) P(i, j) = grid_.At(i, j);
  // Keys' boundary nodes, first along x in every row, then along y in every column (corners
  // included): exact for quadratics, so for planes.
  for (int j = 0; j < ny; ++j) {
    P(-1, j) = 3.0 * P(0, j) - 3.0 * P(1, j) + P(2, j);
    P(nx, j) = 3.0 * P(nx - 1, j) - 3.0 * P(nx - 2, j) + P(nx - 3, j);
  }
  for (int i = -1; i <= nx; ++i) {
    P(i, -1) = 3.0 * P(i, 0) - 3.0 * P(i, 1) + P(i, 2);
    P(i, ny) = 3.0 * P(i, ny - 1) - 3.0 * P(i, ny - 2) + P(i, ny - 3);
  }
  const double h0 = grid_.heights_m.front();
  flat_ = std::all_of(grid_.heights_m.begin(), grid_.heights_m.end(), [h0](double h) { return h == h0; });
  if (flat_) plane_ = PlaneGround(h0);
}

double HeightFieldGround::Height(double x_m, double y_m) const {
  if (flat_) return plane_.height_at_origin_m();  // the node height itself: weights summing to 1 would round
  int i, j;
  double tx, ty;
  Locate((x_m - grid_.x0_m) / grid_.cell_m, grid_.nx, &i, &tx);
  Locate((y_m - grid_.y0_m) / grid_.cell_m, grid_.ny, &j, &ty);
  const CubicWeights wx(tx), wy(ty);
  // Node (i - 1, j - 1) is padded_[j * stride + i]: the stencil's first row and column.
  const double* row = padded_.data() + static_cast<size_t>(j) * stride_ + i;
  double h = 0.0;
  for (int b = 0; b < 4; ++b, row += stride_)
    h += wy.w[b] * (wx.w[0] * row[0] + wx.w[1] * row[1] + wx.w[2] * row[2] + wx.w[3] * row[3]);
  return h;
}

bool HeightFieldGround::Contains(double x_m, double y_m) const {
  return x_m >= grid_.x0_m && x_m <= grid_.x_max_m() && y_m >= grid_.y0_m && y_m <= grid_.y_max_m();
}

}  // namespace touchdown::rft
