// The dynamic (inertial) RFT term of Agarwal et al. 2021 as a decorator law.
#include "rft/dynamic_term.h"

#include <gtest/gtest.h>

#include <memory>

#include "rft/contact_wrench.h"
#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

constexpr double kZetaDynamic = 2.0e6, kLambda = 1.3, kRho = 1600.0;

DynamicTermLaw MakeLaw() { return DynamicTermLaw(std::make_unique<Li2013TreersLaw>(kZetaDynamic), kLambda, kRho); }

TEST(RftDynamicTerm, StressIsLambdaRhoVnSquaredAgainstNormal) {
  const DynamicTermLaw law = MakeLaw();
  EXPECT_EQ(law.name(), "li2013+dynamic");
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, 0.0, -0.9).normalized(), v(0.5, 0.2, -2.0);
  const double vn = n.dot(v);
  EXPECT_TRUE(law.DynamicStress(n, v).isApprox(-kLambda * kRho * vn * vn * n, 1e-14));
  // Trailing and sliding elements: nothing.
  EXPECT_EQ(law.DynamicStress(-n, v), Eigen::Vector3d::Zero());
  EXPECT_EQ(law.DynamicStress(Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 0, 0)), Eigen::Vector3d::Zero());
  // The quasi-static part is the wrapped law's.
  EXPECT_EQ(law.StressPerDepth(n, v), Li2013TreersLaw(kZetaDynamic).StressPerDepth(n, v));
}

TEST(RftDynamicTerm, PlateMovingDownGetsAreaTimesDynamicPressure) {
  const double L = 0.04, speed = 1.5, depth = 0.01;
  const SurfaceElements plate =
      testing::MakeBox(Eigen::Vector3d(-L / 2, -L / 2, 0.0), Eigen::Vector3d(L / 2, L / 2, 1e-3), 2);
  PadKinematics k;
  k.p_WB = Eigen::Vector3d(0.1, 0.0, -depth);  // reference point off the plate: moments matter
  k.v_WB_W = Eigen::Vector3d(0, 0, -speed);
  const DynamicTermLaw law = MakeLaw();
  const ContactWrench with = ComputeContactWrench(plate, k, PlaneGround(), law);
  const ContactWrench without = ComputeContactWrench(plate, k, PlaneGround(), law.quasi_static());
  const Eigen::Vector3d extra = with.force_W - without.force_W;
  EXPECT_NEAR(extra.z(), kLambda * kRho * speed * speed * L * L, 1e-9 * extra.z());  // only the bottom
  EXPECT_NEAR(extra.x(), 0.0, 1e-9 * extra.z());
  // Applied at the bottom's area centroid (the B origin, offset from p_WB by nothing): no
  // extra moment about the reference point at the bottom's centre.
  EXPECT_LT((with.moment_W - without.moment_W).norm(), 1e-9 * extra.z() * L);
  // And it does not depend on depth.
  k.p_WB.z() = -2 * depth;
  const ContactWrench deeper = ComputeContactWrench(plate, k, PlaneGround(), law);
  const ContactWrench deeper_qs = ComputeContactWrench(plate, k, PlaneGround(), law.quasi_static());
  EXPECT_NEAR((deeper.force_W - deeper_qs.force_W).z(), extra.z(), 1e-9 * extra.z());
}

}  // namespace
}  // namespace touchdown::rft
