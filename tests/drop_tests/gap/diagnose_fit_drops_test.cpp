// diagnose's fitter builds its drops with the drop factory (drop_tests/drop/drop_factory.h): what
// it simulates for a dataset drop under a fitted model is, bit for bit, what RunDrop's drop
// of the same pad, soil, atmosphere, zeta override and effects records.
#include "drop_tests/gap/diagnose_fit.h"
#include "lander/pad/effect_soil_response.h"

#include <gtest/gtest.h>

#include <cmath>

#include "drop_tests/dataset/synth.h"
#include "drop_tests/gap/fit_objective.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"

namespace touchdown::gap {
namespace {

// A dataset of one drop simulated by synth (its defaults otherwise), kept in memory.
dataset::Dataset OneDrop(const dataset::SynthDrop& drop) {
  dataset::SynthSpec spec;
  spec.name = "one_drop";
  spec.source = "one_drop.yaml";
  spec.rest_duration_s = 0.008;
  spec.drops.push_back(drop);
  dataset::Dataset ds = dataset::Synthesize(spec);
  ds.directory = "in-memory";
  return ds;
}

TEST(DiagnoseFitDrops, SimulatedRecordIsTheFactorysDrop) {
  const dataset::Dataset ds = OneDrop({"curved", "fjs1_lp", rft::Atmosphere::kAir, 1.2, 1.9, 1.62, 0});
  const FitProblem p = MakeFitProblem(ds, {false}, 1);
  ASSERT_EQ(p.drops.size(), 1u);
  const FitDrop& d = p.drops[0];

  FitResult model;
  model.zeta_N_m3 = {2.3e6};
  model::Effect damping{"rate_damping", {}};
  for (const model::EffectParameterInfo& q : model::FindEffect("rate_damping").parameters)
    damping.values.push_back(2 * q.start + q.scale);
  model.effects = {damping};
  const std::optional<dataset::DatasetTrace> fitted = SimulateRecorded(p, d, model);
  ASSERT_TRUE(fitted.has_value());

  drop::DropConditions c;
  c.impact_speed_m_s = 1.2;
  c.mass_kg = 1.9;
  c.gravity_m_s2 = 1.62;
  c.zeta_N_m3 = 2.3e6;
  c.atmosphere = rft::Atmosphere::kAir;
  c.effects = model.terms();
  drop::DropRunOptions options;
  options.rig = p.rig;
  const drop::PadDrop drop = drop::RunDrop(drop::ResolveDrop(io::LoadPad("curved"), io::LoadSoil("fjs1_lp"), c, options));
  const dataset::DatasetTrace& tr = ds.drops[0].trace;
  ASSERT_EQ(fitted->size(), tr.size());
  for (size_t i = 0; i < tr.size(); ++i) {
    const pad::RecordedSample r =
        pad::RecordedSampleOf(drop.result, 1.62, c.effects, tr.t_s[i], model.sensor.sampling, d.sample_period_s);
    ASSERT_EQ(fitted->force_N[i], r.force_N) << i;
    ASSERT_EQ(fitted->penetration_m[i], r.penetration_m) << i;
  }
}

// An imported record's penetration is zeroed where the free fall put the pad at its recorded
// touchdown (dataset::PenetrationZero::kTouchdown): with the drop's recorded t = 0 dt after the
// true touchdown, the simulated record's penetration is the surface-zeroed one less v dt + g dt^2 / 2,
// v the drop's impact speed with its nuisance, at every sample; its force is unchanged.
TEST(DiagnoseFitDrops, ATouchdownZeroedRecordMovesItsZeroAlongTheFreeFall) {
  const dataset::Dataset ds = OneDrop({"flat", "fjs1_lp", rft::Atmosphere::kVacuum, 1.1, 1.6, 9.81, 0});
  const FitProblem p = MakeFitProblem(ds, {false}, 1);
  FitDrop surface = p.drops[0];
  FitDrop touchdown = surface;
  touchdown.penetration_zero = dataset::PenetrationZero::kTouchdown;
  FitResult model;
  model.zeta_N_m3 = {2.3e6};
  const fit::ModelValues m = fit::ValuesOf(model);
  DropNuisance b;
  b.time_s = 1.5e-3;
  b.log_speed = 0.02;
  const std::optional<pad::RigDropResult> sim = fit::Simulate(p, surface, m, m.Terms(), b);
  ASSERT_TRUE(sim.has_value());
  const std::optional<dataset::DatasetTrace> a = fit::Record(surface, m, m.Terms(), b, sim);
  const std::optional<dataset::DatasetTrace> z = fit::Record(touchdown, m, m.Terms(), b, sim);
  ASSERT_TRUE(a && z);
  const double v = 1.1 * std::exp(0.02), dt = 1.5e-3;
  const double zero = v * dt + 0.5 * 9.81 * dt * dt;
  for (size_t i = 0; i < a->size(); ++i) {
    ASSERT_NEAR(z->penetration_m[i], a->penetration_m[i] - zero, 1e-15) << i;
    ASSERT_EQ(z->force_N[i], a->force_N[i]) << i;
  }
  // With no time offset the two zeros agree.
  b.time_s = 0.0;
  const std::optional<pad::RigDropResult> at0 = fit::Simulate(p, surface, m, m.Terms(), b);
  EXPECT_EQ(fit::Record(touchdown, m, m.Terms(), b, at0)->penetration_m, fit::Record(surface, m, m.Terms(), b, at0)->penetration_m);
}

}  // namespace
}  // namespace touchdown::gap
