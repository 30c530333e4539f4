// Each landing's soil parameters, drawn from the calibrations' joint normals by the counter-based
// streams, and what the plan's digest holds of them (soil_uncertainty.h).
#include "drop_tests/stability/soil_uncertainty.h"

#include <nlohmann/json.hpp>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/stability/rare_event.h"
#include "drop_tests/sweep/sweep_plan.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::stability {

const SoilFieldInfo& InfoOf(SoilField f) {
  static const std::vector<SoilFieldInfo> infos = [] {
    std::vector<SoilFieldInfo> out{{"soil_zeta", "zeta_N_cm3", "N/cm^3", &limits::kZeta_N_cm3, nullptr},
                                   {"soil_dynamic_lambda", "dynamic_lambda", "-", &limits::kDynamicLambda, nullptr}};
    for (const model::BekkerOverrideField& e : model::BekkerOverrideFields())
      out.push_back({std::string("soil_bekker_") + e.short_name, std::string("bekker_") + e.key, e.unit, e.range, &e});
    return out;
  }();
  return infos.at(size_t(f));
}

namespace {
bool InsideBoxes(const SoilUncertainty& u, const std::vector<double>& x, const std::vector<size_t>& which) {
  for (const size_t k : which) {
    const UncertainParameter& q = u.parameters[k];
    if (!(q.low_open ? x[k] > q.low : x[k] >= q.low) || !(x[k] <= q.high)) return false;
  }
  return true;
}
}  // namespace

std::vector<double> DrawSoilParameters(const SoilUncertainty& u, int64_t index) {
  std::vector<double> x(u.parameters.size());
  for (const CalibrationGroup& g : u.groups) {
    const Eigen::Index n = Eigen::Index(g.parameters.size());
    bool accepted = false;
    for (int attempt = 0; attempt < kMaxDrawAttempts && !accepted; ++attempt) {
      Eigen::VectorXd z(n), mean(n);
      for (Eigen::Index a = 0; a < n; ++a) {
        const uint64_t stream = kSoilDrawStream + uint64_t(attempt) * kSoilAttemptStride + g.parameters[size_t(a)];
        z(a) = StandardNormal(u.seed, uint64_t(index), stream);
        mean(a) = u.parameters[g.parameters[size_t(a)]].mean;
      }
      const Eigen::VectorXd v = mean + g.lower * z;
      for (Eigen::Index a = 0; a < n; ++a) x[g.parameters[size_t(a)]] = v(a);
      accepted = InsideBoxes(u, x, g.parameters);
    }
    if (!accepted)
      for (const size_t k : g.parameters) x[k] = u.parameters[k].mean;
  }
  return x;
}

std::map<std::string, model::SoilOverride> SoilOverrides(const SoilUncertainty& u, const std::vector<double>& drawn) {
  std::map<std::string, model::SoilOverride> out;
  for (size_t k = 0; k < u.parameters.size(); ++k) {
    const UncertainParameter& q = u.parameters[k];
    const auto [it, added] = out.try_emplace(q.soil);
    model::SoilOverride& o = it->second;
    if (added) {  // the soil file's zeta until a drawn zeta replaces it
      o.zeta_N_m3 = q.soil_zeta_N_m3;
      o.reference_gravity_m_s2 = q.reference_gravity_m_s2;
    }
    if (q.field == SoilField::kZeta) {
      o.zeta_N_m3 = units::ZetaFromN_cm3(drawn[k]);
      o.reference_gravity_m_s2 = q.reference_gravity_m_s2;
    } else if (const model::BekkerOverrideField* b = InfoOf(q.field).bekker) {
      o.*b->member = drawn[k] * b->si_per_unit;
    } else {
      o.dynamic_lambda = drawn[k];
    }
  }
  return out;
}

std::string SoilUncertaintyDigestText(const SoilUncertainty& u) {
  std::string s = "soil_uncertainty:";
  for (const CalibrationGroup& g : u.groups) {
    s += "[";
    for (const size_t k : g.parameters) {
      const UncertainParameter& p = u.parameters[k];
      if (p.field == SoilField::kZeta)
        s += p.soil + "=" + io::FormatNumber(p.mean) + "@" + io::FormatNumber(p.reference_gravity_m_s2) + ";";
      else if (p.field == SoilField::kDynamicLambda)
        s += p.soil + ".dynamic_lambda=" + io::FormatNumber(p.mean) + ";";
      else
        s += p.soil + "." + InfoOf(p.field).column_suffix + "=" + io::FormatNumber(p.mean) + ";";
      // A box narrowed to the fit's bounds draws other values: another plan.
      if (p.fit_bounded) s += "in[" + io::FormatNumber(p.low) + "," + io::FormatNumber(p.high) + "];";
    }
    for (Eigen::Index a = 0; a < g.covariance.rows(); ++a)
      for (Eigen::Index b = 0; b < g.covariance.cols(); ++b) s += io::FormatNumber(g.covariance(a, b)) + ",";
    s += "]";
  }
  return s;
}

void AttachSoilUncertainty(sweep::SweepPlan& plan, const SoilUncertainty& u) {
  plan.soil_overrides_at = [u](int64_t index) { return SoilOverrides(u, DrawSoilParameters(u, index)); };
  plan.soil_parameters_at = [u](int64_t index) {
    const std::vector<double> x = DrawSoilParameters(u, index);
    std::vector<std::pair<std::string, double>> named;
    for (size_t k = 0; k < x.size(); ++k) named.emplace_back(u.parameters[k].column, x[k]);
    return named;
  };
  plan.variant += std::string(plan.variant.empty() ? "" : ";") + SoilUncertaintyDigestText(u);
}

nlohmann::json DrawnParametersJson(const SoilUncertainty& u, int64_t index) {
  const std::vector<double> x = DrawSoilParameters(u, index);
  nlohmann::json j = nlohmann::json::object();
  for (size_t k = 0; k < x.size(); ++k) j[u.parameters[k].column] = x[k];
  return j;
}

}  // namespace touchdown::stability
