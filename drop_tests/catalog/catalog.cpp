#include "drop_tests/catalog/catalog.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <system_error>

#include <yaml-cpp/yaml.h>

#include "drop_tests/util/nearest_name.h"
#include "rft/input_error.h"
#include "rft/input_file.h"

// Where pads, soils and the other bundled inputs are found: the data directory, a name or a path
// resolved to a file, the names each shelf holds.
namespace touchdown::io {

namespace fs = std::filesystem;

namespace {
// The data installed with the running executable (`cmake --install`: <prefix>/bin/touchdown and
// <prefix>/share/touchdown), if there is such a folder. /proc/self/exe names the executable file
// itself, whatever link or relative path started it. None in the build tree (build/apps/touchdown
// has no share/ beside it), nor for a program elsewhere that links the libraries.
std::optional<std::string> DataBesideExecutable() {
  std::error_code ec;
  const fs::path executable = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  const fs::path data = (executable.parent_path() / TOUCHDOWN_DATA_DIR_FROM_BIN).lexically_normal();
  if (!fs::is_directory(data, ec)) return std::nullopt;
  return data.string();
}
}  // namespace

// $TOUCHDOWN_DATA_DIR, else an installed copy's own data, else the source tree's data/ this
// build was made from (docs/install.md).
std::string DataDirectory() {
  if (const char* env = std::getenv("TOUCHDOWN_DATA_DIR"); env && *env) return env;
  return DataBesideExecutable().value_or(TOUCHDOWN_DATA_DIR);
}

std::string ResolveCatalogFile(const std::string& kind, const std::string& name_or_path) {
  if (name_or_path.empty()) throw MakeInputError("", kind, "empty name");
  const bool is_path = name_or_path.find('/') != std::string::npos ||
                       name_or_path.ends_with(".yaml") || name_or_path.ends_with(".yml");
  const std::string path = is_path ? name_or_path : DataDirectory() + "/" + kind + "/" + name_or_path + ".yaml";
  if (is_path) {
    RequireReadableFile(path);  // says what is wrong: missing, a directory, a loop, no permission
    return path;
  }
  if (!fs::is_regular_file(path)) {
    // No shelf at all means no data directory, not a misspelt name: say where it was looked for.
    const std::string shelf = DataDirectory() + "/" + kind;
    if (!fs::is_directory(shelf))
      throw MakeInputError(shelf, kind,
                           "no such data directory, so no bundled name such as '" + name_or_path +
                               "' (set TOUCHDOWN_DATA_DIR to touchdown's data/ folder, or give a file path)");
    const std::vector<std::string> names = CatalogNames(kind);
    std::string known;
    for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
    throw MakeInputError("", kind, "unknown name '" + name_or_path + "'" + DidYouMean(name_or_path, names) +
                                       " (known: " + known + ")");
  }
  return path;
}

std::string ResolveCatalogFileNear(const std::string& referring_file, const std::string& kind,
                                   const std::string& name_or_path) {
  const bool is_path = name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".yaml") ||
                       name_or_path.ends_with(".yml");
  if (is_path && fs::path(name_or_path).is_relative()) {
    const fs::path beside = fs::path(referring_file).parent_path() / name_or_path;
    if (fs::is_regular_file(beside)) return beside.lexically_normal().string();
  }
  return ResolveCatalogFile(kind, name_or_path);
}

std::vector<std::string> CatalogNames(const std::string& kind) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(DataDirectory() + "/" + kind, ec))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

namespace {
// A YAML file's top-level `type:`; "" when it cannot be read as a map. A campaign file may leave
// it out (LoadCampaignScenario's default; every other input type requires it).
std::string DocumentType(const fs::path& file) {
  try {
    const YAML::Node node = YAML::LoadFile(file.string());
    if (!node.IsMap()) return "";
    return node["type"] ? node["type"].as<std::string>() : "campaign";
  } catch (const std::exception&) {
    return "";  // not a document of any shelf; its loader says why when it is named by path
  }
}
}  // namespace

std::vector<CatalogShelf> ShelvesOf(InputDocument document) {
  const CatalogShelf campaigns{"scenarios", "campaign", "campaign scenarios"};
  const CatalogShelf landers{"scenarios", "lander", "lander scenarios"};
  const CatalogShelf sweeps{"sweeps", "sweep", "sweeps"};
  const CatalogShelf studies{"studies", "stability", "studies"};
  switch (document) {
    case InputDocument::kCampaign: return {campaigns};
    case InputDocument::kLander: return {landers};
    case InputDocument::kSweep: return {sweeps, studies};
    case InputDocument::kTrade: return {sweeps};
    case InputDocument::kStudy: return {studies};
  }
  return {};
}

std::vector<std::string> ShelfNames(const CatalogShelf& shelf) {
  std::vector<std::string> names;
  for (const std::string& name : CatalogNames(shelf.kind))
    if (DocumentType(fs::path(DataDirectory()) / shelf.kind / (name + ".yaml")) == shelf.type) names.push_back(name);
  return names;
}

std::string ResolveInputDocument(InputDocument document, const std::string& name_or_path) {
  const bool is_path = name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".yaml") ||
                       name_or_path.ends_with(".yml");
  std::error_code ec;
  if (is_path || name_or_path.empty() || fs::exists(fs::symlink_status(name_or_path, ec))) return name_or_path;
  std::vector<std::string> all;
  std::string known;
  for (const CatalogShelf& shelf : ShelvesOf(document)) {
    const std::vector<std::string> names = ShelfNames(shelf);
    if (std::find(names.begin(), names.end(), name_or_path) != names.end())
      return DataDirectory() + "/" + shelf.kind + "/" + name_or_path + ".yaml";
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    known += (known.empty() ? "" : "; ") + shelf.label + " in " + DataDirectory() + "/" + shelf.kind + ": " + list;
    all.insert(all.end(), names.begin(), names.end());
  }
  throw MakeInputError(name_or_path, "", "no such file, nor a bundled name" + DidYouMean(name_or_path, all) + " (" +
                                             known + ")");
}

}  // namespace touchdown::io
