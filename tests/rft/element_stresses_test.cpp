// Per-element soil stresses for outputs (rft/element_stresses.h): each element's force is its share
// of ComputeContactWrench's sum, and the stresses are that force per area, split along the normal.
#include "rft/element_stresses.h"

#include <gtest/gtest.h>

#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

// A flat pad (radius 5 cm, 16 mm thick, 64 sectors) tilted 10 degrees, its frame origin 8 mm below the
// level surface.
PadKinematics ElementStressesPose(const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
  PadKinematics k;
  k.R_WB = testing::RotX(0.17453292519943295);
  k.p_WB = Eigen::Vector3d(0.0, 0.0, -0.008);
  k.v_WB_W = v;
  k.w_WB_W = w;
  return k;
}

Eigen::Vector3d SumOfElementForces(const ElementStresses& s) { return s.force_W.rowwise().sum(); }

TEST(RftElementStresses, ElementForcesSumToTheContactWrench) {
  const SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(0.05, 0.016, 2), 64);
  const Li2013TreersLaw law(3.48e6);
  const PlaneGround ground;
  ElementStresses s;
  // Sinking and sliding (the translating path), and spinning (the per-element path): the contact
  // reuses one stress per class of equal normals while translating (1e-12 relative).
  for (const auto& [v, w] : {std::pair{Eigen::Vector3d(0.3, 0.0, -1.0), Eigen::Vector3d::Zero().eval()},
                             std::pair{Eigen::Vector3d(0.0, 0.2, -0.5), Eigen::Vector3d(2.0, -1.0, 4.0)}}) {
    const PadKinematics k = ElementStressesPose(v, w);
    ComputeElementStresses(pad, k, ground, law, DepthLaw{}, &s);
    const ContactWrench whole = ComputeContactWrench(pad, k, ground, law);
    ASSERT_GT(whole.force_W.norm(), 10.0);
    EXPECT_LT((SumOfElementForces(s) - whole.force_W).norm(), 1e-10 * whole.force_W.norm());
    EXPECT_EQ(s.leading.sum(), whole.leading_elements);
  }
}

TEST(RftElementStresses, PowerDepthLawIsAppliedPerElement) {
  const SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(0.05, 0.016, 2), 64);
  const Li2013TreersLaw law(3.48e6);
  PadLevelTerms terms;
  terms.depth = {0.7, 0.01};
  const PadKinematics k = ElementStressesPose(Eigen::Vector3d(0.3, 0.0, -1.0), Eigen::Vector3d::Zero());
  ElementStresses s;
  ComputeElementStresses(pad, k, PlaneGround(), law, terms.depth, &s);
  const ContactWrench whole = ComputeContactWrench(pad, k, PlaneGround(), law, terms);
  EXPECT_LT((SumOfElementForces(s) - whole.force_W).norm(), 1e-10 * whole.force_W.norm());
}

TEST(RftElementStresses, StressesAreTheForcePerAreaAlongAndAcrossTheNormal) {
  const SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(0.05, 0.016, 2), 64);
  const Li2013TreersLaw law(3.48e6);
  const PlaneGround ground(0.001, 0.05, 0.0);  // a slope: depth follows the surface
  const PadKinematics k = ElementStressesPose(Eigen::Vector3d(0.3, 0.0, -1.0), Eigen::Vector3d::Zero());
  ElementStresses s;
  ComputeElementStresses(pad, k, ground, law, DepthLaw{}, &s);
  ASSERT_EQ(s.normal_Pa.size(), pad.size());
  int submerged = 0, above = 0;
  for (int i = 0; i < pad.size(); ++i) {
    const Eigen::Vector3d n = k.R_WB * pad.n_B.col(i);
    const Eigen::Vector3d f = s.force_W.col(i);
    const double a = pad.area_m2[i];
    EXPECT_NEAR(s.normal_Pa[i] * a, -f.dot(n), 1e-12 * (1.0 + f.norm()));
    EXPECT_NEAR(s.shear_Pa[i] * a, (f - f.dot(n) * n).norm(), 1e-12 * (1.0 + f.norm()));
    const Eigen::Vector3d c = k.p_WB + k.R_WB * (pad.p0_B.col(i) + pad.p1_B.col(i) + pad.p2_B.col(i)) / 3.0;
    EXPECT_NEAR(s.depth_m[i], ground.Height(c.x(), c.y()) - c.z(), 1e-15);
    // An element wholly above the surface feels nothing and leads nothing.
    const double d0 = ground.Depth(k.p_WB + k.R_WB * pad.p0_B.col(i));
    const double d1 = ground.Depth(k.p_WB + k.R_WB * pad.p1_B.col(i));
    const double d2 = ground.Depth(k.p_WB + k.R_WB * pad.p2_B.col(i));
    if (std::max({d0, d1, d2}) < 0.0) {
      ++above;
      EXPECT_EQ(f.norm(), 0.0);
      EXPECT_EQ(s.leading[i], 0);
    } else if (std::min({d0, d1, d2}) > 0.0 && s.leading[i] == 1) {
      ++submerged;
      EXPECT_GT(s.normal_Pa[i], 0.0);  // compression on a leading, submerged face
    }
  }
  EXPECT_GT(above, 0);
  EXPECT_GT(submerged, 0);
}

}  // namespace
}  // namespace touchdown::rft
