// A triangle that touches the surface only to rounding. The rotating path
// (contact_wrench_rotating.cpp) decides which elements touch from the depths of its vectorised
// pass and clips them with depths recomputed per element; the two can round differently for a
// vertex on the surface. ClipAndIntegrate took "no vertex below" for "two below", and the hex pad
// landing on an edge got 1e12 N at t = 0.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "rft/contact_internal.h"
#include "rft/contact_wrench.h"
#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

using contact_internal::ClipAndIntegrate;
using contact_internal::Submerged;
using contact_internal::Vec;

TEST(ContactClip, NoVertexBelowTheSurfaceIsNothingSubmerged) {
  const Vec p[3] = {{0.0, 0.0, 0.0}, {0.003, 0.0, 0.0}, {0.0, 0.003, 0.0}};
  // Two nearly equal depths: taken for "two below", the corner fraction d0 / (d0 - d2) was 3e14.
  for (const auto& d : {std::array<double, 3>{-2.3587214394752559e-4, 0.0, -2.3587214394752491e-4},
                        std::array<double, 3>{0.0, 0.0, 0.0}, std::array<double, 3>{-1e-3, -2e-3, -0.0}}) {
    const Submerged s = ClipAndIntegrate<true>(4.5e-6, d.data(), p);
    EXPECT_EQ(s.area, 0.0);
    EXPECT_EQ(s.depth_integral, 0.0);
    EXPECT_EQ(s.depth_moment.x, 0.0);
    EXPECT_EQ(s.area_moment.y, 0.0);
    EXPECT_EQ(s.area_rate, 0.0);
  }
}

// A hexagonal prism as big as the paper's round pads (circumradius 50 mm, 16 mm thick; the
// catalogue's `hex` pad): two of its bottom edges run along x, so tilted about x it lands on a
// whole edge. Its bottom is split into an inner and an outer ring, so more vertices share depths.
SurfaceElements HexPad() { return testing::MakeRevolvedPad({{0.0, 0.0}, {0.025, 0.0}, {0.05, 0.0}, {0.05, 0.016}}, 6); }

// The reference point that puts the pad's lowest vertex `depth_m` below level ground at z = 0.
Eigen::Vector3d PlaceAtDepth(const SurfaceElements& s, const Eigen::Matrix3d& R, double depth_m) {
  double lowest = INFINITY;
  for (const Eigen::Matrix3Xd* vertices : {&s.p0_B, &s.p1_B, &s.p2_B})
    lowest = std::min(lowest, (R.row(2) * *vertices).minCoeff());
  return {0.0, 0.0, -depth_m - lowest};
}

const Li2013TreersLaw kLaw(3.48e6);  // fjs1_lp's zeta at Earth gravity, N/m^3

// The hex pad tilted about x lands on a whole edge (many vertices at one depth). Within rounding
// of the surface, spinning slowly (the rotating path) or not, the wrench is rounding-sized: it
// grows from zero with the depth, never jumps.
TEST(ContactClip, HexPadOnItsEdgeHasNoSpuriousForce) {
  const SurfaceElements pad = HexPad();
  for (const double tilt_deg : {5.0, 10.0}) {
    const Eigen::Matrix3d R = testing::RotX(tilt_deg * std::numbers::pi / 180.0);
    for (const double spin : {0.0, -5.4e-7, 1e-3}) {
      for (const double depth : {-1e-18, 0.0, 1e-19, 1e-18, 1e-17, 1e-16}) {
        SCOPED_TRACE(::testing::Message() << tilt_deg << " deg, spin " << spin << " rad/s, depth " << depth << " m");
        PadKinematics k{R, PlaceAtDepth(pad, R, depth), Eigen::Vector3d(0.0, 0.0, -1.0),
                        Eigen::Vector3d(spin, 0.0, 0.0)};
        const ContactWrench w = ComputeContactWrench(pad, k, PlaneGround(), kLaw);
        EXPECT_LT(w.force_W.norm(), 1e-12);
        EXPECT_LT(w.moment_W.norm(), 1e-12);
        EXPECT_LT(w.submerged_area_m2, 1e-12);
      }
    }
  }
}

// The attitude and motion at touchdown of `touchdown drop --pad hex --soil fjs1_lp --speed 1
// --free --tilt-deg 5` (q_WB, v_WC, w_B), on which the right-hand side returned 5e12 N, with the
// lowest vertex on the surface to rounding.
TEST(ContactClip, HexPadTouchdownStateThatGaveFiveTeraNewtons) {
  const SurfaceElements pad = HexPad();
  const Eigen::Quaterniond q(0.99904822158426054, 0.043619387310304569, 6.0453897080618375e-21,
                             4.3460556768933539e-22);
  const Eigen::Vector3d v_W(1.2403368089982267e-19, -2.3811895166984525e-10, -0.99999995223221172);
  const Eigen::Vector3d w_B(-5.4456585518553173e-07, 7.9361597937968307e-17, 1.2701133929881294e-18);
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  for (const double depth : {-1e-18, 0.0, 1e-18}) {
    const PadKinematics k{R, PlaceAtDepth(pad, R, depth), v_W, R * w_B};
    const ContactWrench w = ComputeContactWrench(pad, k, PlaneGround(), kLaw);
    EXPECT_LT(w.force_W.norm(), 1e-12) << depth;
    EXPECT_LT(w.moment_W.norm(), 1e-12) << depth;
  }
}

}  // namespace
}  // namespace touchdown::rft
