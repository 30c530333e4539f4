#pragma once
// The first place two YAML trees differ, for checking a file's block against the same block
// written again (a resolved copy against the files it names).
#include <string>

#include <yaml-cpp/yaml.h>

namespace touchdown::io {

// Where `given` differs from `expected`, as a dotted path from `at` (`ground.soils[1].name`);
// empty when they agree. Scalars are compared as text, so numbers written at full precision
// compare by value; keys of `given` that `expected` lacks are not looked at.
std::string FirstYamlDifference(const YAML::Node& given, const YAML::Node& expected, const std::string& at);

}  // namespace touchdown::io
