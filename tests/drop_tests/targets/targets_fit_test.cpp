// The targets fit on rig drops: a known answer recovered from another start, bounds, ratios,
// predicted targets, a parameter held at its bound, and results independent of threads.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/targets/target_evaluation.h"
#include "drop_tests/targets/targets_fit.h"
#include "rft/units.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::targets {
namespace {

// A rig drop's result as the targets see it: zeta in N/cm^3 at the soil's reference gravity.
drop::PadDrop RigDropAtZeta(const std::string& pad, const std::string& soil, double zeta_N_cm3, double speed = 1.0) {
  drop::DropConditions c;
  c.impact_speed_m_s = speed;
  c.zeta_N_m3 = units::ZetaFromN_cm3(zeta_N_cm3);
  return drop::RunDrop(drop::ResolveDrop(io::LoadPad(pad), io::LoadSoil(soil), c));
}

std::string Num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

const char* kZetaLp =
    "  - {name: zeta_lp, soil: fjs1_lp, field: zeta_N_cm3, lower: 1.0, upper: 8.0, start: 4.0, source: test}\n";

std::string DropTarget(const std::string& name, const std::string& pad, const std::string& soil,
                       const std::string& quantity, const std::string& bound, const std::string& use = "fit") {
  return "  - {name: " + name + ", drop: {pad: " + pad + ", soil: " + soil + ", speed_m_s: 1.0}, quantity: " +
         quantity + ", " + bound + ", use: " + use + ", source: test}\n";
}

class TargetsFit : public testing_scratch::ScratchDirTest {
 protected:
  TargetsFile Load(const std::string& parameters, const std::string& targets) {
    return LoadTargetsFile(Write("targets.yaml", "schema_version: 1\ntype: targets\nname: t\nparameters:\n" +
                                                     parameters + "targets:\n" + targets));
  }
};

TEST_F(TargetsFit, RecoversTheZetaThatMadeItsTargetsFromAnotherStart) {
  const drop::PadDrop truth = RigDropAtZeta("flat", "fjs1_lp", 2.5);
  const double d = truth.result.final_penetration_m, f = truth.result.peak_force_N;
  const TargetsFile file =
      Load(kZetaLp, DropTarget("depth", "flat", "fjs1_lp", "final_penetration_m",
                               "value: " + Num(d) + ", uncertainty: " + Num(0.01 * d)) +
                        DropTarget("force", "flat", "fjs1_lp", "peak_force_N",
                                   "value: " + Num(f) + ", uncertainty: " + Num(0.01 * f)));
  const TargetsFitResult fit = FitTargets(file);
  ASSERT_TRUE(fit.converged) << fit.termination;
  EXPECT_NEAR(fit.parameters[0].value, 2.5, 1e-6);
  EXPECT_EQ(fit.parameters[0].at_bound, ParameterResult::Bound::kNone);
  EXPECT_NEAR(fit.targets[0].simulated, d, 1e-9 * d);
  EXPECT_LT(std::abs(fit.targets[0].residual), 1e-5);
  EXPECT_LT(fit.cost, 1e-10);
  // The interval: (J^T J)^-1 of two 1 % targets; depth ~ zeta^-1/2 near the stop, so sigma is
  // well under 1 % of zeta and positive.
  ASSERT_TRUE(fit.parameters[0].sigma.has_value());
  EXPECT_GT(*fit.parameters[0].sigma, 1e-4 * 2.5);
  EXPECT_LT(*fit.parameters[0].sigma, 0.02 * 2.5);
  EXPECT_NEAR(*fit.parameters[0].high - 2.5, 1.959963985 * *fit.parameters[0].sigma, 1e-6);
  // The covariance a study draws from (report `covariance`): sigma squared, in N/cm^3 squared,
  // with the soil's name and reference gravity.
  ASSERT_EQ(fit.covariance_parameters, std::vector<size_t>{0});
  EXPECT_NEAR(fit.covariance[0][0], *fit.parameters[0].sigma * *fit.parameters[0].sigma,
              1e-12 * fit.covariance[0][0]);
  const nlohmann::json cov = TargetsReportJson(file, fit)["covariance"];
  EXPECT_EQ(cov["parameters"][0]["soil"], "fjs1_lp");
  EXPECT_EQ(cov["parameters"][0]["kind"], "soil_zeta");
  EXPECT_EQ(cov["parameters"][0]["unit"], "N/cm^3");
  EXPECT_EQ(cov["parameters"][0]["value"].get<double>(), fit.parameters[0].value);
  EXPECT_EQ(cov["matrix"][0][0].get<double>(), fit.covariance[0][0]);
}

// A rig drop on the soil with its dynamic term's lambda replaced (the soil file's is 1.1).
drop::PadDrop RigDropAtLambda(double zeta_N_cm3, double lambda, double speed) {
  rft::SoilParameters soil = io::LoadSoil("fjs1_lp");
  soil.dynamic_lambda = lambda;
  drop::DropConditions c;
  c.impact_speed_m_s = speed;
  c.zeta_N_m3 = units::ZetaFromN_cm3(zeta_N_cm3);
  return drop::RunDrop(drop::ResolveDrop(io::LoadPad("flat"), soil, c));
}

TEST_F(TargetsFit, RecoversZetaAndTheDynamicTermsLambdaJointly) {
  // Truth zeta 2.5, lambda 2.0: the depths at 0.5 and 3 m/s (the inertial term grows as v^2, so the
  // two speeds separate lambda from zeta), each given to 0.5 %; the fit starts at 4.0 and 1.1.
  const double zeta = 2.5, lambda = 2.0;
  std::string targets;
  for (const double v : {0.5, 3.0}) {
    const double d = RigDropAtLambda(zeta, lambda, v).result.final_penetration_m;
    targets += "  - {name: depth_" + Num(v) + ", drop: {pad: flat, soil: fjs1_lp, speed_m_s: " + Num(v) +
               "}, quantity: final_penetration_m, value: " + Num(d) + ", uncertainty: " + Num(0.005 * d) +
               ", use: fit, source: test}\n";
  }
  const TargetsFile file = Load(
      std::string(kZetaLp) +
          "  - {name: lambda_lp, soil: fjs1_lp, field: dynamic_lambda, lower: 0.0, upper: 5.0, start: 1.1, source: test}\n",
      targets);
  ASSERT_EQ(file.parameters[1].kind, ParameterKind::kSoilDynamicLambda);
  const TargetsFitResult fit = FitTargets(file);
  ASSERT_TRUE(fit.converged) << fit.termination;
  EXPECT_NEAR(fit.parameters[0].value, zeta, 1e-4 * zeta);
  EXPECT_NEAR(fit.parameters[1].value, lambda, 1e-3 * lambda);
  for (size_t k = 0; k < 2; ++k) {
    ASSERT_TRUE(fit.parameters[k].sigma.has_value());
    const double truth = k == 0 ? zeta : lambda;
    EXPECT_LT(*fit.parameters[k].low, truth);
    EXPECT_GT(*fit.parameters[k].high, truth);
  }
  // The report's covariance holds both, lambda with its soil and kind, and their correlation.
  const nlohmann::json cov = TargetsReportJson(file, fit)["covariance"];
  ASSERT_EQ(cov["parameters"].size(), 2u);
  EXPECT_EQ(cov["parameters"][1]["kind"], "soil_dynamic_lambda");
  EXPECT_EQ(cov["parameters"][1]["soil"], "fjs1_lp");
  EXPECT_EQ(cov["parameters"][1]["field"], "dynamic_lambda");
  EXPECT_NEAR(cov["matrix"][1][1].get<double>(), *fit.parameters[1].sigma * *fit.parameters[1].sigma,
              1e-12 * cov["matrix"][1][1].get<double>());
  const double rho = cov["matrix"][0][1].get<double>() / (*fit.parameters[0].sigma * *fit.parameters[1].sigma);
  // Both resist the pad: a stiffer soil matches the same depths with less inertia, so the two are
  // anti-correlated (measured -0.77), not degenerate (|rho| < 1).
  EXPECT_LT(rho, -0.3);
  EXPECT_GT(rho, -0.99);
  // The model file carries lambda beside zeta, and a drop under it runs as the truth did.
  const model::ModelFile m = TargetsModel(file, fit, "fit", "");
  ASSERT_TRUE(m.soils.at("fjs1_lp").dynamic_lambda.has_value());
  EXPECT_EQ(*m.soils.at("fjs1_lp").dynamic_lambda, fit.parameters[1].value);
  EXPECT_EQ(model::ApplyModel(m, io::LoadSoil("fjs1_lp")).dynamic_lambda, fit.parameters[1].value);
}

TEST_F(TargetsFit, RecoversABekkerSoilsNKcAndKphiFromTwoPadsAndTwoSpeeds) {
  // Truth: the nominal lunar Bekker soil with n 1.1, k_c 6 kN/m^(n+1), k_phi 900 kN/m^(n+2). The
  // flat pad (b 50 mm) at 0.5 and 1.5 m/s and a 25 mm copy at 1 m/s, depth and peak force each to
  // 0.5 %: the speeds separate n from the modulus k_c / b + k_phi, the two b separate k_c from
  // k_phi. The fit starts at the soil file's 1, 1.4, 820.
  std::string small = Slurp(std::string(TOUCHDOWN_SOURCE_DIR) + "/data/pads/flat.yaml");
  small.replace(small.find("radius_mm: 50"), 13, "radius_mm: 25");
  small.replace(small.find("name: flat"), 10, "name: flat_r25");
  const std::string small_pad = Write("flat_r25.yaml", small);
  rft::SoilParameters truth = io::LoadSoil("lunar_nominal_bekker");
  truth.bekker.n = 1.1;
  truth.bekker.k_c_N_m_n1 = 6e3;
  truth.bekker.k_phi_N_m_n2 = 900e3;
  std::string targets;
  const std::vector<std::pair<std::string, double>> drops{{"flat", 0.5}, {"flat", 1.5}, {small_pad, 1.0}};
  for (size_t k = 0; k < drops.size(); ++k) {
    drop::DropConditions c;
    c.impact_speed_m_s = drops[k].second;
    const drop::PadDrop d = drop::RunDrop(drop::ResolveDrop(io::LoadPad(drops[k].first), truth, c));
    for (const auto& [q, v] : std::vector<std::pair<std::string, double>>{
             {"final_penetration_m", d.result.final_penetration_m}, {"peak_force_N", d.result.peak_force_N}})
      targets += "  - {name: " + q + "_" + std::to_string(k) + ", drop: {pad: " + drops[k].first +
                 ", soil: lunar_nominal_bekker, speed_m_s: " + Num(drops[k].second) + "}, quantity: " + q +
                 ", value: " + Num(v) + ", uncertainty: " + Num(0.005 * v) + ", use: fit, source: test}\n";
  }
  const TargetsFile file = Load(
      "  - {name: n, soil: lunar_nominal_bekker, field: bekker.n, lower: 0.5, upper: 1.5, start: 1, source: test}\n"
      "  - {name: k_c, soil: lunar_nominal_bekker, field: bekker.k_c_kN_m_n1, lower: 0, upper: 40, start: 1.4, source: test}\n"
      "  - {name: k_phi, soil: lunar_nominal_bekker, field: bekker.k_phi_kN_m_n2, lower: 200, upper: 3000, start: 820, "
      "source: test}\n",
      targets);
  ASSERT_EQ(file.parameters[2].kind, ParameterKind::kSoilBekker);
  const TargetsFitResult fit = FitTargets(file);
  ASSERT_TRUE(fit.converged) << fit.termination;
  const double expected[] = {1.1, 6.0, 900.0};
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(fit.parameters[k].value, expected[k], 1e-3 * expected[k]) << k;
    ASSERT_TRUE(fit.parameters[k].sigma.has_value()) << k;
    EXPECT_LT(*fit.parameters[k].low, expected[k]);
    EXPECT_GT(*fit.parameters[k].high, expected[k]);
  }
  // The report's covariance names them by kind and unit, and the model file carries them (SI).
  const nlohmann::json cov = TargetsReportJson(file, fit)["covariance"];
  ASSERT_EQ(cov["parameters"].size(), 3u);
  EXPECT_EQ(cov["parameters"][0]["kind"], "soil_bekker_n");
  EXPECT_EQ(cov["parameters"][1]["kind"], "soil_bekker_k_c");
  EXPECT_EQ(cov["parameters"][2]["kind"], "soil_bekker_k_phi");
  EXPECT_EQ(cov["parameters"][2]["soil"], "lunar_nominal_bekker");
  EXPECT_EQ(cov["parameters"][2]["unit"], "kN/m^(n+2)");
  const model::ModelFile m = TargetsModel(file, fit, "fit", "");
  const model::SoilOverride& o = m.soils.at("lunar_nominal_bekker");
  EXPECT_EQ(o.zeta_N_m3, 0.0);  // the soil has none, and keeps none
  EXPECT_EQ(*o.bekker_k_phi_N_m_n2, fit.parameters[2].value * 1e3);
  const rft::SoilParameters applied = model::ApplyModel(m, io::LoadSoil("lunar_nominal_bekker"));
  EXPECT_EQ(applied.bekker.n, fit.parameters[0].value);
  EXPECT_EQ(applied.bekker.k_c_N_m_n1, fit.parameters[1].value * 1e3);
  EXPECT_EQ(applied.zeta_N_m3, 0.0);
}

