// The split of a study's outcomes into the soil's share and the conditions' share, and P(tip) at
// the soil's interval ends (soil_uncertainty.h, docs/stability_studies.md "The soil's uncertainty").
#include "drop_tests/stability/soil_uncertainty.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include <boost/algorithm/string/join.hpp>
#include <boost/math/distributions/normal.hpp>
#include <nlohmann/json.hpp>

#include "drop_tests/stability/study_summary.h"

namespace touchdown::stability {

namespace {
double Quantile95() { return boost::math::quantile(boost::math::normal(), 0.975); }

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
                      {"unit", InfoOf(q.field).unit}, {"reference_gravity_m_s2", q.reference_gravity_m_s2},
                      {"drawn_within", {q.low, q.high}},
                      {"truncated_to", q.fit_bounded ? "the calibration's fit bounds" : "the physical range"}});
  bool lambda = false, bekker = false, zeta = false;
  for (const UncertainParameter& q : u.parameters) {
    zeta = zeta || q.field == SoilField::kZeta;
    lambda = lambda || q.field == SoilField::kDynamicLambda;
    bekker = bekker || InfoOf(q.field).bekker;
  }
  // The physical ranges of the fields drawn.
  std::vector<std::string> drawn_ranges;
  if (zeta) drawn_ranges.push_back("zeta (0, 1e4] N/cm^3");
  if (lambda) drawn_ranges.push_back("dynamic_lambda [0, 100]");
  if (bekker) drawn_ranges.push_back("Bekker's n (0, 5], k_c [0, 1e6] kN/m^(n+1), k_phi [0, 1e6] kN/m^(n+2)");
  const std::string ranges = "the physical range (" + boost::algorithm::join(drawn_ranges, ", ") + ")";
  nlohmann::json files = nlohmann::json::array();
  for (const CalibrationGroup& g : u.groups) files.push_back(g.file);
  nlohmann::json out{{"parameters", params},
                     {"calibrations", files},
                     {"draws", "per landing from the joint normal of each calibration (Cholesky factor of its covariance), "
                               "counter-based on (seed, landing index); a draw outside a parameter's `drawn_within` (the "
                               "calibration's fit bounds within " + ranges + "; the physical range alone with "
                               "`truncate: physical_limits`) drawn again, up to " +
                               std::to_string(kMaxDrawAttempts) + " times, then the best values"},
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
                      {lambda || bekker ? "slope_per_unit" : "slope_per_N_cm3", slopes}});
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

}  // namespace touchdown::stability
