// The rotating contact's skip of wholly trailing blocks (contact_internal.h, BlockTrails, and
// contact_wrench_rotating.cpp): the bound must never skip a block with an element that could lead,
// and skipping must leave every wrench bit for bit as the full pass computes it, while it does skip
// the top of a buried pad that sinks and the back of one that slides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "rft/contact_internal.h"
#include "rft/contact_wrench.h"
#include "rft/dynamic_term.h"
#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

// The lander-like flat pad at 64 sectors (pad_meshes.h).
SurfaceElements BoundedPad() { return testing::LanderLikeFlatPad(64); }

// The same pad with every block's normal cone opened to the whole sphere: nothing is skipped.
SurfaceElements WithoutSkips(SurfaceElements pad) {
  pad.block_normal_spread.setConstant(2.0);
  return pad;
}

Eigen::Vector3d Velocity(const Eigen::Vector3d& u, const Eigen::Vector3d& w, const Eigen::Vector3d& r) {
  return u + w.cross(r);
}

TEST(RftContactBlockCull, ASkippedBlockHasNoElementThatCouldLead) {
  const SurfaceElements pad = BoundedPad();
  std::mt19937 rng(15);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> spin_scale(0.0, 40.0);
  int skipped = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector3d u(normal(rng), normal(rng), normal(rng));
    const Eigen::Vector3d w = spin_scale(rng) * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    for (int b = 0; b < pad.block_count(); ++b) {
      if (!contact_internal::BlockTrails(pad, b, contact_internal::TwistInB(u, w))) continue;
      ++skipped;
      const int last = std::min(pad.size(), (b + 1) * SurfaceElements::kBlockSize);
      for (int e = b * SurfaceElements::kBlockSize; e < last; ++e) {
        // n.v is affine and |v| convex over a triangle: their largest values are at vertices.
        double lead = -INFINITY, speed = 0.0;
        for (const Eigen::Matrix3Xd* p : {&pad.p0_B, &pad.p1_B, &pad.p2_B}) {
          const Eigen::Vector3d v = Velocity(u, w, p->col(e));
          lead = std::max(lead, pad.n_B.col(e).dot(v));
          speed = std::max(speed, v.norm());
        }
        ASSERT_LT(lead + contact_internal::kTrailingBand * speed, 0.0) << "trial " << trial << " element " << e;
      }
    }
  }
  EXPECT_GT(skipped, 1000);  // the test exercises the skip
}

TEST(RftContactBlockCull, SkippingLeavesEveryWrenchBitForBit) {
  const SurfaceElements pad = BoundedPad();
  const SurfaceElements full = WithoutSkips(pad);
  const Li2013TreersLaw quasi_static(3.48e6);
  const DynamicTermLaw dynamic(std::make_unique<Li2013TreersLaw>(3.48e6), 1.1, 1540.0);
  struct Case {
    const char* name;
    Eigen::Matrix3d R;
    double joint_height_m;
    Eigen::Vector3d v, w;
    bool skips;  // whether some block is skipped (buried, the top or back trailing)
  };
  const std::vector<Case> cases = {
      {"buried, sinking and rocking", testing::RotX(0.07), -0.004, {0.02, -0.01, -0.3}, {0.5, -0.3, 0.1}, true},
      {"buried, sliding and pitching", testing::RotY(0.2), -0.010, {0.4, 0.1, -0.05}, {0.0, 3.0, 0.0}, true},
      {"buried, rising", Eigen::Matrix3d::Identity(), -0.008, {0.0, 0.05, 0.2}, {0.2, 0.0, 0.1}, true},
      {"buried, spinning fast", testing::RotX(0.3), -0.012, {0.1, 0.0, -0.1}, {20.0, -15.0, 5.0}, false},
      {"partly submerged, tilted", testing::RotX(0.15), 0.014, {0.3, -0.1, -0.8}, {4.0, -2.0, 3.0}, false},
  };
  for (const Case& c : cases) {
    PadKinematics k;
    k.R_WB = c.R;
    k.p_WB = Eigen::Vector3d(0.0, 0.0, c.joint_height_m);
    k.v_WB_W = c.v;
    k.w_WB_W = c.w;
    int skipped = 0;
    const contact_internal::TwistInB twist(c.R.transpose() * c.v, c.R.transpose() * c.w);
    const contact_internal::PlaneDepthInB depth = contact_internal::PlaneDepthInB::Of(PlaneGround(), k);
    for (int b = 0; b < pad.block_count(); ++b)
      skipped += depth.BlockBelow(pad, b) && contact_internal::BlockTrails(pad, b, twist);
    EXPECT_EQ(skipped > 0, c.skips) << c.name << ": " << skipped << " blocks skipped";
    const std::vector<const StressLaw3D*> laws = {&quasi_static, &dynamic};
    for (const StressLaw3D* law : laws) {
      const ContactWrench a = ComputeContactWrench(pad, k, PlaneGround(), *law);
      const ContactWrench b = ComputeContactWrench(full, k, PlaneGround(), *law);
      ASSERT_GT(a.leading_elements, 0) << c.name;
      EXPECT_EQ(a.leading_elements, b.leading_elements) << c.name;
      EXPECT_EQ(a.submerged_area_m2, b.submerged_area_m2) << c.name;
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(a.force_W[i], b.force_W[i]) << c.name;
        EXPECT_EQ(a.moment_W[i], b.moment_W[i]) << c.name;
      }
    }
  }
}

