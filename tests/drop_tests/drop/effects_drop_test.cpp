// Every term of the effect library switched on in a catalogue drop keeps the energy accounted for.
#include <gtest/gtest.h>

#include <cmath>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/model/effects.h"

namespace touchdown::drop {
namespace {

class EveryEffect : public ::testing::TestWithParam<const char*> {};

// Every term switched on in a catalogue drop: the energy is accounted for, no rebound.
TEST_P(EveryEffect, PadDropKeepsEnergyBookkeeping) {
  const model::EffectInfo& info = model::FindEffect(GetParam());
  model::Effect e{info.id, {}};
  for (const model::EffectParameterInfo& p : info.parameters) e.values.push_back(p.start != 0.0 ? 3 * p.start : 2 * p.scale);
  DropConditions c;
  c.impact_speed_m_s = 1.2;
  c.atmosphere = rft::Atmosphere::kAir;
  c.effects = model::MakeEffectTerms({e});
  for (const char* pad_name : {"flat", "curved"}) {
    const PadDrop drop = RunDrop(ResolveDrop(io::LoadPad(pad_name), io::LoadSoil("fjs1_lp"), c));
    const pad::RigDropResult& r = drop.result;
    const double input = r.impact_energy_J + r.gravity_work_J;
    EXPECT_NEAR(r.dissipated_energy_J, input, 1e-6 * input) << pad_name;
    EXPECT_GT(r.final_penetration_m, 0.0);
    for (const pad::DropSample& s : r.trace) {
      EXPECT_GE(s.velocity_m_s, -1e-12);
      EXPECT_TRUE(std::isfinite(s.force_N));
    }
  }
}
INSTANTIATE_TEST_SUITE_P(Library, EveryEffect,
                         ::testing::Values("inertial_drag", "rate_damping", "added_mass", "added_mass_plug", "compaction_peak",
                                           "depth_exponent", "gas_cushion", "sensor_offset"));

}  // namespace
}  // namespace touchdown::drop
