#include "drop_tests/yaml_fields.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "rft/input_error.h"

namespace touchdown::drop {

namespace {
std::string Shown(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a mapping";
  return "nothing";
}
}  // namespace

YamlFields YamlFields::LoadFile(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw MakeInputError(path, "", "file not found");
  try {
    YAML::Node root = YAML::LoadFile(path);
    if (!root.IsMap()) throw MakeInputError(path, "", "top level must be a YAML mapping");
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

double YamlFields::Number(const std::string& key) const {
  if (!Has(key)) Fail(key, "missing");
  const YAML::Node n = node_[key];
  double value = 0.0;
  if (!n.IsScalar() || !YAML::convert<double>::decode(n, value))
    Fail(key, "must be a number, got " + Shown(n));
  if (!std::isfinite(value)) Fail(key, "must be finite, got " + Shown(n));
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
  if (v != std::floor(v) || v > 1e9) Fail(key, "must be a whole number, got " + Shown(node_[key]));
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
    if (std::find(known.begin(), known.end(), key) == known.end())
      Fail(key, "unknown field (a typo?)");
  }
}

void YamlFields::RequireSchemaVersion(int supported) const {
  if (!Has("schema_version")) return;  // absent: the current version
  const double v = Number("schema_version");
  if (v != supported)
    Fail("schema_version", "unsupported version " + Shown(node_["schema_version"]) +
                               " (this touchdown reads " + std::to_string(supported) + ")");
}

}  // namespace touchdown::drop