TEST_F(TargetsFit, LambdaAloneKeepsTheSoilsZetaBitForBit) {
  // Only lambda free: at lambda = the file's 1.1 every drop is the unedited soil's, to the bit.
  const TargetsFile file = Load(
      "  - {name: lambda_lp, soil: fjs1_lp, field: dynamic_lambda, lower: 0.0, upper: 5.0, start: 1.1, source: test}\n",
      DropTarget("depth", "flat", "fjs1_lp", "final_penetration_m", "value: 0.01, uncertainty: 0.001"));
  TargetEvaluator evaluator(file, 1);
  drop::DropConditions c;
  c.impact_speed_m_s = 1.0;
  const drop::PadDrop plain = drop::RunDrop(drop::ResolveDrop(io::LoadPad("flat"), io::LoadSoil("fjs1_lp"), c));
  EXPECT_EQ(evaluator.Run({1.1}, false)[0].final_penetration_m, plain.result.final_penetration_m);
  // At lambda 0 the drop is the soil's with its file's zeta and no inertial stress: deeper.
  rft::SoilParameters no_inertia = io::LoadSoil("fjs1_lp");
  no_inertia.dynamic_lambda = 0.0;
  const double deeper = drop::RunDrop(drop::ResolveDrop(io::LoadPad("flat"), no_inertia, c)).result.final_penetration_m;
  EXPECT_EQ(evaluator.Run({0.0}, false)[0].final_penetration_m, deeper);
  EXPECT_GT(deeper, plain.result.final_penetration_m);
}

