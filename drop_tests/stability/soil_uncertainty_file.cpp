// Reading a study's `soil_uncertainty` block against its plan and the calibration reports it names
// (soil_uncertainty.h).
#include "drop_tests/stability/soil_uncertainty.h"

#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/sweep/sweep_spec.h"
#include "rft/input_error.h"

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
                         "or `touchdown calibrate DATASET --out M.yaml --report R.json` holds the fitted parameters' "
                         "covariance");
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

}  // namespace touchdown::stability
