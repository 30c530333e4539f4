// Li 2013 in 3D by the Treers, Cao & Stuart decomposition: reduction to the 2D law, the speed
// weights, the lateral term and the treatment of horizontal facets.
#include "rft/li2013_3d.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rft/contact_wrench.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

constexpr double kZeta = 2.0e6;

TEST(RftTreers, AlgebraicAlphaEqualsLiFit) {
  const Li2013Coefficients c;
  for (double b = -3.0; b <= 3.0; b += 0.37)
    for (double g = -3.1; g <= 3.1; g += 0.29) {
      const Alpha2 ref = Li2013Alpha(b, g);
      const Alpha2 a = Li2013AlphaFromSinCos(c, std::sin(b), std::cos(b), std::sin(g), std::cos(g));
      EXPECT_NEAR(a.z, ref.z, 1e-13) << b << " " << g;
      EXPECT_NEAR(a.x, ref.x, 1e-13) << b << " " << g;
    }
}

// The law uses tabulated weights: they must match the closed forms everywhere, between the nodes
// too, and keep the exact end values. f1 is matched to 1e-11; f23 to 3.1e-8 (measured), its
// worst near s = 0 where the atanh argument b2 s - b3 approaches -0.974 and the fourth derivative,
// which sets the cubic Hermite error h^4 f / 384, reaches ~4e7.
TEST(RftTreers, TabulatedWeightsMatchTheClosedForms) {
  double worst1 = 0.0, worst23 = 0.0;
  for (int i = 0; i <= 100000; ++i) {
    const double s = i / 100000.0 + 3.7e-7 * (i % 7);  // off the nodes as well
    worst1 = std::max(worst1, std::abs(TreersLateralWeightTabulated(s) - TreersLateralWeight(s)));
    worst23 = std::max(worst23, std::abs(TreersInPlaneWeightTabulated(s) - TreersInPlaneWeight(s)));
  }
  EXPECT_LT(worst1, 1e-11);
  EXPECT_LT(worst23, 5e-8);
  EXPECT_EQ(TreersLateralWeightTabulated(0.0), 0.0);
  EXPECT_EQ(TreersInPlaneWeightTabulated(1.0), 1.0);
  EXPECT_EQ(TreersInPlaneWeightTabulated(-1.0), 0.0);
  EXPECT_EQ(TreersLateralWeightTabulated(2.0), 1.0);
}

TEST(RftTreers, SpeedWeightsAreNormalised) {
  EXPECT_EQ(TreersLateralWeight(0.0), 0.0);
  EXPECT_EQ(TreersInPlaneWeight(0.0), 0.0);
  EXPECT_EQ(TreersLateralWeight(1.0), 1.0);
  EXPECT_EQ(TreersInPlaneWeight(1.0), 1.0);
  // Continuous at both ends and increasing in between.
  EXPECT_NEAR(TreersLateralWeight(1e-9), 0.0, 1e-7);
  EXPECT_NEAR(TreersInPlaneWeight(1.0 - 1e-9), 1.0, 1e-6);
  EXPECT_NEAR(TreersInPlaneWeight(1e-9), 0.0, 1e-7);
  double last1 = 0.0, last23 = 0.0;
  for (double s = 0.05; s < 1.0; s += 0.05) {
    EXPECT_GT(TreersLateralWeight(s), last1);
    EXPECT_GT(TreersInPlaneWeight(s), last23);
    last1 = TreersLateralWeight(s);
    last23 = TreersInPlaneWeight(s);
  }
  // The unnormalised fits with Treers' published constants are already 1 at s = 1.
  const double f23_raw = 1.99392673405210 *
                         (std::atanh(1.61146827229181 - 0.973746396532650) + std::atanh(0.973746396532650)) /
                         5.81083560370960;
  EXPECT_NEAR(f23_raw, 1.0, 1e-12);
  EXPECT_NEAR(TreersInPlaneWeight(0.5),
              1.99392673405210 *
                  (std::atanh(1.61146827229181 * 0.5 - 0.973746396532650) + std::atanh(0.973746396532650)) /
                  5.81083560370960 / f23_raw,
              1e-14);
}

// A thin extruded plate (length L along its attack direction, width W along y, thickness t)
// at attack angle beta, moving at intrusion angle gamma in the x-z plane, fully submerged:
// per unit area and depth of its leading face it feels zeta (-alpha_x, 0, alpha_z).
class RftTreersThinPlate : public ::testing::TestWithParam<std::pair<double, double>> {};

