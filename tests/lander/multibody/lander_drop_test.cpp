// Lander drops on the paper's Table II grounds, built in code (fixtures/paper_lander.h):
// level symmetric landing, energy with dissipation as a state, close-packed pads, tolerances.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "lander/multibody/lander_simulation.h"
#include "rft/units.h"
#include "fixtures/paper_lander.h"

namespace touchdown::lander {
namespace {

using units::kDeg;

struct CaseRun {
  std::string name;
  test::PaperLander setup;
  LanderRunResult result;
  std::array<std::string, kNumLegs> soil_under_pad;  // at rest (or at the end)
};

// lander_case_*.yaml: simulation.
LanderRunOptions CaseOptions() {
  LanderRunOptions options;
  options.duration_s = 1.0;
  options.sample_rate_hz = 1000.0;
  return options;
}

CaseRun RunCase(char ground_case, const LanderRunOptions& options) {
  CaseRun run{std::string("lander_case_") + ground_case, test::MakePaperLander(ground_case), {}, {}};
  run.setup.options = options;
  run.result = SimulateLander(run.setup);
  const StateLayout L(run.setup.model);
  const LanderPose pose = ComputePose(run.setup.model, L, run.result.final_state);
  for (int i = 0; i < kNumLegs; ++i) {
    const Eigen::Vector3d& p = pose.pads[i].p_WJ;
    run.soil_under_pad[i] = run.setup.terrain.soils[run.setup.terrain.SoilAt(p.x(), p.y())].name;
  }
  return run;
}

const CaseRun& Case(char ground_case) {
  static std::map<char, CaseRun> cache;
  auto it = cache.find(ground_case);
  if (it == cache.end()) it = cache.emplace(ground_case, RunCase(ground_case, CaseOptions())).first;
  return it->second;
}

TEST(LanderDrop, CaseASymmetricLandingIsLevelAndEven) {
  const CaseRun& run = Case('A');
  const LanderRunResult& r = run.result;
  ASSERT_TRUE(r.rest_time_s) << "the lander must come to rest";
  EXPECT_FALSE(r.tipped_over);
  for (int i = 1; i < 4; ++i) EXPECT_NEAR(r.final_penetration_m[i], r.final_penetration_m[0], 1e-9) << "pad " << i + 1;
  EXPECT_GT(r.final_penetration_m[0], 1e-3);
  EXPECT_NEAR(r.final_attitude.roll_rad, 0.0, 1e-9);
  EXPECT_NEAR(r.final_attitude.pitch_rad, 0.0, 1e-9);
  EXPECT_LT(r.max_tilt_rad, 1e-9);
  // At rest nothing moves and the held pads did not drift.
  EXPECT_LT(r.final_kinetic_J, 1e-20);
  EXPECT_LT(r.max_held_drift_m, 1e-9);
  std::printf("[ case A ] depth %.3f mm (each pad), time to rest %.1f ms, peak pad force %.1f N\n",
              r.final_penetration_m[0] * 1e3, (*r.rest_time_s - *r.first_touchdown_s) * 1e3, r.peak_pad_force_N[0]);
}

TEST(LanderDrop, EnergyIsConservedWithDissipationAsAState) {
  for (char name : {'A', 'B', 'C'}) {
    const LanderRunResult& r = Case(name).result;
    const double final_energy = r.final_kinetic_J + r.final_potential_J + r.dissipated_J;
    const double turned_over = r.initial_energy_J - r.final_potential_J;  // released energy, ~4 J
    EXPECT_GT(r.dissipated_J, 0.0);
    // The dissipated work is a state, so the balance closes to the integrator's tolerance: 5e-6 of
    // the released energy measured at the default rtol 1e-7 (1e-6 at 1e-9).
    EXPECT_NEAR(final_energy, r.initial_energy_J, 1e-5 * turned_over) << name;
  }
}

TEST(LanderDrop, ClosePackedPadsSinkLessAndTiltTheBodyTheRightWay) {
  const CaseRun& a = Case('A');
  const CaseRun& b = Case('B');
  const CaseRun& c = Case('C');
  for (const CaseRun* run : {&b, &c}) ASSERT_TRUE(run->result.rest_time_s) << run->name;
  const auto& db = b.result.final_penetration_m;
  const auto& dc = c.result.final_penetration_m;
  // B: pad 1 on CP sinks least; pad 1 (front-left) high: right side down (roll > 0), nose up (pitch > 0).
  EXPECT_EQ(b.soil_under_pad[0], "fjs1_cp");
  for (int i = 1; i < 4; ++i) EXPECT_LT(db[0], db[i]);
  EXPECT_GT(b.result.final_attitude.roll_rad, 0.0);
  EXPECT_GT(b.result.final_attitude.pitch_rad, 0.0);
  // C: pads 1 and 2 (front) on CP sink less; nose up, no roll (mirror symmetry about x-z). The
  // symmetry holds only to the mesh's: a revolved mesh splits its quads along one diagonal, so
  // it is chiral and its mirror image is a different mesh (the pads also pick up a small spin
  // about their axes). Measured between pads 1 and 2: 1.6e-3 relative (0.018 mm) and 5e-4 deg of
  // roll at 16 segments, 1e-3 at 24 - so a bound of 5e-3 relative and 0.01 deg, not rounding level.
  EXPECT_EQ(c.soil_under_pad[1], "fjs1_cp");
  EXPECT_LT(std::max(dc[0], dc[1]), std::min(dc[2], dc[3]));
  EXPECT_NEAR(dc[0], dc[1], 5e-3 * dc[0]);
  EXPECT_NEAR(dc[2], dc[3], 5e-3 * dc[2]);
  EXPECT_GT(c.result.final_attitude.pitch_rad, 0.0);
  EXPECT_NEAR(c.result.final_attitude.roll_rad, 0.0, 0.01 * kDeg);
  EXPECT_GT(c.result.final_attitude.pitch_rad, 10.0 * std::abs(c.result.final_attitude.roll_rad));
  for (const CaseRun* run : {&a, &b, &c}) {
    const auto& d = run->result.final_penetration_m;
    std::printf("[ %s ] depths %.2f %.2f %.2f %.2f mm, roll %+.3f deg, pitch %+.3f deg (paper, vacuum: within +-0.5)\n",
                run->name.c_str(), d[0] * 1e3, d[1] * 1e3, d[2] * 1e3, d[3] * 1e3,
                run->result.final_attitude.roll_rad / kDeg, run->result.final_attitude.pitch_rad / kDeg);
  }
}

// The absolute tolerances are rtol times each state's scale (lander_simulation.cpp): case B then
// lands as with the scalar atol of 1e-11 it replaced, in fewer steps (the old one resolved the
// pads' rocking about their ball joints to 1e-11 rad/s).
TEST(LanderDrop, ScaledTolerancesLandCaseBAsTheScalarOneInFewerSteps) {
  const CaseRun& scaled = Case('B');
  LanderRunOptions options = CaseOptions();
  options.scale_tolerances = false;
  const CaseRun scalar = RunCase('B', options);
  ASSERT_TRUE(scaled.result.rest_time_s && scalar.result.rest_time_s);
  std::printf("[ tolerances ] case B steps: scaled %ld, scalar atol 1e-11 %ld\n", scaled.result.solver.steps,
              scalar.result.solver.steps);
  // Within the default rtol 1e-7's own accuracy (3e-5 in depth against a reference at 1e-11,
  // docs/lander_dynamics.md): measured 1.3e-6 to 5e-6.
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(scaled.result.final_penetration_m[i], scalar.result.final_penetration_m[i],
                2e-5 * scalar.result.final_penetration_m[i]);
  EXPECT_NEAR(scaled.result.final_attitude.roll_rad, scalar.result.final_attitude.roll_rad, 1e-5 * kDeg);
  EXPECT_NEAR(scaled.result.final_attitude.pitch_rad, scalar.result.final_attitude.pitch_rad, 1e-5 * kDeg);
  EXPECT_LT(scaled.result.solver.steps, scalar.result.solver.steps);
}

}  // namespace
}  // namespace touchdown::lander

