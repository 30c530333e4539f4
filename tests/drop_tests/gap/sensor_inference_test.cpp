// The sensor inferred from the data (drop_tests/gap/sensor_inference.h): on drops synthesised
// through a known sampling, with replicates and nothing hidden, the inference names that sampling
// and no load cell, and its evidence names the runner-up. (The independent generator's sets, with
// anti-alias filters and ringing load cells drawn at random, are tools/gapbench's; this checks the
// choice itself on data whose sensor is certain.)
#include <gtest/gtest.h>

#include "drop_tests/dataset/synth.h"
#include "drop_tests/gap/sensor_inference.h"

namespace touchdown::gap {
namespace {

dataset::Dataset Drops(pad::SensorSampling sampling) {
  dataset::SynthSpec s;
  s.name = "sensor_inference";
  s.source = "sensor_inference.yaml";
  s.seed = 7;
  s.rest_duration_s = 0.008;
  s.sample_rate_hz = 2000.0;
  s.sensor_sampling = sampling;
  for (const char* pad : {"flat", "curved"})
    for (double v : {0.8, 1.4})
      for (int trial = 0; trial < 2; ++trial)
        s.drops.push_back({pad, "fjs1_lp", rft::Atmosphere::kVacuum, v, std::nullopt, 9.81, trial});
  s.noise = dataset::SynthNoise{0.5, 1e-5, 1.0, 2e-5, 0.1, 5e-6};
  dataset::Dataset ds = dataset::Synthesize(s);
  ds.directory = "in-memory";
  return ds;
}

TEST(SensorInference, NamesTheSamplingTheDataWereRecordedWith) {
  for (const pad::SensorSampling truth : {pad::SensorSampling::kInstantaneous, pad::SensorSampling::kPeriodMean}) {
    const dataset::Dataset ds = Drops(truth);
    FitProblem p = MakeFitProblem(ds, std::vector<bool>(ds.drops.size(), false), 2);
    const SensorInference s = InferSensor(p, 10.0);
    EXPECT_EQ(s.chosen.sampling, truth) << s.evidence;
    EXPECT_EQ(s.chosen.lowpass_order, 0) << s.evidence;
    EXPECT_EQ(s.chosen.load_cell_hz, 0.0) << s.evidence;
    EXPECT_EQ(p.sensor, s.chosen);
    int chosen = 0;
    for (const SensorCandidate& c : s.candidates) chosen += c.chosen;
    EXPECT_EQ(chosen, 1);
    EXPECT_NE(s.evidence.find("than the next"), std::string::npos) << s.evidence;
  }
}

}  // namespace
}  // namespace touchdown::gap