// A prior is one more normalised residual: for one parameter near the solution the precisions add,
// 1 / sigma^2 = 1 / sigma_targets^2 + 1 / sd^2, and the best value is the precision-weighted mean of
// the targets' and the prior's (exact for a linear model; the depth's curvature over one sigma, about
// 1 % of zeta, bounds the difference).
TEST_F(TargetsFit, APriorAddsItsPrecisionAndPullsTheValueByItsWeight) {
  const double d = RigDropAtZeta("flat", "fjs1_lp", 2.5).result.final_penetration_m;
  const std::string target =
      DropTarget("depth", "flat", "fjs1_lp", "final_penetration_m", "value: " + Num(d) + ", uncertainty: " + Num(0.01 * d));
  const TargetsFitResult plain = FitTargets(Load(kZetaLp, target));
  ASSERT_TRUE(plain.converged && plain.parameters[0].sigma) << plain.termination;
  const double s0 = *plain.parameters[0].sigma;
  EXPECT_FALSE(plain.parameters[0].prior_residual.has_value());
  const auto with_prior = [&](double value, double sd) {
    const std::string p = "  - {name: zeta_lp, soil: fjs1_lp, field: zeta_N_cm3, lower: 1.0, upper: 8.0, start: 4.0, "
                          "source: test, prior: {value: " + Num(value) + ", sd: " + Num(sd) + ", source: test}}\n";
    return Load(p, target);
  };
  // Prior at the targets' answer, as tight as they are: the value stays, sigma falls by sqrt(2).
  const TargetsFitResult agree = FitTargets(with_prior(2.5, s0));
  ASSERT_TRUE(agree.parameters[0].sigma.has_value());
  EXPECT_NEAR(agree.parameters[0].value, 2.5, 1e-5);
  EXPECT_NEAR(*agree.parameters[0].sigma, s0 / std::sqrt(2.0), 1e-4 * s0);
  EXPECT_NEAR(*agree.parameters[0].prior_residual, 0.0, 1e-3);
  // Prior one sigma above, three times as tight: the value moves 0.9 sigma up (weights 1 and 9).
  const TargetsFitResult pulled = FitTargets(with_prior(2.5 + s0, s0 / 3.0));
  ASSERT_TRUE(pulled.parameters[0].sigma.has_value());
  EXPECT_NEAR(pulled.parameters[0].value, 2.5 + 0.9 * s0, 0.02 * s0);
  EXPECT_NEAR(*pulled.parameters[0].sigma, s0 / std::sqrt(10.0), 0.02 * s0);
  EXPECT_NEAR(*pulled.parameters[0].prior_residual, -0.3, 0.02);
  // The cost holds both residuals: the target's (0.9 sigma) and the prior's (0.3).
  EXPECT_NEAR(pulled.cost, 0.5 * (0.81 + 0.09), 0.02);
  const nlohmann::json report = TargetsReportJson(with_prior(2.5 + s0, s0 / 3.0), pulled);
  EXPECT_EQ(report["parameters"][0]["prior"]["sd"].get<double>(), s0 / 3.0);
  EXPECT_EQ(report["parameters"][0]["prior"]["residual"].get<double>(), *pulled.parameters[0].prior_residual);
}