namespace touchdown::lander {
namespace {

// Across a 10 deg slope (bench_lander's Slope10_Sideways at the tests' mesh): three pads are held and
// fix the body; the fourth, lifted, could only swing about its fixed ball joint. The lander is at
// rest there, with that pad's spin stopped and its kinetic energy counted as dissipated.
TEST(LanderDrop, ThreeHeldPadsThatFixTheBodyAreARest) {
  test::PaperLander setup = test::MakePaperLander('A');
  setup.terrain.surface = std::make_shared<rft::PlaneGround>(0.0, -std::tan(10.0 * kDeg), 0.0);
  setup.initial.v_WB_W = Eigen::Vector3d(0.0, 0.5, 0.0);
  setup.initial.p_WB.z() = BodyHeightForClearance(setup.model, setup.terrain, setup.initial, setup.drop_height_m);
  setup.options = CaseOptions();
  const LanderRunResult r = SimulateLander(setup);
  ASSERT_TRUE(r.rest_time_s);
  EXPECT_FALSE(r.tipped_over);
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.back().kind, LanderEventKind::kRest);
  int held = 0;
  for (int h : r.trace.back().pad_held) held += h;
  EXPECT_EQ(held, 3);
  LanderModes modes;
  for (int i = 0; i < kNumLegs; ++i) modes.pad[i] = r.trace.back().pad_held[i] ? PadMode::kHeld : PadMode::kFree;
  const StateLayout L(setup.model);
  EXPECT_TRUE(HoldsFixTheStance(setup.model, L, modes, r.final_state));
  EXPECT_LT(r.final_kinetic_J, 1e-20);
  const double turned_over = r.initial_energy_J - r.final_potential_J;
  EXPECT_NEAR(r.final_kinetic_J + r.final_potential_J + r.dissipated_J, r.initial_energy_J, 1e-5 * turned_over);
  // Two held pads leave the body free to turn about the line through their joints.
  LanderModes two = modes;
  for (int i = 0, kept = 0; i < kNumLegs; ++i)
    if (two.pad[i] == PadMode::kHeld && ++kept > 2) two.pad[i] = PadMode::kFree;
  EXPECT_FALSE(HoldsFixTheStance(setup.model, L, two, r.final_state));
  std::printf("[ slope 10 deg ] at rest at %.4f s on three pads, tilt %.2f deg\n", *r.rest_time_s,
              r.final_attitude.tilt_rad / kDeg);
}

}  // namespace
}  // namespace touchdown::lander

