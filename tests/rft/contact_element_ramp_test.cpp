// The element ramp (PadKinematics::element_ramp_speed_m_s): an element slower than the ramp has its
// stress scaled by its speed over the ramp's, so the wrench is continuous through v = 0 at every
// element, whatever the pad's spin. Checked against closed forms of RFT's direction-only stress:
// a translation scales the whole wrench by |v| / ramp; a spin about the pad's axis at a rate whose
// rim speed is below the ramp gives a torque linear in the rate; a spin whose slowest element is
// above the ramp gives RFT's torque unchanged; and the vectorised and general paths agree.
#include <gtest/gtest.h>

#include <cmath>

#include "rft/contact_wrench.h"
#include "rft/li2013_3d.h"
#include "tests/rft/pad_meshes.h"

namespace touchdown::rft {
namespace {

constexpr double kRamp = 1e-4;  // the lander's default soil ramp [m/s]

SurfaceElements Pad(bool bounds) {
  SurfaceElements pad = testing::MakeRevolvedPad(testing::FlatProfile(0.05, 0.016, 3), 48);
  if (bounds) pad.UpdateBounds();
  return pad;
}

PadKinematics Sunk(const Eigen::Vector3d& v_W, const Eigen::Vector3d& w_W, double ramp) {
  PadKinematics k;
  k.R_WB = testing::RotX(0.1);
  k.p_WB = Eigen::Vector3d(0.0, 0.0, -0.012);
  k.v_WB_W = v_W;
  k.w_WB_W = w_W;
  k.element_ramp_speed_m_s = ramp;
  return k;
}

// Without a ramp RFT depends on the direction of motion only; with it, a pad translating below the
// ramp carries |v| / ramp of that wrench, on both the class (translation) path and the general one.
TEST(RftElementRamp, TranslationBelowTheRampScalesTheWrenchBySpeedOverRamp) {
  const Li2013TreersLaw law(3.48e6);
  const Eigen::Vector3d dir = Eigen::Vector3d(0.3, -0.1, -1.0).normalized();
  for (bool bounds : {true, false}) {
    const SurfaceElements pad = Pad(bounds);
    const ContactWrench rft = ComputeContactWrench(pad, Sunk(dir, Eigen::Vector3d::Zero(), 0.0), PlaneGround(), law);
    ASSERT_GT(rft.force_W.norm(), 1.0);
    for (double speed : {2e-5, 5e-5, 9.9e-5}) {
      const ContactWrench w =
          ComputeContactWrench(pad, Sunk(speed * dir, Eigen::Vector3d::Zero(), kRamp), PlaneGround(), law);
      EXPECT_LE((w.force_W - (speed / kRamp) * rft.force_W).norm(), 1e-12 * rft.force_W.norm()) << speed;
      EXPECT_LE((w.moment_W - (speed / kRamp) * rft.moment_W).norm(), 1e-12 * rft.moment_W.norm()) << speed;
      EXPECT_EQ(w.submerged_area_m2, rft.submerged_area_m2);
    }
    // Above the ramp the wrench is RFT's, to the bit.
    const ContactWrench fast = ComputeContactWrench(pad, Sunk(0.5 * dir, Eigen::Vector3d::Zero(), kRamp), PlaneGround(), law);
    const ContactWrench fast_rft = ComputeContactWrench(pad, Sunk(0.5 * dir, Eigen::Vector3d::Zero(), 0.0), PlaneGround(), law);
    EXPECT_EQ(fast.force_W, fast_rft.force_W);
    EXPECT_EQ(fast.moment_W, fast_rft.moment_W);
  }
}

// A level pad spinning about its own vertical axis (no translation): every element's velocity is
// horizontal, w r. Without a ramp the torque is RFT's sideways resistance whatever the rate, a
// Coulomb torque with a jump at w = 0. With the ramp, at rim speeds below it every element is
// scaled by w r / ramp: the torque is linear in w through 0 (odd, proportional), the continuity
// the lander's creeping pads need.
TEST(RftElementRamp, SpinBelowTheRampGivesATorqueLinearInTheRate) {
  const Li2013TreersLaw law(3.48e6);
  for (bool bounds : {true, false}) {
    const SurfaceElements pad = Pad(bounds);
    auto torque = [&](double w, double ramp) {
      PadKinematics k = Sunk(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, w), ramp);
      k.R_WB = Eigen::Matrix3d::Identity();
      return ComputeContactWrench(pad, k, PlaneGround(), law).moment_W.z();
    };
    const double rim = 0.05;
    const double w1 = 0.2 * kRamp / rim, w2 = 0.4 * kRamp / rim;  // rim speeds 0.2 and 0.4 of the ramp
    const double coulomb = torque(w1, 0.0);
    ASSERT_LT(coulomb, 0.0);                                     // resists the spin
    EXPECT_NEAR(torque(1e3 * w1, 0.0), coulomb, 1e-9 * std::abs(coulomb));  // rate-independent
    const double t1 = torque(w1, kRamp), t2 = torque(w2, kRamp);
    EXPECT_LT(t1, 0.0);
    EXPECT_NEAR(t2, 2.0 * t1, 1e-9 * std::abs(t2));
    // Odd in w to the mesh's chirality: each quad is split along one diagonal, so the revolved pad
    // is not its own mirror image (6e-5 relative, the same without the ramp).
    EXPECT_NEAR(torque(-w1, kRamp), -t1, 1e-4 * std::abs(t1));
    EXPECT_NEAR(torque(-w1, 0.0), -coulomb, 1e-4 * std::abs(coulomb));
    EXPECT_LT(std::abs(t1), 0.2 * std::abs(coulomb));  // below the ramp: a fraction of RFT's
  }
}

// A tilted pad sliding and spinning slowly, so that part of it is below the ramp and the leading
// boundary cuts elements: the vectorised rotating path and the general element-by-element path
// give the same wrench with the ramp as without; the ramp takes off less than the share of slow
// elements could carry.
TEST(RftElementRamp, VectorisedAndGeneralPathsAgree) {
  const Li2013TreersLaw law(3.48e6);
  const SurfaceElements bounded = Pad(true), general_pad = Pad(false);
  const PadKinematics k = Sunk(Eigen::Vector3d(4e-5, 1e-5, -3e-5), Eigen::Vector3d(2e-4, -4e-4, 6e-4), kRamp);
  PadKinematics no_ramp = k;
  no_ramp.element_ramp_speed_m_s = 0.0;
  const ContactWrench fast = ComputeContactWrench(bounded, k, PlaneGround(), law);
  const ContactWrench general = ComputeContactWrench(general_pad, k, PlaneGround(), law);
  const ContactWrench rft = ComputeContactWrench(bounded, no_ramp, PlaneGround(), law);
  ASSERT_GT(general.leading_elements, 0);
  EXPECT_EQ(fast.leading_elements, general.leading_elements);
  EXPECT_LE((fast.force_W - general.force_W).norm(), 1e-12 * general.force_W.norm());
  EXPECT_LE((fast.moment_W - general.moment_W).norm(), 1e-12 * general.moment_W.norm());
  EXPECT_LT(general.force_W.norm(), rft.force_W.norm());  // every element is below the ramp here
  EXPECT_GT(general.force_W.norm(), 0.1 * rft.force_W.norm());
}

}  // namespace
}  // namespace touchdown::rft
