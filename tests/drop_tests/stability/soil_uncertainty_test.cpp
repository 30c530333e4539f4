// A study's soil uncertainty (drop_tests/stability/soil_uncertainty.h): the `soil_uncertainty`
// block checked at load, the draws' distribution (the calibration's mean and covariance), the same
// draws and landings on 1 and 2 threads, landings that run with the drawn zeta, and the summary's
// split of the outcome's variance.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <nlohmann/json.hpp>

#include "drop_tests/stability/soil_pairing.h"
#include "drop_tests/stability/soil_uncertainty.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/sweep/sweep.h"
#include "rft/input_error.h"
#include "rft/units.h"
#include "drop_tests/catalog/catalog.h"
#include "tests/drop_tests/scenario/lander_test_support.h"
#include "tests/drop_tests/stability/study_test_support.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::stability {
namespace {

// A calibration report's covariance block as `calibrate --targets --report` writes it: zeta of LP
// and CP (N/cm^3), correlated, and a pad field that a study does not draw.
std::string Calibration(double lp, double cp, double s_lp, double s_cp, double rho) {
  const double c = rho * s_lp * s_cp;
  nlohmann::json j = {
      {"written_by", "touchdown calibrate --targets (it may replace this file)"},
      {"covariance",
       {{"parameters",
         {{{"name", "zeta_lp"}, {"kind", "soil_zeta"}, {"soil", "fjs1_lp"}, {"value", lp}, {"unit", "N/cm^3"},
           {"reference_gravity_m_s2", 9.81}},
          {{"name", "zeta_cp"}, {"kind", "soil_zeta"}, {"soil", "fjs1_cp"}, {"value", cp}, {"unit", "N/cm^3"},
           {"reference_gravity_m_s2", 9.81}},
          {{"name", "curved_a1"}, {"kind", "pad_field"}, {"object", "curved"}, {"value", 0.047}}}},
        {"matrix", {{s_lp * s_lp, c, 0.0}, {c, s_cp * s_cp, 0.0}, {0.0, 0.0, 1e-4}}}}}};
  return j.dump(2);
}

struct SoilUncertaintyTest : testing_scratch::ScratchDirTest {
  std::string StudyText(const std::string& study_block, const std::string& extra = "") {
    return std::string("schema_version: 1\ntype: stability\nname: soil\nlander: {scenario: ") + TOUCHDOWN_SOURCE_DIR +
           "/data/scenarios/lander_case_A.yaml}\n" + extra + "study: {recheck: none, joint_range_sensitivity: none" +
           study_block + "}\n";
  }
  Study Load(const std::string& study_block, const std::string& extra = "") {
    return LoadStudy(Write("study.yaml", StudyText(study_block, extra)));
  }
  // The InputError's message of loading the study.
  std::string Refusal(const std::string& study_block, const std::string& extra = "") {
    try {
      Load(study_block, extra);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(loaded)";
  }
};

constexpr const char* kPadSoils = "random: {samples: 4, seed: 3, pad_soils: {per_pad_choice: [fjs1_lp, fjs1_cp]}}\n";

TEST_F(SoilUncertaintyTest, LoadTimeValidationNamesFileAndField) {
  Write("cal.json", Calibration(3.5, 4.1, 0.2, 0.1, 0.5));
  Write("no_cov.json", "{\"parameters\": []}");
  Write("not_json.json", "{oops");
  Write("singular.json", Calibration(3.5, 4.1, 0.2, 0.1, 1.0));
  Write("asymmetric.json",
        R"({"covariance": {"parameters": [{"name": "z", "kind": "soil_zeta", "soil": "fjs1_lp", "value": 3},
            {"name": "y", "kind": "soil_zeta", "soil": "fjs1_cp", "value": 4}], "matrix": [[1, 0.5], [0, 1]]}})");
  Write("negative.json", Calibration(-1.0, 4.1, 0.2, 0.1, 0.0));
  // A key given twice (the parser kept the last silently), and a kind no report writes (ignored).
  Write("twice.json",
        R"({"covariance": {"parameters": [{"name": "z", "kind": "soil_zeta", "soil": "fjs1_lp", "value": 3, "value": 30}],
            "matrix": [[0.01]]}})");
  Write("unknown_kind.json",
        R"({"covariance": {"parameters": [{"name": "z", "kind": "soil_zetta", "soil": "fjs1_lp", "value": 3}],
            "matrix": [[0.01]]}})");
  struct Row {
    std::string block, extra, expected;
  };
  const std::vector<Row> rows = {
      {", soil_uncertainty: {toyoura: {calibration: cal.json}}", kPadSoils, "study.soil_uncertainty.toyoura"},
      {", soil_uncertainty: {toyoura: {calibration: cal.json}}", kPadSoils, "not a soil this study's landings stand on"},
      {", soil_uncertainty: {fjs1_lp: {calibration: missing.json}}", kPadSoils, "cannot read the calibration report"},
      {", soil_uncertainty: {fjs1_lp: {calibration: missing.json}}", kPadSoils, "study.soil_uncertainty.fjs1_lp.calibration"},
      {", soil_uncertainty: {fjs1_lp: {calibration: no_cov.json}}", kPadSoils, "no_cov.json: covariance"},
      {", soil_uncertainty: {fjs1_lp: {calibration: not_json.json}}", kPadSoils, "is not JSON"},
      {", soil_uncertainty: {fjs1_lp: {calibration: cal.json, sigma: 2}}", kPadSoils, "sigma"},
      {", soil_uncertainty: {fjs1_lp: {calibration: singular.json}, fjs1_cp: {calibration: singular.json}}", kPadSoils,
       "positive definite"},
      {", soil_uncertainty: {fjs1_lp: {calibration: asymmetric.json}}", kPadSoils, "must be symmetric"},
      {", soil_uncertainty: {fjs1_lp: {calibration: negative.json}}", kPadSoils, "covariance.parameters[0].value"},
      {", soil_uncertainty: {fjs1_lp: {calibration: twice.json}}", kPadSoils, "twice.json: value: given twice in one object"},
      {", soil_uncertainty: {fjs1_lp: {calibration: unknown_kind.json}}", kPadSoils,
       "unknown_kind.json: covariance.parameters[0].kind: unknown kind \"soil_zetta\""},
      {", soil_uncertainty: fjs1_lp", kPadSoils, "must be a mapping of soil names"},
      {", soil_uncertainty: {}", kPadSoils, "must be a mapping of soil names"},
      // The pairing: only beside draws, `none` or {samples: K}.
      {", soil_pairing: {samples: 10}", kPadSoils, "study.soil_pairing: pairs the drawn soils"},
      {", soil_uncertainty: {fjs1_lp: {calibration: cal.json}}, soil_pairing: all", kPadSoils,
       "study.soil_pairing: must be none or a mapping {samples}"},
      {", soil_uncertainty: {fjs1_lp: {calibration: cal.json}}, soil_pairing: {samples: 0}", kPadSoils,
       "study.soil_pairing.samples"},
      {", soil_uncertainty: {fjs1_lp: {calibration: cal.json}}, soil_pairing: {landings: 3}", kPadSoils,
       "study.soil_pairing.landings"},
  };
  for (const Row& r : rows) EXPECT_NE(Refusal(r.block, r.extra).find(r.expected), std::string::npos) << r.block << "\n" << Refusal(r.block, r.extra);
  // A soil the calibration holds no interval for (held fixed, or at a bound) is refused by name.
  Write("lp_only.json",
        R"({"covariance": {"parameters": [{"name": "z", "kind": "soil_zeta", "soil": "fjs1_lp", "value": 3}], "matrix": [[0.01]]}})");
  const std::string held = Refusal(", soil_uncertainty: {fjs1_cp: {calibration: lp_only.json}}", kPadSoils);
  EXPECT_NE(held.find("no interval for the zeta, dynamic_lambda or Bekker fields of soil 'fjs1_cp'"), std::string::npos) << held;
  // Singular only in the parameters not drawn: the drawn soil's own block is fine.
  EXPECT_NO_THROW(Load(", soil_uncertainty: {fjs1_lp: {calibration: singular.json}}", kPadSoils));
}