// Wholly submerged elements that trail the motion at every vertex add their area in the vectorised
// pass, without the per-element code (contact_wrench_rotating.cpp, kTrailMargin): over random poses,
// depths and twists - spins from none to fast, joint speeds down to the element ramp's, buried and
// partly submerged, the soil ramp on and off - the leading elements and the submerged area are the
// per-element code's exactly and the wrench is to rounding, and the shortcut had elements to serve.
TEST(RftContactBlockCull, TrailingElementsSkipTheElementCodeAndChangeNothing) {
  const SurfaceElements pad = BoundedPad();
  const Li2013TreersLaw quasi_static(3.48e6);
  const DynamicTermLaw dynamic(std::make_unique<Li2013TreersLaw>(3.48e6), 1.1, 1540.0);
  std::mt19937 rng(30);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  long trailing_submerged = 0;
  double largest_difference = 0.0;
  for (int trial = 0; trial < 3000; ++trial) {
    PadKinematics k;
    k.R_WB = Eigen::AngleAxisd(0.6 * unit(rng), Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized())
                 .toRotationMatrix();
    k.p_WB = Eigen::Vector3d(0.0, 0.0, -0.012 + 0.040 * unit(rng));  // buried to lifted clear
    const double speed = std::pow(10.0, -5.0 + 5.0 * unit(rng));   // 10 um/s to 1 m/s
    k.v_WB_W = speed * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    k.w_WB_W = std::pow(10.0, -3.0 + 4.0 * unit(rng)) * speed / 0.0275 *
               Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    if (trial % 5 == 0) k.w_WB_W.setZero();
    k.element_ramp_speed_m_s = trial % 2 == 0 ? 1e-4 : 0.0;
    for (const StressLaw3D* law : {static_cast<const StressLaw3D*>(&quasi_static), static_cast<const StressLaw3D*>(&dynamic)}) {
      const ContactWrench a = contact_internal::RotatingWrenchOverPlane(pad, k, PlaneGround(), *law, true);
      const ContactWrench b = contact_internal::RotatingWrenchOverPlane(pad, k, PlaneGround(), *law, false);
      // An element skipped that the per-element code would have let lead, even by a sliver, would
      // be one leading element more there.
      ASSERT_EQ(a.leading_elements, b.leading_elements) << "trial " << trial;
      ASSERT_EQ(a.submerged_area_m2, b.submerged_area_m2) << "trial " << trial;
      // The two paths are separate instantiations, which the compiler may contract into fused
      // multiply-adds differently: the sums agree to rounding.
      const double force = b.force_W.norm(), moment = b.moment_W.norm() + 0.0275 * force;
      largest_difference = std::max({largest_difference, (a.force_W - b.force_W).norm() / std::max(force, 1e-300),
                                     (a.moment_W - b.moment_W).norm() / std::max(moment, 1e-300)});
      ++compared;
    }
    // Elements the shortcut is for: every vertex submerged and trailing beyond the band there.
    for (int e = 0; e < pad.size(); ++e) {
      bool trails = true;
      for (const Eigen::Matrix3Xd* p : {&pad.p0_B, &pad.p1_B, &pad.p2_B}) {
        const Eigen::Vector3d r_W = k.R_WB * p->col(e);
        const Eigen::Vector3d v = Velocity(k.v_WB_W, k.w_WB_W, r_W);
        trails &= k.p_WB.z() + r_W.z() < 0.0 &&
                  (k.R_WB * pad.n_B.col(e)).dot(v) + contact_internal::kTrailingBand * v.norm() < -1e-6 * v.norm();
      }
      trailing_submerged += trails;
    }
  }
  EXPECT_EQ(compared, 6000);
  EXPECT_LT(largest_difference, 1e-13);
  EXPECT_GT(trailing_submerged, 100000);  // the shortcut had elements to serve
}

}  // namespace
}  // namespace touchdown::rft
