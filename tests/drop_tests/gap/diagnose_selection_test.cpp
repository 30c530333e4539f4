// Forward selection's rules (diagnose_selection.h) on scored models given by hand, so each rule is
// checked by itself without fitting: the case is the blind test's floor control generated without
// the dynamic term (docs/model_gap.md), with its measured held-out gaps. The term's absence explains
// 70 % of the base's excess over the noise floor; a depth exponent on top of it explains 44 % of what
// the absence leaves. The second step must not be taken (a term explaining a small part of what
// remains is fitting a misfit outside the library), while a term that leaves only the noise is.
#include "drop_tests/gap/diagnose_selection.h"

#include <gtest/gtest.h>

#include <map>
#include <tuple>
#include <utility>

namespace touchdown::gap {
namespace {

constexpr double kNoise = 0.0018;  // held-out force NRMSE of the noise floor

// `exponent_interval`: the depth exponent's 95 % interval; its range is [0.2, 3] as in the library.
CandidateScore Scored(const std::vector<std::string>& ids, double nrmse, double bic,
                      std::pair<double, double> exponent_interval = {1.28, 1.32}) {
  CandidateScore c;
  c.effect_ids = ids;
  for (size_t i = 0; i < ids.size(); ++i) c.name += (i ? "+" : "") + ids[i];
  c.held_out.force_nrmse = nrmse;
  c.held_out.mean_square = nrmse * nrmse;
  c.held_out.noise_mean_square = kNoise * kNoise;
  c.fit.bic = bic;
  c.fit.parameters = 1 + static_cast<int>(ids.size());
  for (const std::string& id : ids) {
    ParameterEstimate e;
    e.effect = id;
    if (id == kWeakerDynamicTerm) {
      e.value = 0.0056;  // the blind row's lambda [0, 0.17]
      e.low = 0.0;
      e.high = 0.17;
    }
    if (id == "depth_exponent") {
      e.value = 1.3;
      std::tie(e.low, e.high) = exponent_interval;
      e.bound_low = 0.2;
      e.bound_high = 3.0;
    }
    c.fit.estimates.push_back(e);
  }
  return c;
}

// The floor control's models; `pair_nrmse` is the held-out gap of the term's absence with a depth
// exponent (measured 0.0188).
Diagnosis Select(double pair_nrmse, DiagnoseOptions options = {},
                 std::pair<double, double> exponent_interval = {1.28, 1.32}) {
  Diagnosis d;
  d.problem.shipped_lambda = 1.1;
  for (const char* t : {kWeakerDynamicTerm, "depth_exponent", "rate_damping"}) d.problem.terms.push_back({t, {}, {}});
  d.base = Scored({}, 0.0456, 0.0);
  d.floor.noise_ms = d.floor.ms = kNoise * kNoise;  // no replicates: the sensor's noise is the floor
  const std::map<std::vector<std::string>, std::pair<double, double>> models = {
      {{kWeakerDynamicTerm}, {0.0250, -1500.0}},
      {{"depth_exponent"}, {0.0350, -600.0}},
      {{"rate_damping"}, {0.0420, -100.0}},
      {{kWeakerDynamicTerm, "depth_exponent"}, {pair_nrmse, -1900.0}},
      {{kWeakerDynamicTerm, "rate_damping"}, {0.0245, -1505.0}},
  };
  const ScoreModel score = [&](const std::vector<std::string>& ids, const FitResult&) {
    const auto it = models.find(ids);
    return it != models.end() ? Scored(ids, it->second.first, it->second.second, exponent_interval)
                              : Scored(ids, 0.05, 100.0);
  };
  const ScreenModel screen = [&](const std::vector<std::string>& ids, const FitResult& start) {
    return std::optional<FitResult>(score(ids, start).fit);
  };
  io::Progress progress("diagnose", "fits", 0, {io::ProgressMode::kNone});
  SelectForward(d, options, score, screen, progress);
  return d;
}

// With more candidates than kFullyScored, a step scores in full only the best kFullyScored by their
// screening BIC; the rest are listed as screened out, with their screening BIC, and never chosen -
// even one that would cut the held-out gap most.
TEST(DiagnoseSelection, OnlyTheBestScreenedCandidatesAreScoredAndChosen) {
  Diagnosis d;
  d.problem.shipped_lambda = 1.1;
  const std::vector<std::string> terms{"a", "b", "c", "d", "e"};
  for (const std::string& t : terms) d.problem.terms.push_back({t, {}, {}});
  d.base = Scored({}, 0.0456, 0.0);
  // Screening BIC: e best, then c, a, d, b; b has the best held-out gap but screens last.
  const std::map<std::string, double> screen_bic = {{"a", -300.0}, {"b", -50.0}, {"c", -400.0}, {"d", -200.0}, {"e", -500.0}};
  std::vector<std::string> scored;
  const ScoreModel score = [&](const std::vector<std::string>& ids, const FitResult& start) {
    scored.push_back(ids.back());
    EXPECT_EQ(start.bic, screen_bic.at(ids.back()));  // fitted in full from its screening fit
    return Scored(ids, ids.back() == "e" ? 0.0020 : 0.0300, screen_bic.at(ids.back()) - 10.0);
  };
  const ScreenModel screen = [&](const std::vector<std::string>& ids, const FitResult&) {
    if (ids.size() > 1) return std::optional<FitResult>();  // the second step: nothing applies
    FitResult f;
    f.bic = screen_bic.at(ids.back());
    f.parameters = 2;
    return std::optional<FitResult>(f);
  };
  DiagnoseOptions o;
  o.try_pairs = false;
  io::Progress progress("diagnose", "fits", 0, {io::ProgressMode::kNone});
  SelectForward(d, o, score, screen, progress);
  EXPECT_EQ(scored, (std::vector<std::string>{"a", "c", "e"}));
  ASSERT_EQ(d.candidates.size(), 5u);
  for (const CandidateScore& c : d.candidates) {
    const bool out = c.name == "b" || c.name == "d";
    EXPECT_EQ(c.screened_out, out) << c.name;
    if (out) {
      EXPECT_EQ(c.delta_bic, -screen_bic.at(c.name)) << c.name;
    }
  }
  ASSERT_EQ(d.selection.size(), 1u) << d.decision;
  EXPECT_EQ(d.candidates[d.selection[0]].name, "e");
}

TEST(DiagnoseSelection, AStepThatExplainsLessThanHalfOfWhatRemainsIsNotTaken) {
  const Diagnosis d = Select(0.0188);
  ASSERT_EQ(d.selection.size(), 1u) << d.decision;
  EXPECT_EQ(d.candidates[d.selection[0]].name, kWeakerDynamicTerm);
  // The pair explains (0.0250^2 - 0.0188^2) / (0.0250^2 - 0.0018^2) = 43.7 % of what the absence leaves.
  const CandidateScore& pair = d.candidates[d.candidates.size() - 2];
  ASSERT_EQ(pair.name, std::string(kWeakerDynamicTerm) + "+depth_exponent");
  EXPECT_NEAR(pair.step_explained, (0.0250 * 0.0250 - 0.0188 * 0.0188) / (0.0250 * 0.0250 - kNoise * kNoise), 1e-12);
  EXPECT_NE(d.decision.find("explains only 44 % of the held-out excess"), std::string::npos) << d.decision;
  // The absence alone cuts the base's gap by 45 %: no model is named, but the statement on the
  // shipped term stands on the step that selected it.
  EXPECT_EQ(d.named_effect, "none") << d.decision;
  EXPECT_LT(d.winner, 0);
  EXPECT_EQ(d.dynamic_term_statement.rfind("The data do not support the shipped default's dynamic term", 0), 0u)
      << d.dynamic_term_statement;
}

// `--min-step-explained 0` is the rule before the share: the floor's pair is taken and named, as
// it was (the blind test's row before the rule).
TEST(DiagnoseSelection, WithoutTheShareRuleTheFloorsPairIsNamedAsBefore) {
  DiagnoseOptions old_rule;
  old_rule.min_step_explained = 0.0;
  const Diagnosis d = Select(0.0188, old_rule);
  ASSERT_EQ(d.selection.size(), 2u) << d.decision;
  EXPECT_EQ(d.named_effect, "depth_exponent") << d.decision;
}

TEST(DiagnoseSelection, AStepThatLeavesOnlyTheNoiseIsTakenAndNamed) {
  const Diagnosis d = Select(0.0020);
  ASSERT_EQ(d.selection.size(), 2u) << d.decision;
  ASSERT_GE(d.winner, 0) << d.decision;
  EXPECT_EQ(d.named_effect, "depth_exponent") << d.decision;
  EXPECT_GT(d.candidates[d.winner].step_explained, 0.99);
}

// A step whose term the training drops do not identify (its interval covers its whole range, as a
// fit on one drop can give) is not taken, however much it explains; a tight interval is.
TEST(DiagnoseSelection, AStepWhoseParameterIsNotIdentifiedIsNotTaken) {
  const Diagnosis d = Select(0.0020, {}, {0.2, 3.0});
  ASSERT_EQ(d.selection.size(), 1u) << d.decision;
  EXPECT_NE(d.decision.find("depth_exponent (Delta BIC 400.0), is not identified by the training drops: "
                            "depth_exponent. = 1.3 with a 95 % interval [0.2, 3] over its whole range"),
            std::string::npos)
      << d.decision;
  // 95 % of the range is the bound: [0.22, 2.9] (96 %) is not identified, [0.3, 2.9] (93 %) is.
  EXPECT_EQ(Select(0.0020, {}, {0.22, 2.9}).selection.size(), 1u);
  EXPECT_EQ(Select(0.0020, {}, {0.3, 2.9}).named_effect, "depth_exponent");
}

// A design of 12 drops in two cells holds out 4 (diagnose's split): the sign-flip test's smallest
// p on 4 drops is 2^-4 = 0.0625, above the 0.05 level, so at that level no term could be taken on
// such a design. The level is then the smallest p the drops can give: every held-out drop fitted
// better takes the term; three of four refuse it, saying why.
Diagnosis SelectOnFourHeldOutDrops(const std::vector<double>& candidate_nrmse) {
  const std::vector<double> base_nrmse{0.030, 0.028, 0.034, 0.031};
  Diagnosis d;
  d.problem.shipped_lambda = 1.1;
  d.problem.terms.push_back({"depth_exponent", {}, {}});
  d.floor.noise_ms = kNoise * kNoise;
  d.floor.ms = d.floor.ms_upper = 0.004 * 0.004;  // the replicates' pure error and its bound
  d.floor.from_replicates = true;
  const auto with_gaps = [](CandidateScore c, const std::vector<double>& nrmse) {
    for (size_t i = 0; i < nrmse.size(); ++i) {
      DropGap g;
      g.drop_id = "h" + std::to_string(i);
      g.held_out = true;
      g.force_nrmse = nrmse[i];
      c.gaps.push_back(g);
    }
    return c;
  };
  d.base = with_gaps(Scored({}, 0.031, 0.0), base_nrmse);
  const ScoreModel score = [&](const std::vector<std::string>& ids, const FitResult&) {
    return with_gaps(Scored(ids, 0.0035, -5000.0), candidate_nrmse);
  };
  DiagnoseOptions o;
  o.try_pairs = false;
  io::Progress progress("diagnose", "fits", 0, {io::ProgressMode::kNone});
  SelectForward(d, o, score, nullptr, progress);
  return d;
}

TEST(DiagnoseSelection, FourHeldOutDropsTakeATermThatFitsEveryOneBetter) {
  const Diagnosis d = SelectOnFourHeldOutDrops({0.0036, 0.0033, 0.0038, 0.0034});
  ASSERT_EQ(d.candidates.size(), 1u);
  EXPECT_EQ(d.candidates[0].step_improvement_p, 1.0 / 16.0);
  EXPECT_EQ(d.candidates[0].step_improvement_p_min, 1.0 / 16.0);
  EXPECT_EQ(d.named_effect, "depth_exponent") << d.decision;
}

TEST(DiagnoseSelection, FourHeldOutDropsRefuseATermThatFitsOneWorse) {
  const Diagnosis d = SelectOnFourHeldOutDrops({0.0036, 0.0033, 0.0038, 0.0400});
  ASSERT_EQ(d.candidates.size(), 1u);
  EXPECT_GT(d.candidates[0].step_improvement_p, 1.0 / 16.0);
  EXPECT_EQ(d.named_effect, "none") << d.decision;
  EXPECT_NE(d.decision.find("too few to reach 0.05: every one must fit better"), std::string::npos) << d.decision;
}

// With a floor from replicates, a model whose held-out mean square lies within the floor's 95 %
// upper bound is not extended: what it leaves, the replicates cannot tell from their scatter. The
// first term (held-out NRMSE 0.0041 against a bound of 0.0043) is named alone; with the search on
// (--search-within-floor, the release before) a second term that fits every held-out drop better,
// towards the floor's estimate, is added too, as a compaction was on the independent blind set gb015.
Diagnosis SelectNearTheFloor(bool stop_within_floor) {
  Diagnosis d;
  d.problem.shipped_lambda = 1.1;
  for (const char* t : {"rate_damping", "compaction_peak"}) d.problem.terms.push_back({t, {}, {}});
  d.floor.noise_ms = kNoise * kNoise;
  d.floor.ms = 0.0030 * 0.0030;
  d.floor.ms_upper = 0.0043 * 0.0043;
  d.floor.from_replicates = true;
  const auto scored = [](const std::vector<std::string>& ids, double nrmse, double bic) {
    CandidateScore c = Scored(ids, nrmse, bic);
    for (int i = 0; i < 8; ++i) {
      DropGap g;
      g.drop_id = "h" + std::to_string(i);
      g.held_out = true;
      g.force_nrmse = nrmse * (1.0 + 0.01 * i);
      c.gaps.push_back(g);
    }
    c.held_out.mean_square = 0.0;
    for (const DropGap& g : c.gaps) c.held_out.mean_square += g.force_nrmse * g.force_nrmse / 8.0;
    return c;
  };
  d.base = scored({}, 0.0063, 0.0);
  const std::map<std::vector<std::string>, std::pair<double, double>> models = {
      {{"rate_damping"}, {0.0040, -4192.0}},
      {{"compaction_peak"}, {0.0060, -300.0}},
      {{"rate_damping", "compaction_peak"}, {0.0033, -4269.0}},
  };
  const ScoreModel score = [&](const std::vector<std::string>& ids, const FitResult&) {
    const auto it = models.find(ids);
    return it != models.end() ? scored(ids, it->second.first, it->second.second) : scored(ids, 0.05, 100.0);
  };
  DiagnoseOptions o;
  o.stop_within_floor = stop_within_floor;
  o.floor_from_best_model = false;
  io::Progress progress("diagnose", "fits", 0, {io::ProgressMode::kNone});
  SelectForward(d, o, score, nullptr, progress);
  return d;
}

TEST(DiagnoseSelection, AModelWithinTheReplicatesFloorIsNotExtended) {
  const Diagnosis d = SelectNearTheFloor(true);
  EXPECT_EQ(d.named_effects, std::vector<std::string>{"rate_damping"}) << d.decision;
  EXPECT_NE(d.decision.find("step 2: rate_damping already fits within the replicates' floor (held-out RMS force "
                            "NRMSE 0.0041 within its 95 % upper bound 0.0043)"),
            std::string::npos)
      << d.decision;
  const Diagnosis searched = SelectNearTheFloor(false);
  EXPECT_EQ(searched.named_effects, (std::vector<std::string>{"rate_damping", "compaction_peak"})) << searched.decision;
}

}  // namespace
}  // namespace touchdown::gap
