#include "drop_tests/targets/object_edit.h"

#include <charconv>
#include <filesystem>
#include <sstream>

#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace fs = std::filesystem;

namespace touchdown::targets {

namespace {
std::vector<std::string> SplitPath(const std::string& dotted) {
  std::vector<std::string> keys;
  std::stringstream s(dotted);
  for (std::string k; std::getline(s, k, '.');) keys.push_back(k);
  return keys;
}

// The node at a dotted path of mappings, or an undefined node.
YAML::Node At(YAML::Node node, const std::string& dotted) {
  for (const std::string& key : SplitPath(dotted)) {
    if (!node.IsMap() || !node[key].IsDefined()) return YAML::Node(YAML::NodeType::Undefined);
    node.reset(node[key]);  // (operator= would overwrite the node it refers to)
  }
  return node;
}

// The shortest text that reads back to exactly `v` (so an edited file holds the value as fitted).
std::string Exact(double v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

bool IsNumber(const YAML::Node& n) {
  double v = 0.0;
  return n.IsScalar() && YAML::convert<double>::decode(n, v);
}

void LoadEdited(const Parameter& p, const YAML::Node& node) {
  if (p.kind == ParameterKind::kPadField)
    io::LoadPad(io::YamlFields(node, p.file, ""));
  else
    scenario::LoadLanderSpec(io::YamlFields(node, p.file, ""));
}

std::vector<std::string> GroundSoilNames(const scenario::LanderScenario& s) {
  std::vector<std::string> names{s.ground.default_soil};
  for (const scenario::LanderPatchSpec& patch : s.ground.patches) names.push_back(patch.soil);
  if (s.ground.soil_field) names.insert(names.end(), s.ground.soil_field->soils.begin(), s.ground.soil_field->soils.end());
  for (std::string& n : names) n = io::LoadSoil(n).name;
  return names;
}
}  // namespace

void CheckEditable(const Parameter& p, const io::YamlFields& where) {
  const io::YamlFields file = io::YamlFields::LoadFile(p.file);
  if (!IsNumber(At(file.node(), p.field)))
    where.Fail("field", "'" + p.field + "' is not a number of " + p.file + " (a dotted path such as " +
                            (p.kind == ParameterKind::kPadField ? "profile.a1_per_mm" : "legs.joint_radius_mm") + ")");
  for (const auto& [key, value] : {std::pair{"lower", p.lower}, {"start", p.start}, {"upper", p.upper}}) {
    YAML::Node copy = YAML::Clone(file.node());
    At(copy, p.field) = Exact(value);
    try {
      LoadEdited(p, copy);
    } catch (const InputError& e) {
      where.Fail(key, p.file + " does not load with " + p.field + " = " + Exact(value) + ": " + e.what());
    }
  }
}

bool Changes(const Parameter& p, const ScenarioRun& run) {
  const bool lander = run.kind == ScenarioRun::Kind::kLander;
  switch (p.kind) {
    case ParameterKind::kSoilZeta:
    case ParameterKind::kSoilDynamicLambda:
    case ParameterKind::kSoilBekker:
      if (!lander) return run.soil.name == p.soil_name;
      for (const std::string& name : GroundSoilNames(*run.lander))
        if (name == p.soil_name) return true;
      return false;
    case ParameterKind::kPadField:
      return Canonical(lander ? run.lander->lander.pad.source : run.pad->source) == p.file;
    case ParameterKind::kLanderField:
      return lander && Canonical(run.lander->lander.source) == p.file;
  }
  return false;
}

bool ChangesAnyScenario(const Parameter& p, const std::vector<ScenarioRun>& scenarios) {
  for (const ScenarioRun& run : scenarios)
    if (Changes(p, run)) return true;
  return false;
}

model::ModelFile SoilModel(const std::vector<Parameter>& parameters, const std::vector<double>& values) {
  model::ModelFile m;
  m.name = "targets_fit";
  for (size_t i = 0; i < parameters.size(); ++i) {
    const Parameter& p = parameters[i];
    if (!p.IsSoil()) continue;
    // A soil whose zeta is not freed keeps the soil file's own (no zeta in the override).
    model::SoilOverride& o = m.soils[p.soil_name];
    if (p.kind == ParameterKind::kSoilZeta) {
      o.zeta_N_m3 = units::ZetaFromN_cm3(values[i]);
      o.reference_gravity_m_s2 = p.soil_reference_gravity_m_s2;
    } else if (p.kind == ParameterKind::kSoilBekker)
      o.*p.bekker->member = values[i] * p.bekker->si_per_unit;
    else
      o.dynamic_lambda = values[i];
  }
  return m;
}

ObjectEditor::ObjectEditor(const std::vector<Parameter>& parameters) : parameters_(parameters) {
  for (const Parameter& p : parameters)
    if (!p.IsSoil() && !files_.contains(p.file))
      files_.emplace(p.file, io::YamlFields::LoadFile(p.file).node());
}

YAML::Node ObjectEditor::EditedNode(const std::string& file, const std::vector<double>& values) const {
  YAML::Node copy;
  {
    const std::lock_guard<std::mutex> lock(clone_mutex_);
    copy = YAML::Clone(files_.at(file));
  }
  for (size_t i = 0; i < parameters_.size(); ++i)
    if (!parameters_[i].IsSoil() && parameters_[i].file == file)
      At(copy, parameters_[i].field) = Exact(values[i]);
  return copy;
}

std::optional<io::PadSpec> ObjectEditor::EditedPad(const std::string& pad_file, const std::vector<double>& values,
                                                   int angular_segments, geom::RimPolygon rim) const {
  const std::string file = Canonical(pad_file);
  for (const Parameter& p : parameters_)
    if (p.kind == ParameterKind::kPadField && p.file == file) {
      YAML::Node node = EditedNode(file, values);
      if (angular_segments > 0) node["angular_segments"] = angular_segments;
      return io::LoadPad(io::YamlFields(node, file, ""), angular_segments > 0 ? rim : geom::RimPolygon::kInscribed);
    }
  return std::nullopt;
}

scenario::LanderSpec ObjectEditor::EditedLander(const scenario::LanderSpec& lander, const std::vector<double>& values,
                                                int angular_segments, geom::RimPolygon rim) const {
  const std::string file = Canonical(lander.source);
  scenario::LanderSpec out = lander;
  for (const Parameter& p : parameters_)
    if (p.kind == ParameterKind::kLanderField && p.file == file) {
      out = scenario::LoadLanderSpec(io::YamlFields(EditedNode(file, values), file, ""));
      break;
    }
  if (std::optional<io::PadSpec> pad = EditedPad(out.pad.source, values, angular_segments, rim)) {
    out = scenario::LanderSpecWithPad(out, *pad);
  } else if (angular_segments > 0 && (out.pad.file.angular_segments != angular_segments || out.pad.rim != rim)) {
    // An edited lander file was read again, and its pad at the pad file's resolution.
    out = scenario::LanderSpecWithPad(out, io::PadWithAngularSegments(out.pad, angular_segments, rim));
  }
  return out;
}

}  // namespace touchdown::targets
