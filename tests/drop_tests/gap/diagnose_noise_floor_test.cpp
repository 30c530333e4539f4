// diagnose's sensor-noise floor: read at rest and pooled over a dataset's drops, it recovers the
// noise a synthetic dataset was made with, reads no noise where there is none (the stroke's own
// curvature does not leak in), and falls back to each drop's stroke when the records have no rest.
#include "drop_tests/gap/diagnose_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "drop_tests/dataset/synth.h"

namespace touchdown::gap {
namespace {

// The model-gap tests' 12 drops (tests/drop_tests/gap/diagnose_test.cpp): 1 kHz, 8 ms at rest.
dataset::SynthSpec TwelveDrops(unsigned long long seed, double rest_duration_s) {
  dataset::SynthSpec s;
  s.name = "noise_floor";
  s.source = "noise_floor.yaml";
  s.seed = seed;
  s.rest_duration_s = rest_duration_s;
  for (const char* pad : {"flat", "curved"})
    for (rft::Atmosphere atm : {rft::Atmosphere::kAir, rft::Atmosphere::kVacuum})
      for (double v : {0.8, 1.2, 1.6}) s.drops.push_back({pad, "fjs1_lp", atm, v, std::nullopt, 9.81, 0});
  s.noise = dataset::SynthNoise{0.5, 1e-5, 1.0, 2e-5, 0.1, 5e-6};
  return s;
}

FitProblem Problem(const dataset::SynthSpec& spec) {
  dataset::Dataset ds = dataset::Synthesize(spec);
  ds.directory = "in-memory";
  return MakeFitProblem(ds, std::vector<bool>(ds.drops.size(), false), 2);
}

TEST(DiagnoseNoiseFloor, RecoversTheSensorNoiseFromTheRestPhases) {
  // Noise 0.5 N plus quantisation to 0.1 N (0.029 N rms): 0.501 N in all. About 70 rest differences
  // a dataset give the median-based scale a relative standard error of about 0.14 (1.17/sqrt 70).
  // The whole-stroke second differences read 0.55-2.7 N on these drops (about 3x on average).
  double sum = 0.0;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    const FitProblem p = Problem(TwelveDrops(static_cast<unsigned long long>(seed), 0.008));
    ASSERT_EQ(p.drops.size(), 12u);
    for (const FitDrop& d : p.drops) EXPECT_EQ(d.noise_force_N, p.drops[0].noise_force_N) << "one sensor, one floor";
    std::printf("[ rest estimate ] seed %d: %.3f N\n", seed, p.drops[0].noise_force_N);
    EXPECT_NEAR(p.drops[0].noise_force_N, 0.501, 0.501 * 0.4) << "seed " << seed;
    sum += p.drops[0].noise_force_N;
  }
  EXPECT_NEAR(sum / seeds, 0.501, 0.501 * 0.12);  // 3 standard errors of an 8-seed mean
}

TEST(DiagnoseNoiseFloor, NoiseFreeRecordsHaveNoFloor) {
  dataset::SynthSpec spec = TwelveDrops(1, 0.008);
  spec.noise = dataset::SynthNoise{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const FitProblem p = Problem(spec);
  for (const FitDrop& d : p.drops) EXPECT_LT(d.noise_force_N, 1e-9 * d.force_scale_N);
}

TEST(DiagnoseNoiseFloor, RecordsWithoutARestFallBackToTheirStroke) {
  // No rest phase: each drop keeps its own estimate from third differences of its 20-31 stroke
  // samples (a relative standard error of about 0.27 each), which still carry some of the signal's
  // curvature: their mean lies above the noise, within a few times it.
  const FitProblem p = Problem(TwelveDrops(1, 0.0));
  bool differ = false;
  double sum = 0.0;
  for (const FitDrop& d : p.drops) {
    std::printf("[ stroke estimate ] %s %.3f N\n", d.drop_id.c_str(), d.noise_force_N);
    EXPECT_GT(d.noise_force_N, 0.1);
    sum += d.noise_force_N;
    differ |= d.noise_force_N != p.drops[0].noise_force_N;
  }
  EXPECT_TRUE(differ) << "per-drop estimates";
  EXPECT_GT(sum / 12, 0.501);
  EXPECT_LT(sum / 12, 3 * 0.501);
}

}  // namespace
}  // namespace touchdown::gap
