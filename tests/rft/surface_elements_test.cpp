// SurfaceElements::UpdateBounds and the contact sum's use of it: block boxes that skip emerged
// elements, the stored radius that tells spin from translation, and the normal classes that let a
// translating pad evaluate its law once per normal must leave every wrench as the plain element
// loop computes it (bit for bit where the classes play no part, to 1e-12 where the law sees a
// class's normal instead of a run's, equal to kSameNormal), over level and sloped ground, tilted,
// sliding and spinning pads, from first contact to full burial.
#include "rft/surface_elements.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rft/contact_wrench.h"
#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

using testing::FlatProfile;
using testing::MakeBox;
using testing::MakeRevolvedPad;
using testing::RotX;
using testing::RotZ;

TEST(RftSurfaceElements, BoundsEncloseEveryBlockAndTheRadiusIsTheFarthestVertex) {
  SurfaceElements pad = MakeRevolvedPad(FlatProfile(0.0275, 0.01, 3), 40);
  EXPECT_FALSE(pad.HasBounds());
  pad.UpdateBounds();
  ASSERT_TRUE(pad.HasBounds());
  EXPECT_EQ(pad.block_count(), (pad.size() + SurfaceElements::kBlockSize - 1) / SurfaceElements::kBlockSize);
  double r_max = 0.0;
  for (int e = 0; e < pad.size(); ++e) {
    const int b = e / SurfaceElements::kBlockSize;
    for (const Eigen::Matrix3Xd* p : {&pad.p0_B, &pad.p1_B, &pad.p2_B}) {
      EXPECT_TRUE((p->col(e).array() >= pad.block_min_B.col(b).array()).all());
      EXPECT_TRUE((p->col(e).array() <= pad.block_max_B.col(b).array()).all());
      r_max = std::max(r_max, p->col(e).norm());
    }
  }
  EXPECT_NEAR(pad.max_vertex_radius_m, r_max, 1e-15);
  // A pad's elements are laid out ring by ring: its rims and bottom make thin boxes.
  pad.Resize(3);
  EXPECT_FALSE(pad.HasBounds());  // resizing drops bounds that no longer fit
}

TEST(RftSurfaceElements, BlockConesHoldEveryNormalAndTheirSpheresEveryVertex) {
  SurfaceElements pad = MakeRevolvedPad(FlatProfile(0.0275, 0.01, 3), 64);
  pad.UpdateBounds();
  ASSERT_EQ(pad.block_normal_axis_B.cols(), pad.block_count());
  int flat_blocks = 0;
  for (int b = 0; b < pad.block_count(); ++b) {
    EXPECT_NEAR(pad.block_normal_axis_B.col(b).norm(), 1.0, 1e-15);
    double spread = 0.0;
    const int last = std::min(pad.size(), (b + 1) * SurfaceElements::kBlockSize);
    for (int e = b * SurfaceElements::kBlockSize; e < last; ++e) {
      spread = std::max(spread, (pad.n_B.col(e) - pad.block_normal_axis_B.col(b)).norm());
      for (const Eigen::Matrix3Xd* p : {&pad.p0_B, &pad.p1_B, &pad.p2_B})
        EXPECT_LE((p->col(e) - pad.block_centre_B.col(b)).norm(), pad.block_radius_m[b]);
    }
    EXPECT_EQ(spread, pad.block_normal_spread[b]);
    flat_blocks += pad.block_normal_spread[b] == 0.0;
  }
  // The bottom and top discs' blocks lie in one plane each: a cone of zero width.
  EXPECT_GE(flat_blocks, 2 * 64 / SurfaceElements::kBlockSize);
}

TEST(RftSurfaceElements, NormalClassesGroupEqualNormalsUpToTheirCap) {
  // A revolved flat pad: one class for the bottom, one for the top, one per sector of the side wall.
  SurfaceElements pad = MakeRevolvedPad(FlatProfile(0.0275, 0.01, 3), 64);
  pad.UpdateBounds();
  EXPECT_EQ(pad.class_normal_B.cols(), 2 + 64);
  for (int e = 0; e < pad.size(); ++e) {
    const int c = pad.normal_class[e];
    ASSERT_GE(c, 0);
    EXPECT_LE((pad.n_B.col(e) - pad.class_normal_B.col(c)).cwiseAbs().sum(), SurfaceElements::kSameNormal);
  }
  // More distinct normals than the cap: the first kMaxNormalClasses get classes, the rest none.
  SurfaceElements many = MakeRevolvedPad(FlatProfile(0.0275, 0.01, 3), 400);
  many.UpdateBounds();
  EXPECT_EQ(many.class_normal_B.cols(), SurfaceElements::kMaxNormalClasses);
  EXPECT_GT((many.normal_class.array() < 0).count(), 0);
}

