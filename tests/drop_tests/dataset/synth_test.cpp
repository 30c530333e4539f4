// The synthetic-dataset generator: seeded and deterministic, labelled synthetic everywhere,
// noise of the stated size and resolution, and a hidden air-only effect leaves vacuum drops alone.
#include "drop_tests/dataset/synth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include "rft/input_error.h"

namespace touchdown::dataset {
namespace {

SynthSpec Spec() {
  SynthSpec s;
  s.name = "unit";
  s.source = "unit.yaml";
  s.seed = 5;
  s.rest_duration_s = 0.01;
  for (rft::Atmosphere atm : {rft::Atmosphere::kAir, rft::Atmosphere::kVacuum})
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
  hidden.hidden_effect = model::Effect{"gas_cushion", {0.3, 8000.0}};
  const Dataset a = Synthesize(base), b = Synthesize(hidden);
  for (size_t i = 0; i < a.drops.size(); ++i) {
    if (a.drops[i].atmosphere == rft::Atmosphere::kVacuum) EXPECT_TRUE(a.drops[i] == b.drops[i]) << a.drops[i].drop_id;
    else EXPECT_GT(std::abs(b.drops[i].FinalPenetration() / a.drops[i].FinalPenetration() - 1), 0.05) << a.drops[i].drop_id;
  }
}

}  // namespace
}  // namespace touchdown::dataset

// Synth builds its dataset in memory, so its size is capped at load, each
// refusal naming the field and the limit.
namespace touchdown::dataset {
namespace {

std::string LoadError(const std::string& fields, const std::string& drops = "[{pads: [flat], soils: [fjs1_lp], "
                                                                              "impact_speeds_m_s: [1.0]}]") {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("touchdown_synth_caps_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream(path) << "schema_version: 1\ntype: synth\n" << fields << "drops: " << drops << "\n";
  std::string message;
  try {
    LoadSynthSpec(path.string());
  } catch (const InputError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

TEST(Synth, ResourceCapsAreRefusedAtLoadWithTheLimit) {
  EXPECT_EQ(LoadError("sample_rate_hz: 1000\nrest_duration_s: 0.04\ntrials: 2\n"), "");
  std::string e = LoadError("sample_rate_hz: 1e9\n");
  EXPECT_NE(e.find("sample_rate_hz"), std::string::npos) << e;
  EXPECT_NE(e.find("at most 1e+06 Hz"), std::string::npos) << e;
  e = LoadError("rest_duration_s: 1e6\n");
  EXPECT_NE(e.find("rest_duration_s"), std::string::npos) << e;
  EXPECT_NE(e.find("at most 60 s"), std::string::npos) << e;
  e = LoadError("trials: 100000000\n");
  EXPECT_NE(e.find("trials"), std::string::npos) << e;
  EXPECT_NE(e.find("at most 1000"), std::string::npos) << e;
  // Each within its own cap, together too many samples: 1,000 trials x 60 s x 1 MHz.
  e = LoadError("sample_rate_hz: 1e6\nrest_duration_s: 60\ntrials: 1000\n");
  EXPECT_NE(e.find("drops"), std::string::npos) << e;
  EXPECT_NE(e.find("samples"), std::string::npos) << e;
  // Too many drops is refused while the list is expanded, not after.
  std::string speeds;
  for (int i = 1; i <= 101; ++i) {
    if (i > 1) speeds += ',';
    speeds += std::to_string(i * 0.01);
  }
  e = LoadError("trials: 1000\n", "[{pads: [flat], soils: [fjs1_lp], impact_speeds_m_s: [" + speeds + "]}]");
  EXPECT_NE(e.find("more than 100000 drops"), std::string::npos) << e;
}

}  // namespace
}  // namespace touchdown::dataset
