// The synthetic-dataset generator: seeded and deterministic, labelled synthetic everywhere,
// noise of the stated size and resolution, and a hidden air-only effect leaves vacuum drops alone.
#include "drop_tests/synth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace touchdown::drop {
namespace {

SynthSpec Spec() {
  SynthSpec s;
  s.name = "unit";
  s.source = "unit.yaml";
  s.seed = 5;
  s.rest_duration_s = 0.01;
  for (const char* atm : {"air", "vacuum"})
    for (double v : {0.8, 1.4}) s.drops.push_back({"flat", "fjs1_lp", atm, v, std::nullopt, 9.81, 0});
  return s;
}

TEST(Synth, SeededDeterministicAndLabelled) {
  const SynthSpec spec = Spec();
  const Dataset a = Synthesize(spec), b = Synthesize(spec);
  EXPECT_TRUE(a == b);
  SynthSpec other = spec;
  other.seed = 6;
  EXPECT_FALSE(a == Synthesize(other));
  const std::string dir = ::testing::TempDir() + "/synth_unit";
  std::filesystem::remove_all(dir);  // a fresh target: touchdown refuses directories it did not write
  WriteSyntheticDataset(spec, a, dir);
  for (const char* f : {"README.md", "synthetic.yaml", "synthetic_truth.yaml", "drops.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + f)) << f;
  std::ifstream readme(dir + "/README.md");
  std::stringstream text;
  text << readme.rdbuf();
  EXPECT_NE(text.str().find("SYNTHETIC"), std::string::npos);
  EXPECT_NE(text.str().find("not measurements"), std::string::npos);
  const Dataset back = ReadDataset(dir);
  EXPECT_TRUE(back == a);
  ASSERT_EQ(back.extra_columns.back(), "data_origin");
  for (const DatasetDrop& d : back.drops) EXPECT_EQ(d.extra.back(), "synthetic");
}

TEST(Synth, NoiseHasItsSizeAndResolution) {
  SynthSpec clean = Spec(), noisy = Spec();
  clean.rest_duration_s = noisy.rest_duration_s = 0.2;  // ~1000 samples
  clean.noise = SynthNoise{0, 0, 0, 0, 0, 0};
  noisy.noise = SynthNoise{2.0, 5e-5, 0, 0, 0.5, 1e-5};
  const Dataset c = Synthesize(clean), n = Synthesize(noisy);
  double sum2 = 0, count = 0;
  for (size_t i = 0; i < c.drops.size(); ++i) {
    const DatasetTrace &tc = c.drops[i].trace, &tn = n.drops[i].trace;
    ASSERT_EQ(tc.size(), tn.size());
    for (size_t k = 0; k < tc.size(); ++k) {
      sum2 += std::pow(tn.force_N[k] - tc.force_N[k], 2), count += 1;
      EXPECT_NEAR(std::remainder(tn.force_N[k], 0.5), 0.0, 1e-9);
      EXPECT_NEAR(std::remainder(tn.penetration_m[k], 1e-5), 0.0, 1e-12);
    }
  }
  // Noise sigma 2 N plus the quantisation's 0.5^2 / 12: sd 2.005 N; sampling error ~2.3 %.
  ASSERT_GT(count, 800);
  EXPECT_NEAR(std::sqrt(sum2 / count), std::sqrt(4.0 + 0.25 / 12), 0.08 * 2.0);
  // 1 kHz from t = 0, the stop plus the rest recorded.
  EXPECT_EQ(c.drops[0].trace.t_s[1], 1e-3);
}

TEST(Synth, GasCushionHidesOnlyInAirDrops) {
  SynthSpec base = Spec(), hidden = Spec();
  hidden.hidden_effect = Effect{"gas_cushion", {0.3, 8000.0}};
  const Dataset a = Synthesize(base), b = Synthesize(hidden);
  for (size_t i = 0; i < a.drops.size(); ++i) {
    if (a.drops[i].atmosphere == "vacuum") EXPECT_TRUE(a.drops[i] == b.drops[i]) << a.drops[i].drop_id;
    else EXPECT_GT(std::abs(b.drops[i].FinalPenetration() / a.drops[i].FinalPenetration() - 1), 0.05) << a.drops[i].drop_id;
  }
}

}  // namespace
}  // namespace touchdown::drop