// Lambda and zeta from one depth: the targets fix only a combination of the two; a prior on lambda
// makes both determined, lambda's interval no wider than the prior's.
TEST_F(TargetsFit, APriorDeterminesWhatTheTargetsAloneCannot) {
  const std::string target = DropTarget("depth", "flat", "fjs1_lp", "final_penetration_m",
                                        "value: " + Num(RigDropAtLambda(2.5, 1.1, 1.0).result.final_penetration_m) +
                                            ", uncertainty: 1.0e-4");
  const std::string lambda =
      "  - {name: lambda_lp, soil: fjs1_lp, field: dynamic_lambda, lower: 0.0, upper: 5.0, start: 1.1, source: test";
  const TargetsFitResult free = FitTargets(Load(std::string(kZetaLp) + lambda + "}\n", target));
  // Without the prior the fit slides along the ridge of equal depths until lambda meets a bound
  // (measured: lambda 0, zeta 2.74): lambda gets no interval either way.
  EXPECT_FALSE(free.parameters[1].sigma.has_value());
  const TargetsFitResult held =
      FitTargets(Load(std::string(kZetaLp) + lambda + ", prior: {value: 1.1, sd: 0.5, source: test}}\n", target));
  ASSERT_TRUE(held.converged) << held.termination;
  ASSERT_TRUE(held.parameters[0].sigma && held.parameters[1].sigma);
  EXPECT_NEAR(held.parameters[0].value, 2.5, 1e-3);  // at the prior's lambda the depth is the truth's
  EXPECT_NEAR(held.parameters[1].value, 1.1, 1e-3);
  EXPECT_LE(*held.parameters[1].sigma, 0.5 * (1.0 + 1e-9));
  EXPECT_EQ(held.covariance_parameters, (std::vector<size_t>{0, 1}));
}

