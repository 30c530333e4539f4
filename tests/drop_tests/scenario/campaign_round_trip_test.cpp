// Campaign scenarios: the bundled paper campaign, and one with a pad and a soil given by path
// and per-entry numbers, loaded, written resolved and the resolved copy loaded again give the
// same campaign (cases, pads, soils, numbers, paper checks); a second write is the same text.
// A resolved copy whose derived values no longer match its files is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/scenario/campaign.h"
#include "rft/input_error.h"
#include "tests/round_trip.h"

namespace touchdown::scenario {
namespace {

namespace fs = std::filesystem;

struct CampaignRoundTrip : testing_scratch::ScratchDirTest {};

void ExpectSameCampaign(const CampaignScenario& a, const CampaignScenario& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(fs::weakly_canonical(a.source), fs::weakly_canonical(b.source));
  EXPECT_EQ(a.reference_speed_m_s, b.reference_speed_m_s);
  ASSERT_EQ(a.cases.size(), b.cases.size());
  for (size_t i = 0; i < a.cases.size(); ++i) {
    const CampaignCase &p = a.cases[i], &q = b.cases[i];
    SCOPED_TRACE(p.drop_id);
    EXPECT_EQ(p.drop_id, q.drop_id);
    EXPECT_EQ(p.pad->name, q.pad->name);
    EXPECT_EQ(fs::weakly_canonical(p.pad->source), fs::weakly_canonical(q.pad->source));
    EXPECT_EQ(p.pad->mass_kg, q.pad->mass_kg);
    EXPECT_EQ(p.pad->profile.points.size(), q.pad->profile.points.size());
    EXPECT_EQ(p.soil.name, q.soil.name);
    EXPECT_EQ(fs::weakly_canonical(p.soil_source), fs::weakly_canonical(q.soil_source));
    EXPECT_EQ(p.soil.zeta_N_m3, q.soil.zeta_N_m3);
    EXPECT_EQ(p.soil.atmosphere, q.soil.atmosphere);
    EXPECT_EQ(p.conditions.impact_speed_m_s, q.conditions.impact_speed_m_s);
    EXPECT_EQ(p.conditions.mass_kg.value_or(p.pad->mass_kg), q.conditions.mass_kg.value_or(q.pad->mass_kg));
    EXPECT_EQ(p.conditions.gravity_m_s2, q.conditions.gravity_m_s2);
    ASSERT_EQ(p.conditions.zeta_N_m3.has_value(), q.conditions.zeta_N_m3.has_value());
    if (p.conditions.zeta_N_m3) {
      EXPECT_DOUBLE_EQ(*p.conditions.zeta_N_m3, *q.conditions.zeta_N_m3);
    }
  }
  ASSERT_EQ(a.checks.size(), b.checks.size());
  for (size_t i = 0; i < a.checks.size(); ++i) {
    const PaperCheck &p = a.checks[i], &q = b.checks[i];
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.quantity, q.quantity);
    EXPECT_EQ(p.numerator_pad, q.numerator_pad);
    EXPECT_EQ(p.numerator_soil, q.numerator_soil);
    EXPECT_EQ(p.denominator_pad, q.denominator_pad);
    EXPECT_EQ(p.denominator_soil, q.denominator_soil);
    EXPECT_EQ(p.speed_m_s, q.speed_m_s);
    EXPECT_EQ(p.paper_experiment, q.paper_experiment);
    EXPECT_EQ(p.paper_rft, q.paper_rft);
    EXPECT_EQ(p.source, q.source);
    EXPECT_EQ(p.used_for_fit, q.used_for_fit);
    EXPECT_EQ(p.fit_by, q.fit_by);
    EXPECT_EQ(p.reading, q.reading);
  }
}

// The resolved copies live in `dir`, as a campaign's output directory holds its copy.
void RoundTripCampaign(const std::string& source, const std::string& first, const std::string& second) {
  const std::string out = fs::path(first).parent_path().string();
  testing_scratch::ExpectRoundTrip(
      LoadCampaignScenario(source), first, second,
      [&](const CampaignScenario& c, const std::string& path) { WriteResolvedScenario(c, path, out); },
      LoadCampaignScenario, ExpectSameCampaign);
}

TEST_F(CampaignRoundTrip, PaperCampaign) {
  RoundTripCampaign(io::DataDirectory() + "/scenarios/sutoh2017_single_footpad.yaml", Path("paper_1.yaml"),
            Path("paper_2.yaml"));
  const std::string text = Slurp(Path("paper_1.yaml"));
  EXPECT_NE(text.find("type: campaign_resolved"), std::string::npos);
  EXPECT_NE(text.find("file: $TOUCHDOWN_DATA_DIR/soils/fjs1_lp.yaml"), std::string::npos);
  EXPECT_NE(text.find("paper_checks:"), std::string::npos);
}

TEST_F(CampaignRoundTrip, PathsAndPerEntryNumbers) {
  io::WriteSoil(io::LoadSoil("fjs1_cp"), Path("my_soil.yaml"));
  fs::copy_file(io::DataDirectory() + "/pads/curved.yaml", Path("my_pad.yaml"));
  std::ofstream(Path("campaign.yaml")) << "schema_version: 1\ntype: campaign\nname: mine\ngravity_m_s2: 1.62\n"
                                          "drops:\n"
                                          "  - {pad: " << Path("my_pad.yaml") << ", soil: " << Path("my_soil.yaml")
                                       << ", impact_speeds_m_s: [0, 0.35, 1.004], mass_kg: 2.25,"
                                          " zeta_N_cm3: 1.7}\n"
                                          "  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: 0.9, gravity_m_s2: 3.7}\n";
  const CampaignScenario loaded = LoadCampaignScenario(Path("campaign.yaml"));
  ASSERT_EQ(loaded.cases.size(), 4u);
  EXPECT_EQ(loaded.reference_speed_m_s, 0.0);  // the first case's speed
  fs::create_directories(dir_ / "out");
  RoundTripCampaign(Path("campaign.yaml"), Path("out/resolved_1.yaml"), Path("out/resolved_2.yaml"));
  const std::string text = Slurp(Path("out/resolved_1.yaml"));
  EXPECT_NE(text.find("file: ../my_soil.yaml"), std::string::npos);  // relative to the copy's directory
  EXPECT_NE(text.find("zeta_override_N_cm3: 1.7"), std::string::npos);
  EXPECT_NE(text.find("mass_kg: 2.25"), std::string::npos);
}

TEST_F(CampaignRoundTrip, ResolvedCopyMustMatchItsFiles) {
  const CampaignScenario loaded = LoadCampaignScenario(io::DataDirectory() + "/scenarios/sutoh2017_single_footpad.yaml");
  WriteResolvedScenario(loaded, Path("resolved.yaml"), dir_.string());
  std::string text = Slurp(Path("resolved.yaml"));
  const std::string from = "radius_mm: 50", to = "radius_mm: 51";
  ASSERT_NE(text.find(from), std::string::npos);
  text.replace(text.find(from), from.size(), to);
  std::ofstream(Path("edited.yaml")) << text;
  try {
    LoadCampaignScenario(Path("edited.yaml"));
    FAIL() << "an edited derived value was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("radius_mm"), std::string::npos) << e.what();
  }
}

// A paper check names the reading of the paper's LP/CP sentence it compares with: the shipped LP/CP
// check takes the default R1z, the resolved copy and summary.json carry it, an unknown reading is
// refused naming the field.
TEST_F(CampaignRoundTrip, PaperCheckNamesItsReading) {
  const CampaignScenario paper = LoadCampaignScenario(io::DataDirectory() + "/scenarios/sutoh2017_single_footpad.yaml");
  const PaperCheck* lp_cp = nullptr;
  for (const PaperCheck& c : paper.checks)
    if (c.name == "lp_over_cp_penetration_flat") lp_cp = &c;
  ASSERT_NE(lp_cp, nullptr);
  ASSERT_TRUE(lp_cp->reading.has_value());
  EXPECT_EQ(*lp_cp->reading, PaperReading::kR1z);
  EXPECT_EQ(lp_cp->paper_experiment, 1.09);
  const nlohmann::json j = CheckOutcomeJson(CheckOutcome{*lp_cp, 1.1});
  EXPECT_EQ(j.at("reading"), "R1z");
  EXPECT_FALSE(CheckOutcomeJson(CheckOutcome{paper.checks.front(), 1.9}).contains("reading"));

  const std::string head = "schema_version: 1\ntype: campaign\nname: r\ngravity_m_s2: 9.81\n"
                           "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: 1.0}\n"
                           "  - {pad: flat, soil: fjs1_cp, impact_speeds_m_s: 1.0}\n"
                           "paper_checks:\n  - {name: c, quantity: final_penetration_m, numerator: {pad: flat, soil: fjs1_lp},"
                           " denominator: {pad: flat, soil: fjs1_cp}, speed_m_s: 1.0, paper: {experiment: 1.9}, reading: ";
  std::ofstream(Path("r3.yaml")) << head << "R3}\n";
  EXPECT_EQ(LoadCampaignScenario(Path("r3.yaml")).checks.at(0).reading, PaperReading::kR3);
  fs::create_directories(dir_ / "out");
  RoundTripCampaign(Path("r3.yaml"), Path("out/r3_1.yaml"), Path("out/r3_2.yaml"));
  EXPECT_NE(Slurp(Path("out/r3_1.yaml")).find("reading: R3"), std::string::npos);
  for (const char* bad : {"r1", "R4", "\"\"", "[R1]"}) {
    std::ofstream(Path("bad.yaml")) << head << bad << "}\n";
    try {
      LoadCampaignScenario(Path("bad.yaml"));
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("paper_checks[0].reading"), std::string::npos) << e.what();
    }
  }
}