// The sample mean and covariance of the drawn parameters over landings 0..n-1.
std::pair<Eigen::VectorXd, Eigen::MatrixXd> SampleMoments(const SoilUncertainty& u, int n) {
  const Eigen::Index m = Eigen::Index(u.parameters.size());
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(m);
  Eigen::MatrixXd outer = Eigen::MatrixXd::Zero(m, m);
  for (int i = 0; i < n; ++i) {
    const std::vector<double> x = DrawSoilParameters(u, i);
    const Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(x.data(), m);
    sum += v;
    outer += v * v.transpose();
  }
  const Eigen::VectorXd mean = sum / n;
  return {mean, (outer - n * mean * mean.transpose()) / (n - 1)};
}

TEST_F(SoilUncertaintyTest, DrawsHaveTheCalibrationsMeanAndCovariance) {
  Write("cal.json", Calibration(3.5, 4.1, 0.2, 0.1, 0.6));
  const Study study = Load(", soil_uncertainty: {fjs1_lp: {calibration: cal.json}, fjs1_cp: {calibration: cal.json}}",
                           kPadSoils);
  ASSERT_TRUE(study.soil_uncertainty);
  const SoilUncertainty& u = *study.soil_uncertainty;
  ASSERT_EQ(u.parameters.size(), 2u);
  ASSERT_EQ(u.groups.size(), 1u);  // one file: drawn jointly
  const int n = 40000;
  const auto [mean, cov] = SampleMoments(u, n);
  // Means within 4 standard errors; variances within 4 of theirs (sqrt(2/n) relative), the
  // correlation within 4 / sqrt(n).
  EXPECT_NEAR(mean(0), 3.5, 4 * 0.2 / std::sqrt(n));
  EXPECT_NEAR(mean(1), 4.1, 4 * 0.1 / std::sqrt(n));
  EXPECT_NEAR(cov(0, 0), 0.04, 4 * 0.04 * std::sqrt(2.0 / n));
  EXPECT_NEAR(cov(1, 1), 0.01, 4 * 0.01 * std::sqrt(2.0 / n));
  EXPECT_NEAR(cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), 0.6, 4.0 / std::sqrt(n));
  // A pure function of the landing's index.
  EXPECT_EQ(DrawSoilParameters(u, 17), DrawSoilParameters(u, 17));
  EXPECT_NE(DrawSoilParameters(u, 17), DrawSoilParameters(u, 18));
}

TEST_F(SoilUncertaintyTest, DrawsOutsideThePhysicalRangeAreDrawnAgain) {
  // Mean 0.05 N/cm^3 with sigma 0.05: a sixth of the untruncated draws would be <= 0.
  Write("wide.json", Calibration(0.05, 4.1, 0.05, 0.1, 0.0));
  const Study study = Load(", soil_uncertainty: {fjs1_lp: {calibration: wide.json}}", kPadSoils);
  int below_mean = 0;
  for (int i = 0; i < 2000; ++i) {
    const double z = DrawSoilParameters(*study.soil_uncertainty, i)[0];
    EXPECT_GT(z, 0.0) << i;
    below_mean += z < 0.05;
  }
  EXPECT_LT(below_mean, 1000);  // the truncation removed the lower tail
}

