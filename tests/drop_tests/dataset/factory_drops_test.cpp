// synth and calibrate build their drops with the drop factory (drop_tests/drop/drop_factory.h):
// a noise-free synthetic trace is what RunDrop's drop records, bit for bit, and calibrate's
// regressor is the factory's rig integral at a unit zeta scaled to the drop's gravity.
#include <gtest/gtest.h>

#include <cmath>

#include "drop_tests/dataset/calibrate.h"
#include "drop_tests/dataset/sensor_model.h"
#include "drop_tests/dataset/synth.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::dataset {
namespace {

constexpr double kMoonG = 1.62, kTrueZeta = 2.7e6;

SynthSpec CleanSpec() {
  SynthSpec s;
  s.name = "factory";
  s.source = "factory.yaml";
  s.rest_duration_s = 0.01;
  s.noise = SynthNoise{0, 0, 0, 0, 0, 0};
  s.true_zeta_N_m3 = {{"fjs1_lp", kTrueZeta}};
  s.drops.push_back({"curved", "fjs1_lp", rft::Atmosphere::kAir, 1.3, 2.1, kMoonG, 0});
  return s;
}

TEST(FactoryDrops, SynthRecordsTheFactorysDrop) {
  SynthSpec spec = CleanSpec();
  model::Effect damping{"rate_damping", {}};
  for (const model::EffectParameterInfo& q : model::FindEffect("rate_damping").parameters)
    damping.values.push_back(2 * q.start + q.scale);
  spec.hidden_effect = damping;
  // Both sensors: the value at each sample time, and the mean over each sample period.
  std::vector<double> instantaneous_force;
  for (pad::SensorSampling sampling : {pad::SensorSampling::kInstantaneous, pad::SensorSampling::kPeriodMean}) {
    spec.sensor_sampling = sampling;
    const Dataset ds = Synthesize(spec);
    ASSERT_EQ(ds.drops.size(), 1u);

    drop::DropConditions c;
    c.impact_speed_m_s = 1.3;
    c.mass_kg = 2.1;
    c.gravity_m_s2 = kMoonG;
    c.zeta_N_m3 = kTrueZeta;
    c.atmosphere = rft::Atmosphere::kAir;
    c.effects = model::MakeEffectTerms({damping});
    drop::DropRunOptions options;
    options.rig.rest_duration_s = spec.rest_duration_s + std::abs(c.effects.sensor_dt_s) + 2.0 / spec.sample_rate_hz;
    options.rig.sample_rate_hz = SimulationRateFor_Hz(spec.sample_rate_hz);  // as synth simulates
    const drop::PadDrop drop = drop::RunDrop(drop::ResolveDrop(io::LoadPad("curved"), io::LoadSoil("fjs1_lp"), c, options));
    const DatasetTrace& tr = ds.drops[0].trace;
    ASSERT_GT(tr.size(), 20u);
    for (size_t i = 0; i < tr.size(); ++i) {
      const pad::RecordedSample r = pad::RecordedSampleOf(drop.result, kMoonG, c.effects, tr.t_s[i],
                                                          spec.sensor_sampling, 1.0 / spec.sample_rate_hz);
      ASSERT_EQ(tr.force_N[i], r.force_N) << i;
      ASSERT_EQ(tr.penetration_m[i], r.penetration_m) << i;
    }
    if (sampling == pad::SensorSampling::kInstantaneous) instantaneous_force = tr.force_N;
    else EXPECT_NE(tr.force_N, instantaneous_force);  // the two sensors record different samples
  }
}

TEST(FactoryDrops, CalibrateRegressesOnTheFactorysRigIntegral) {
  // Forces that are exactly zeta times the factory's unit-zeta rig force at the drop's gravity
  // plus the soil's dynamic term lambda rho v^2 I_3(d) at the trace's sink rate (1 m/s, exact by
  // differences): calibrate finds that zeta (to rounding), so its regressor is the factory's and
  // it takes the soil's dynamic term off first (without: 2 % too high).
  const rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  const auto intrusion = drop::MakeRigIntrusion(io::LoadPad("curved").profile);
  const double unit_at_g = drop::ZetaAtGravity(drop::DropSoil(soil, 1.0, std::nullopt), kMoonG);
  EXPECT_EQ(unit_at_g, kMoonG / soil.reference_gravity_m_s2);
  const double lambda_rho = rft::WithSoilDynamicTerm({}, soil).inertial_lambda * soil.bulk_density_kg_m3;
  ASSERT_GT(lambda_rho, 0.0);  // the shipped soil carries the term
  Dataset ds;
  ds.directory = ".";
  DatasetDrop d;
  d.drop_id = "d0";
  d.pad = "curved";
  d.soil = "fjs1_lp";
  d.atmosphere = rft::Atmosphere::kVacuum;
  d.impact_speed_m_s = 1.0;
  d.pad_mass_kg = 1.6;
  d.gravity_m_s2 = kMoonG;
  for (int i = 1; i <= 40; ++i) {
    const double depth = 1e-3 * i;
    d.trace.t_s.push_back(1e-3 * i);
    d.trace.penetration_m.push_back(depth);
    d.trace.force_N.push_back(kTrueZeta * unit_at_g * intrusion->VerticalForce(depth, 1.0) +
                              lambda_rho * intrusion->CosinePowerIntegral(depth, 3));
  }
  ds.drops.push_back(d);
  const std::vector<ZetaFit> fits = CalibrateZeta(ds, CalibrationOptions{});
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_NEAR(fits[0].zeta_N_m3, kTrueZeta, 1e-12 * kTrueZeta);
  EXPECT_LT(fits[0].residual_rms_N, 1e-9);
}

}  // namespace
}  // namespace touchdown::dataset
