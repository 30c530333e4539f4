// Touchdown found on records with a known onset: a flat pad's jump and linear rise, a curved pad's
// point contact (force ~ d^3), noise, touchdowns at every phase within a sample; and a record that
// holds none is refused with the reason.
#include "drop_tests/dataset/touchdown_onset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "rft/input_error.h"
#include "tests/drop_tests/dataset/daq_test_drop.h"

namespace touchdown::dataset {
namespace {

using testing_drop::DropShape;
using testing_drop::MakeDrop;

struct OnsetCase {
  const char* name;
  double rate_hz, stiffness, exponent, dynamic, noise_N;
  double max_bias_samples;  // |mean error| over the phases, in samples
};

class OnsetAccuracy : public ::testing::TestWithParam<OnsetCase> {};

// Over 12 phases and noise draws: the mean error within the case's bound, every error within
// 3 uncertainties, and about two thirds or more within one.
TEST_P(OnsetAccuracy, FindsTheKnownTouchdownWithinItsUncertainty) {
  const OnsetCase& c = GetParam();
  double sum = 0;
  int inside = 0;
  const int draws = 12;
  for (int k = 0; k < draws; ++k) {
    DropShape s;
    s.rate_hz = c.rate_hz, s.stiffness = c.stiffness, s.exponent = c.exponent, s.dynamic = c.dynamic;
    s.force_noise_N = c.noise_N, s.phase = (k + 0.5) / draws, s.seed = 100 + k;
    const auto r = MakeDrop(s);
    const TouchdownOnset onset = DetectTouchdown(r.t_s, r.force_N, {}, "drop.csv");
    const double error = onset.t0_s - s.touchdown_in_file_s;
    sum += error;
    inside += std::abs(error) <= onset.uncertainty_s;
    EXPECT_LE(std::abs(error), 3 * onset.uncertainty_s) << "phase " << s.phase;
    EXPECT_GE(onset.uncertainty_s, 0.5 / c.rate_hz);
    EXPECT_LT(onset.pretrigger_end, r.t_s.size());
    EXPECT_LT(r.t_s[onset.pretrigger_end - 1], onset.t0_s);
  }
  EXPECT_LE(std::abs(sum / draws) * c.rate_hz, c.max_bias_samples);
  EXPECT_GE(inside, draws * 2 / 3);
}

INSTANTIATE_TEST_SUITE_P(
    Pads, OnsetAccuracy,
    ::testing::Values(OnsetCase{"flat_clean_10kHz", 10000, 3e4, 1.0, 13.0, 0.0, 0.1},
                      OnsetCase{"flat_noisy_10kHz", 10000, 3e4, 1.0, 13.0, 1.0, 0.5},
                      OnsetCase{"flat_noisy_1kHz", 1000, 3e4, 1.0, 13.0, 1.0, 0.5},
                      OnsetCase{"curved_clean_5kHz", 5000, 1.5e8, 3.0, 0.0, 0.0, 0.5},
                      OnsetCase{"curved_noisy_10kHz", 10000, 1.5e8, 3.0, 0.0, 0.5, 5.0},
                      OnsetCase{"curved_noisy_2kHz", 2000, 1.5e8, 3.0, 0.0, 0.5, 1.0}),
    [](const ::testing::TestParamInfo<OnsetCase>& info) { return std::string(info.param.name); });

TEST(Onset, ZeroAndNoiseComeFromThePretrigger) {
  DropShape s;
  s.force_noise_N = 0.8;
  auto r = MakeDrop(s);
  for (double& f : r.force_N) f += 7.5;  // a load cell's bias
  const TouchdownOnset onset = DetectTouchdown(r.t_s, r.force_N, {}, "drop.csv");
  EXPECT_NEAR(onset.baseline_N, 7.5, 0.3);
  EXPECT_NEAR(onset.noise_N, 0.8, 0.15);
  EXPECT_GT(onset.jump_N, 5.0);  // the flat face's c v0^2 = 13 N
  EXPECT_NEAR(onset.threshold_N, 5 * onset.noise_N, 0.5);
}

TEST(Onset, AFixedThresholdIsUsed) {
  DropShape s;
  s.force_noise_N = 0.5;
  const auto r = MakeDrop(s);
  OnsetOptions options;
  options.threshold_N = 10.0;
  const TouchdownOnset onset = DetectTouchdown(r.t_s, r.force_N, options, "drop.csv");
  EXPECT_EQ(onset.threshold_N, 10.0);
  EXPECT_NEAR(onset.t0_s, s.touchdown_in_file_s, 2.0 / s.rate_hz);
}

void ExpectOnsetRefused(const std::vector<double>& t, const std::vector<double>& f, const std::string& part) {
  try {
    DetectTouchdown(t, f, {}, "raw/x.csv");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("raw/x.csv: force: ", 0), 0u) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

TEST(Onset, RecordsWithoutATouchdownAreRefused) {
  DropShape s;
  s.force_noise_N = 0.5;
  const auto r = MakeDrop(s);
  std::vector<double> negative = r.force_N;
  for (double& f : negative) f = -f;
  ExpectOnsetRefused(r.t_s, negative, "flip the gain's sign");
  const std::vector<double> late_t(r.t_s.begin() + 148, r.t_s.end()), late_f(r.force_N.begin() + 148, r.force_N.end());
  ExpectOnsetRefused(late_t, late_f, "must start before touchdown");
  std::vector<double> flat(r.t_s.size(), 0.0);
  ExpectOnsetRefused(r.t_s, flat, "no touchdown");
  ExpectOnsetRefused({0, 1, 2}, {0, 0, 1}, "only 3 samples");
}

}  // namespace
}  // namespace touchdown::dataset