TEST_F(SoilUncertaintyTest, StudiesWithoutItAreUnchanged) {
  const Study plain = Load("", kPadSoils);
  EXPECT_FALSE(plain.soil_uncertainty);
  EXPECT_FALSE(plain.plan.soil_overrides_at);
  EXPECT_TRUE(plain.plan.variant.empty());  // the plan's digest as before
  Write("cal.json", Calibration(3.5, 4.1, 0.2, 0.1, 0.0));
  const Study drawn = Load(", soil_uncertainty: {fjs1_lp: {calibration: cal.json}}", kPadSoils);
  EXPECT_NE(sweep::PlanDigest(drawn.plan), sweep::PlanDigest(plain.plan));  // another database
}

// A report of `calibrate --targets` that freed LP's zeta and its dynamic_lambda (kind
// soil_dynamic_lambda), correlated (a deeper pad needs a softer soil or less inertia).
std::string ZetaLambdaCalibration(double zeta, double lambda, double s_zeta, double s_lambda, double rho) {
  const double c = rho * s_zeta * s_lambda;
  nlohmann::json j = {
      {"covariance",
       {{"parameters",
         {{{"name", "zeta_lp"}, {"kind", "soil_zeta"}, {"soil", "fjs1_lp"}, {"value", zeta}, {"unit", "N/cm^3"},
           {"reference_gravity_m_s2", 9.81}},
          {{"name", "lambda_lp"}, {"kind", "soil_dynamic_lambda"}, {"soil", "fjs1_lp"}, {"field", "dynamic_lambda"},
           {"value", lambda}, {"unit", "-"}}}},
        {"matrix", {{s_zeta * s_zeta, c}, {c, s_lambda * s_lambda}}}}}};
  return j.dump(2);
}

double NormalPdf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI); }
double NormalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// A report that gives the fit's bounds (calibrate --targets does) truncates the draws to them: the
// one-dimensional truncated normal, mean mu + sigma (pdf(a) - pdf(b)) / (cdf(b) - cdf(a)) with a, b
// the bounds in standard units. `truncate: physical_limits` draws from the physical range alone.
TEST_F(SoilUncertaintyTest, DrawsStayWithinTheFitsBoundsUnlessTheStudySaysPhysicalLimits) {
  nlohmann::json j = nlohmann::json::parse(ZetaLambdaCalibration(3.5, 1.1, 0.2, 0.15, 0.0));
  j["covariance"]["parameters"][0]["lower"] = 3.4;  // half a sigma below the best value
  j["covariance"]["parameters"][0]["upper"] = 8.0;
  Write("bounded.json", j.dump(2));
  const Study study = Load(", soil_uncertainty: {fjs1_lp: {calibration: bounded.json}}", kPadSoils);
  const SoilUncertainty& u = *study.soil_uncertainty;
  EXPECT_EQ(u.parameters[0].low, 3.4);
  EXPECT_EQ(u.parameters[0].high, 8.0);
  EXPECT_TRUE(u.parameters[0].fit_bounded);
  EXPECT_FALSE(u.parameters[1].fit_bounded);  // lambda's entry has no bounds: the physical range
  const int n = 20000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    const double z = DrawSoilParameters(u, i)[0];
    ASSERT_GE(z, 3.4) << i;
    sum += z;
  }
  const double a = (3.4 - 3.5) / 0.2, b = (8.0 - 3.5) / 0.2;
  const double mean = 3.5 + 0.2 * (NormalPdf(a) - NormalPdf(b)) / (NormalCdf(b) - NormalCdf(a));
  const double var = 0.04 * (1 + (a * NormalPdf(a) - b * NormalPdf(b)) / (NormalCdf(b) - NormalCdf(a)) -
                             std::pow((NormalPdf(a) - NormalPdf(b)) / (NormalCdf(b) - NormalCdf(a)), 2));
  EXPECT_NEAR(sum / n, mean, 4 * std::sqrt(var / n));
  // The bounds are part of the plan: a database of the untruncated draws is another plan's.
  const Study physical =
      Load(", soil_uncertainty: {fjs1_lp: {calibration: bounded.json, truncate: physical_limits}}", kPadSoils);
  EXPECT_FALSE(physical.soil_uncertainty->parameters[0].fit_bounded);
  EXPECT_EQ(physical.soil_uncertainty->parameters[0].low, 0.0);
  EXPECT_NE(physical.plan.variant, study.plan.variant);
  int below = 0;
  for (int i = 0; i < 2000; ++i) below += DrawSoilParameters(*physical.soil_uncertainty, i)[0] < 3.4;
  EXPECT_GT(below, 400);  // about 31 % of the normal lies below 3.4
  // Refusals: an unknown rule; a best value outside its own bounds.
  const std::string bad = Refusal(", soil_uncertainty: {fjs1_lp: {calibration: bounded.json, truncate: box}}", kPadSoils);
  EXPECT_NE(bad.find("soil_uncertainty.fjs1_lp.truncate"), std::string::npos) << bad;
  EXPECT_NE(bad.find("'box'"), std::string::npos) << bad;
  j["covariance"]["parameters"][0]["lower"] = 3.6;
  Write("outside.json", j.dump(2));
  const std::string outside = Refusal(", soil_uncertainty: {fjs1_lp: {calibration: outside.json}}", kPadSoils);
  EXPECT_NE(outside.find("covariance.parameters[0]"), std::string::npos) << outside;
  EXPECT_NE(outside.find("outside its bounds [3.6, 8]"), std::string::npos) << outside;
}