TEST_F(TargetsFit, RecoversZetaAndACurvedProfileConstantJointly) {
  // The curved pad at a coarser profile and body (each evaluation reloads it: the test stays fast);
  // truth: zeta 2.5 and a1 = 0.045 /mm, the same pad copied with that constant.
  std::string curved = Slurp(std::string(TOUCHDOWN_SOURCE_DIR) + "/data/pads/curved.yaml");
  curved.replace(curved.find("segments: 400"), 13, "segments: 60");
  curved += "angular_segments: 8\n";
  const std::string coarse = Write("curved_coarse.yaml", curved);
  curved.replace(curved.find("a1_per_mm: 0.031901"), 19, "a1_per_mm: 0.045");
  const std::string pad_file = Write("curved_truth.yaml", curved);
  const double flat = RigDropAtZeta("flat", "fjs1_lp", 2.5).result.final_penetration_m;
  const double bent = RigDropAtZeta(pad_file, "fjs1_lp", 2.5).result.final_penetration_m;
  const TargetsFile file = Load(
      std::string(kZetaLp) +
          "  - {name: a1, pad: " + coarse + ", field: profile.a1_per_mm, lower: 0.01, upper: 0.08, start: 0.03, source: test}\n",
      DropTarget("flat", "flat", "fjs1_lp", "final_penetration_m", "value: " + Num(flat) + ", uncertainty: 1e-4") +
          DropTarget("curved", coarse, "fjs1_lp", "final_penetration_m", "value: " + Num(bent) + ", uncertainty: 1e-4"));
  const TargetsFitResult fit = FitTargets(file);
  ASSERT_TRUE(fit.converged) << fit.termination;
  EXPECT_NEAR(fit.parameters[0].value, 2.5, 1e-5);
  EXPECT_NEAR(fit.parameters[1].value, 0.045, 1e-6);
  // Exactly solvable: the fit stops once both targets are met to 1e-6 of their uncertainty, well
  // before the iteration cap (30) at which Ceres' relative criteria alone would stop it.
  EXPECT_EQ(fit.termination.rfind("exact:", 0), 0u) << fit.termination;
  EXPECT_LT(fit.iterations, 15);
  for (const TargetResult& t : fit.targets) EXPECT_LT(std::abs(t.residual), 1e-6);
}

