// A sweep's pad drops are the drop factory's drops (drop_tests/drop/drop_factory.h): each
// record's trace is RunDrop's for the same pad, soil, gravity, mass and zeta override, bit
// for bit, and its zeta is the override scaled to the drop's gravity.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/sweep/sweep_drop.h"
#include "drop_tests/sweep/sweep_plan.h"
#include "rft/units.h"

namespace touchdown::sweep {
namespace {

TEST(SweepFactoryDrops, RecordsAreTheFactorysDrops) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("touchdown_sweep_factory_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(file) << R"(schema_version: 1
type: sweep
name: factory
traces: full
rest_duration_s: 0.01
fixed: {soil: fjs1_lp, gravity_m_s2: 1.62}
grid: {pad: [flat, curved], impact_speed_m_s: {from: 0.6, to: 1.4, count: 2}}
random: {samples: 2, seed: 3, pad_mass_kg: {uniform: [1.2, 2.0]}, zeta_N_cm3: {choice: [2.5, 4.5]}}
)";
  const SweepPlan plan = LoadSweepPlan(file.string());
  std::filesystem::remove(file);
  const SweepModels models(plan);
  ASSERT_EQ(plan.size(), 8);
  for (int64_t i = 0; i < plan.size(); ++i) {
    const SweepDropParams p = plan.DropAt(i);
    ASSERT_TRUE(p.zeta_N_m3.has_value());
    const DropRecord r = SimulateSweepDrop(models, i);
    ASSERT_TRUE(r.ok) << r.failure;

    drop::DropConditions c;
    c.impact_speed_m_s = p.impact_speed_m_s;
    c.mass_kg = p.mass_kg;
    c.gravity_m_s2 = p.gravity_m_s2;
    c.zeta_N_m3 = p.zeta_N_m3;
    drop::DropRunOptions options;
    options.rig = plan.rig;
    const drop::PadDrop own = drop::RunDrop(drop::ResolveDrop(plan.pads[p.pad], plan.soils[p.soil], c, options));
    ASSERT_EQ(r.trace.size(), own.result.trace.size()) << i;
    for (size_t k = 0; k < r.trace.size(); ++k) {
      ASSERT_EQ(r.trace[k].force_N, own.result.trace[k].force_N) << i << " " << k;
      ASSERT_EQ(r.trace[k].penetration_m, own.result.trace[k].penetration_m) << i << " " << k;
    }
    EXPECT_EQ(r.final_penetration_m, own.result.final_penetration_m);
    const rft::SoilParameters& soil = plan.soils[p.soil];
    EXPECT_EQ(r.zeta_N_cm3, units::ZetaToN_cm3(*p.zeta_N_m3 * 1.62 / soil.reference_gravity_m_s2));
    EXPECT_EQ(r.zeta_N_cm3, units::ZetaToN_cm3(drop::ZetaAtGravity(drop::DropSoil(soil, p.zeta_N_m3, std::nullopt), 1.62)));
  }
}

}  // namespace
}  // namespace touchdown::sweep