TEST_F(SoilUncertaintyTest, DrawsZetaAndLambdaJointlyWithTheirCorrelation) {
  Write("zl.json", ZetaLambdaCalibration(3.5, 1.1, 0.2, 0.15, -0.7));
  const Study study = Load(", soil_uncertainty: {fjs1_lp: {calibration: zl.json}}", kPadSoils);
  const SoilUncertainty& u = *study.soil_uncertainty;
  ASSERT_EQ(u.parameters.size(), 2u);
  EXPECT_EQ(u.parameters[0].column, "fjs1_lp_zeta_N_cm3");
  EXPECT_EQ(u.parameters[1].column, "fjs1_lp_dynamic_lambda");
  EXPECT_EQ(u.parameters[1].field, SoilField::kDynamicLambda);
  const int n = 40000;
  const auto [mean, cov] = SampleMoments(u, n);
  // Lambda 7 sigma above 0: no truncation acts. Means within 4 standard errors, variances within 4 of
  // theirs (sqrt(2/n) relative), the correlation within 4 / sqrt(n).
  EXPECT_NEAR(mean(0), 3.5, 4 * 0.2 / std::sqrt(n));
  EXPECT_NEAR(mean(1), 1.1, 4 * 0.15 / std::sqrt(n));
  EXPECT_NEAR(cov(0, 0), 0.04, 4 * 0.04 * std::sqrt(2.0 / n));
  EXPECT_NEAR(cov(1, 1), 0.0225, 4 * 0.0225 * std::sqrt(2.0 / n));
  EXPECT_NEAR(cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), -0.7, 4.0 / std::sqrt(n));
  // A landing runs with both: zeta and lambda in the soil's override, lambda as drawn.
  const std::vector<double> x = DrawSoilParameters(u, 5);
  const std::map<std::string, model::SoilOverride> o = SoilOverrides(u, x);
  ASSERT_TRUE(o.at("fjs1_lp").dynamic_lambda.has_value());
  EXPECT_EQ(*o.at("fjs1_lp").dynamic_lambda, x[1]);
  EXPECT_EQ(o.at("fjs1_lp").zeta_N_m3, units::ZetaFromN_cm3(x[0]));
  EXPECT_EQ(DrawnParametersJson(u, 5)["fjs1_lp_dynamic_lambda"].get<double>(), x[1]);
}

// A report of `calibrate --targets` that freed a Bekker soil's n, k_c and k_phi (kinds
// soil_bekker_*, the soil file's units), with their correlations rho (n-k_c, n-k_phi, k_c-k_phi).
std::string BekkerCalibration(const std::string& soil, const Eigen::Vector3d& mean, const Eigen::Vector3d& sigma,
                              const Eigen::Vector3d& rho) {
  Eigen::Matrix3d r;
  r << 1, rho(0), rho(1), rho(0), 1, rho(2), rho(1), rho(2), 1;
  const Eigen::Matrix3d c = sigma.asDiagonal() * r * sigma.asDiagonal();
  nlohmann::json matrix = nlohmann::json::array();
  for (int a = 0; a < 3; ++a) matrix.push_back({c(a, 0), c(a, 1), c(a, 2)});
  const char* kinds[] = {"soil_bekker_n", "soil_bekker_k_c", "soil_bekker_k_phi"};
  const char* fields[] = {"bekker.n", "bekker.k_c_kN_m_n1", "bekker.k_phi_kN_m_n2"};
  nlohmann::json params = nlohmann::json::array();
  for (int a = 0; a < 3; ++a)
    params.push_back({{"name", fields[a]}, {"kind", kinds[a]}, {"soil", soil}, {"field", fields[a]}, {"value", mean(a)}});
  return nlohmann::json{{"covariance", {{"parameters", params}, {"matrix", matrix}}}}.dump(2);
}

TEST_F(SoilUncertaintyTest, DrawsABekkerTripleJointlyWithItsCorrelations) {
  // The nominal lunar Bekker soil's n 1 +- 0.05, k_c 1.4 +- 0.3, k_phi 820 +- 60 (k_c 4.7 sigma
  // above 0: the truncation removes about 1e-6 of the draws, far below the tolerances).
  const Eigen::Vector3d mean0(1.0, 1.4, 820.0), sigma(0.05, 0.3, 60.0), rho(0.3, -0.6, -0.5);
  Write("b.json", BekkerCalibration("lunar_nominal_bekker", mean0, sigma, rho));
  const Study study = LoadStudy(Write(
      "bekker_study.yaml", std::string("schema_version: 1\ntype: stability\nname: b\nlander: {scenario: ") +
                               TOUCHDOWN_SOURCE_DIR + "/data/scenarios/lander_lunar_bekker.yaml}\n" +
                               "random: {samples: 4, seed: 3}\nstudy: {recheck: none, joint_range_sensitivity: none, "
                               "soil_uncertainty: {lunar_nominal_bekker: {calibration: b.json}}}\n"));
  const SoilUncertainty& u = *study.soil_uncertainty;
  ASSERT_EQ(u.parameters.size(), 3u);
  EXPECT_EQ(u.parameters[0].column, "lunar_nominal_bekker_bekker_n");
  EXPECT_EQ(u.parameters[1].column, "lunar_nominal_bekker_bekker_k_c_kN_m_n1");
  EXPECT_EQ(u.parameters[2].column, "lunar_nominal_bekker_bekker_k_phi_kN_m_n2");
  EXPECT_EQ(u.parameters[2].field, SoilField::kBekkerKphi);
  const int n = 40000;
  const auto [mean, cov] = SampleMoments(u, n);
  // Means within 4 standard errors, variances within 4 sqrt(2/n) relative, correlations within 4 / sqrt(n).
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(mean(a), mean0(a), 4 * sigma(a) / std::sqrt(n)) << a;
    EXPECT_NEAR(cov(a, a), sigma(a) * sigma(a), 4 * sigma(a) * sigma(a) * std::sqrt(2.0 / n)) << a;
  }
  const auto corr = [](const Eigen::MatrixXd& c, int a, int b) { return c(a, b) / std::sqrt(c(a, a) * c(b, b)); };
  EXPECT_NEAR(corr(cov, 0, 1), rho(0), 4.0 / std::sqrt(n));
  EXPECT_NEAR(corr(cov, 0, 2), rho(1), 4.0 / std::sqrt(n));
  EXPECT_NEAR(corr(cov, 1, 2), rho(2), 4.0 / std::sqrt(n));
  // A landing runs with the drawn triple in SI as the soil's override; its zeta (none) stays none.
  const std::vector<double> x = DrawSoilParameters(u, 7);
  const model::SoilOverride o = SoilOverrides(u, x).at("lunar_nominal_bekker");
  EXPECT_EQ(o.zeta_N_m3, 0.0);
  EXPECT_EQ(*o.bekker_n, x[0]);
  EXPECT_EQ(*o.bekker_k_c_N_m_n1, x[1] * 1e3);
  EXPECT_EQ(*o.bekker_k_phi_N_m_n2, x[2] * 1e3);
  model::ModelFile m;
  m.soils["lunar_nominal_bekker"] = o;
  const rft::SoilParameters applied = model::ApplyModel(m, io::LoadSoil("lunar_nominal_bekker"));
  EXPECT_EQ(applied.bekker.n, x[0]);
  EXPECT_EQ(applied.bekker.k_phi_N_m_n2, x[2] * 1e3);
  EXPECT_EQ(DrawnParametersJson(u, 7)["lunar_nominal_bekker_bekker_k_c_kN_m_n1"].get<double>(), x[1]);
}