TEST_F(TargetsFit, ABoundIsZeroInsideAndActiveOutside) {
  Target t;
  t.at_most = 0.02;
  t.uncertainty = 0.001;
  EXPECT_EQ(Residual(t, 0.015), 0.0);
  EXPECT_EQ(Residual(t, 0.02), 0.0);
  EXPECT_NEAR(Residual(t, 0.023), 3.0, 1e-12);
  t.at_least = 0.01;
  EXPECT_NEAR(Residual(t, 0.008), -2.0, 1e-12);
  EXPECT_EQ(Residual(t, 0.012), 0.0);
  Target v;
  v.value = 1.9;
  v.uncertainty = 0.1;
  EXPECT_NEAR(Residual(v, 2.1), 2.0, 1e-12);

  // A fit to a bound the start violates ends on the bound, not beyond it.
  const double at_start = RigDropAtZeta("flat", "fjs1_lp", 4.0).result.final_penetration_m;
  const double limit = 0.8 * at_start;  // shallower: needs a stiffer soil
  const TargetsFitResult fit = FitTargets(
      Load(kZetaLp, DropTarget("shallow", "flat", "fjs1_lp", "final_penetration_m",
                               "at_most: " + Num(limit) + ", uncertainty: 1e-4")));
  EXPECT_GT(fit.parameters[0].value, 4.0 / (0.8 * 0.8) * 0.9);
  EXPECT_LT(fit.targets[0].simulated, limit + 1e-7);
  EXPECT_LT(std::abs(fit.targets[0].residual), 1e-3);
}