TEST_P(RftTreersThinPlate, ReproducesLi2DAlphas) {
  const auto [beta, gamma] = GetParam();
  const double L = 0.04, W = 0.04, t = 1e-7;
  const SurfaceElements plate =
      testing::MakeBox(Eigen::Vector3d(-L / 2, -W / 2, -t / 2), Eigen::Vector3d(L / 2, W / 2, t / 2), 3);
  PadKinematics k;
  // Rotating about y by -beta turns the bottom normal -z into (sin beta, 0, -cos beta).
  k.R_WB = testing::RotY(-beta);
  k.p_WB = Eigen::Vector3d(0.01, 0.0, -0.05);
  k.v_WB_W = Eigen::Vector3d(std::cos(gamma), 0.0, -std::sin(gamma));
  const ContactWrench w = ComputeContactWrench(plate, k, PlaneGround(), Li2013TreersLaw(kZeta));
  const double depth_integral = L * W * 0.05;  // leading face centroid at depth 0.05 (+- t/2)
  const Alpha2 a = Li2013Alpha(beta, gamma);
  const double tol = 1e-5;  // the plate's thin edges (relative area t/L = 2.5e-6)
  EXPECT_NEAR(w.force_W.x() / (kZeta * depth_integral), -a.x, tol) << beta << " " << gamma;
  EXPECT_NEAR(w.force_W.z() / (kZeta * depth_integral), a.z, tol) << beta << " " << gamma;
  EXPECT_NEAR(w.force_W.y() / (kZeta * depth_integral), 0.0, tol);
}

std::vector<std::pair<double, double>> PlateCases() {
  std::vector<std::pair<double, double>> cases;
  for (double b : {-1.2, -0.6, 0.0, 0.3, 0.9, 1.4})
    for (double g : {-1.2, -0.5, 0.2, 0.8, 1.3, std::numbers::pi / 2, 2.0, 2.8})
      if (std::abs(std::sin(b + g)) > 0.05) cases.push_back({b, g});  // one face clearly leads
  return cases;
}
INSTANTIATE_TEST_SUITE_P(BetaGammaGrid, RftTreersThinPlate, ::testing::ValuesIn(PlateCases()));

TEST(RftTreers, VerticalPlateDraggedSidewaysFeelsAlphaY) {
  // Normal along x, motion along y: pure lateral (s1 = 1), resisted by alpha_y along -v.
  const Li2013TreersLaw law(kZeta);
  const Eigen::Vector3d s = law.StressPerDepth(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0.3, 0));
  EXPECT_NEAR(s.y(), -kZeta * kTreersAlphaY, 1e-9 * kZeta);
  EXPECT_NEAR(s.x(), 0.0, 1e-9 * kZeta);
  EXPECT_NEAR(s.z(), 0.0, 1e-9 * kZeta);
}

TEST(RftTreers, StressIsIndependentOfSpeed) {
  const Li2013TreersLaw law(kZeta);
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.2, -0.9).normalized(), v(0.4, 0.5, -0.6);
  EXPECT_TRUE(law.StressPerDepth(n, v).isApprox(law.StressPerDepth(n, 7.5 * v), 1e-14));
}

TEST(RftTreers, ContinuousAsAFacetTiltsThroughHorizontal) {
  // Dragging a near-horizontal facet sideways: the stress must not jump as its tilt (in any
  // azimuth) goes to zero, and must be finite at exactly zero.
  const Li2013TreersLaw law(kZeta);
  const Eigen::Vector3d v(1.0, 0.2, -0.3);
  const Eigen::Vector3d flat = law.StressPerDepth(Eigen::Vector3d(0, 0, -1), v);
  ASSERT_TRUE(flat.allFinite());
  for (double azimuth : {0.0, 0.7, std::numbers::pi / 2, 2.5}) {
    Eigen::Vector3d previous = flat;
    // Steps of 1e-4 rad through the 1-degree blend: the stress changes by O(step), never O(1)
    // (the largest slope, 1.5 |difference| / band, gives under 0.005 zeta per step).
    for (int i = 1; i <= 300; ++i) {
      const double tilt = 1e-4 * i;
      const Eigen::Vector3d n(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth),
                              -std::cos(tilt));
      const Eigen::Vector3d s = law.StressPerDepth(n, v);
      EXPECT_LT((s - previous).norm(), 0.01 * kZeta) << azimuth << " " << tilt;
      previous = s;
    }
    const Eigen::Vector3d tiny(std::sin(1e-9) * std::cos(azimuth), std::sin(1e-9) * std::sin(azimuth), -1.0);
    EXPECT_LT((law.StressPerDepth(tiny.normalized(), v) - flat).norm(), 1e-6 * kZeta) << azimuth;
  }
}

TEST(RftTreers, HorizontalPlateMovingStraightDownIsZeta) {
  const Li2013TreersLaw law(kZeta);
  const Eigen::Vector3d s = law.StressPerDepth(Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 0, -2));
  EXPECT_NEAR(s.z(), kZeta, 1e-12 * kZeta);
  EXPECT_NEAR(s.x(), 0.0, 1e-12 * kZeta);
  EXPECT_NEAR(s.y(), 0.0, 1e-12 * kZeta);
}

}  // namespace
}  // namespace touchdown::rft
