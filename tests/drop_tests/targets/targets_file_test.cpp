// Loading a targets file: scenarios shared between targets, campaign rows and lander files found,
// and every bad entry refused at load with its file, field and value.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "drop_tests/targets/targets_file.h"
#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::targets {
namespace {

const char* kGoodParameter =
    "  - {name: zeta_lp, soil: fjs1_lp, field: zeta_N_cm3, lower: 1.0, upper: 8.0, start: 3.0, source: test}\n";
const char* kGoodTarget =
    "  - {name: depth, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0}, quantity: final_penetration_m,"
    " value: 0.02, uncertainty: 0.001, use: fit, source: test}\n";

class TargetsFileLoad : public testing_scratch::ScratchDirTest {
 protected:
  std::string WriteTargets(const std::string& parameters, const std::string& targets) {
    return Write("t.yaml", "schema_version: 1\ntype: targets\nparameters:\n" + parameters + "targets:\n" + targets);
  }
  // The one-line message of the InputError the file raises ("" if it loads).
  std::string ErrorOf(const std::string& parameters, const std::string& targets) {
    try {
      LoadTargetsFile(WriteTargets(parameters, targets));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(TargetsFileLoad, SharesScenariosAndFindsCampaignRowsAndLanders) {
  const std::string campaign = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/scenarios/sutoh2017_single_footpad.yaml";
  const TargetsFile f = LoadTargetsFile(WriteTargets(
      std::string(kGoodParameter) +
          "  - {name: r, lander: sutoh2017_lander, field: legs.joint_radius_mm, lower: 200, upper: 400, start: 300, source: t}\n",
      std::string(kGoodTarget) +
          "  - {name: force, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0}, quantity: peak_force_N, at_most: 900,"
          " uncertainty: 10, use: predict, source: test}\n"
          "  - {name: row, campaign: {file: " + campaign + ", pad: curved, soil: fjs1_lp, speed_m_s: 1.5},"
          " quantity: final_penetration_m, at_least: 0.01, at_most: 0.05, uncertainty: 0.001, use: fit, source: test}\n"
          "  - {name: roll, lander: lander_case_B, quantity: final_roll_deg, at_least: -0.5, at_most: 0.5,"
          " uncertainty: 0.1, use: fit, source: test}\n"
          "  - {name: pad3, lander: lander_case_B, quantity: pad_depth_m, pad: 3, value: 0.02, uncertainty: 0.001,"
          " use: predict, source: test}\n"));
  ASSERT_EQ(f.scenarios.size(), 3u);  // the drop once, the campaign row, the lander once
  EXPECT_EQ(f.targets[0].measure.scenario, f.targets[1].measure.scenario);
  EXPECT_EQ(f.scenarios[1].kind, ScenarioRun::Kind::kCampaign);
  EXPECT_EQ(f.scenarios[1].pad->name, "curved");
  EXPECT_DOUBLE_EQ(f.scenarios[1].conditions.impact_speed_m_s, 1.5);
  EXPECT_EQ(f.scenarios[2].kind, ScenarioRun::Kind::kLander);
  EXPECT_EQ(f.targets[4].measure.pad, 3);
  EXPECT_FALSE(f.targets[1].fit);
  EXPECT_EQ(f.parameters[1].kind, ParameterKind::kLanderField);
  EXPECT_EQ(f.parameters[1].Address(), "lander sutoh2017_lander: legs.joint_radius_mm");
}

// The shipped targets files load; the spot variant runs its lander cases on the spot soil, from
// scenario files found beside it.
TEST_F(TargetsFileLoad, ShippedTargetsFilesLoad) {
  const std::string dir = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/targets/";
  for (const char* name : {"sutoh2017", "sutoh2017_r1", "sutoh2017_r1_single_footpad", "sutoh2017_r1_spots", "sutoh2017_r3",
                           "sutoh2017_lambda"}) {
    SCOPED_TRACE(name);
    const TargetsFile f = LoadTargetsFile(dir + name + ".yaml");
    EXPECT_FALSE(f.parameters.empty());
    EXPECT_FALSE(f.targets.empty());
  }
  const TargetsFile spots = LoadTargetsFile(dir + "sutoh2017_r1_spots.yaml");
  int spot_landers = 0;
  for (const ScenarioRun& run : spots.scenarios)
    if (run.kind == ScenarioRun::Kind::kLander && run.lander->name.ends_with("_spots")) ++spot_landers;
  EXPECT_EQ(spot_landers, 2);
  bool spot_zeta = false;
  for (const Parameter& p : spots.parameters) spot_zeta |= p.soil_name == "fjs1_cp_spot";
  EXPECT_TRUE(spot_zeta);
}

const Target& TargetNamed(const TargetsFile& f, const std::string& name) {
  for (const Target& t : f.targets)
    if (t.name == name) return t;
  throw std::runtime_error("no target " + name);
}

// Each shipped file encodes its reading of the paper's LP/CP sentence (docs/calibration_targets.md):
// the default (R1z) fits the single-pad ratios only, vacuum LP/CP 1.09, and predicts every lander
// target; R1 fits 1.9; R3 has only the bound LP/CP >= 1.
TEST_F(TargetsFileLoad, ShippedFilesEncodeTheirReading) {
  const std::string dir = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/targets/";
  const TargetsFile r1z = LoadTargetsFile(dir + "sutoh2017.yaml");
  const Target& lp_cp = TargetNamed(r1z, "lp_over_cp_flat");
  EXPECT_TRUE(lp_cp.fit);
  EXPECT_DOUBLE_EQ(*lp_cp.value, 1.09);
  int landers = 0;
  for (const Target& t : r1z.targets)
    if (r1z.scenarios[t.measure.scenario].kind == ScenarioRun::Kind::kLander) {
      SCOPED_TRACE(t.name);
      EXPECT_FALSE(t.fit);
      ++landers;
    }
  EXPECT_EQ(landers, 9);  // cases A, B and C: roll, pitch, pad spread
  for (const Parameter& p : r1z.parameters) EXPECT_NE(p.kind, ParameterKind::kLanderField);

  EXPECT_DOUBLE_EQ(*TargetNamed(LoadTargetsFile(dir + "sutoh2017_r1.yaml"), "lp_over_cp_flat").value, 1.9);
  const TargetsFile r3_file = LoadTargetsFile(dir + "sutoh2017_r3.yaml");  // outlives the reference below
  const Target& r3 = TargetNamed(r3_file, "lp_over_cp_flat");
  EXPECT_FALSE(r3.value.has_value());
  EXPECT_DOUBLE_EQ(*r3.at_least, 1.0);
  EXPECT_FALSE(r3.at_most.has_value());
}

// A parameter's prior is read with its source, and refused when it could not be a normal prior
// of that parameter.
TEST_F(TargetsFileLoad, ReadsAPriorAndRefusesABadOne) {
  const std::string prior_lambda =
      "  - {name: l, soil: fjs1_lp, field: dynamic_lambda, lower: 0, upper: 4, start: 1, source: s, prior: ";
  const TargetsFile f = LoadTargetsFile(WriteTargets(prior_lambda + "{value: 1.1, sd: 0.5, source: lit}}\n", kGoodTarget));
  ASSERT_TRUE(f.parameters[0].prior.has_value());
  EXPECT_EQ(f.parameters[0].prior->value, 1.1);
  EXPECT_EQ(f.parameters[0].prior->sd, 0.5);
  EXPECT_EQ(f.parameters[0].prior->source, "lit");
  EXPECT_FALSE(LoadTargetsFile(WriteTargets(kGoodParameter, kGoodTarget)).parameters[0].prior.has_value());
  struct Case {
    std::string prior, field, value;
  };
  const Case cases[] = {
      {"{value: 4.5, sd: 0.5, source: lit}", "parameters[0].prior.value", "4.5"},  // outside [lower, upper]
      {"{value: 1.1, sd: 0, source: lit}", "parameters[0].prior.sd", "0"},
      {"{value: 1.1, sd: -0.5, source: lit}", "parameters[0].prior.sd", "-0.5"},
      {"{value: 1.1, sd: 0.5, source: ''}", "parameters[0].prior.source", "non-empty"},
      {"{value: 1.1, sd: 0.5}", "parameters[0].prior.source", "source"},
      {"{value: 1.1, sd: 0.5, source: lit, weight: 2}", "parameters[0].prior", "weight"},
      {"1.1", "parameters[0].prior", "mapping"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.prior);
    const std::string message = ErrorOf(prior_lambda + c.prior + "}\n", kGoodTarget);
    EXPECT_NE(message.find("t.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find(c.field), std::string::npos) << message;
    EXPECT_NE(message.find(c.value), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST_F(TargetsFileLoad, RefusesBadEntriesNamingFileFieldAndValue) {
  const std::string p = kGoodParameter, t = kGoodTarget;
  struct Case {
    std::string parameters, targets, field, value;
  };
  const std::vector<Case> cases{
      {"  - {name: z, soil: fjs1_xx, field: zeta_N_cm3, lower: 1, upper: 8, start: 3, source: s}\n", t,
       "parameters[0].soil", "fjs1_xx"},
      {"  - {name: z, pad: curved, field: profile.a9_per_mm, lower: 1, upper: 8, start: 3, source: s}\n", t,
       "parameters[0].field", "profile.a9_per_mm"},
      {"  - {name: z, soil: fjs1_lp, field: zeta_N_cm3, lower: 8, upper: 1, start: 3, source: s}\n", t,
       "parameters[0].upper", "1"},
      {"  - {name: z, soil: fjs1_lp, field: zeta_N_cm3, lower: 1, upper: 8, start: 9, source: s}\n", t,
       "parameters[0].start", "9"},
      {"  - {name: z, pad: curved, field: profile.a1_per_mm, lower: -0.01, upper: 0.08, start: 0.03, source: s}\n",
       "  - {name: d, drop: {pad: curved, soil: fjs1_lp, speed_m_s: 1.0}, quantity: final_penetration_m, value: 0.02,"
       " uncertainty: 0.001, use: fit, source: s}\n",
       "parameters[0].lower", "-0.01"},
      {"  - {name: z, lander: sutoh2017_lander, field: legs.joint_radius_mm, lower: 200, upper: 400, start: 300, source: s}\n",
       t, "parameters[0]", "legs.joint_radius_mm"},  // changes none of the targets' scenarios
      {p, "  - {name: d, lander: lander_case_Q, quantity: final_roll_deg, value: 0, uncertainty: 1, use: fit, source: s}\n",
       "targets[0].lander", "lander_case_Q"},
      {p, "  - {name: d, campaign: {file: sutoh2017_single_footpad, pad: flat, soil: fjs1_lp, speed_m_s: 1.2},"
          " quantity: final_penetration_m, value: 0.02, uncertainty: 0.001, use: fit, source: s}\n",
       "targets[0].campaign.pad", "1.2"},
      {p, "  - {name: d, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0}, quantity: final_roll_deg, value: 0,"
          " uncertainty: 1, use: fit, source: s}\n",
       "targets[0].quantity", "final_roll_deg"},
      {p, "  - {name: d, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0}, quantity: final_penetration_m, value: 0.02,"
          " uncertainty: 0.001, use: maybe, source: s}\n",
       "targets[0].use", "maybe"},
      {p, "  - {name: d, drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0}, quantity: final_penetration_m, at_least: 0.03,"
          " at_most: 0.02, uncertainty: 0.001, use: fit, source: s}\n",
       "targets[0].at_most", "0.02"},
      {p, t + t, "targets[1].name", "depth"},
      {"  - {name: z, soil: fjs1_lp, field: friction_deg, lower: 1, upper: 8, start: 3, source: s}\n", t,
       "parameters[0].field", "friction_deg"},
      {"  - {name: l, soil: fjs1_lp, field: dynamic_lambda, lower: -0.5, upper: 4, start: 1, source: s}\n", t,
       "parameters[0].lower", "-0.5"},
      {"  - {name: l, soil: fjs1_lp, field: dynamic_lambda, lower: 0, upper: 400, start: 1, source: s}\n", t,
       "parameters[0].upper", "400"},
      // toyoura_bekker has no dynamic term: its lambda would be fitted to nothing.
      {"  - {name: l, soil: toyoura_bekker, field: dynamic_lambda, lower: 0, upper: 4, start: 1, source: s}\n",
       "  - {name: d, drop: {pad: flat, soil: toyoura_bekker, speed_m_s: 1.0}, quantity: final_penetration_m,"
       " value: 0.02, uncertainty: 0.001, use: fit, source: s}\n",
       "parameters[0].field", "dynamic_term"},
      // A bekker soil without zeta but with its dynamic term on: no model-file override carries lambda.
      {"  - {name: l, soil: " + Write("bekker_dynamic.yaml", Slurp(std::string(TOUCHDOWN_SOURCE_DIR) +
                                                                      "/data/soils/toyoura_bekker.yaml") +
                                                                    "dynamic_term: true\nbulk_density_kg_m3: 1600\n") +
           ", field: dynamic_lambda, lower: 0, upper: 4, start: 1, source: s}\n",
       "  - {name: d, drop: {pad: flat, soil: toyoura_bekker, speed_m_s: 1.0}, quantity: final_penetration_m,"
       " value: 0.02, uncertainty: 0.001, use: fit, source: s}\n",
       "parameters[0].field", "zeta_N_cm3"},
      // A Bekker field: only on a soil whose law is bekker, a key of the soil file's bekker block,
      // bounds within the physical range (n in (0, 5]).
      {"  - {name: n, soil: fjs1_lp, field: bekker.n, lower: 0.5, upper: 1.5, start: 1, source: s}\n", t,
       "parameters[0].field", "law: bekker"},
      {"  - {name: n, soil: lunar_nominal_bekker, field: bekker.cohesion_kPa, lower: 0, upper: 1, start: 0.2, "
       "source: s}\n",
       t, "parameters[0].field", "bekker.cohesion_kPa"},
      {"  - {name: n, soil: lunar_nominal_bekker, field: bekker.n, lower: 0.5, upper: 6, start: 1, source: s}\n", t,
       "parameters[0].upper", "6"},
      {"  - {name: k, soil: lunar_nominal_bekker, field: bekker.k_phi_kN_m_n2, lower: -5, upper: 900, start: 820, "
       "source: s}\n",
       t, "parameters[0].lower", "-5"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.field);
    const std::string message = ErrorOf(c.parameters, c.targets);
    EXPECT_NE(message.find("t.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find(c.field), std::string::npos) << message;
    EXPECT_NE(message.find(c.value), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace touchdown::targets
