#pragma once
// The free parameters applied in memory: a pad or lander file read once, its number at a dotted
// path replaced and the copy loaded by the catalogue's own loader (so it is validated as the file
// would be); a soil's zeta, dynamic_lambda and Bekker fields as a model file's override (the form `--model` takes). The user's files
// are never written.
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "drop_tests/targets/targets_file.h"

namespace touchdown::targets {

// Throws InputError (naming the targets file's field `where`) if the parameter's field is not a
// number of its file, or the file does not load with the field at lower, start or upper.
void CheckEditable(const Parameter& p, const io::YamlFields& where);
// Whether the parameter changes what the scenario runs.
bool Changes(const Parameter& p, const ScenarioRun& run);
bool ChangesAnyScenario(const Parameter& p, const std::vector<ScenarioRun>& scenarios);

// The model file that carries the soil parameters (zeta in N/cm^3 at each soil's reference gravity,
// dynamic_lambda, Bekker fields in SI); a soil without its zeta free keeps its file's zeta.
model::ModelFile SoilModel(const std::vector<Parameter>& parameters, const std::vector<double>& values);

class ObjectEditor {
 public:
  explicit ObjectEditor(const std::vector<Parameter>& parameters);
  // The pad of `pad_file` with the pad parameters' values; none when no parameter changes it.
  // `angular_segments` > 0: revolved at that many rim segments with rings `rim` (a scenario's
  // pad_angular_segments and pad_rim).
  std::optional<io::PadSpec> EditedPad(const std::string& pad_file, const std::vector<double>& values,
                                       int angular_segments = 0,
                                       geom::RimPolygon rim = geom::RimPolygon::kInscribed) const;
  // The lander as the scenario has it, with the lander's and its pad's parameters applied, its pad
  // at the scenario's `angular_segments` (> 0) and `rim` whether or not a parameter reloads it.
  scenario::LanderSpec EditedLander(const scenario::LanderSpec& lander, const std::vector<double>& values,
                                    int angular_segments = 0,
                                    geom::RimPolygon rim = geom::RimPolygon::kInscribed) const;

 private:
  YAML::Node EditedNode(const std::string& file, const std::vector<double>& values) const;
  const std::vector<Parameter>& parameters_;
  std::map<std::string, YAML::Node> files_;  // pad and lander files as read, by canonical path
  // yaml-cpp nodes are not safe to read from two threads at once (iterating a node updates its
  // cached sizes), and the scenarios are evaluated on the work pool: one clone at a time.
  mutable std::mutex clone_mutex_;
};

}  // namespace touchdown::targets