namespace touchdown::lander {
namespace {

// The studies' fast model (24-segment pads, rtol 1e-5, the shipped soils, the 30 deg joint range) on
// bench_lander's slope landing, with the pads' spins' absolute tolerance as every state's (factor 1)
// and 10 times looser (the studies' pad_spin_tolerance_factor): the error test no longer resolves the
// spins' quasi-static rocking, and the landing takes far fewer steps (635 against 389). Its answers
// move well inside the accuracy contract (2 % in a loaded pad's depth, 0.1 deg in roll and pitch; the
// fast model itself is within 0.82 % and 0.025 deg of the reference): measured 0.07 % and 0.002 deg.
TEST(LanderDrop, LooserPadSpinsLandTheFastModelInFewerSteps) {
  const auto run = [](double factor) {
    test::PaperLander setup = test::MakePaperLander('A', 24, 0.10, /*shipped_soils=*/true);
    for (Leg& leg : setup.model.legs)
      leg.cone = ConeLimit{.half_angle_rad = 30.0 * kDeg, .stiffness_N_m_rad = 200.0, .damping_N_m_s_rad = 0.16};
    setup.terrain.surface = std::make_shared<rft::PlaneGround>(0.0, -std::tan(10.0 * kDeg), 0.0);
    setup.initial.v_WB_W = Eigen::Vector3d(0.0, 0.5, 0.0);
    setup.initial.p_WB.z() = BodyHeightForClearance(setup.model, setup.terrain, setup.initial, setup.drop_height_m);
    setup.options = CaseOptions();
    setup.options.integrator.rtol = 1e-5;
    setup.options.pad_spin_tolerance_factor = factor;
    return SimulateLander(setup);
  };
  const LanderRunResult tight = run(1.0), loose = run(10.0);
  ASSERT_TRUE(tight.rest_time_s && loose.rest_time_s);
  std::printf("[ spin tolerance ] slope landing steps: factor 1 %ld, factor 10 %ld\n", tight.solver.steps,
              loose.solver.steps);
  for (int i = 0; i < kNumLegs; ++i)
    EXPECT_NEAR(loose.final_penetration_m[i], tight.final_penetration_m[i], 2e-3 * tight.final_penetration_m[i]) << i;
  EXPECT_NEAR(loose.final_attitude.roll_rad, tight.final_attitude.roll_rad, 0.006 * kDeg);
  EXPECT_NEAR(loose.final_attitude.pitch_rad, tight.final_attitude.pitch_rad, 0.006 * kDeg);
  EXPECT_LT(loose.solver.steps, 0.7 * tight.solver.steps);
}

}  // namespace
}  // namespace touchdown::lander
