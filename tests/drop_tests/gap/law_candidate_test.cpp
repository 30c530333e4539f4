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
  EXPECT_FALSE(plain.problem.bekker_base);  // the default base is RFT's, and its JSON says nothing new
  EXPECT_FALSE(DiagnosisJson(plain)["base"].contains("law"));
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

// diagnose --base bekker on the same synthetic Toyoura drops (n = 0.63, k_c = 0, k_phi = 1796 kN/m^4,
// data/soils/toyoura_bekker.yaml): the base's Bekker soil is recovered, its modulus scale stays 1,
// the base fits to the noise and the outputs say which base ran; the default base is RFT's.
TEST(BekkerBase, RecoversTheSoilOfDropsMadeOnABekkerSoil) {
  const dataset::Dataset ds = ToyouraBekkerDrops();
  DiagnoseOptions o;
  o.threads = 2;
  o.try_pairs = false;
  o.permutations = 200;
  EXPECT_EQ(o.base, DiagnoseBase::kRft);
  o.base = DiagnoseBase::kBekker;
  const Diagnosis d = RunDiagnosis(ds, o);
  ASSERT_TRUE(d.problem.bekker_base);
  ASSERT_EQ(d.bekker_base.size(), 1u);
  // n and k_phi move together along the fit's ridge (a lower n, a lower k_phi: the same force at
  // these depths, the held-out NRMSE stays at 0.003). The loading strokes are 15-25 samples, and
  // leaving out each stroke's first and last sample (calibrate.h) moves the pair by about 1 % in n
  // and 3 % in k_phi; measured n 0.6242 and k_phi 1738.3 kN/m^(n+2) on instantaneous samples, and
  // n 0.6354, k_phi 1846.0 (2.8 % high) on the period means these drops are recorded as (the default).
  EXPECT_NEAR(d.bekker_base[0].bekker.n, 0.63, 0.01);
  EXPECT_NEAR(d.bekker_base[0].bekker.k_phi_N_m_n2 / 1796e3, 1.0, 0.04);
  EXPECT_NEAR(d.base.fit.zeta_N_m3[0], 1.0, 0.01);  // the scale of the calibrated moduli (measured 1.0015)
  std::printf("[ bekker base ] n %.4f k_phi %.1f kN/m^(n+2) scale %.4f held-out force NRMSE %.4f (noise %.4f)\n",
              d.bekker_base[0].bekker.n, d.bekker_base[0].bekker.k_phi_N_m_n2 / 1e3, d.base.fit.zeta_N_m3[0],
              d.base.held_out.force_nrmse, d.base.held_out.noise_nrmse);
  EXPECT_LT(d.base.held_out.force_nrmse, 0.01);  // measured 0.0024, below the noise floor 0.0080
  const nlohmann::json j = DiagnosisJson(d);
  EXPECT_EQ(j["base"]["law"], "bekker");
  EXPECT_EQ(j["base"]["bekker_soils"][0]["soil"], "toyoura_bekker");
  for (const CandidateScore& c : d.candidates)
    if (c.name == "depth_exponent") {
      EXPECT_FALSE(c.applies);
    }
  EXPECT_EQ(d.named_effect, "none");
}

}  // namespace
}  // namespace touchdown::gap