TEST_F(TargetsFit, FitsARatioOfTwoScenarios) {
  const std::string params =
      "  - {name: zeta_cp, soil: fjs1_cp, field: zeta_N_cm3, lower: 1.0, upper: 30.0, start: 5.0, source: test}\n";
  const TargetsFile file = Load(params,
                                "  - {name: lp_over_cp, ratio: {numerator: {drop: {pad: flat, soil: fjs1_lp, speed_m_s: 1.0},"
                                " quantity: final_penetration_m}, denominator: {drop: {pad: flat, soil: fjs1_cp, speed_m_s: 1.0},"
                                " quantity: final_penetration_m}}, value: 1.9, uncertainty: 0.01, use: fit, source: test}\n");
  ASSERT_EQ(file.scenarios.size(), 2u);
  const TargetsFitResult fit = FitTargets(file);
  ASSERT_TRUE(fit.converged) << fit.termination;
  EXPECT_NEAR(fit.targets[0].simulated, 1.9, 1e-7);
  // The same ratio from two drops run here at the fitted zeta.
  drop::DropConditions own;
  own.impact_speed_m_s = 1.0;
  const double lp = drop::RunDrop(drop::ResolveDrop(io::LoadPad("flat"), io::LoadSoil("fjs1_lp"), own)).result.final_penetration_m;
  const double cp = RigDropAtZeta("flat", "fjs1_cp", fit.parameters[0].value).result.final_penetration_m;
  EXPECT_NEAR(lp / cp, fit.targets[0].simulated, 1e-12);
}

TEST_F(TargetsFit, PredictedTargetsAreReportedButNotFitted) {
  const double d = RigDropAtZeta("flat", "fjs1_lp", 3.0).result.final_penetration_m;
  const std::string fitted =
      DropTarget("depth", "flat", "fjs1_lp", "final_penetration_m", "value: " + Num(d) + ", uncertainty: 1e-4");
  const TargetsFitResult alone = FitTargets(Load(kZetaLp, fitted));
  const TargetsFitResult with_prediction = FitTargets(Load(
      kZetaLp, fitted + DropTarget("force", "c4", "fjs1_lp", "peak_force_N", "value: 1, uncertainty: 0.1", "predict")));
  EXPECT_EQ(alone.parameters[0].value, with_prediction.parameters[0].value);  // bit for bit
  EXPECT_EQ(alone.cost, with_prediction.cost);
  const double force = RigDropAtZeta("c4", "fjs1_lp", with_prediction.parameters[0].value).result.peak_force_N;
  EXPECT_NEAR(with_prediction.targets[1].simulated, force, 1e-9 * force);
  EXPECT_NEAR(with_prediction.targets[1].residual, (force - 1.0) / 0.1, 1e-6);
}

TEST_F(TargetsFit, AParameterPushedPastItsBoundStaysThereWithoutAnInterval) {
  const double deep = RigDropAtZeta("flat", "fjs1_lp", 0.5).result.final_penetration_m;  // needs zeta 0.5 < lower
  const TargetsFile file =
      Load(kZetaLp, DropTarget("deep", "flat", "fjs1_lp", "final_penetration_m", "value: " + Num(deep) + ", uncertainty: 1e-4"));
  const TargetsFitResult fit = FitTargets(file);
  EXPECT_EQ(fit.parameters[0].value, 1.0);
  EXPECT_EQ(fit.parameters[0].at_bound, ParameterResult::Bound::kLower);
  EXPECT_FALSE(fit.parameters[0].sigma.has_value());
  EXPECT_NE(fit.parameters[0].interval_note.find("at a bound"), std::string::npos);
  EXPECT_LT(fit.targets[0].simulated, deep);
  const nlohmann::json report = TargetsReportJson(file, fit);
  EXPECT_EQ(report["parameters"][0]["at_bound"], "lower");
  EXPECT_FALSE(report["parameters"][0].contains("interval"));
}