// A check's numerator and denominator take a pad and a soil and nothing else: a misspelt key is
// refused with its path (it used to pass unread).
TEST_F(CampaignRoundTrip, CheckSidesRefuseUnknownKeys) {
  const std::string head = "schema_version: 1\ntype: campaign\nname: k\n"
                           "drops:\n  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: 1.0}\n"
                           "  - {pad: flat, soil: fjs1_cp, impact_speeds_m_s: 1.0}\n"
                           "paper_checks:\n  - {name: c, quantity: final_penetration_m, speed_m_s: 1.0, ";
  std::ofstream(Path("ok.yaml")) << head << "numerator: {pad: flat, soil: fjs1_lp}, denominator: {pad: flat, soil: fjs1_cp}}\n";
  EXPECT_EQ(LoadCampaignScenario(Path("ok.yaml")).checks.at(0).denominator_soil, "fjs1_cp");
  for (const auto& [sides, path] :
       {std::pair<std::string, std::string>{"numerator: {pad: flat, soil: fjs1_lp, sol: fjs1_cp}, "
                                            "denominator: {pad: flat, soil: fjs1_cp}",
                                            "paper_checks[0].numerator.sol"},
        {"numerator: {pad: flat, soil: fjs1_lp}, denominator: {pad: flat, soil: fjs1_cp, speed_m_s: 2}",
         "paper_checks[0].denominator.speed_m_s"}}) {
    std::ofstream(Path("bad.yaml")) << head << sides << "}\n";
    try {
      LoadCampaignScenario(Path("bad.yaml"));
      ADD_FAILURE() << sides << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path + ": unknown field"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace touchdown::scenario
