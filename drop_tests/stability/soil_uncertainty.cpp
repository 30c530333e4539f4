#include "drop_tests/stability/soil_uncertainty.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <set>
#include <tuple>

#include <boost/math/distributions/normal.hpp>
#include <nlohmann/json.hpp>

#include "drop_tests/io/catalog.h"
#include "drop_tests/io/dataset_csv.h"
#include "drop_tests/io/yaml_fields.h"
#include "drop_tests/stability/study_summary.h"
#include "drop_tests/sweep/sweep_spec.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::stability {

namespace {
namespace fs = std::filesystem;

// The soils a landing of the plan can stand on, by name: the scenario's ground (default soil,
// patches, a patch field's soils) and the study's `soil` and `pad_soils` values.
std::set<std::string> StudySoilNames(const sweep::SweepPlan& plan) {
  std::set<std::string> names;
  for (const rft::SoilParameters& s : plan.soils) names.insert(s.name);
  if (plan.lander) {
    const scenario::LanderGroundSpec& g = plan.lander->ground;
    names.insert(io::LoadSoil(g.default_soil).name);
    for (const scenario::LanderPatchSpec& p : g.patches) names.insert(io::LoadSoil(p.soil).name);
    if (g.soil_field)
      for (const std::string& s : g.soil_field->soils) names.insert(io::LoadSoil(s).name);
  }
  return names;
}

std::string Joined(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

nlohmann::json ReadJsonFile(const std::string& path, const std::string& study_file, const std::string& field) {
  std::ifstream in(path);
  if (!fs::is_regular_file(path) || !in)
    throw MakeInputError(study_file, field, "cannot read the calibration report '" + path + "'");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw MakeInputError(path, "", std::string("is not JSON: ") + e.what());
  }
}

double JsonNumber(const nlohmann::json& j, const std::string& file, const std::string& field) {
  if (!j.is_number() || !std::isfinite(j.get<double>())) throw MakeInputError(file, field, "must be a finite number, got " + j.dump());
  return j.get<double>();
}

// The calibration's covariance block, checked: parameters with names, values and units, and a
// square symmetric matrix of their size.
struct CalibrationCovariance {
  std::vector<nlohmann::json> parameters;
  Eigen::MatrixXd matrix;
};

CalibrationCovariance ReadCovariance(const nlohmann::json& report, const std::string& file) {
  if (!report.is_object() || !report.contains("covariance") || !report["covariance"].is_object())
    throw MakeInputError(file, "covariance",
                         "missing: a calibration report written by `touchdown calibrate --targets FILE --report R.json` "
                         "holds the fitted parameters' covariance");
  const nlohmann::json& c = report["covariance"];
  if (!c.contains("parameters") || !c["parameters"].is_array() || !c.contains("matrix") || !c["matrix"].is_array())
    throw MakeInputError(file, "covariance", "must hold `parameters` and `matrix` lists");
  CalibrationCovariance out;
  const size_t n = c["parameters"].size();
  out.matrix.resize(Eigen::Index(n), Eigen::Index(n));
  if (c["matrix"].size() != n)
    throw MakeInputError(file, "covariance.matrix", "must have " + std::to_string(n) + " rows (one per parameter), got " +
                                                        std::to_string(c["matrix"].size()));
  for (size_t a = 0; a < n; ++a) {
    const nlohmann::json& row = c["matrix"][a];
    const std::string field = "covariance.matrix[" + std::to_string(a) + "]";
    if (!row.is_array() || row.size() != n)
      throw MakeInputError(file, field, "must be a list of " + std::to_string(n) + " numbers");
    for (size_t b = 0; b < n; ++b) out.matrix(Eigen::Index(a), Eigen::Index(b)) = JsonNumber(row[b], file, field);
  }
  for (size_t a = 0; a < n; ++a) {
    const nlohmann::json& p = c["parameters"][a];
    const std::string field = "covariance.parameters[" + std::to_string(a) + "]";
    if (!p.is_object() || !p.contains("name") || !p["name"].is_string() || !p.contains("value") || !p.contains("kind"))
      throw MakeInputError(file, field, "must have a name, a kind and a value");
    JsonNumber(p["value"], file, field + ".value");
    out.parameters.push_back(p);
  }
  if (!out.matrix.isApprox(out.matrix.transpose(), 1e-9))
    throw MakeInputError(file, "covariance.matrix", "must be symmetric");
  return out;
}

// The index in the calibration's covariance of soil `soil`'s zeta.
size_t ZetaOf(const CalibrationCovariance& c, const std::string& soil, const std::string& file) {
  std::vector<size_t> found;
  std::set<std::string> soils;
  for (size_t a = 0; a < c.parameters.size(); ++a) {
    const nlohmann::json& p = c.parameters[a];
    if (p.value("kind", "") != "soil_zeta") continue;
    soils.insert(p.value("soil", ""));
    if (p.value("soil", "") == soil) found.push_back(a);
  }
  if (found.size() != 1)
    throw MakeInputError(file, "covariance.parameters",
                         found.empty() ? "has no interval for the zeta of soil '" + soil + "' (its soils with one: " +
                                             (soils.empty() ? std::string("none") : Joined(soils)) +
                                             "; a parameter at a bound or held fixed gets none)"
                                       : "has the zeta of soil '" + soil + "' more than once");
  return found.front();
}

double Quantile95() { return boost::math::quantile(boost::math::normal(), 0.975); }

bool InsideLimits(const std::vector<double>& x, const std::vector<size_t>& which) {
  for (const size_t k : which) {
    const limits::Range& r = limits::kZeta_N_cm3;
    if (!(r.low_open ? x[k] > r.low : x[k] >= r.low) || !(x[k] <= r.high)) return false;
  }
  return true;
}
}  // namespace

