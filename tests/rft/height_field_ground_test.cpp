// HeightFieldGround: Keys' cubic convolution interpolates the nodes, is exact for a plane, C1
// across cell edges, clamps outside; a flat grid is an exact plane; a pad on a tilted plane given
// as a height field feels the wrench it feels on PlaneGround with that slope.
#include "rft/height_field_ground.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "rft/contact_wrench.h"
#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

// Heights h(x, y) sampled at the nodes of an nx x ny grid.
template <class Fn>
HeightGrid SampledGrid(double x0, double y0, double cell, int nx, int ny, Fn h) {
  HeightGrid g{.x0_m = x0, .y0_m = y0, .cell_m = cell, .nx = nx, .ny = ny, .heights_m = {}};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) g.heights_m.push_back(h(x0 + i * cell, y0 + j * cell));
  return g;
}

// Reproducible pseudo-random heights in [-1, 1] (a rough terrain: no smoothness to hide behind).
HeightGrid RoughGrid(int nx, int ny, double cell) {
  unsigned state = 12345u;
  return SampledGrid(0.0, 0.0, cell, nx, ny, [&](double, double) {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 23) - 1.0;
  });
}

TEST(RftHeightField, TiltedPlaneIsExactInsideTheGrid) {
  const double h0 = 0.3, sx = 0.2, sy = -0.35;
  auto plane = [&](double x, double y) { return h0 + sx * x + sy * y; };
  const HeightFieldGround ground(SampledGrid(-1.3, 2.1, 0.25, 7, 5, plane));
  // Every cell, boundary cells included (they use Keys' boundary nodes), on an irregular lattice.
  for (double x = -1.3; x <= -1.3 + 6 * 0.25; x += 0.0173)
    for (double y = 2.1; y <= 2.1 + 4 * 0.25; y += 0.0219)
      EXPECT_NEAR(ground.Height(x, y), plane(x, y), 1e-14) << x << ", " << y;  // a few ulps of O(1)
  EXPECT_EQ(ground.ExactPlane(), nullptr);                                     // clamped outside: a plane only inside
}

TEST(RftHeightField, InterpolatesTheNodes) {
  const HeightGrid g = RoughGrid(6, 5, 0.5);  // x0 = y0 = 0, a power-of-two cell: node positions exact
  const HeightFieldGround ground(g);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) EXPECT_EQ(ground.Height(i * 0.5, j * 0.5), g.At(i, j)) << i << ", " << j;
}

// One-sided slopes on both sides of every interior cell edge agree to O(step): the height is C1.
// Their difference is at most step x the largest curvature (about 100 m^-2 for unit heights on a
// 0.5 m grid, hence 1e-5 x 100 = 1e-3), while the slopes themselves are O(4) and jump by O(1) across
// a bilinear (C0) grid's edges.
TEST(RftHeightField, SlopeIsContinuousAcrossCellEdges) {
  const double cell = 0.5, step = 1e-5;
  const HeightGrid g = RoughGrid(7, 6, cell);
  const HeightFieldGround ground(g);
  double largest_slope = 0.0;
  for (int k = 1; k <= g.nx - 2; ++k)
    for (double y = 0.1; y < g.y_max_m(); y += 0.37) {
      const double xe = k * cell;
      const double left = (ground.Height(xe, y) - ground.Height(xe - step, y)) / step;
      const double right = (ground.Height(xe + step, y) - ground.Height(xe, y)) / step;
      EXPECT_NEAR(left, right, 1e-3) << "x edge " << k << ", y " << y;
      largest_slope = std::max(largest_slope, std::abs(left));
    }
  for (int k = 1; k <= g.ny - 2; ++k)
    for (double x = 0.1; x < g.x_max_m(); x += 0.37) {
      const double ye = k * cell;
      const double below = (ground.Height(x, ye) - ground.Height(x, ye - step)) / step;
      const double above = (ground.Height(x, ye + step) - ground.Height(x, ye)) / step;
      EXPECT_NEAR(below, above, 1e-3) << "y edge " << k << ", x " << x;
    }
  EXPECT_GT(largest_slope, 0.5);  // the slopes compared are not all small
}