TEST_F(SoilUncertaintyTest, ABekkerFieldNeedsABekkerGroundAndAZetaAnRftOne) {
  // fjs1_lp's Bekker fields on the li2013 ground of case A: no landing would use them.
  Write("lp_bekker.json", BekkerCalibration("fjs1_lp", {1.0, 1.4, 820.0}, {0.05, 0.3, 60.0}, {0, 0, 0}));
  const std::string on_rft = Refusal(", soil_uncertainty: {fjs1_lp: {calibration: lp_bekker.json}}", kPadSoils);
  EXPECT_NE(on_rft.find("study.soil_uncertainty.fjs1_lp.calibration"), std::string::npos) << on_rft;
  EXPECT_NE(on_rft.find("bekker.n of soil 'fjs1_lp'"), std::string::npos) << on_rft;
  EXPECT_NE(on_rft.find("bekker law"), std::string::npos) << on_rft;
  // A zeta drawn on the bekker ground: the law does not use it.
  Write("zeta.json", R"({"covariance": {"parameters": [{"name": "z", "kind": "soil_zeta", "soil": "lunar_nominal_bekker",
      "value": 3}], "matrix": [[0.01]]}})");
  std::string on_bekker;
  try {
    LoadStudy(Write("z_study.yaml", std::string("schema_version: 1\ntype: stability\nname: b\nlander: {scenario: ") +
                                        TOUCHDOWN_SOURCE_DIR + "/data/scenarios/lander_lunar_bekker.yaml}\n" +
                                        "random: {samples: 4, seed: 3}\nstudy: {recheck: none, joint_range_sensitivity: "
                                        "none, soil_uncertainty: {lunar_nominal_bekker: {calibration: zeta.json}}}\n"));
  } catch (const InputError& e) {
    on_bekker = e.what();
  }
  EXPECT_NE(on_bekker.find("draws zeta, which the ground's bekker law does not use"), std::string::npos) << on_bekker;
}

// The shipped study with lambda drawn: both soils name one report, so zeta CP and the two soils'
// lambdas are one group, drawn with the report's covariance, cross-soil correlations included.
TEST_F(SoilUncertaintyTest, TheShippedLambdaStudyDrawsBothSoilsFromOneJointNormal) {
  const std::string dir = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/";
  const Study study = LoadStudy(dir + "studies/lunar_paper_lander_soil_lambda.yaml", "", 4);
  const SoilUncertainty& u = *study.soil_uncertainty;
  ASSERT_EQ(u.groups.size(), 1u);
  ASSERT_EQ(u.parameters.size(), 3u);
  EXPECT_EQ(u.parameters[0].column, "fjs1_cp_zeta_N_cm3");
  EXPECT_EQ(u.parameters[1].column, "fjs1_cp_dynamic_lambda");
  EXPECT_EQ(u.parameters[2].column, "fjs1_lp_dynamic_lambda");
  std::ifstream in(dir + "soils/calibrations/sutoh2017_r1z_lambda.json");
  const nlohmann::json report = nlohmann::json::parse(in)["covariance"];
  // The report's rows: zeta_cp, curved_a1 (a pad field: not drawn), lambda_cp, lambda_lp.
  const int rows[] = {0, 2, 3};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      EXPECT_EQ(u.groups[0].covariance(a, b), report["matrix"][rows[a]][rows[b]].get<double>()) << a << "," << b;
  // The draws follow the joint normal truncated to the box: zeta CP at least the fit's lower bound
  // 4.0 N/cm^3 (a third of the normal lies below it), the lambdas within the fit's [0, 5] (1-2 % of
  // the normal below 0). Its moments, from an independent sample (another generator), are the
  // reference.
  EXPECT_EQ(u.parameters[0].low, 4.0);
  EXPECT_EQ(u.parameters[1].high, 5.0);
  const Eigen::MatrixXd l = u.groups[0].lower;
  const Eigen::Vector3d mu(u.parameters[0].mean, u.parameters[1].mean, u.parameters[2].mean);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  const int n_ref = 200000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  for (int i = 0; i < n_ref;) {
    const Eigen::Vector3d x = mu + l * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    bool inside = true;
    for (int k = 0; k < 3; ++k) inside = inside && x(k) >= u.parameters[size_t(k)].low && x(k) <= u.parameters[size_t(k)].high;
    if (!inside) continue;
    sum += x;
    outer += x * x.transpose();
    ++i;
  }
  const Eigen::Vector3d ref_mean = sum / n_ref;
  const Eigen::Matrix3d ref_cov = (outer - n_ref * ref_mean * ref_mean.transpose()) / (n_ref - 1);
  const int n = 20000;
  const auto [mean, cov] = SampleMoments(u, n);
  const double se = std::sqrt(1.0 / n + 1.0 / n_ref);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(mean(a), ref_mean(a), 4 * std::sqrt(ref_cov(a, a)) * se) << a;
  EXPECT_GT(ref_mean(0) - mu(0), 0.1);  // the truncation shows: zeta CP's mean moves up
  // Lambda LP is drawn correlated with zeta CP (+0.65 in the report) though it is another soil's.
  const auto rho = [](const Eigen::MatrixXd& c, int a, int b) { return c(a, b) / std::sqrt(c(a, a) * c(b, b)); };
  EXPECT_GT(rho(u.groups[0].covariance, 0, 2), 0.5);
  for (const auto& [a, b] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}})
    EXPECT_NEAR(rho(cov, a, b), rho(ref_cov, a, b), 4.0 * se) << a << "," << b;
}