// The bounds are where the model means something: no evaluation of the fit, the differences of
// its derivatives included, runs outside them, even with the largest step (a tenth of u in [1, 2],
// which stepped a zeta bounded below by 4 to -0.78) and a solution pressed against the lower bound.
TEST_F(TargetsFit, NoEvaluationLeavesTheBounds) {
  const double deep = RigDropAtZeta("flat", "fjs1_lp", 0.5).result.final_penetration_m;  // needs zeta 0.5 < lower
  const TargetsFile file = LoadTargetsFile(Write(
      "bounded.yaml", "schema_version: 1\ntype: targets\nname: t\nfit: {relative_step: 0.1}\nparameters:\n"
                      "  - {name: zeta_lp, soil: fjs1_lp, field: zeta_N_cm3, lower: 4.0, upper: 52.0, start: 5.0, "
                      "source: test}\ntargets:\n" +
                          DropTarget("deep", "flat", "fjs1_lp", "final_penetration_m",
                                     "value: " + Num(deep) + ", uncertainty: 1e-4")));
  std::vector<double> evaluated;
  TargetsFitOptions options;
  options.on_evaluation = [&](const std::vector<double>& values) { evaluated.push_back(values.at(0)); };
  const TargetsFitResult fit = FitTargets(file, options);
  ASSERT_GT(evaluated.size(), 3u);
  for (double zeta : evaluated) {
    EXPECT_GE(zeta, 4.0);
    EXPECT_LE(zeta, 52.0);
  }
  EXPECT_EQ(fit.parameters[0].value, 4.0);
  EXPECT_EQ(fit.parameters[0].at_bound, ParameterResult::Bound::kLower);
}

TEST_F(TargetsFit, ResultsDoNotDependOnThreads) {
  const double d = RigDropAtZeta("flat", "fjs1_lp", 2.0).result.final_penetration_m;
  const TargetsFile file = Load(
      std::string(kZetaLp) +
          "  - {name: zeta_cp, soil: fjs1_cp, field: zeta_N_cm3, lower: 1.0, upper: 30.0, start: 5.0, source: test}\n",
      DropTarget("depth", "flat", "fjs1_lp", "final_penetration_m", "value: " + Num(d) + ", uncertainty: 1e-4") +
          "  - {name: ratio, ratio: {numerator: {drop: {pad: c4, soil: fjs1_lp, speed_m_s: 1.0}, quantity: final_penetration_m},"
          " denominator: {drop: {pad: flat, soil: fjs1_cp, speed_m_s: 1.0}, quantity: final_penetration_m}},"
          " value: 2.0, uncertainty: 0.01, use: fit, source: test}\n");
  TargetsFitOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const TargetsFitResult a = FitTargets(file, one), b = FitTargets(file, two);
  EXPECT_EQ(TargetsReportJson(file, a).dump(), TargetsReportJson(file, b).dump());
  const model::ModelFile m = TargetsModel(file, a, "fitted", Path(""));
  ASSERT_EQ(m.soils.size(), 2u);
  EXPECT_NEAR(units::ZetaToN_cm3(m.soils.at("fjs1_lp").zeta_N_m3), a.parameters[0].value, 1e-12);
  EXPECT_NE(m.provenance_yaml.find("targets_used: [depth, ratio]"), std::string::npos) << m.provenance_yaml;
}

}  // namespace
}  // namespace touchdown::targets
