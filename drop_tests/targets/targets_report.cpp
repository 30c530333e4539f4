// The report of a targets fit: JSON, a short table, and the model file of the fitted zeta.
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "drop_tests/catalog/paths_in_outputs.h"
#include "drop_tests/targets/object_edit.h"
#include "drop_tests/targets/targets_fit.h"
#include "rft/units.h"

namespace touchdown::targets {

namespace {
bool HasPriors(const TargetsFile& file) {
  for (const Parameter& p : file.parameters)
    if (p.prior) return true;
  return false;
}

const char* BoundName(ParameterResult::Bound b) { return NameIn(kBoundNames, b); }

std::string TargetText(const Target& t) {
  char buffer[96];
  if (t.value) {
    std::snprintf(buffer, sizeof buffer, "%.6g", *t.value);
  } else if (t.at_most && t.at_least) {
    std::snprintf(buffer, sizeof buffer, "[%.6g, %.6g]", *t.at_least, *t.at_most);
  } else if (t.at_most) {
    std::snprintf(buffer, sizeof buffer, "<= %.6g", *t.at_most);
  } else {
    std::snprintf(buffer, sizeof buffer, ">= %.6g", *t.at_least);
  }
  return buffer;
}

std::string ApplyHint(const Parameter& p) {
  switch (p.kind) {
    case ParameterKind::kSoilZeta:
    case ParameterKind::kSoilDynamicLambda:
    case ParameterKind::kSoilBekker: return "in this model file: --model MODEL.yaml";
    case ParameterKind::kPadField:
      return "not in the model file: set " + p.field + " in a copy of pad " + p.object + "'s file and name that copy";
    case ParameterKind::kLanderField:
      return "not in the model file: set " + p.field + " in a copy of lander " + p.object +
             "'s file and name that copy";
  }
  return "";
}

std::string KindName(const Parameter& p) {
  switch (p.kind) {
    case ParameterKind::kSoilZeta: return "soil_zeta";
    case ParameterKind::kSoilDynamicLambda: return "soil_dynamic_lambda";
    case ParameterKind::kSoilBekker: return std::string("soil_bekker_") + p.bekker->short_name;
    case ParameterKind::kPadField: return "pad_field";
    case ParameterKind::kLanderField: return "lander_field";
  }
  return "";
}

// The joint covariance of the parameters with an interval, for a study to draw them from
// (drop_tests/stability/soil_uncertainty.h): best values, names, units (a field's unit is its
// suffix; a soil's zeta is N/cm^3 at the soil's reference gravity) and the matrix, row by row.
nlohmann::json CovarianceJson(const TargetsFile& file, const TargetsFitResult& fit) {
  nlohmann::json params = nlohmann::json::array();
  for (const size_t i : fit.covariance_parameters) {
    const Parameter& p = file.parameters[i];
    nlohmann::json j{{"name", p.name},   {"kind", KindName(p)}, {"field", p.field}, {"value", fit.parameters[i].value},
                     {"lower", p.lower}, {"upper", p.upper}};
    if (p.kind == ParameterKind::kSoilZeta) {
      j["soil"] = p.soil_name;
      j["unit"] = "N/cm^3";
      j["reference_gravity_m_s2"] = p.soil_reference_gravity_m_s2;
    } else if (p.kind == ParameterKind::kSoilDynamicLambda) {
      j["soil"] = p.soil_name;
      j["unit"] = "-";
    } else if (p.kind == ParameterKind::kSoilBekker) {
      j["soil"] = p.soil_name;
      j["unit"] = p.bekker->unit;
    } else {
      j["object"] = p.object;
      j["unit"] = "as the field's suffix";
    }
    params.push_back(j);
  }
  return {{"meaning", "(J^T J)^-1 of the normalised residuals at the solution, in the parameters' file units, over the "
                      "parameters with an interval (not at a bound, determined); the targets' uncertainties taken as one "
                      "standard deviation" +
                          std::string(HasPriors(file) ? "; the parameters' priors are residuals too: the posterior's "
                                                        "Laplace approximation"
                                                      : "")},
          {"parameters", params},
          {"matrix", fit.covariance}};
}

std::vector<std::string> TargetNames(const TargetsFile& file, bool fit) {
  std::vector<std::string> names;
  for (const Target& t : file.targets)
    if (t.fit == fit) names.push_back(t.name);
  return names;
}
}  // namespace

nlohmann::json TargetsReportJson(const TargetsFile& file, const TargetsFitResult& fit) {
  nlohmann::json params = nlohmann::json::array(), targets = nlohmann::json::array();
  for (size_t i = 0; i < file.parameters.size(); ++i) {
    const Parameter& p = file.parameters[i];
    const ParameterResult& r = fit.parameters[i];
    nlohmann::json j{{"name", p.name},   {"address", p.Address()}, {"value", r.value}, {"lower", p.lower},
                     {"upper", p.upper}, {"start", p.start},       {"at_bound", BoundName(r.at_bound)},
                     {"source", p.source}};
    if (r.sigma) {
      j["sigma"] = *r.sigma;
      j["interval"] = {*r.low, *r.high};
    } else {
      j["interval_note"] = r.interval_note;
    }
    if (p.prior)
      j["prior"] = {{"value", p.prior->value}, {"sd", p.prior->sd}, {"source", p.prior->source},
                    {"residual", r.prior_residual.value_or(0.0)}};
    params.push_back(j);
  }
  for (size_t i = 0; i < file.targets.size(); ++i) {
    const Target& t = file.targets[i];
    nlohmann::json j{{"name", t.name},
                     {"what", t.Describe(file.scenarios)},
                     {"use", t.fit ? "fit" : "predict"},
                     {"uncertainty", t.uncertainty},
                     {"simulated", fit.targets[i].simulated},
                     {"residual", fit.targets[i].residual},
                     {"source", t.source}};
    if (t.value) j["value"] = *t.value;
    if (t.at_most) j["at_most"] = *t.at_most;
    if (t.at_least) j["at_least"] = *t.at_least;
    targets.push_back(j);
  }
  return {{"targets_file", file.source},
          {"name", file.name},
          {"method", "bounded least squares (Ceres, Levenberg-Marquardt, central differences, relative step " +
                         std::to_string(file.settings.relative_step) + ") of (simulated - value) / uncertainty" +
                         (HasPriors(file) ? " and each prior's (value - prior) / sd" : "")},
          {"interval_method", "Ceres covariance of the normalised residuals, (J^T J)^-1 at the solution, value -+ z sigma"},
          {"confidence", file.settings.confidence},
          {"parameters", params},
          {"covariance", CovarianceJson(file, fit)},
          {"targets_fitted", TargetNames(file, true)},
          {"targets_predicted", TargetNames(file, false)},
          {"targets", targets},
          {"cost", fit.cost},
          {"iterations", fit.iterations},
          {"scenario_runs", fit.scenario_runs},
          {"converged", fit.converged},
          {"termination", fit.termination}};
}

std::string TargetsReportTable(const TargetsFile& file, const TargetsFitResult& fit) {
  std::ostringstream o;
  char line[256];
  std::snprintf(line, sizeof line, "%-22s %12s %12s %12s  %-6s %s\n", "parameter", "value", "lower", "upper", "bound",
                "interval");
  o << line;
  for (size_t i = 0; i < file.parameters.size(); ++i) {
    const Parameter& p = file.parameters[i];
    const ParameterResult& r = fit.parameters[i];
    char interval[96];
    if (r.sigma)
      std::snprintf(interval, sizeof interval, "[%.6g, %.6g]", *r.low, *r.high);
    else
      std::snprintf(interval, sizeof interval, "(%s)", r.interval_note.c_str());
    std::snprintf(line, sizeof line, "%-22s %12.6g %12.6g %12.6g  %-6s %s\n", p.name.c_str(), r.value, p.lower, p.upper,
                  BoundName(r.at_bound), interval);
    o << line;
  }
  for (size_t i = 0; i < file.parameters.size(); ++i)
    if (const std::optional<ParameterPrior>& prior = file.parameters[i].prior) {
      std::snprintf(line, sizeof line, "prior of %s: %.6g +- %.6g (residual %.4g)\n", file.parameters[i].name.c_str(),
                    prior->value, prior->sd, fit.parameters[i].prior_residual.value_or(0.0));
      o << line;
    }
  std::snprintf(line, sizeof line, "\n%-30s %-8s %16s %12s %10s\n", "target", "use", "value", "simulated", "residual");
  o << line;
  for (size_t i = 0; i < file.targets.size(); ++i) {
    const Target& t = file.targets[i];
    std::snprintf(line, sizeof line, "%-30s %-8s %16s %12.6g %10.4g\n", t.name.c_str(), t.fit ? "fit" : "predict",
                  TargetText(t).c_str(), fit.targets[i].simulated, fit.targets[i].residual);
    o << line;
  }
  std::snprintf(line, sizeof line, "\ncost %.6g after %d iterations, %d simulations: %s\n", fit.cost, fit.iterations,
                fit.scenario_runs, fit.termination.c_str());
  o << line;
  return o.str();
}

model::ModelFile TargetsModel(const TargetsFile& file, const TargetsFitResult& fit, const std::string& name,
                              const std::string& output_dir) {
  std::vector<double> values;
  for (const ParameterResult& r : fit.parameters) values.push_back(r.value);
  model::ModelFile m;
  m.name = name;
  bool zeta = false, lambda = false, bekker = false;
  for (const Parameter& p : file.parameters) {
    zeta = zeta || p.kind == ParameterKind::kSoilZeta;
    lambda = lambda || p.kind == ParameterKind::kSoilDynamicLambda;
    bekker = bekker || p.kind == ParameterKind::kSoilBekker;
  }
  std::string what = lambda ? "zeta and dynamic_lambda" : "zeta";
  if (bekker) what = std::string(zeta ? "zeta, " : "") + (lambda ? "dynamic_lambda, " : "") + "Bekker's n, k_c, k_phi";
  m.description = what + " per soil fitted to the scalar targets of " + file.name;
  m.soils = SoilModel(file.parameters, values).soils;
  for (size_t i = 0; i < file.parameters.size(); ++i) {
    const Parameter& p = file.parameters[i];
    if (p.kind != ParameterKind::kSoilZeta || !fit.parameters[i].sigma) continue;
    model::SoilOverride& o = m.soils.at(p.soil_name);
    o.zeta_low_N_m3 = units::ZetaFromN_cm3(*fit.parameters[i].low);
    o.zeta_high_N_m3 = units::ZetaFromN_cm3(*fit.parameters[i].high);
    o.confidence = file.settings.confidence;
  }
  YAML::Emitter y;
  y.SetDoublePrecision(10);
  y << YAML::BeginMap << YAML::Key << "fit" << YAML::Value
    << "touchdown calibrate --targets " + std::filesystem::path(file.source).filename().string() +
           ": bounded least squares of (simulated - value) / uncertainty (Ceres)";
  y << YAML::Key << "targets_file" << YAML::Value << io::PathForOutput(file.source, output_dir);
  y << YAML::Key << "targets_used" << YAML::Value << YAML::Flow << TargetNames(file, true);
  y << YAML::Key << "targets_predicted" << YAML::Value << YAML::Flow << TargetNames(file, false);
  y << YAML::Key << "parameters" << YAML::Value << YAML::BeginMap;
  for (size_t i = 0; i < file.parameters.size(); ++i) {
    const Parameter& p = file.parameters[i];
    y << YAML::Key << p.name << YAML::Value << YAML::BeginMap << YAML::Key << "address" << YAML::Value << p.Address()
      << YAML::Key << "value" << YAML::Value << values[i] << YAML::Key << "bounds" << YAML::Value << YAML::Flow
      << YAML::BeginSeq << p.lower << p.upper << YAML::EndSeq << YAML::Key << "at_bound" << YAML::Value
      << BoundName(fit.parameters[i].at_bound);
    if (p.prior)
      y << YAML::Key << "prior" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "value" << YAML::Value
        << p.prior->value << YAML::Key << "sd" << YAML::Value << p.prior->sd << YAML::Key << "source" << YAML::Value
        << p.prior->source << YAML::EndMap;
    y << YAML::Key << "apply" << YAML::Value << ApplyHint(p) << YAML::EndMap;
  }
  y << YAML::EndMap << YAML::EndMap;
  m.provenance_yaml = y.c_str();
  return m;
}

}  // namespace touchdown::targets