SoilUncertainty ReadSoilUncertainty(const io::YamlFields& study_block, const sweep::SweepPlan& plan) {
  SoilUncertainty u;
  u.seed = plan.seed;
  const std::string key = "soil_uncertainty";
  const YAML::Node node = study_block.node()[key];
  if (!node.IsMap() || node.size() == 0)
    study_block.Fail(key, "must be a mapping of soil names to {calibration: FILE.json}");
  if (plan.lander && plan.lander->ground.law == rft::LawKind::kBekker)
    study_block.Fail(key, "draws zeta, which the ground's bekker law does not use");
  const std::set<std::string> soils = StudySoilNames(plan);
  const fs::path base = fs::path(study_block.file()).parent_path();
  std::map<std::string, size_t> group_of_file;
  std::map<std::string, CalibrationCovariance> read;
  std::vector<std::vector<size_t>> rows_in_file;  // per group: the covariance rows of its parameters
  const io::YamlFields all = study_block.Child(key);
  for (const auto& entry : node) {
    const std::string soil = entry.first.as<std::string>();
    if (!soils.count(soil))
      all.Fail(soil, "is not a soil this study's landings stand on (" + Joined(soils) + ")");
    const io::YamlFields f = all.Child(soil);
    f.RequireOnly({"calibration"});
    const std::string given = f.String("calibration");
    const fs::path p = fs::path(given).is_absolute() ? fs::path(given) : base / given;
    const std::string path = fs::absolute(p).lexically_normal().string();
    if (!read.count(path)) read.emplace(path, ReadCovariance(ReadJsonFile(path, f.file(), f.Path("calibration")), path));
    const CalibrationCovariance& c = read.at(path);
    const size_t row = ZetaOf(c, soil, path);
    UncertainParameter q;
    q.soil = soil;
    q.name = c.parameters[row]["name"].get<std::string>();
    q.column = soil + "_zeta_N_cm3";
    q.mean = c.parameters[row]["value"].get<double>();
    q.reference_gravity_m_s2 = c.parameters[row].value("reference_gravity_m_s2", rft::kEarthGravity_m_s2);
    limits::Require(limits::kZeta_N_cm3, q.mean, path, "covariance.parameters[" + std::to_string(row) + "].value");
    limits::Require(limits::kGravity_m_s2, q.reference_gravity_m_s2, path,
                    "covariance.parameters[" + std::to_string(row) + "].reference_gravity_m_s2");
    if (!group_of_file.count(path)) {
      group_of_file[path] = u.groups.size();
      u.groups.push_back({path, {}, {}, {}});
      rows_in_file.emplace_back();
    }
    const size_t g = group_of_file[path];
    u.groups[g].parameters.push_back(u.parameters.size());
    rows_in_file[g].push_back(row);
    u.parameters.push_back(q);
  }
  if (u.parameters.size() > size_t(kMaxUncertainParameters))
    study_block.Fail(key, "draws at most " + std::to_string(kMaxUncertainParameters) + " parameters");
  for (size_t g = 0; g < u.groups.size(); ++g) {
    CalibrationGroup& group = u.groups[g];
    const Eigen::MatrixXd& m = read.at(group.file).matrix;
    const Eigen::Index n = Eigen::Index(rows_in_file[g].size());
    group.covariance.resize(n, n);
    for (Eigen::Index a = 0; a < n; ++a)
      for (Eigen::Index b = 0; b < n; ++b) group.covariance(a, b) = m(Eigen::Index(rows_in_file[g][size_t(a)]), Eigen::Index(rows_in_file[g][size_t(b)]));
    const Eigen::LLT<Eigen::MatrixXd> llt(group.covariance);
    if (llt.info() != Eigen::Success || !(group.covariance.diagonal().minCoeff() > 0.0))
      throw MakeInputError(group.file, "covariance.matrix", "must be positive definite over the drawn soils' zeta");
    group.lower = llt.matrixL();
    for (Eigen::Index a = 0; a < n; ++a) u.parameters[group.parameters[size_t(a)]].sigma = std::sqrt(group.covariance(a, a));
  }
  return u;
}