TEST(RftHeightField, OutsideTheGridTheEdgeHeightsContinue) {
  const HeightGrid g = RoughGrid(5, 4, 0.5);
  const HeightFieldGround ground(g);
  EXPECT_EQ(ground.Height(g.x_max_m() + 3.0, 0.5), ground.Height(g.x_max_m(), 0.5));
  EXPECT_EQ(ground.Height(-7.0, -2.0), g.At(0, 0));
  EXPECT_EQ(ground.Height(0.75, g.y_max_m() + 0.1), ground.Height(0.75, g.y_max_m()));
  EXPECT_TRUE(ground.Contains(g.x_max_m(), 0.0));
  EXPECT_FALSE(ground.Contains(g.x_max_m() + 1e-9, 0.0));
}

TEST(RftHeightField, FlatGridIsAnExactPlane) {
  const HeightFieldGround flat(SampledGrid(-1.0, -1.0, 0.5, 5, 5, [](double, double) { return 0.25; }));
  ASSERT_NE(flat.ExactPlane(), nullptr);
  EXPECT_EQ(flat.ExactPlane()->height_at_origin_m(), 0.25);
  EXPECT_EQ(flat.ExactPlane()->slope_x(), 0.0);
  EXPECT_EQ(flat.Height(0.3, -0.7), 0.25);
}

TEST(RftHeightField, RefusesGridsItCannotInterpolate) {
  HeightGrid g = RoughGrid(3, 3, 1.0);
  EXPECT_EQ(HeightGridProblem(g), "");
  g.cell_m = 0.0;
  EXPECT_NE(HeightGridProblem(g).find("cell size must be positive"), std::string::npos);
  EXPECT_THROW(HeightFieldGround{g}, std::invalid_argument);
  g = RoughGrid(2, 3, 1.0);
  EXPECT_NE(HeightGridProblem(g).find("at least 3 x 3"), std::string::npos);
  g = RoughGrid(3, 3, 1.0);
  g.heights_m.pop_back();
  EXPECT_NE(HeightGridProblem(g).find("holds 8 heights for 3 x 3"), std::string::npos);
  g = RoughGrid(3, 3, 1.0);
  g.heights_m[4] = std::nan("");
  EXPECT_NE(HeightGridProblem(g).find("node (1, 1) is not finite"), std::string::npos);
}

// A tilted, sliding pad on a 12 deg slope: PlaneGround against the same plane as a 2 cm grid.
// The height field takes the general path (depths from Height per vertex in the world frame, no
// block culling) instead of the plane's (depths linear in the pad frame), so the two agree only
// to rounding: the interpolated heights are the plane's to a few ulps, and the clipping of each
// triangle by its vertex depths is exact for both because the surface is a plane (on a curved
// field it would be a linear approximation within each triangle). 1e-12 of the force is some
// thousand times the rounding of a sum over a few hundred elements.
TEST(RftHeightField, PadOnTiltedGridMatchesPlaneGround) {
  const double slope = std::tan(12.0 * M_PI / 180.0), az = 0.6;
  const double sx = -slope * std::cos(az), sy = -slope * std::sin(az), h0 = 0.004;
  const PlaneGround plane(h0, sx, sy);
  const HeightFieldGround field(
      SampledGrid(-0.3, -0.3, 0.02, 31, 31, [&](double x, double y) { return h0 + sx * x + sy * y; }));
  const SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(0.05, 0.016, 3), 48);
  const Li2013TreersLaw law(3.48e6);
  for (const double spin : {0.0, 1.5}) {
    PadKinematics k;
    k.R_WB = testing::RotX(0.15) * testing::RotZ(0.4);
    k.p_WB = Eigen::Vector3d(0.03, -0.02, -0.01);
    k.v_WB_W = Eigen::Vector3d(0.4, -0.2, -1.1);
    k.w_WB_W = Eigen::Vector3d(0.1, 0.0, spin);
    const ContactWrench a = ComputeContactWrench(pad, k, plane, law);
    const ContactWrench b = ComputeContactWrench(pad, k, field, law);
    ASSERT_GT(a.force_W.norm(), 10.0);
    const double tol = 1e-12 * a.force_W.norm();
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(b.force_W[i], a.force_W[i], tol) << "spin " << spin << " axis " << i;
      EXPECT_NEAR(b.moment_W[i], a.moment_W[i], tol * 0.1) << "spin " << spin << " axis " << i;  // lever < 0.1 m
    }
    EXPECT_NEAR(b.submerged_area_m2, a.submerged_area_m2, 1e-12 * a.submerged_area_m2);
    EXPECT_EQ(b.leading_elements, a.leading_elements);
  }
}

}  // namespace
}  // namespace touchdown::rft
