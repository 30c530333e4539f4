#include "drop_tests/formats/yaml_fields.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "drop_tests/util/file_name.h"
#include "drop_tests/util/nearest_name.h"
#include "rft/input_error.h"
#include "rft/input_file.h"
#include "rft/physical_limits.h"

namespace touchdown::io {

namespace {
using limits::kMaxWholeNumber;

std::string Shown(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a mapping";
  return "nothing";
}

std::string LineOf(const YAML::Node& n) { return "line " + std::to_string(n.Mark().line + 1); }

// What a walk over the tree may meet: limits::kMaxYamlDepth and kMaxYamlNodes (aliases).
using limits::kMaxYamlDepth;
using limits::kMaxYamlNodes;

struct TreeWalk {
  const std::string& file;
  long nodes = 0;
};

// What yaml-cpp accepts but a touchdown file must not contain, checked once over the whole
// tree: a tree beyond the bounds above, a key given twice in one mapping (yaml-cpp keeps both
// pairs and lookups see the first, so the second would be dropped silently), and text that is not
// UTF-8 (names and ids go into JSON and file names).
void CheckTree(const YAML::Node& node, TreeWalk& walk, const std::string& path, int depth) {
  const std::string& file = walk.file;
  // Paths name the field a message is about; past a few levels they stop growing (a path 64
  // levels deep would be no clearer).
  constexpr int kShownDepth = 8;
  auto join = [&](const std::string& key) {
    return depth >= kShownDepth ? path : path.empty() ? key : path + "." + key;
  };
  auto index = [&](size_t i) { return depth >= kShownDepth ? path : path + "[" + std::to_string(i) + "]"; };
  if (depth > kMaxYamlDepth)
    throw MakeInputError(file, path, "nested more than " + std::to_string(kMaxYamlDepth) +
                                         " levels deep (an alias inside its own anchor?) at " + LineOf(node));
  if (++walk.nodes > kMaxYamlNodes)
    throw MakeInputError(file, path, "expands to more than " + std::to_string(kMaxYamlNodes) +
                                         " values (aliases of aliases?) at " + LineOf(node));
  if (node.IsScalar()) {
    if (!IsValidUtf8(node.Scalar()))
      throw MakeInputError(file, path.empty() ? LineOf(node) : path, "not valid UTF-8 text (" + LineOf(node) + ")");
  } else if (node.IsSequence()) {
    for (size_t i = 0; i < node.size(); ++i) CheckTree(node[i], walk, index(i), depth + 1);
  } else if (node.IsMap()) {
    std::map<std::string, YAML::Node> seen;
    for (const auto& item : node) {
      if (!item.first.IsScalar()) throw MakeInputError(file, path, "a key must be plain text (" + LineOf(item.first) + ")");
      const std::string key = item.first.Scalar();
      if (!IsValidUtf8(key)) throw MakeInputError(file, path, "a key is not valid UTF-8 text (" + LineOf(item.first) + ")");
      const auto [first, fresh] = seen.emplace(key, item.first);
      if (!fresh)
        throw MakeInputError(file, join(key),
                             "duplicate key (" + LineOf(item.first) + "; first at " + LineOf(first->second) + ")");
      // yaml-cpp reads a merge key as a key named "<<": the keys it merges would be missing, and
      // the first of them reported so ("profile.shape: missing").
      if (key == "<<")
        throw MakeInputError(file, join(key),
                             "YAML merge keys are not supported: write the keys out (" + LineOf(item.first) + ")");
      // `key: ~`, `key: null` or `key:` alone would read as the key left out, its default taken.
      if (item.second.IsNull())
        throw MakeInputError(file, join(key),
                             "is empty (~, null or nothing): leave the key out for its default, or give a value (" +
                                 LineOf(item.first) + ")");
      CheckTree(item.second, walk, join(key), depth + 1);
    }
  }
}
// The line (1-based) where a second YAML document starts, or 0. Documents are separated by a
// line that begins with "---" or ends one with "..." (column 0, then a space or the line's end);
// no scalar may hold such a line, so a text scan finds them exactly.
int SecondDocumentLine(const std::string& text) {
  auto marker = [](const std::string& l, const char* m) {
    return l.compare(0, 3, m) == 0 && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r');
  };
  bool content = false, ended = false;
  int number = 0;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    ++number;
    start = end + 1;
    const size_t first = line.find_first_not_of(" \t\r");
    const bool blank = first == std::string::npos || line[first] == '#';
    if (marker(line, "---")) {
      if (content || ended) return number;
      const size_t rest = line.find_first_not_of(" \t\r", 3);
      content = rest != std::string::npos && line[rest] != '#';
    } else if (marker(line, "...")) {
      ended = true;
    } else if (!blank && line[0] != '%') {
      if (ended) return number;
      content = true;
    }
  }
  return 0;
}
}  // namespace

YamlFields YamlFields::LoadFile(const std::string& path) {
  const std::string text = ReadInputFile(path);
  try {
    // yaml-cpp reads the first document only: one that follows would be dropped unread. (Its
    // LoadAll, which would see them all, loops forever on some malformed text: found by fuzzing.)
    if (const int line = SecondDocumentLine(text); line > 0)
      throw MakeInputError(path, "", "holds a second YAML document (line " + std::to_string(line) +
                                         "); a touchdown file is one document: remove the '---' and what follows");
    YAML::Node root = YAML::Load(text);
    if (!root.IsMap()) throw MakeInputError(path, "", "top level must be a YAML mapping");
    TreeWalk walk{path};
    CheckTree(root, walk, "", 0);
    return YamlFields(root, path, "");
  } catch (const YAML::Exception& e) {
    throw MakeInputError(path, "", std::string("malformed YAML: ") + e.what());
  }
}

