// The free (6-DOF) pad drop against the rig drop and its own energy bookkeeping.
#include "drop_tests/free_drop.h"

#include <gtest/gtest.h>

#include <cmath>

#include "drop_tests/catalog.h"
#include "drop_tests/pad_drop.h"
#include "footpad_geom/revolve.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::drop {
namespace {

TEST(FreeDrop, VerticalLevelDropMatchesTheRigDrop) {
  // A level pad dropped straight down has no reason to tilt or slide: it is the rig drop, with
  // the 3D contact on the revolved mesh instead of the profile integral.
  const PadSpec pad = LoadPad("flat");
  const rft::SoilParameters soil = LoadSoil("fjs1_lp");
  const auto law = rft::MakeStressLaw3D("li2013", soil, 9.81);
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  const FreeDropResult free = RunFreeDrop(pad.body, *law, rft::PlaneGround(), in);
  DropConditions c;
  c.impact_speed_m_s = 1.0;
  const RigDropResult rig = RunPadDrop(pad, soil, c).result;
  EXPECT_NEAR(free.final_penetration_m, rig.final_penetration_m, 2e-3 * rig.final_penetration_m);
  EXPECT_NEAR(free.peak_force_N, rig.peak_force_N, 5e-3 * rig.peak_force_N);
  EXPECT_NEAR(free.final_tilt_deg, 0.0, 1e-9);
  EXPECT_NEAR(free.horizontal_travel_m, 0.0, 1e-12);
  // Energy: kinetic at touchdown + the weight's work = work against the soil (+ the tiny
  // kinetic energy left below the rest threshold).
  const double input = free.impact_energy_J + free.gravity_work_J;
  EXPECT_NEAR(free.dissipated_energy_J + free.final_kinetic_energy_J, input, 1e-6 * input);
}

TEST(FreeDrop, SidewaysDropTravelsAndStaysLevelEnough) {
  // A coarse revolved curved pad (fast) landing with a horizontal speed: it must come to rest,
  // travel forward (+x), balance its energy, and report its final tilt.
  const PadSpec spec = LoadPad("curved");
  const geom::PadBody body = geom::RevolveProfileToBody(spec.profile, 24, spec.mass_kg,
                                                        Eigen::Vector3d(0.0, 0.0, spec.profile.thickness_m()));
  const auto law = rft::MakeStressLaw3D("li2013", LoadSoil("fjs1_lp"), 9.81);
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.horizontal_speed_m_s = 0.2;
  const FreeDropResult r = RunFreeDrop(body, *law, rft::PlaneGround(), in);
  EXPECT_GT(r.horizontal_travel_m, 1e-3);
  EXPECT_GT(r.trace.back().horizontal_m, 0.0);
  EXPECT_GT(r.final_penetration_m, 0.0);
  EXPECT_LT(r.final_tilt_deg, 10.0);
  const double input = r.impact_energy_J + r.gravity_work_J;
  EXPECT_NEAR(r.dissipated_energy_J + r.final_kinetic_energy_J, input, 1e-5 * input);
}

}  // namespace
}  // namespace touchdown::drop
