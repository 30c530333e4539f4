// Sweep files: every bundled sweep, and one with converted units (degrees, N/cm^3), loaded,
// written with WriteSweepPlan and loaded again give the same plan (its digest covers pads, soils,
// model, parameters and options), the same drops and limits; a second write is the same text.
#include <gtest/gtest.h>

#include <fstream>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/sweep/sweep_plan.h"
#include "tests/round_trip.h"

namespace touchdown::sweep {
namespace {

struct SweepPlanRoundTrip : testing_scratch::ScratchDirTest {};

void ExpectSamePlan(const SweepPlan& a, const SweepPlan& b) {
  EXPECT_EQ(a.DigestText(), b.DigestText());
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.size(), b.size());
  EXPECT_EQ(a.rig.integrator.max_rhs_evaluations, b.rig.integrator.max_rhs_evaluations);
  EXPECT_EQ(a.rig.integrator.max_wall_time_s, b.rig.integrator.max_wall_time_s);
  EXPECT_EQ(a.lander.has_value(), b.lander.has_value());
  for (int64_t i : {int64_t{0}, a.size() / 2, a.size() - 1}) {
    const SweepDropParams p = a.DropAt(i), q = b.DropAt(i);
    EXPECT_EQ(p.pad, q.pad);
    EXPECT_EQ(p.soil, q.soil);
    EXPECT_EQ(p.impact_speed_m_s, q.impact_speed_m_s);
    EXPECT_EQ(p.mass_kg, q.mass_kg);
    EXPECT_EQ(p.gravity_m_s2, q.gravity_m_s2);
    EXPECT_EQ(p.tilt_rad, q.tilt_rad);
    EXPECT_EQ(p.zeta_N_m3, q.zeta_N_m3);
    EXPECT_EQ(p.pad_soils, q.pad_soils);
    EXPECT_EQ(p.given, q.given);
  }
}

void RoundTrip(const std::string& source, const std::string& first, const std::string& second) {
  testing_scratch::ExpectRoundTrip(
      LoadSweepPlan(source), first, second, WriteSweepPlan, [](const std::string& path) { return LoadSweepPlan(path); },
      ExpectSamePlan);
}

TEST_F(SweepPlanRoundTrip, BundledSweeps) {
  for (const char* name : {"pad_trade", "mesh_pad_trade", "lunar_monte_carlo", "lander_ground_cases",
                           "lander_speed_soil"}) {
    SCOPED_TRACE(name);
    RoundTrip(io::DataDirectory() + "/sweeps/" + name + ".yaml", Path(std::string(name) + "_1.yaml"),
              Path(std::string(name) + "_2.yaml"));
  }
}

TEST_F(SweepPlanRoundTrip, ConvertedUnitsAndOptions) {
  std::ofstream(Path("units.yaml")) << "schema_version: 1\ntype: sweep\nname: units\ntraces: full\n"
                                       "rest_duration_s: 0.05\nmax_drop_evaluations: 300000\n"
                                       "fixed: {pad: flat, impact_speed_m_s: 1.1}\n"
                                       "grid: {tilt_deg: [0, 5, 12.5], zeta_N_cm3: {from: 1.5, to: 2.5, count: 3}}\n"
                                       "random: {samples: 4, seed: 11, soil: {choice: [fjs1_lp, fjs1_cp]},\n"
                                       "         horizontal_speed_m_s: {uniform: [0.1, 0.3]}}\n";
  RoundTrip(Path("units.yaml"), Path("units_1.yaml"), Path("units_2.yaml"));
}

}  // namespace
}  // namespace touchdown::sweep
