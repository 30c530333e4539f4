// Reading a study's `soil_uncertainty` block against its plan and the calibration reports it names
// (soil_uncertainty.h).
#include "drop_tests/stability/soil_uncertainty.h"

#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/sweep/sweep_plan.h"
#include "rft/input_error.h"

namespace touchdown::stability {

namespace {
namespace fs = std::filesystem;

// The soils a landing of the plan can stand on, by name: the scenario's ground (default soil,
// patches, a patch field's soils) and the study's `soil` and `pad_soils` values.
std::map<std::string, rft::SoilParameters> StudySoils(const sweep::SweepPlan& plan) {
  std::map<std::string, rft::SoilParameters> soils;
  const auto add = [&soils](const rft::SoilParameters& s) { soils.emplace(s.name, s); };
  for (const rft::SoilParameters& s : plan.soils) add(s);
  if (plan.lander) {
    const scenario::LanderGroundSpec& g = plan.lander->ground;
    add(io::LoadSoil(g.default_soil));
    for (const scenario::LanderPatchSpec& p : g.patches) add(io::LoadSoil(p.soil));
    if (g.soil_field)
      for (const std::string& s : g.soil_field->soils) add(io::LoadSoil(s));
  }
  return soils;
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
  // A key given twice in one object: the parser keeps the last silently; a report never has one.
  std::vector<std::set<std::string>> keys;  // per open object
  std::string duplicate;
  const nlohmann::json::parser_callback_t check = [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    if (event == nlohmann::json::parse_event_t::object_start) keys.emplace_back();
    if (event == nlohmann::json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == nlohmann::json::parse_event_t::key && !keys.empty() && !keys.back().insert(parsed.get<std::string>()).second &&
        duplicate.empty())
      duplicate = parsed.get<std::string>();
    return true;
  };
  nlohmann::json report;
  try {
    report = nlohmann::json::parse(in, check);
  } catch (const nlohmann::json::exception& e) {
    throw MakeInputError(path, "", std::string("is not JSON: ") + e.what());
  }
  if (!duplicate.empty()) throw MakeInputError(path, duplicate, "given twice in one object (a report has each key once)");
  return report;
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
    // The kinds a calibration report writes: a soil field's (kSoilFields), a pad's or a lander's
    // field. Another is a report this touchdown does not know, whose rows would be skipped unseen.
    std::set<std::string> kinds = {"pad_field", "lander_field"};
    for (const SoilField f : kSoilFields) kinds.insert(InfoOf(f).kind);
    if (!p["kind"].is_string() || !kinds.count(p["kind"].get<std::string>()))
      throw MakeInputError(file, field + ".kind", "unknown kind " + p["kind"].dump() + " (" + Joined(kinds) + ")");
    JsonNumber(p["value"], file, field + ".value");
    out.parameters.push_back(p);
  }
  if (!out.matrix.isApprox(out.matrix.transpose(), 1e-9))
    throw MakeInputError(file, "covariance.matrix", "must be symmetric");
  return out;
}

// The rows in the calibration's covariance of soil `soil`'s parameters a study draws (in
// kSoilFields order: zeta, dynamic_lambda, Bekker's n, k_c, k_phi), each with its field.
std::vector<std::pair<size_t, SoilField>> SoilRowsOf(const CalibrationCovariance& c, const std::string& soil,
                                                     const std::string& file) {
  std::vector<std::pair<size_t, SoilField>> found;
  std::set<std::string> soils;
  for (const SoilField field : kSoilFields) {
    const std::string& kind = InfoOf(field).kind;
    size_t count = 0;
    for (size_t a = 0; a < c.parameters.size(); ++a) {
      const nlohmann::json& p = c.parameters[a];
      if (p.value("kind", "") != kind) continue;
      soils.insert(p.value("soil", ""));
      if (p.value("soil", "") != soil) continue;
      found.emplace_back(a, field);
      ++count;
    }
    if (count > 1)
      throw MakeInputError(file, "covariance.parameters",
                           "has the " + (field == SoilField::kZeta ? std::string("zeta") : InfoOf(field).column_suffix) + " of soil '" +
                               soil + "' more than once");
  }
  if (found.empty())
    throw MakeInputError(file, "covariance.parameters",
                         "has no interval for the zeta, dynamic_lambda or Bekker fields of soil '" + soil + "' (its soils with one: " +
                             (soils.empty() ? std::string("none") : Joined(soils)) +
                             "; a parameter at a bound or held fixed gets none)");
  return found;
}
SoilTruncation ReadTruncation(const io::YamlFields& f) {
  const std::string t = f.StringOr("truncate", "fit_bounds");
  if (t == "fit_bounds") return SoilTruncation::kFitBounds;
  if (t == "physical_limits") return SoilTruncation::kPhysicalLimits;
  f.Fail("truncate", "must be fit_bounds or physical_limits, got '" + t + "'");
}

// The box a parameter's draws must lie in: its physical range, narrowed to the fit's [lower, upper]
// when the report gives them (`calibrate --targets` does) and the study keeps the default. The
// fit never evaluated the model outside those bounds, and they say where the user holds it to be
// meaningful; the normal of the covariance does not know them.
void SetBox(UncertainParameter& q, const nlohmann::json& entry, SoilTruncation truncation, const std::string& file,
            const std::string& at) {
  const limits::Range& r = *InfoOf(q.field).range;
  q.low = r.low;
  q.high = r.high;
  q.low_open = r.low_open;
  if (truncation != SoilTruncation::kFitBounds || !entry.contains("lower") || !entry.contains("upper")) return;
  const double lower = JsonNumber(entry["lower"], file, at + ".lower"), upper = JsonNumber(entry["upper"], file, at + ".upper");
  if (!(lower <= q.mean && q.mean <= upper))
    throw MakeInputError(file, at, "its value " + io::FormatNumber(q.mean) + " lies outside its bounds [" +
                                       io::FormatNumber(lower) + ", " + io::FormatNumber(upper) + "]");
  if (lower > q.low) {
    q.low = lower;
    q.low_open = false;
  }
  q.high = std::min(q.high, upper);
  q.fit_bounded = true;
}
}  // namespace