std::vector<double> DrawSoilParameters(const SoilUncertainty& u, int64_t index) {
  std::vector<double> x(u.parameters.size());
  for (const CalibrationGroup& g : u.groups) {
    const Eigen::Index n = Eigen::Index(g.parameters.size());
    bool accepted = false;
    for (int attempt = 0; attempt < kMaxDrawAttempts && !accepted; ++attempt) {
      Eigen::VectorXd z(n), mean(n);
      for (Eigen::Index a = 0; a < n; ++a) {
        const uint64_t stream = kSoilDrawStream + uint64_t(attempt) * kSoilAttemptStride + g.parameters[size_t(a)];
        // In (0, 1): the counter's [0, 1) moved by half its step, so the quantile is finite.
        const double p = sweep::CounterUniform(u.seed, uint64_t(index), stream) + 0x1.0p-54;
        z(a) = boost::math::quantile(boost::math::normal(), p);
        mean(a) = u.parameters[g.parameters[size_t(a)]].mean;
      }
      const Eigen::VectorXd v = mean + g.lower * z;
      for (Eigen::Index a = 0; a < n; ++a) x[g.parameters[size_t(a)]] = v(a);
      accepted = InsideLimits(x, g.parameters);
    }
    if (!accepted)
      for (const size_t k : g.parameters) x[k] = u.parameters[k].mean;
  }
  return x;
}

std::map<std::string, model::SoilOverride> SoilOverrides(const SoilUncertainty& u, const std::vector<double>& drawn) {
  std::map<std::string, model::SoilOverride> out;
  for (size_t k = 0; k < u.parameters.size(); ++k) {
    model::SoilOverride& o = out[u.parameters[k].soil];
    o.zeta_N_m3 = units::ZetaFromN_cm3(drawn[k]);
    o.reference_gravity_m_s2 = u.parameters[k].reference_gravity_m_s2;
  }
  return out;
}

std::string SoilUncertaintyDigestText(const SoilUncertainty& u) {
  std::string s = "soil_uncertainty:";
  for (const CalibrationGroup& g : u.groups) {
    s += "[";
    for (const size_t k : g.parameters) {
      const UncertainParameter& p = u.parameters[k];
      s += p.soil + "=" + io::FormatNumber(p.mean) + "@" + io::FormatNumber(p.reference_gravity_m_s2) + ";";
    }
    for (Eigen::Index a = 0; a < g.covariance.rows(); ++a)
      for (Eigen::Index b = 0; b < g.covariance.cols(); ++b) s += io::FormatNumber(g.covariance(a, b)) + ",";
    s += "]";
  }
  return s;
}

void AttachSoilUncertainty(sweep::SweepPlan& plan, const SoilUncertainty& u) {
  plan.soil_overrides_at = [u](int64_t index) { return SoilOverrides(u, DrawSoilParameters(u, index)); };
  plan.variant += std::string(plan.variant.empty() ? "" : ";") + SoilUncertaintyDigestText(u);
}

