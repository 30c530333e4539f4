// "The gap is the law" (drop_tests/gap/law_candidate.h): on SYNTHETIC drops made on a Bekker soil of
// exponent n = 0.63, RFT's linear depth law leaves a gap that the Bekker law, fitted on the training
// drops, closes on the held-out ones; without --law-candidate nothing of it is computed.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "drop_tests/dataset/synth.h"
#include "drop_tests/gap/diagnose.h"

namespace touchdown::gap {
namespace {

dataset::Dataset ToyouraBekkerDrops() {
  dataset::SynthSpec spec;
  spec.name = "toyoura_law_gap";
  spec.source = "toyoura_law_gap.yaml";
  spec.seed = 3;
  spec.rest_duration_s = 0.01;
  for (double v : {0.6, 0.8, 1.0, 1.2, 1.4, 1.6})
    spec.drops.push_back({"flat", "toyoura_bekker", rft::Atmosphere::kAir, v, std::nullopt, 9.81, 0});
  dataset::Dataset ds = dataset::Synthesize(spec);
  ds.directory = ".";
  return ds;
}

TEST(LawCandidate, BekkerClosesTheGapOfDropsMadeOnABekkerSoil) {
  const dataset::Dataset ds = ToyouraBekkerDrops();
  DiagnoseOptions o;
  o.threads = 2;
  o.try_pairs = false;
  o.permutations = 200;
  const Diagnosis plain = RunDiagnosis(ds, o);
  EXPECT_FALSE(plain.law_candidate);
  EXPECT_FALSE(DiagnosisJson(plain).contains("law_candidate"));
  o.law_candidate = true;
  const Diagnosis d = RunDiagnosis(ds, o);
  ASSERT_TRUE(d.law_candidate);
  const LawCandidate& l = *d.law_candidate;
  ASSERT_TRUE(l.applies) << l.why_not;
  EXPECT_EQ(l.held_out_drops, 2);
  EXPECT_EQ(l.failed, 0);
  ASSERT_EQ(l.fits.size(), 1u);
  EXPECT_NEAR(l.fits[0].bekker.n, 0.63, 0.03);
  std::printf("[ law candidate ] held-out force NRMSE: RFT %.4f, Bekker %.4f\n", l.base_held_out_force_nrmse,
              l.held_out_force_nrmse);
  EXPECT_GT(l.gap_reduction, 0.5);
  EXPECT_EQ(DiagnosisJson(d)["law_candidate"]["law"], "bekker");
}

}  // namespace
}  // namespace touchdown::gap