TEST_F(SoilUncertaintyTest, LambdaDrawsAreTruncatedAtZero) {
  // Lambda 0.2 +- 0.3: a quarter of the untruncated draws would be negative. The accepted draws'
  // marginal is the normal truncated to [0, inf): mean mu + sigma phi(a) / (1 - Phi(a)), a = -mu/sigma.
  Write("zl.json", ZetaLambdaCalibration(3.5, 0.2, 0.2, 0.3, 0.5));
  const Study study = Load(", soil_uncertainty: {fjs1_lp: {calibration: zl.json}}", kPadSoils);
  const int n = 40000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double l = DrawSoilParameters(*study.soil_uncertainty, i)[1];
    ASSERT_GE(l, 0.0) << i;
    sum += l;
    sum2 += l * l;
  }
  const double a = -0.2 / 0.3, tail = 1.0 - NormalCdf(a);
  const double expected = 0.2 + 0.3 * NormalPdf(a) / tail;
  const double var = 0.09 * (1.0 + a * NormalPdf(a) / tail - std::pow(NormalPdf(a) / tail, 2));
  EXPECT_NEAR(sum / n, expected, 4.0 * std::sqrt(var / n));  // 4 standard errors
  EXPECT_NEAR(sum2 / n - (sum / n) * (sum / n), var, 4.0 * var * std::sqrt(2.0 / n));
}

TEST_F(SoilUncertaintyTest, LambdaAloneKeepsTheSoilsZeta) {
  Write("l.json", R"({"covariance": {"parameters": [{"name": "l", "kind": "soil_dynamic_lambda", "soil": "fjs1_cp",
      "value": 1.3}], "matrix": [[0.04]]}})");
  const Study study = Load(", soil_uncertainty: {fjs1_cp: {calibration: l.json}}", kPadSoils);
  const SoilUncertainty& u = *study.soil_uncertainty;
  ASSERT_EQ(u.parameters.size(), 1u);
  const rft::SoilParameters cp = io::LoadSoil("fjs1_cp");
  const std::map<std::string, model::SoilOverride> o = SoilOverrides(u, DrawSoilParameters(u, 3));
  model::ModelFile m;
  m.soils = o;
  const rft::SoilParameters applied = model::ApplyModel(m, cp);
  EXPECT_EQ(applied.zeta_N_m3, cp.zeta_N_m3);  // bit for bit
  EXPECT_EQ(applied.dynamic_lambda, DrawSoilParameters(u, 3)[0]);
  EXPECT_NE(applied.dynamic_lambda, cp.dynamic_lambda);
  // The split's estimator takes lambda like zeta: an outcome linear in it is all soil.
  std::vector<sweep::DropRecord> records;
  for (int i = 0; i < 500; ++i) {
    sweep::DropRecord r;
    r.index = i;
    r.ok = true;
    r.tipped_over = 0.0;
    r.time_to_rest_s = 1.0;
    r.max_tilt_deg = 5.0;
    r.final_penetration_m = 0.05 - 0.002 * DrawSoilParameters(u, i)[0];
    records.push_back(r);
  }
  const std::optional<SoilSplit> split = SplitBySoil(u, records);
  ASSERT_TRUE(split);
  for (const ShareEstimate& e : split->shares)
    if (e.outcome == "max_pad_penetration_m") {
      EXPECT_NEAR(e.soil_share, 1.0, 1e-9);
      EXPECT_NEAR(e.slope.at(0), -0.002, 1e-9);
    }
  EXPECT_EQ(SoilSplitJson(u, split)["parameters"][0]["unit"], "-");
}