namespace {
// The least-squares fit of y on the columns of x (an intercept added): its slopes and adjusted R^2.
struct LinearFit {
  Eigen::VectorXd slope;
  double mean = 0.0, variance = 0.0, r2 = 0.0, adjusted_r2 = 0.0;
};

LinearFit FitLinear(const Eigen::MatrixXd& x, const Eigen::VectorXd& y) {
  const Eigen::Index n = y.size(), p = x.cols();
  LinearFit f;
  f.mean = y.mean();
  const Eigen::VectorXd yc = y.array() - f.mean;
  const Eigen::MatrixXd xc = x.rowwise() - x.colwise().mean();
  const double total = yc.squaredNorm();
  f.variance = total / double(n - 1);
  f.slope = Eigen::VectorXd::Zero(p);
  if (!(total > 0.0)) return f;  // a constant outcome: nothing to explain
  f.slope = xc.colPivHouseholderQr().solve(yc);
  const double residual = (yc - xc * f.slope).squaredNorm();
  f.r2 = std::clamp(1.0 - residual / total, 0.0, 1.0);
  f.adjusted_r2 = std::clamp(1.0 - (1.0 - f.r2) * double(n - 1) / double(n - p - 1), 0.0, 1.0);
  return f;
}

// The 95 % interval of R^2 from Fisher's z of the multiple correlation R (approximate: exact for
// one parameter and a normal outcome), clipped to [0, 1].
std::pair<double, double> ShareInterval(double r2, int64_t n) {
  const double r = std::sqrt(std::clamp(r2, 0.0, 1.0 - 1e-12));
  const double half = Quantile95() / std::sqrt(double(n - 3));
  const double lo = std::tanh(std::atanh(r) - half), hi = std::tanh(std::atanh(r) + half);
  return {lo > 0.0 ? lo * lo : 0.0, hi * hi};
}

ShareEstimate Share(const std::string& outcome, const std::vector<std::vector<double>>& rows, const std::vector<double>& y) {
  const Eigen::Index n = Eigen::Index(y.size()), p = Eigen::Index(rows.empty() ? 0 : rows.front().size());
  Eigen::MatrixXd x(n, p);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < p; ++k) x(i, k) = rows[size_t(i)][size_t(k)];
  const LinearFit f = FitLinear(x, Eigen::Map<const Eigen::VectorXd>(y.data(), n));
  ShareEstimate s;
  s.outcome = outcome;
  s.landings = n;
  s.variance = f.variance;
  s.soil_share = f.adjusted_r2;
  std::tie(s.soil_share_low, s.soil_share_high) = ShareInterval(f.r2, n);
  s.slope.assign(f.slope.data(), f.slope.data() + p);
  return s;
}

Eigen::MatrixXd JointCovariance(const SoilUncertainty& u) {
  const Eigen::Index p = Eigen::Index(u.parameters.size());
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(p, p);
  for (const CalibrationGroup& g : u.groups)
    for (size_t a = 0; a < g.parameters.size(); ++a)
      for (size_t b = 0; b < g.parameters.size(); ++b)
        c(Eigen::Index(g.parameters[a]), Eigen::Index(g.parameters[b])) = g.covariance(Eigen::Index(a), Eigen::Index(b));
  return c;
}
}  // namespace

std::optional<SoilSplit> SplitBySoil(const SoilUncertainty& u, const std::vector<sweep::DropRecord>& records) {
  const size_t p = u.parameters.size();
  std::vector<std::vector<double>> all_rows, up_rows;
  std::vector<double> tipped;
  std::vector<const sweep::DropRecord*> up;
  for (const sweep::DropRecord& r : records) {
    if (!r.ok) continue;
    all_rows.push_back(DrawSoilParameters(u, r.index));
    tipped.push_back(r.tipped_over > 0.5 ? 1.0 : 0.0);
    if (StayedUp(r)) {
      up_rows.push_back(all_rows.back());
      up.push_back(&r);
    }
  }
  if (tipped.size() < p + 3) return std::nullopt;
  SoilSplit split;
  split.shares.push_back(Share("tipped_over", all_rows, tipped));
  for (const StudyMetric& m : StudyMetrics()) {
    std::vector<std::vector<double>> rows;
    std::vector<double> y;
    for (size_t i = 0; i < up.size(); ++i) {
      const double v = m.value(*up[i]);
      if (!std::isfinite(v)) continue;
      rows.push_back(up_rows[i]);
      y.push_back(v);
    }
    if (y.size() >= p + 3) split.shares.push_back(Share(m.name, rows, y));
  }
  const ShareEstimate& tip = split.shares.front();
  split.p_tip = std::accumulate(tipped.begin(), tipped.end(), 0.0) / double(tipped.size());
  const double z = Quantile95();
  for (size_t k = 0; k < p; ++k) {
    const double d = tip.slope[k] * z * u.parameters[k].sigma;
    split.p_tip_at_parameter_ends.push_back(
        {std::clamp(split.p_tip - d, 0.0, 1.0), std::clamp(split.p_tip + d, 0.0, 1.0)});
  }
  const Eigen::VectorXd b = Eigen::Map<const Eigen::VectorXd>(tip.slope.data(), Eigen::Index(p));
  split.p_tip_soil_sd = std::sqrt(std::max(0.0, b.dot(JointCovariance(u) * b)));
  split.p_tip_at_soil_ends = {std::clamp(split.p_tip - z * split.p_tip_soil_sd, 0.0, 1.0),
                              std::clamp(split.p_tip + z * split.p_tip_soil_sd, 0.0, 1.0)};
  return split;
}

