// The two samples either side of a measured stop (diagnose_fit.h StopSamples): found on the
// record, and left out of the force residual, so that a stop shifted within one sample period no
// longer costs the whole peak force.
#include <cmath>

#include <gtest/gtest.h>

#include "drop_tests/dataset/synth.h"
#include "drop_tests/gap/diagnose_fit.h"

namespace touchdown::gap {
namespace {

TEST(StopSamples, AreTheTwoEitherSideOfTheSteepestFallPastThePeak) {
  // A rise, a plateau with a ripple, the stop between samples 6 and 7, rest at the weight.
  const std::vector<double> f{0, 40, 80, 120, 140, 139, 141, 16, 15.5, 16.2, 15.9};
  const SampleRange stop = StopSamples(f);
  EXPECT_EQ(stop.begin, 6u);
  EXPECT_EQ(stop.end, 8u);
  // A record that ends before the stop has none.
  const SampleRange none = StopSamples({0, 10, 20, 30, 40});
  EXPECT_EQ(none.begin, none.end);
}

// One drop sampled at instants at 5 kHz, its stop somewhere within a sample period.
dataset::Dataset InstantDrop() {
  dataset::SynthSpec s;
  s.name = "stop_samples";
  s.source = "stop_samples.yaml";
  s.sample_rate_hz = 5000.0;
  s.rest_duration_s = 0.01;
  s.sensor_sampling = pad::SensorSampling::kInstantaneous;
  s.noise = dataset::SynthNoise{0.05, 1e-7, 0.0, 0.0, 0.01, 1e-7};
  s.drops.push_back({"flat", "fjs1_lp", rft::Atmosphere::kVacuum, 0.9, std::nullopt, 9.81, 0});
  dataset::Dataset ds = dataset::Synthesize(s);
  ds.directory = "in-memory";
  return ds;
}

TEST(StopSamples, AStopShiftedWithinASampleNoLongerCostsThePeakForce) {
  const dataset::Dataset ds = InstantDrop();
  const FitProblem skipped = MakeFitProblem(ds, {false}, 1);
  const FitProblem counted = MakeFitProblem(ds, {false}, 1, false);
  ASSERT_TRUE(skipped.stop_samples_skipped);
  const FitDrop& d = skipped.drops[0];
  EXPECT_EQ(d.stop_skip_end - d.stop_skip_begin, 2u);
  EXPECT_EQ(counted.drops[0].stop_skip_begin, counted.drops[0].stop_skip_end);

  FitResult truth;
  truth.zeta_N_m3 = {skipped.soils[0].zeta_N_m3};
  truth.sensor = skipped.sensor;
  truth.sensor.sampling = pad::SensorSampling::kInstantaneous;
  // Shifts of 0.95 of a sample either way: one of them (both, unless the stop sits within 5 % of a
  // sample time) moves the simulated stop across a sample.
  const double period = 1.0 / 5000.0;
  std::vector<Recording> shifts;
  for (const double dt : {-0.95 * period, 0.0, 0.95 * period}) shifts.push_back({truth.sensor, dt});
  const std::vector<double> with_skip = TrainingCostsUnder(skipped, truth, shifts);
  const std::vector<double> with_all = TrainingCostsUnder(counted, truth, shifts);
  ASSERT_EQ(with_skip.size(), 3u);
  // Unshifted, the stop's samples agree: leaving them out changes the cost by their noise only.
  EXPECT_NEAR(with_skip[1], with_all[1], 0.1 * with_all[1]);
  // Shifted, counting them adds a step of about (peak - weight)^2 / peak^2 / samples: the worse
  // shift costs several times what the same shift costs without them.
  const double worst_all = std::max(with_all[0], with_all[2]), worst_skip = std::max(with_skip[0], with_skip[2]);
  const double samples = static_cast<double>(ds.drops[0].trace.size());
  EXPECT_GT(worst_all - worst_skip, 0.5 / samples);
  EXPECT_LT(worst_skip, 0.5 * worst_all);
}

}  // namespace
}  // namespace touchdown::gap
