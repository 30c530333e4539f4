// The free (6-DOF) pad drop against the rig drop and its own energy bookkeeping.
#include "lander/pad/free_drop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "drop_tests/io/catalog.h"
#include "drop_tests/drop/pad_drop.h"
#include "footpad_geom/revolve.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::pad {
namespace {

TEST(FreeDrop, VerticalLevelDropMatchesTheRigDrop) {
  // A level pad dropped straight down has no reason to tilt or slide: it is the rig drop, with
  // the 3D contact on the revolved mesh instead of the profile integral.
  const io::PadSpec pad = io::LoadPad("flat");
  const rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, soil, 9.81, {});
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  const FreeDropResult free = RunFreeDrop(pad.body, law, rft::PlaneGround(), in);
  drop::DropConditions c;
  c.impact_speed_m_s = 1.0;
  const RigDropResult rig = drop::RunPadDrop(pad, soil, c).result;
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
  const io::PadSpec spec = io::LoadPad("curved");
  const geom::PadBody body = geom::RevolveProfileToBody(spec.profile, 24, spec.mass_kg,
                                                        Eigen::Vector3d(0.0, 0.0, spec.profile.thickness_m()));
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, io::LoadSoil("fjs1_lp"), 9.81, {});
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.horizontal_speed_m_s = 0.2;
  const FreeDropResult r = RunFreeDrop(body, law, rft::PlaneGround(), in);
  EXPECT_GT(r.horizontal_travel_m, 1e-3);
  EXPECT_GT(r.trace.back().horizontal_m, 0.0);
  EXPECT_GT(r.final_penetration_m, 0.0);
  EXPECT_LT(r.final_tilt_deg, 10.0);
  const double input = r.impact_energy_J + r.gravity_work_J;
  EXPECT_NEAR(r.dissipated_energy_J + r.final_kinetic_energy_J, input, 1e-5 * input);
}

}  // namespace
}  // namespace touchdown::pad

namespace touchdown::pad {
namespace {

// The free drop's absolute tolerances are rtol times each state's scale (free_drop.cpp). A tilted
// drop with them matches a run 100 times tighter, and needs several times fewer steps than the
// scalar atol of 1e-11 (in every unit) it replaced, which resolved the wobble about the symmetric
// axis, driven by the mesh's small asymmetries, to 1e-11 rad/s.
TEST(FreeDrop, ScaledTolerancesMatchATighterRunInFewerSteps) {
  const io::PadSpec spec = io::LoadPad("flat");
  const geom::PadBody body = geom::RevolveProfileToBody(spec.profile, 48, spec.mass_kg,
                                                        Eigen::Vector3d(0.0, 0.0, spec.profile.thickness_m()));
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, io::LoadSoil("fjs1_lp"), 9.81, {});
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  in.tilt_rad = 5.0 * std::numbers::pi / 180.0;
  const FreeDropOptions defaults;
  const FreeDropResult r = RunFreeDrop(body, law, rft::PlaneGround(), in, defaults);
  FreeDropOptions tight = defaults;
  tight.integrator.rtol = 1e-10;
  tight.integrator.max_num_steps = 200000;
  const FreeDropResult ref = RunFreeDrop(body, law, rft::PlaneGround(), in, tight);
  FreeDropOptions scalar = defaults;
  scalar.integrator.component_atol.assign(14, 1e-11);
  scalar.integrator.max_num_steps = 200000;
  const FreeDropResult old = RunFreeDrop(body, law, rft::PlaneGround(), in, scalar);
  std::printf("[ tolerances ] steps: scaled %ld, scalar 1e-11 %ld, rtol 1e-10 %ld; depth %.7f / %.7f mm, "
              "tilt %.6f / %.6f deg\n",
              r.solver.steps, old.solver.steps, ref.solver.steps, 1e3 * r.final_penetration_m,
              1e3 * ref.final_penetration_m, r.final_tilt_deg, ref.final_tilt_deg);
  EXPECT_NEAR(r.final_penetration_m, ref.final_penetration_m, 1e-5 * ref.final_penetration_m);
  EXPECT_NEAR(r.final_tilt_deg, ref.final_tilt_deg, 1e-3 * ref.final_tilt_deg + 1e-6);
  EXPECT_NEAR(r.horizontal_travel_m, ref.horizontal_travel_m, 1e-8);
  EXPECT_NEAR(r.time_to_rest_s, ref.time_to_rest_s, 1e-6);
  EXPECT_LT(3 * r.solver.steps, old.solver.steps);
  const double input = r.impact_energy_J + r.gravity_work_J;
  EXPECT_NEAR(r.dissipated_energy_J + r.final_kinetic_energy_J, input, 1e-6 * input);
}

// Touchdown is t = 0 with the lowest point exactly on the surface: nothing is submerged in the
// first sample, whatever the root finder's rounding.
TEST(FreeDrop, FirstSampleIsAtTheSurface) {
  const io::PadSpec pad = io::LoadPad("flat");
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, io::LoadSoil("fjs1_lp"), 9.81, {});
  FreeDropInput in;
  in.impact_speed_m_s = 1.0;
  const FreeDropResult r = RunFreeDrop(pad.body, law, rft::PlaneGround(), in);
  ASSERT_FALSE(r.trace.empty());
  EXPECT_EQ(r.trace.front().t_s, 0.0);
  EXPECT_EQ(r.trace.front().penetration_m, 0.0);
  EXPECT_EQ(r.trace.front().force_N, 0.0);
}

}  // namespace
}  // namespace touchdown::pad