TEST_F(SoilUncertaintyTest, DrawnParametersRoundTripThroughTheDatabaseAndTheMpiFormat) {
  sweep::DropRecord a;
  a.index = 7;
  a.drop_id = "d07";
  a.ok = true;
  a.soil_parameters = {{"fjs1_lp_zeta_N_cm3", 3.4999999999999996}, {"fjs1_lp_dynamic_lambda", 1.0000000000000002}};
  sweep::DropRecord b = a;
  b.index = 8;
  b.drop_id = "d08";
  b.soil_parameters.clear();  // a record without draws (another plan) has none
  {
    sweep::ResultsDb db(Path("r.sqlite"));
    db.Insert({a, b});
    db.Insert({a});  // an overlapping shard's identical record: accepted
    sweep::DropRecord moved = a;
    moved.soil_parameters[1].second = 1.0;
    EXPECT_THROW(db.Insert({moved}), std::runtime_error);  // the same landing drawn otherwise: refused
  }
  for (const auto access : {sweep::ResultsDb::Access::kReadWrite, sweep::ResultsDb::Access::kReadOnly}) {
    const std::vector<sweep::DropRecord> back = sweep::ResultsDb(Path("r.sqlite"), access).ReadAll(false);
    ASSERT_EQ(back.size(), 2u);
    EXPECT_TRUE(sweep::SameRecord(back[0], a));
    EXPECT_TRUE(sweep::SameRecord(back[1], b));
    const std::vector<sweep::DropRecord> page = sweep::ResultsDb(Path("r.sqlite"), access).ReadPage(0, 10, false);
    EXPECT_TRUE(sweep::SameRecord(page[0], a));
  }
  const std::vector<sweep::DropRecord> sent = sweep::DeserializeRecords(sweep::SerializeRecords({a, b}));
  EXPECT_TRUE(sweep::SameRecord(sent[0], a));
  EXPECT_TRUE(sweep::SameRecord(sent[1], b));
  // A database with no draws gets no table: a study without soil uncertainty writes the file it did.
  { sweep::ResultsDb(Path("plain.sqlite")).Insert({b}); }
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(Path("plain.sqlite").c_str(), &raw), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(raw, "SELECT COUNT(*) FROM sqlite_master WHERE name = 'soil_parameters'", -1, &st, nullptr);
  ASSERT_EQ(sqlite3_step(st), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(st, 0), 0);
  sqlite3_finalize(st);
  sqlite3_close(raw);
}

// A small study on the coarse test pads: the lander on LP or CP per pad with both soils' zeta drawn
// wide (so the soil matters), run on 1 and on 2 threads.
struct SoilUncertaintyLandings : SoilUncertaintyTest {
  Study SmallStudy(int samples) {
    Write("cal.json", Calibration(3.5, 6.0, 1.2, 2.0, 0.3));
    Study study = Load(", soil_uncertainty: {fjs1_lp: {calibration: cal.json}, fjs1_cp: {calibration: cal.json}}",
                       "random: {samples: " + std::to_string(samples) +
                           ", seed: 5, slope_deg: {uniform: [0, 20]}, horizontal_speed_m_s: {uniform: [0, 1.5]},\n"
                           "  pad_soils: {per_pad_choice: [fjs1_lp, fjs1_cp]}}\n"
                           "fixed: {downhill_azimuth_deg: 0, horizontal_azimuth_deg: 0, yaw_relative_to_slope_deg: 45}\n");
    test::CoarsenPad(*study.plan.lander);
    study.plan.lander->options.duration_s = 0.6;  // short: the test's budget, not a settled answer
    return study;
  }
  std::vector<sweep::DropRecord> Run(const Study& study, const std::string& out, int threads) {
    sweep::SweepRunOptions options;
    options.threads = threads;
    options.progress = sweep::ProgressMode::kNone;
    sweep::RunSweep(study.plan, Path(out), options);
    return ReadStudyRecords(study, Path(out));
  }
};

TEST_F(SoilUncertaintyLandings, SameLandingsOnOneAndTwoThreadsAndTheDrawnZetaActs) {
  const Study study = SmallStudy(4);
  const std::vector<sweep::DropRecord> one = Run(study, "t1", 1), two = Run(study, "t2", 2);
  ASSERT_EQ(one.size(), two.size());
  for (size_t i = 0; i < one.size(); ++i) {
    ASSERT_TRUE(one[i].ok) << one[i].failure;
    EXPECT_EQ(one[i].final_penetration_m, two[i].final_penetration_m) << i;  // bit for bit
    EXPECT_EQ(one[i].max_tilt_deg, two[i].max_tilt_deg) << i;
    // The database holds the landing's drawn parameters, by column, bit for bit.
    const std::vector<double> x = DrawSoilParameters(*study.soil_uncertainty, one[i].index);
    ASSERT_EQ(one[i].soil_parameters.size(), 2u);
    EXPECT_EQ(one[i].soil_parameters[0].first, "fjs1_lp_zeta_N_cm3");
    EXPECT_EQ(one[i].soil_parameters[1].first, "fjs1_cp_zeta_N_cm3");
    EXPECT_EQ(one[i].soil_parameters[0].second, x[0]);
    EXPECT_EQ(one[i].soil_parameters[1].second, x[1]);
    EXPECT_TRUE(sweep::SameRecord(one[i], two[i]));
  }
  // The same landings without the draws (the catalogue's zeta) sink otherwise.
  Study fixed = study;
  fixed.plan.soil_overrides_at = nullptr;
  fixed.plan.variant.clear();
  const std::vector<sweep::DropRecord> catalogue = Run(fixed, "fixed", 2);
  int differ = 0;
  for (size_t i = 0; i < one.size(); ++i) differ += one[i].final_penetration_m != catalogue[i].final_penetration_m;
  EXPECT_EQ(differ, int(one.size()));
}