TEST(RftSurfaceElements, BoundedContactEqualsThePlainLoop) {
  const Li2013TreersLaw law(3.48e6);
  for (const bool box : {false, true}) {
    const SurfaceElements plain = box ? MakeBox(Eigen::Vector3d(-0.03, -0.02, 0), Eigen::Vector3d(0.03, 0.02, 0.012), 6)
                                      : MakeRevolvedPad(FlatProfile(0.0275, 0.01, 4), 48);
    SurfaceElements bounded = plain;
    bounded.UpdateBounds();
    for (const double slope : {0.0, 0.2}) {
      const PlaneGround ground(0.0, slope, -0.5 * slope);
      for (const double tilt : {0.0, 0.15, 0.6})
        for (const double depth : {0.0005, 0.004, 0.011, 0.03})
          for (const double spin : {0.0, 1e-13, 2.0}) {
            PadKinematics k;
            k.R_WB = RotZ(0.3) * RotX(tilt);
            k.p_WB = Eigen::Vector3d(0.01, -0.02, -depth);
            k.v_WB_W = Eigen::Vector3d(0.3, 0.1, -1.0);
            k.w_WB_W = Eigen::Vector3d(0.5, -1.0, 0.2) * spin;
            const ContactWrench a = ComputeContactWrench(plain, k, ground, law);
            const ContactWrench b = ComputeContactWrench(bounded, k, ground, law);
            const std::string where = "box " + std::to_string(box) + " slope " + std::to_string(slope) + " tilt " +
                                      std::to_string(tilt) + " depth " + std::to_string(depth) + " spin " +
                                      std::to_string(spin);
            const double scale = 1e-12 * std::max(1.0, a.force_W.norm());
            EXPECT_LE((a.force_W - b.force_W).norm(), scale) << where;
            EXPECT_LE((a.moment_W - b.moment_W).norm(), 0.1 * scale) << where;  // lever arms < 0.1 m
            // With spin, bounded elements over a plane take the batched rotating path
            // (contact_wrench_rotating.cpp): the same sums grouped differently, so rounding only.
            if (spin > 1.0) {
              EXPECT_NEAR(a.submerged_area_m2, b.submerged_area_m2, 1e-14 * a.submerged_area_m2) << where;
            } else {
              EXPECT_EQ(a.submerged_area_m2, b.submerged_area_m2) << where;
            }
            EXPECT_EQ(a.leading_elements, b.leading_elements) << where;
          }
    }
  }
}

TEST(RftSurfaceElements, SpinBelowOneBillionthOfTheSpeedCountsAsTranslation) {
  // A rounding-size spin (as a pad dropped straight down picks up) takes the translation path:
  // the wrench equals the pure translation's to 1e-9 relative.
  SurfaceElements pad = MakeRevolvedPad(FlatProfile(0.0275, 0.01, 3), 64);
  pad.UpdateBounds();
  const Li2013TreersLaw law(3.48e6);
  const PlaneGround ground;
  PadKinematics k;
  k.p_WB = Eigen::Vector3d(0, 0, -0.008);
  k.v_WB_W = Eigen::Vector3d(0, 0, -0.02);  // slowing down near the stop
  const ContactWrench still = ComputeContactWrench(pad, k, ground, law);
  k.w_WB_W = Eigen::Vector3d(1e-11, -2e-11, 0.0);  // |w| r / |v| ~ 3e-11
  const ContactWrench noise = ComputeContactWrench(pad, k, ground, law);
  EXPECT_EQ(still.force_W, noise.force_W);
  k.w_WB_W = Eigen::Vector3d(1e-3, 0.0, 0.0);  // a real rotation: the per-element path
  const ContactWrench turning = ComputeContactWrench(pad, k, ground, law);
  EXPECT_GT((turning.moment_W - still.moment_W).norm(), 1e-9 * still.force_W.norm() * 0.0275);
}

}  // namespace
}  // namespace touchdown::rft
