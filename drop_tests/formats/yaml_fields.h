#pragma once
// Reading user YAML at the IO boundary: every accessor validates and, on failure, throws
// InputError naming the file, the field (as a dotted path) and the offending value.
// Unit suffixes in keys (`radius_mm`, `tilt_deg`) are converted to SI by the callers.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace touchdown::io {

class YamlFields {
 public:
  // Loads `path`; throws InputError if it is missing or not valid YAML.
  static YamlFields LoadFile(const std::string& path);
  YamlFields(YAML::Node node, std::string file, std::string prefix);

  bool Has(const std::string& key) const;
  YamlFields Child(const std::string& key) const;        // a required mapping
  std::vector<YamlFields> List(const std::string& key) const;  // a required sequence of mappings
  std::string String(const std::string& key) const;
  std::string StringOr(const std::string& key, const std::string& fallback) const;
  // A name that becomes part of file names (a pad's, a soil's, a sweep's: util/file_name.h): the
  // string at `key` (or `fallback`, the file's stem, where the key is optional), refused unless it
  // can be one. Name(key) requires the key.
  std::string Name(const std::string& key) const;
  std::string Name(const std::string& key, const std::string& fallback) const;
  double Number(const std::string& key) const;  // finite
  bool Bool(const std::string& key) const;      // true/false (yes/no, on/off as YAML 1.1 has them)
  double Positive(const std::string& key) const;
  double NonNegative(const std::string& key) const;
  double PositiveOr(const std::string& key, double fallback) const;
  int PositiveInt(const std::string& key) const;
  // A number or a list of numbers; every value must be > 0 (or >= 0 if allow_zero).
  std::vector<double> NumberList(const std::string& key, bool allow_zero) const;
  // Rejects keys not in `known`, so a typo never passes silently.
  void RequireOnly(const std::vector<std::string>& known) const;
  void RequireSchemaVersion(int supported) const;

  const std::string& file() const { return file_; }
  const std::string& prefix() const { return prefix_; }
  std::string Path(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }
  [[noreturn]] void Fail(const std::string& key, const std::string& message) const;
  // A handle (yaml-cpp nodes share their data), not a const reference: yaml-cpp's const operator[]
  // on a missing key gives an invalid node whose IsSequence() throws YAML::InvalidNode (the pad
  // fuzzer's `profile: {shape: table}` without points_mm), where a handle's gives an undefined node.
  YAML::Node node() const { return node_; }

 private:
  YAML::Node node_;
  std::string file_;
  std::string prefix_;
};

}  // namespace touchdown::io