nlohmann::json SoilSplitJson(const SoilUncertainty& u, const std::optional<SoilSplit>& split) {
  nlohmann::json params = nlohmann::json::array();
  for (const UncertainParameter& q : u.parameters)
    params.push_back({{"soil", q.soil}, {"parameter", q.name}, {"column", q.column}, {"mean", q.mean}, {"sigma", q.sigma},
                      {"unit", "N/cm^3"}, {"reference_gravity_m_s2", q.reference_gravity_m_s2}});
  nlohmann::json files = nlohmann::json::array();
  for (const CalibrationGroup& g : u.groups) files.push_back(g.file);
  nlohmann::json out{{"parameters", params},
                     {"calibrations", files},
                     {"draws", "per landing from the joint normal of each calibration (Cholesky factor of its covariance), "
                               "counter-based on (seed, landing index); a draw outside zeta's physical range (0, 1e4] "
                               "N/cm^3 drawn again, up to " + std::to_string(kMaxDrawAttempts) + " times, then the best values"},
                     {"split_method",
                      "soil_share: adjusted R^2 of the least-squares fit of the outcome on the drawn parameters (the "
                      "first-order share of the variance the soil explains, for an outcome locally linear in them); "
                      "conditions_share = 1 - soil_share (touchdown conditions, and their interactions with the soil); "
                      "interval_95: Fisher z of the multiple correlation"}};
  if (!split) {
    out["split_reason"] = "too few completed landings to fit the outcome on " + std::to_string(u.parameters.size()) +
                          " parameter(s)";
    return out;
  }
  nlohmann::json shares = nlohmann::json::array();
  for (const ShareEstimate& s : split->shares) {
    nlohmann::json slopes = nlohmann::json::object();
    for (size_t k = 0; k < u.parameters.size(); ++k) slopes[u.parameters[k].column] = s.slope[k];
    shares.push_back({{"outcome", s.outcome},
                      {"landings", s.landings},
                      {"variance", s.variance},
                      {"soil_share", s.soil_share},
                      {"soil_share_interval_95", {s.soil_share_low, s.soil_share_high}},
                      {"conditions_share", 1.0 - s.soil_share},
                      {"slope_per_N_cm3", slopes}});
  }
  out["variance_split"] = shares;
  nlohmann::json ends = nlohmann::json::object();
  for (size_t k = 0; k < u.parameters.size(); ++k)
    ends[u.parameters[k].column] = {{"at", {u.parameters[k].mean - Quantile95() * u.parameters[k].sigma,
                                            u.parameters[k].mean + Quantile95() * u.parameters[k].sigma}},
                                    {"tip_over_probability", {split->p_tip_at_parameter_ends[k].first,
                                                              split->p_tip_at_parameter_ends[k].second}}};
  out["tip_over_probability_at_interval_ends"] = {
      {"method", "linear fit of the tip-over indicator on the drawn parameters, evaluated at each parameter's 95 % "
                 "interval ends (the others at their best values) and at +-1.96 sd of the soil's combined effect; "
                 "clipped to [0, 1]"},
      {"tip_over_probability", split->p_tip},
      {"per_parameter", ends},
      {"soil_sd", split->p_tip_soil_sd},
      {"at_soil_interval_ends", {split->p_tip_at_soil_ends.first, split->p_tip_at_soil_ends.second}}};
  return out;
}

nlohmann::json DrawnParametersJson(const SoilUncertainty& u, int64_t index) {
  const std::vector<double> x = DrawSoilParameters(u, index);
  nlohmann::json j = nlohmann::json::object();
  for (size_t k = 0; k < x.size(); ++k) j[u.parameters[k].column] = x[k];
  return j;
}

}  // namespace touchdown::stability
