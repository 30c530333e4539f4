// The rig drop: final depth against the closed-form energy balance, energy bookkeeping,
// no rebound, no creep at rest, and the stop found as an event.
#include "lander/pad/rig_drop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "footpad_geom/axisymmetric_intrusion.h"
#include "tests/lander/pad/test_rig.h"

namespace touchdown::pad {
namespace {

using namespace test_rig;
constexpr double kH = 0.016;

double WallAlpha() { return rft::Li2013Alpha(std::numbers::pi / 2, std::numbers::pi / 2).z; }

VerticalResistance FlatPad(const geom::AxisymmetricIntrusion& pad) {
  return [&pad](double d, double) { return pad.VerticalForce(d, kZeta); };
}

// Depth at which the work of F_z(d) = zeta (pi r^2 d + a_w pi r d^2) equals 0.5 m v^2 + m g d.
double ClosedFormFlatDepth(double v) {
  auto residual = [v](double d) {
    const double work = kZeta * (std::numbers::pi * kR * kR * d * d / 2 + WallAlpha() * std::numbers::pi * kR * d * d * d / 3);
    return work - 0.5 * kMass * v * v - kMass * kG * d;
  };
  double lo = 1e-9, hi = kH;  // all paper speeds stop shallower than the pad thickness
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (residual(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

class RigDropSpeeds : public ::testing::TestWithParam<double> {};

TEST_P(RigDropSpeeds, FlatPadDepthMatchesEnergyBalance) {
  const geom::AxisymmetricIntrusion pad(geom::MakeFlatProfile(kR, kH), rft::Li2013Law{});
  const RigDropResult r = RunRig(FlatPad(pad), kMass, kG, GetParam());
  const double expected = ClosedFormFlatDepth(GetParam());
  ASSERT_LT(expected, kH);
  EXPECT_NEAR(r.final_penetration_m, expected, 1e-4 * expected);
}

TEST_P(RigDropSpeeds, EnergyIsAccountedFor) {
  // Kinetic energy at touchdown plus the weight's work during the stroke is all dissipated.
  const geom::AxisymmetricIntrusion pad(geom::MakeFlatProfile(kR, kH), rft::Li2013Law{});
  const RigDropResult r = RunRig(FlatPad(pad), kMass, kG, GetParam());
  EXPECT_NEAR(r.impact_energy_J, 0.5 * kMass * GetParam() * GetParam(), 1e-9);
  const double input = r.impact_energy_J + r.gravity_work_J;
  EXPECT_NEAR(r.dissipated_energy_J, input, 1e-6 * input);
}

INSTANTIATE_TEST_SUITE_P(PaperSpeeds, RigDropSpeeds, ::testing::Values(0.7, 1.0, 1.5));

TEST(RigDrop, NoReboundAndNoCreepAtRest) {
  const geom::AxisymmetricIntrusion pad(geom::MakeFlatProfile(kR, kH), rft::Li2013Law{});
  RigDropOptions options;
  options.rest_duration_s = 1.0;
  const RigDropResult r = RunRig(FlatPad(pad), kMass, kG, 1.0, options);
  double max_depth = 0.0;
  for (const DropSample& s : r.trace) {
    EXPECT_GE(s.velocity_m_s, -1e-12) << "rebound at t " << s.t_s;
    max_depth = std::max(max_depth, s.penetration_m);
  }
  EXPECT_NEAR(max_depth, r.final_penetration_m, 1e-12);
  EXPECT_LT(std::abs(r.rest_creep_m), 1e-6);
  EXPECT_NEAR(r.trace.back().t_s, r.time_to_rest_s + 1.0, 1e-3);
  EXPECT_NEAR(r.trace.back().force_N, kMass * kG, 1e-9);  // the soil carries the weight
}

TEST(RigDrop, StopIsAnEventNotASample) {
  const geom::AxisymmetricIntrusion pad(geom::MakeFlatProfile(kR, kH), rft::Li2013Law{});
  const RigDropResult r = RunRig(FlatPad(pad), kMass, kG, 1.0);
  // The stop time is off the 1 kHz grid and the trace holds a sample exactly there, at rest.
  EXPECT_GT(std::abs(r.time_to_rest_s * 1000 - std::round(r.time_to_rest_s * 1000)), 1e-9);
  bool found = false;
  for (const DropSample& s : r.trace) {
    if (s.t_s != r.time_to_rest_s) continue;
    found = true;
    EXPECT_EQ(s.velocity_m_s, 0.0);
  }
  EXPECT_TRUE(found);
  // Against a closed-form-free check: a linear spring F = k d stops at a quarter period.
  const double k = 1e4;
  const RigDropResult spring = RunRig([k](double d, double) { return k * d; }, 1.0, 1e-12, 1.0);
  EXPECT_NEAR(spring.time_to_rest_s, 0.25 * 2 * std::numbers::pi / std::sqrt(k), 1e-7);
  EXPECT_NEAR(spring.final_penetration_m, 1.0 / std::sqrt(k), 1e-8);
}

TEST(RigDrop, SamplesAtOneKilohertzFromTouchdown) {
  const geom::AxisymmetricIntrusion pad(geom::MakeFlatProfile(kR, kH), rft::Li2013Law{});
  const RigDropResult r = RunRig(FlatPad(pad), kMass, kG, 1.5);
  ASSERT_GE(r.trace.size(), 3u);
  EXPECT_EQ(r.trace[0].t_s, 0.0);
  EXPECT_EQ(r.trace[0].penetration_m, 0.0);
  EXPECT_NEAR(r.trace[0].velocity_m_s, 1.5, 1e-9);  // touchdown speed reached through the approach
  EXPECT_NEAR(r.trace[1].t_s, 1e-3, 1e-15);
  EXPECT_NEAR(r.trace[2].t_s, 2e-3, 1e-15);
}

TEST(RigDrop, PeakForceAndDecelerationAreAtTheStop) {
  // Quasi-static RFT force grows with depth, and depth grows until the stop.
  const geom::AxisymmetricIntrusion pad(geom::MakeFlatProfile(kR, kH), rft::Li2013Law{});
  const RigDropResult r = RunRig(FlatPad(pad), kMass, kG, 1.0);
  const double f_stop = pad.VerticalForce(r.final_penetration_m, kZeta);
  EXPECT_NEAR(r.peak_force_N, f_stop, 1e-9 * f_stop);
  EXPECT_NEAR(r.max_deceleration_m_s2, (f_stop - kMass * kG) / kMass, 1e-6);
}

TEST(RigDrop, ZeroSpeedPlacementSinksToStaticEquilibriumOvershoot) {
  // Placed with no speed, the pad sinks until the work of F equals m g d (F = m g at half way
  // for a linear law): with F = k d, d_final = 2 m g / k.
  const double k = 5e4;
  const RigDropResult r = RunRig([k](double d, double) { return k * d; }, 2.0, 9.81, 0.0);
  EXPECT_NEAR(r.final_penetration_m, 2 * 2.0 * 9.81 / k, 1e-9);
}

TEST(RigDrop, BadArgumentsAreRejected) {
  auto f = [](double d, double) { return 1e5 * d; };
  EXPECT_THROW(RunRig(f, 0.0, 9.81, 1.0), std::invalid_argument);
  EXPECT_THROW(RunRig(f, 1.0, -1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(RunRig(f, 1.0, 9.81, NAN), std::invalid_argument);
  EXPECT_THROW(RunRigDrop({{1.0}, nullptr, {9.81, 1.0}, {}}), std::invalid_argument);  // no soil
}

TEST(RigDrop, PadThatNeverStopsIsAFailureNotAHang) {
  RigDropOptions options;
  options.max_stroke_duration_s = 0.5;
  EXPECT_THROW(RunRig([](double, double) { return 0.0; }, 1.0, 9.81, 1.0, options), integ::IntegrationFailure);
}

}  // namespace
}  // namespace touchdown::pad
