#include "drop_tests/formats/yaml_diff.h"

namespace touchdown::io {

std::string FirstYamlDifference(const YAML::Node& given, const YAML::Node& expected, const std::string& at) {
  if (given.Type() != expected.Type()) return at;
  if (given.IsScalar()) return given.Scalar() == expected.Scalar() ? "" : at;
  if (given.size() != expected.size()) return at;
  if (given.IsSequence()) {
    for (size_t i = 0; i < given.size(); ++i)
      if (std::string d = FirstYamlDifference(given[i], expected[i], at + "[" + std::to_string(i) + "]"); !d.empty())
        return d;
    return "";
  }
  for (const auto& kv : expected) {
    const std::string key = kv.first.Scalar();
    if (!given[key]) return at + "." + key;
    if (std::string d = FirstYamlDifference(given[key], kv.second, at + "." + key); !d.empty()) return d;
  }
  return "";
}

}  // namespace touchdown::io
