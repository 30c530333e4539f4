// The paper's single-footpad campaign (Sutoh et al. 2017, vacuum): the orderings it reports,
// with the simulated ratios printed beside the paper's figures.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/drop/pad_drop.h"
#include "drop_tests/scenario/campaign.h"

namespace touchdown::scenario {
namespace {

class PaperCampaign : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scenario_ = new CampaignScenario(LoadCampaignScenario(io::DataDirectory() + "/scenarios/sutoh2017_single_footpad.yaml"));
    result_ = new CampaignResult(RunCampaign(*scenario_));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete scenario_;
  }
  static const drop::PadDrop& Drop(const std::string& pad, const std::string& soil, double v) {
    for (const drop::PadDrop& d : result_->drops)
      if (d.pad.name == pad && d.soil.name == soil && std::abs(d.conditions.impact_speed_m_s - v) < 1e-9) return d;
    throw std::runtime_error("no drop " + pad + "/" + soil);
  }
  static CampaignScenario* scenario_;
  static CampaignResult* result_;
};
CampaignScenario* PaperCampaign::scenario_ = nullptr;
CampaignResult* PaperCampaign::result_ = nullptr;

TEST_F(PaperCampaign, RunsTheTwelveDrops) {
  EXPECT_EQ(result_->drops.size(), 12u);  // 4 pad/soil cases x 3 speeds
}

TEST_F(PaperCampaign, CurvedPadIsDeepestWithLowestPeakForce) {
  for (double v : {0.7, 1.0, 1.5}) {
    const drop::PadDrop &curved = Drop("curved", "fjs1_lp", v), &flat = Drop("flat", "fjs1_lp", v),
                  &c4 = Drop("c4", "fjs1_lp", v);
    EXPECT_GT(curved.result.final_penetration_m, flat.result.final_penetration_m) << v;
    EXPECT_GT(curved.result.final_penetration_m, c4.result.final_penetration_m) << v;
    EXPECT_LT(curved.result.peak_force_N, flat.result.peak_force_N) << v;
    EXPECT_LT(curved.result.peak_force_N, c4.result.peak_force_N) << v;
    // and the lowest energy-conversion rate (paper Sec. II-C3)
    EXPECT_LT(curved.result.mean_conversion_rate_W, flat.result.mean_conversion_rate_W) << v;
  }
}

TEST_F(PaperCampaign, C4IsWithinAFewPercentOfFlat) {
  for (double v : {0.7, 1.0, 1.5}) {
    const double ratio = Drop("c4", "fjs1_lp", v).result.final_penetration_m /
                         Drop("flat", "fjs1_lp", v).result.final_penetration_m;
    EXPECT_GT(ratio, 1.0) << v;   // the chamfer removes bottom area
    EXPECT_LT(ratio, 1.08) << v;  // ... but little of it: within a few percent
  }
}

TEST_F(PaperCampaign, ClosePackingIsShallowerThanLoose) {
  for (double v : {0.7, 1.0, 1.5}) {
    EXPECT_LT(Drop("flat", "fjs1_cp", v).result.final_penetration_m,
              Drop("flat", "fjs1_lp", v).result.final_penetration_m);
    EXPECT_GT(Drop("flat", "fjs1_cp", v).result.peak_force_N, Drop("flat", "fjs1_lp", v).result.peak_force_N);
  }
}

TEST_F(PaperCampaign, FasterIsDeeper) {
  for (const char* pad : {"flat", "c4", "curved"})
    EXPECT_LT(Drop(pad, "fjs1_lp", 0.7).result.final_penetration_m, Drop(pad, "fjs1_lp", 1.5).result.final_penetration_m);
}

TEST_F(PaperCampaign, CurvedPadFitGivesThePapersRftRatioUnderQuasiStaticRft) {
  rft::SoilParameters lp = io::LoadSoil("fjs1_lp");
  lp.dynamic_term = false;  // the paper's RFT
  drop::DropConditions c;
  c.impact_speed_m_s = 1.0;
  const double ratio = drop::RunDrop(drop::ResolveDrop(io::LoadPad("curved"), lp, c)).result.final_penetration_m /
                       drop::RunDrop(drop::ResolveDrop(io::LoadPad("flat"), lp, c)).result.final_penetration_m;
  EXPECT_NEAR(ratio, 2.0, 1e-3);  // tools/fit_curved_pad solves it to 1e-4 of a1
}

TEST_F(PaperCampaign, RatiosPrintedBesideThePapers) {
  const std::vector<CheckOutcome> checks = EvaluateChecks(*result_);
  ASSERT_EQ(checks.size(), 3u);
  std::map<std::string, double> simulated;
  for (const CheckOutcome& c : checks) {
    std::printf("  %-34s simulated %.3f   paper experiment %.2f   paper RFT %.2f\n", c.check.name.c_str(), c.simulated,
                c.check.paper_experiment, c.check.paper_rft);
    simulated[c.check.name] = c.simulated;
  }
  // The curved pad's a0, a1 were fitted to the paper's RFT ratio of 2.0 (data/pads/curved.yaml)
  // under the paper's quasi-static RFT, and the check says so; the others are predictions. The
  // shipped soils' dynamic term moves the ratio up (the curved pad's cos^3 area is smaller, so the
  // term holds it back less).
  // Regression pin: 2.044, this campaign (data/scenarios/sutoh2017_single_footpad.yaml) with the
  // shipped soils, as RunCampaign computes it; the tolerance takes rounding-level changes.
  EXPECT_NEAR(simulated["curved_over_flat_penetration_lp"], 2.044, 0.005);
  for (const CheckOutcome& c : checks) {
    EXPECT_EQ(c.check.used_for_fit, c.check.name == "curved_over_flat_penetration_lp") << c.check.name;
    EXPECT_EQ(c.check.fit_by.empty(), !c.check.used_for_fit) << c.check.name;
  }
  // Derived (not fitted) soils: the LP/CP ratio is reported, and must lie on the right side of 1.
  EXPECT_GT(simulated["lp_over_cp_penetration_flat"], 1.0);
}

}  // namespace
}  // namespace touchdown::scenario
