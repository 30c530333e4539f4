// Issue 13, section 7: a triangle that touches the surface only to rounding. The rotating path
// (contact_wrench_rotating.cpp) decides which elements touch from the depths of its vectorised
// pass and clips them with depths recomputed per element; the two can round differently for a
// vertex on the surface. ClipAndIntegrate took "no vertex below" for "two below", and the hex pad
// landing on an edge got 1e12 N at t = 0.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numbers>

#include "drop_tests/io/catalog.h"
#include "lander/pad/pad_pose.h"
#include "rft/contact_internal.h"
#include "rft/contact_wrench.h"
#include "rft/stress_law_3d_factory.h"

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

// The hex pad tilted about x lands on a whole edge (many vertices at one depth). Within rounding
// of the surface, spinning slowly (the rotating path) or not, the wrench is rounding-sized: it
// grows from zero with the depth, never jumps.
TEST(ContactClip, HexPadOnItsEdgeHasNoSpuriousForce) {
  const io::PadSpec pad = io::LoadPad("hex");
  const auto law = MakeStressLaw3D("li2013", io::LoadSoil("fjs1_lp"), 9.81);
  for (const double tilt_deg : {5.0, 10.0}) {
    const Eigen::Matrix3d R = pad::TiltRotation(pad::TiltAxis::kX, tilt_deg * std::numbers::pi / 180.0);
    for (const double spin : {0.0, -5.4e-7, 1e-3}) {
      for (const double depth : {-1e-18, 0.0, 1e-19, 1e-18, 1e-17, 1e-16}) {
        SCOPED_TRACE(testing::Message() << tilt_deg << " deg, spin " << spin << " rad/s, depth " << depth << " m");
        PadKinematics k{R, pad::PlaceAtDepth(pad.body, R, depth), Eigen::Vector3d(0.0, 0.0, -1.0),
                        Eigen::Vector3d(spin, 0.0, 0.0)};
        const ContactWrench w = ComputeContactWrench(pad.body.surface, k, PlaneGround(), *law);
        EXPECT_LT(w.force_W.norm(), 1e-12);
        EXPECT_LT(w.moment_W.norm(), 1e-12);
        EXPECT_LT(w.submerged_area_m2, 1e-12);
      }
    }
  }
}

// The state at touchdown of `touchdown drop --pad hex --soil fjs1_lp --speed 1 --free --tilt-deg 5`
// (p_WC, q_WB, v_WC, w_B), on which the right-hand side returned 5e12 N.
TEST(ContactClip, HexPadTouchdownStateOfIssue13) {
  const io::PadSpec pad = io::LoadPad("hex");
  const auto law = MakeStressLaw3D("li2013", io::LoadSoil("fjs1_lp"), 9.81);
  const Eigen::Vector3d p_WC(1.4392125832560127e-18, 0.00069724594193307503, 0.011743511887971163);
  const Eigen::Quaterniond q(0.99904822158426054, 0.043619387310304569, 6.0453897080618375e-21,
                             4.3460556768933539e-22);
  const Eigen::Vector3d v_WC(1.2403368089982267e-19, -2.3811895166984525e-10, -0.99999995223221172);
  const Eigen::Vector3d w_B(-5.4456585518553173e-07, 7.9361597937968307e-17, 1.2701133929881294e-18);
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  const Eigen::Vector3d w_W = R * w_B, p_WB = p_WC - R * pad.body.com_B;
  const PadKinematics k{R, p_WB, v_WC + w_W.cross(p_WB - p_WC), w_W};
  const ContactWrench w = ComputeContactWrench(pad.body.surface, k, PlaneGround(), *law);
  EXPECT_LT(w.force_W.norm(), 1e-12);
  EXPECT_LT(w.moment_W.norm(), 1e-12);
}

}  // namespace
}  // namespace touchdown::rft
