// The resolved documents behind touchdown.Pad, Soil, Lander and Scenario (touchdown/objects.py):
// each input loaded by the command line's own loader and written back by the writer that already
// states what a load resolved (WriteSoil, WritePad, the lander's scenario_resolved.yaml), handed
// to Python as JSON. So a default, a derived zeta or a pad's mass from its density reads in Python
// as the simulation uses it, without a second implementation of the loaders.
#include "objects_bindings.h"

#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "rft/units.h"

namespace touchdown::python {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;  // the fields in the order the writers write them

// A plain YAML scalar as the number, flag or null it reads as; a quoted one stays text.
json ScalarJson(const YAML::Node& node) {
  const std::string& text = node.Scalar();
  if (node.Tag() == "!") return text;
  if (text == "~" || text == "null" || text.empty()) return nullptr;
  if (text == "true") return true;
  if (text == "false") return false;
  char* end = nullptr;
  errno = 0;
  const long long whole = std::strtoll(text.c_str(), &end, 10);
  if (errno == 0 && end != text.c_str() && *end == '\0') return whole;
  const double number = std::strtod(text.c_str(), &end);  // the writers print doubles round-trip
  if (end != text.c_str() && *end == '\0') return number;
  if (text == ".nan") return std::nan("");
  return text;
}

json YamlJson(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      json object = json::object();
      for (const auto& entry : node) object[entry.first.Scalar()] = YamlJson(entry.second);
      return object;
    }
    case YAML::NodeType::Sequence: {
      json list = json::array();
      for (const auto& item : node) list.push_back(YamlJson(item));
      return list;
    }
    case YAML::NodeType::Scalar:
      return ScalarJson(node);
    default:
      return nullptr;
  }
}

json Millimetres(const Eigen::Vector3d& v_m) { return json::array({v_m.x() * units::kMmPerM, v_m.y() * units::kMmPerM, v_m.z() * units::kMmPerM}); }

// A soil as `touchdown` uses it: WriteSoil's text (zeta as a number, every field the file left
// to its default stated when the writer states it).
std::string ResolvedSoil(const std::string& name_or_path) {
  const rft::SoilParameters soil = io::LoadSoil(name_or_path);
  std::ostringstream text;
  io::WriteSoil(soil, text);
  return YamlJson(YAML::Load(text.str())).dump();
}

// A pad: WritePad's document (written to `scratch_file`, a file of the caller's private temporary
// directory; its mesh named by its resolved path) and, under `body`, the rigid body the loader
// built from it (mass, centre of mass and inertia about it, in the pad frame).
std::string ResolvedPad(const std::string& name_or_path, const std::string& scratch_file) {
  const io::PadSpec pad = io::LoadPad(name_or_path);
  io::WritePad(pad, scratch_file);
  json doc = YamlJson(YAML::LoadFile(scratch_file));
  if (pad.kind == io::PadKind::kMesh) doc["mesh"]["file"] = fs::absolute(pad.mesh_file).lexically_normal().string();
  const geom::PadBody& b = pad.body;
  json inertia = json::array();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) inertia.push_back(b.inertia_com_B(r, c));
  doc["body"] = {{"mass_kg", b.mass_kg},
                 {"center_of_mass_mm", Millimetres(b.com_B)},
                 {"inertia_kg_m2", inertia},
                 {"lowest_point_mm", b.lowest_z_B * units::kMmPerM},
                 {"triangles", b.surface.area_m2.size()},
                 {"rim_segments", io::PadRimSegments(pad)}};
  return doc.dump();
}

// A lander scenario as `touchdown lander --out` resolves it (scenario_resolved.yaml, written to
// `scratch_file`; the files it names as seen from `output_dir`).
std::string ResolvedScenario(const std::string& name_or_path, const std::string& scratch_file,
                             const std::string& output_dir) {
  const std::string path = io::ResolveInputDocument(io::InputDocument::kLander, name_or_path);
  scenario::WriteResolvedLanderScenario(scenario::LoadLanderScenario(path), scratch_file, output_dir);
  return YamlJson(YAML::LoadFile(scratch_file)).dump();
}

// A lander alone as a scenario's resolved copy states it (its `lander` block), from its file: no
// ground, release or landing setup is built for it.
std::string ResolvedLander(const std::string& name_or_path, const std::string& scratch_file,
                           const std::string& output_dir) {
  scenario::WriteResolvedLander(scenario::LoadLanderSpec(name_or_path), scratch_file, output_dir);
  return YamlJson(YAML::LoadFile(scratch_file)).dump();
}

}  // namespace

void RegisterObjectBindings(py::module_& m) {
  m.def("catalog_file", &io::ResolveCatalogFile, py::arg("kind"), py::arg("name_or_path"),
        "The file a pad, soil or lander name or path reads (data/<kind>/<name>.yaml for a name)");
  m.def(
      "lander_scenario_file",
      [](const std::string& name_or_path) { return io::ResolveInputDocument(io::InputDocument::kLander, name_or_path); },
      py::arg("name_or_path"), "The file a lander scenario name or path reads, as `touchdown lander` finds it");
  m.def(
      "resolved_soil",
      [](const std::string& name_or_path) {
        py::gil_scoped_release unlocked;
        return ResolvedSoil(name_or_path);
      },
      py::arg("name_or_path"));
  m.def(
      "resolved_pad",
      [](const std::string& name_or_path, const std::string& scratch_file) {
        py::gil_scoped_release unlocked;
        return ResolvedPad(name_or_path, scratch_file);
      },
      py::arg("name_or_path"), py::arg("scratch_file"));
  m.def(
      "resolved_scenario",
      [](const std::string& name_or_path, const std::string& scratch_file, const std::string& output_dir) {
        py::gil_scoped_release unlocked;
        return ResolvedScenario(name_or_path, scratch_file, output_dir);
      },
      py::arg("name_or_path"), py::arg("scratch_file"), py::arg("output_dir"));
  m.def(
      "resolved_lander",
      [](const std::string& name_or_path, const std::string& scratch_file, const std::string& output_dir) {
        py::gil_scoped_release unlocked;
        return ResolvedLander(name_or_path, scratch_file, output_dir);
      },
      py::arg("name_or_path"), py::arg("scratch_file"), py::arg("output_dir"));
}

}  // namespace touchdown::python