TEST_F(SoilUncertaintyLandings, SummaryReportsTheSplit) {
  const Study study = SmallStudy(12);
  Run(study, "out", 2);
  const StudySummary s = test::AnalyseStudy(study, Path("out"));
  ASSERT_TRUE(s.soil_split);
  ASSERT_FALSE(s.soil_split->shares.empty());
  EXPECT_EQ(s.soil_split->shares.front().outcome, "tipped_over");
  for (const ShareEstimate& e : s.soil_split->shares) {
    EXPECT_GE(e.soil_share, 0.0) << e.outcome;
    EXPECT_LE(e.soil_share, 1.0) << e.outcome;
    EXPECT_LE(e.soil_share_low, e.soil_share_high) << e.outcome;
  }
  std::ifstream in(Path("out/summary.json"));
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_TRUE(j.contains("soil_uncertainty"));
  const nlohmann::json& u = j["soil_uncertainty"];
  EXPECT_EQ(u["parameters"].size(), 2u);
  EXPECT_TRUE(u.contains("variance_split"));
  EXPECT_TRUE(u["tip_over_probability_at_interval_ends"].contains("at_soil_interval_ends"));
  bool depth = false;
  for (const nlohmann::json& e : u["variance_split"]) depth = depth || e["outcome"] == "max_pad_penetration_m";
  EXPECT_TRUE(depth);
  // Listed landings carry their drawn parameters; soil_parameters.csv has every landing's.
  for (const nlohmann::json& l : j["worst_max_tilt"]) EXPECT_TRUE(l["soil_parameters"].contains("fjs1_cp_zeta_N_cm3"));
  std::ifstream csv(Path("out/soil_parameters.csv"));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header, "drop_id,drop_index,fjs1_lp_zeta_N_cm3,fjs1_cp_zeta_N_cm3");
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 12);
  // The pairing (on by default): the 12 landings again at the best values, which the stored
  // records carry as their soil parameters, against the drawn study.
  ASSERT_TRUE(s.soil_pairing);
  EXPECT_TRUE(s.soil_pairing->ran);
  EXPECT_EQ(s.soil_pairing->samples, 12);
  EXPECT_EQ(s.soil_pairing->landings + s.soil_pairing->failed, 12);
  EXPECT_EQ(s.soil_pairing->tipped_drawn, s.tipped);
  const nlohmann::json& p = u["paired_with_best_values"];
  EXPECT_EQ(p["samples"], 12);
  EXPECT_EQ(p["outcomes"][0]["outcome"], "tipped_over");
  const sweep::ResultsDb db(sweep::ResultsDbPath(Path("out/soil_at_best_values")), sweep::ResultsDb::Access::kReadOnly);
  int stored = 0;
  db.ForEach(
      [&](const sweep::DropRecord& r) {
        ++stored;
        ASSERT_EQ(r.soil_parameters.size(), 2u);
        EXPECT_EQ(r.soil_parameters[0].second, 3.5);  // zeta LP's best value, exactly
        EXPECT_EQ(r.soil_parameters[1].second, 6.0);
      },
      /*with_traces=*/false);
  EXPECT_EQ(stored, 12);
  // Every best-value landing differs from its drawn twin only by the soil: the same conditions.
  const std::map<std::string, model::SoilOverride> best = SoilAtBestValuesPlan(study).soil_overrides_at(5);
  EXPECT_EQ(best.at("fjs1_lp").zeta_N_m3, units::ZetaFromN_cm3(3.5));
  EXPECT_EQ(best.at("fjs1_cp").zeta_N_m3, units::ZetaFromN_cm3(6.0));
}

// The estimator on hand-made records: an outcome that is a function of the drawn zeta alone is all
// soil; one that ignores it is all conditions; P(tip) at the interval ends follows the slope.
TEST_F(SoilUncertaintyTest, SplitEstimatorSeparatesTheSources) {
  Write("cal.json", Calibration(3.5, 4.1, 0.2, 0.1, 0.0));
  const Study study = Load(", soil_uncertainty: {fjs1_lp: {calibration: cal.json}}", kPadSoils);
  const SoilUncertainty& u = *study.soil_uncertainty;
  std::vector<sweep::DropRecord> soil_only, conditions_only;
  for (int i = 0; i < 2000; ++i) {
    sweep::DropRecord r;
    r.index = i;
    r.ok = true;
    r.tipped_over = 0.0;
    r.time_to_rest_s = 1.0;
    const double zeta = DrawSoilParameters(u, i)[0];
    r.final_penetration_m = 0.1 - 0.01 * zeta;  // linear in zeta: the soil's share is 1
    r.max_tilt_deg = 5.0;
    soil_only.push_back(r);
    r.final_penetration_m = 0.05 + 0.01 * sweep::CounterUniform(99, uint64_t(i), 7);  // independent of zeta
    r.tipped_over = zeta > 3.5 ? 1.0 : 0.0;  // a tip-over decided by the soil
    conditions_only.push_back(r);
  }
  const auto share = [](const SoilSplit& s, const std::string& outcome) {
    for (const ShareEstimate& e : s.shares)
      if (e.outcome == outcome) return e;
    return ShareEstimate{};
  };
  const std::optional<SoilSplit> a = SplitBySoil(u, soil_only), b = SplitBySoil(u, conditions_only);
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(share(*a, "max_pad_penetration_m").soil_share, 1.0, 1e-9);
  EXPECT_NEAR(share(*a, "max_pad_penetration_m").slope.at(0), -0.01, 1e-9);
  EXPECT_LT(share(*b, "max_pad_penetration_m").soil_share, 0.01);
  EXPECT_EQ(share(*b, "max_pad_penetration_m").soil_share_low, 0.0);
  // Tip when zeta > its mean: P = 1/2, the linear fit's share 2/pi ~ 0.64 (a step seen linearly),
  // and P(tip) at the soil's interval ends near 0 and 1.
  EXPECT_NEAR(b->p_tip, 0.5, 0.05);
  EXPECT_NEAR(share(*b, "tipped_over").soil_share, 2.0 / M_PI, 0.05);
  EXPECT_LT(b->p_tip_at_soil_ends.first, 0.1);
  EXPECT_GT(b->p_tip_at_soil_ends.second, 0.9);
  // Too few landings to fit: no split (and summary.json says why).
  EXPECT_FALSE(SplitBySoil(u, std::vector<sweep::DropRecord>(soil_only.begin(), soil_only.begin() + 3)));
}

}  // namespace
}  // namespace touchdown::stability