YamlFields::YamlFields(YAML::Node node, std::string file, std::string prefix)
    : node_(std::move(node)), file_(std::move(file)), prefix_(std::move(prefix)) {}

void YamlFields::Fail(const std::string& key, const std::string& message) const {
  throw MakeInputError(file_, Path(key), message);
}

bool YamlFields::Has(const std::string& key) const { return node_[key].IsDefined() && !node_[key].IsNull(); }

YamlFields YamlFields::Child(const std::string& key) const {
  if (!Has(key)) Fail(key, "missing");
  if (!node_[key].IsMap()) Fail(key, "must be a mapping, got " + Shown(node_[key]));
  return YamlFields(node_[key], file_, Path(key));
}

std::vector<YamlFields> YamlFields::List(const std::string& key) const {
  if (!Has(key)) Fail(key, "missing");
  const YAML::Node list = node_[key];
  if (!list.IsSequence() || list.size() == 0) Fail(key, "must be a non-empty list");
  std::vector<YamlFields> out;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string path = Path(key) + "[" + std::to_string(i) + "]";
    if (!list[i].IsMap()) throw MakeInputError(file_, path, "must be a mapping, got " + Shown(list[i]));
    out.emplace_back(list[i], file_, path);
  }
  return out;
}

std::string YamlFields::String(const std::string& key) const {
  if (!Has(key)) Fail(key, "missing");
  if (!node_[key].IsScalar() || node_[key].Scalar().empty()) Fail(key, "must be a non-empty string");
  return node_[key].Scalar();
}

std::string YamlFields::StringOr(const std::string& key, const std::string& fallback) const {
  return Has(key) ? String(key) : fallback;
}

std::string YamlFields::Name(const std::string& key) const {
  const std::string name = String(key);
  if (const std::string problem = FileNameProblem("", name); !problem.empty()) Fail(key, problem);
  return name;
}

std::string YamlFields::Name(const std::string& key, const std::string& fallback) const {
  if (Has(key)) return Name(key);
  if (const std::string problem = FileNameProblem("", fallback); !problem.empty())
    Fail(key, problem + ", and the file's name gives it where the key is left out");
  return fallback;
}

double YamlFields::Number(const std::string& key) const {
  if (!Has(key)) Fail(key, "missing");
  const YAML::Node n = node_[key];
  double value = 0.0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, value))
    Fail(key, "must be a number, got " + Shown(n));
  if (!std::isfinite(value)) Fail(key, "must be finite, got " + Shown(n));
  return value;
}

bool YamlFields::Bool(const std::string& key) const {
  if (!Has(key)) Fail(key, "missing");
  bool value = false;
  if (!node_[key].IsScalar() || !YAML::convert<bool>::decode(node_[key], value))
    Fail(key, "must be true or false, got " + Shown(node_[key]));
  return value;
}

double YamlFields::Positive(const std::string& key) const {
  const double v = Number(key);
  if (!(v > 0.0)) Fail(key, "must be positive, got " + Shown(node_[key]));
  return v;
}

double YamlFields::NonNegative(const std::string& key) const {
  const double v = Number(key);
  if (!(v >= 0.0)) Fail(key, "must be >= 0, got " + Shown(node_[key]));
  return v;
}

double YamlFields::PositiveOr(const std::string& key, double fallback) const {
  return Has(key) ? Positive(key) : fallback;
}

int YamlFields::PositiveInt(const std::string& key) const {
  const double v = Positive(key);
  if (v != std::floor(v)) Fail(key, "must be a whole number, got " + Shown(node_[key]));
  if (v > kMaxWholeNumber) Fail(key, "must be at most 1000000000 (1e9), got " + Shown(node_[key]));
  return static_cast<int>(v);
}

std::vector<double> YamlFields::NumberList(const std::string& key, bool allow_zero) const {
  if (!Has(key)) Fail(key, "missing");
  const YAML::Node n = node_[key];
  std::vector<double> values;
  auto take = [&](const YAML::Node& item, const std::string& path) {
    double v = 0.0;
    if (!item.IsScalar() || !YAML::convert<double>::decode(item, v) || !std::isfinite(v))
      throw MakeInputError(file_, path, "must be a finite number, got " + Shown(item));
    if (allow_zero ? !(v >= 0.0) : !(v > 0.0))
      throw MakeInputError(file_, path, std::string("must be ") + (allow_zero ? ">= 0" : "positive") +
                                            ", got " + Shown(item));
    values.push_back(v);
  };
  if (n.IsSequence()) {
    if (n.size() == 0) Fail(key, "must not be an empty list");
    for (size_t i = 0; i < n.size(); ++i) take(n[i], Path(key) + "[" + std::to_string(i) + "]");
  } else {
    take(n, Path(key));
  }
  return values;
}

void YamlFields::RequireOnly(const std::vector<std::string>& known) const {
  for (const auto& item : node_) {
    const std::string key = item.first.Scalar();
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      // The fields this block takes, as the loader lists them (docs/reference.md documents each;
      // tests/python/test_reference.py reads this list to keep that reference true).
      std::string listed;
      for (const std::string& k : known) listed += (listed.empty() ? "" : ", ") + k;
      const std::string hint = DidYouMean(key, known);
      Fail(key, "unknown field" + (hint.empty() ? std::string(" (a typo?)") : hint) + "; known: " + listed);
    }
  }
}

void YamlFields::RequireSchemaVersion(int supported) const {
  if (!Has("schema_version")) return;  // absent: the current version
  const double v = Number("schema_version");
  if (v != supported)
    Fail("schema_version", "unsupported version " + Shown(node_["schema_version"]) +
                               " (this touchdown reads " + std::to_string(supported) + ")");
}

}  // namespace touchdown::io