// Issue 13, section 7: every shipped pad (data/pads/*.yaml), tilted about x and about y, lands as a
// free drop at three speeds. The hex pad tilted 5 or 10 degrees about x lands on a whole edge; it
// failed at t = 0 (CV_CONV_FAILURE, h = 2e-31) because a triangle touching the surface only to
// rounding was clipped as if two of its vertices were submerged (rft/contact_internal.h,
// ClipAndIntegrate), and several other tilted drops took a smaller kick of the same kind without
// failing. Tilts 0, 5, 10, 20 and 30 degrees, a coarse set: about 2 s of CPU per pad (one test per
// pad, so ctest runs them side by side); 1-degree steps would take a minute per pad.
namespace touchdown::pad {
namespace {

std::vector<std::string> ShippedPads() {
  namespace fs = std::filesystem;
  std::vector<std::string> pads;
  for (const fs::directory_entry& e : fs::directory_iterator(fs::path(io::DataDirectory()) / "pads"))
    if (e.path().extension() == ".yaml") pads.push_back(e.path().stem().string());
  std::sort(pads.begin(), pads.end());
  return pads;
}

class ShippedPadFreeDrop : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedPadFreeDrop, LandsAtEveryTiltAboutXAndY) {
  const io::PadSpec pad = io::LoadPad(GetParam());
  const rft::SoilContactModel law = rft::MakeSoilContactModel(rft::LawKind::kLi2013, io::LoadSoil("fjs1_lp"), 9.81, {});
  int drops = 0;
  for (const double speed : {0.5, 1.0, 2.0}) {
    for (const double tilt_deg : {0.0, 5.0, 10.0, 20.0, 30.0}) {
      for (const char* axis : {"x", "y"}) {
        if (tilt_deg == 0.0 && std::string(axis) == "y") continue;  // the same drop as about x
        SCOPED_TRACE(GetParam() + " at " + std::to_string(speed) + " m/s, tilted " + std::to_string(tilt_deg) +
                     " deg about " + axis);
        FreeDropInput in;
        in.impact_speed_m_s = speed;
        in.tilt_rad = tilt_deg * std::numbers::pi / 180.0;
        in.tilt_axis = axis;
        FreeDropResult r;
        ASSERT_NO_THROW(r = RunFreeDrop(pad.body, law, rft::PlaneGround(), in));
        ++drops;
        EXPECT_GT(r.final_penetration_m, 0.0);
        EXPECT_LT(r.final_penetration_m, 0.1);
        EXPECT_GT(r.time_to_rest_s, 0.0);
        EXPECT_NEAR(r.touchdown_tilt_deg, tilt_deg, 1e-6);
        // The first sample is at the surface: no force yet but rounding (the defect's was 1e12 N).
        EXPECT_LT(std::abs(r.trace.front().force_N), 1e-9);
        const double input = r.impact_energy_J + r.gravity_work_J;
        EXPECT_NEAR(r.dissipated_energy_J + r.final_kinetic_energy_J, input, 1e-5 * input);
      }
    }
  }
  EXPECT_EQ(drops, 3 * 9);
}

INSTANTIATE_TEST_SUITE_P(Issue13, ShippedPadFreeDrop, ::testing::ValuesIn(ShippedPads()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(FreeDrop, EveryShippedPadIsSwept) { EXPECT_GE(ShippedPads().size(), 4u); }

}  // namespace
}  // namespace touchdown::pad