const std::vector<std::string>& SoilUncertaintyEntryKeys() {
  static const std::vector<std::string> keys{"calibration", "truncate"};
  return keys;
}

SoilUncertainty ReadSoilUncertainty(const io::YamlFields& study_block, const sweep::SweepPlan& plan) {
  SoilUncertainty u;
  u.seed = plan.seed;
  const std::string key = "soil_uncertainty";
  const YAML::Node node = study_block.node()[key];
  if (!node.IsMap() || node.size() == 0)
    study_block.Fail(key, "must be a mapping of soil names to {calibration: FILE.json}");
  const bool bekker_ground = plan.lander && plan.lander->ground.law == rft::LawKind::kBekker;
  // Where a soil's Bekker fields act: a lander's ground law decides for every soil of its ground.
  const auto runs_bekker = [&](const rft::SoilParameters& s) {
    return plan.lander ? bekker_ground : s.rft_law_3d == rft::LawKind::kBekker;
  };
  const std::map<std::string, rft::SoilParameters> soils = StudySoils(plan);
  std::set<std::string> names;
  for (const auto& [name, soil] : soils) names.insert(name);
  const fs::path base = fs::path(study_block.file()).parent_path();
  std::map<std::string, size_t> group_of_file;
  std::map<std::string, CalibrationCovariance> read;
  std::vector<std::vector<size_t>> rows_in_file;  // per group: the covariance rows of its parameters
  const io::YamlFields all = study_block.Child(key);
  for (const auto& entry : node) {
    const std::string soil = entry.first.as<std::string>();
    if (!soils.count(soil))
      all.Fail(soil, "is not a soil this study's landings stand on (" + Joined(names) + ")");
    const rft::SoilParameters& soil_file = soils.at(soil);
    const io::YamlFields f = all.Child(soil);
    f.RequireOnly(SoilUncertaintyEntryKeys());
    const std::string given = f.String("calibration");
    const SoilTruncation truncation = ReadTruncation(f);
    const fs::path p = fs::path(given).is_absolute() ? fs::path(given) : base / given;
    const std::string path = fs::absolute(p).lexically_normal().string();
    if (!read.count(path)) read.emplace(path, ReadCovariance(ReadJsonFile(path, f.file(), f.Path("calibration")), path));
    const CalibrationCovariance& c = read.at(path);
    for (const auto& [row, field] : SoilRowsOf(c, soil, path)) {
      const std::string at = "covariance.parameters[" + std::to_string(row) + "]";
      UncertainParameter q;
      q.soil = soil;
      q.name = c.parameters[row]["name"].get<std::string>();
      q.field = field;
      q.mean = c.parameters[row]["value"].get<double>();
      q.soil_zeta_N_m3 = soil_file.zeta_N_m3;
      if (field == SoilField::kZeta) {
        if (bekker_ground) study_block.Fail(key, "draws zeta, which the ground's bekker law does not use");
        q.column = soil + "_zeta_N_cm3";
        q.reference_gravity_m_s2 = c.parameters[row].value("reference_gravity_m_s2", rft::kEarthGravity_m_s2);
        limits::Require(limits::kZeta_N_cm3, q.mean, path, at + ".value");
        limits::Require(limits::kGravity_m_s2, q.reference_gravity_m_s2, path, at + ".reference_gravity_m_s2");
      } else if (const model::BekkerOverrideField* b = InfoOf(field).bekker) {
        // As a drawn lambda: a Bekker field no landing uses would only look like uncertainty carried through.
        if (!runs_bekker(soil_file))
          f.Fail("calibration", path + " holds the bekker." + b->key + " of soil '" + soil +
                                    "', which this study's landings do not run on the bekker law");
        q.column = soil + "_" + InfoOf(field).column_suffix;
        q.reference_gravity_m_s2 = soil_file.reference_gravity_m_s2;
        limits::Require(*b->range, q.mean, path, at + ".value");
      } else {
        // A drawn lambda that no landing uses would only look like uncertainty carried through.
        if (!soil_file.dynamic_term)
          f.Fail("calibration", path + " holds the dynamic_lambda of soil '" + soil +
                                    "', whose dynamic term is off (dynamic_term: false in its soil file)");
        q.column = soil + "_dynamic_lambda";
        q.reference_gravity_m_s2 = soil_file.reference_gravity_m_s2;
        limits::Require(limits::kDynamicLambda, q.mean, path, at + ".value");
      }
      SetBox(q, c.parameters[row], truncation, path, at);
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
      throw MakeInputError(group.file, "covariance.matrix", "must be positive definite over the drawn soils' parameters");
    group.lower = llt.matrixL();
    for (Eigen::Index a = 0; a < n; ++a) u.parameters[group.parameters[size_t(a)]].sigma = std::sqrt(group.covariance(a, a));
  }
  return u;
}

}  // namespace touchdown::stability
