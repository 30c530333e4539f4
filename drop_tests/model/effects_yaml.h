#pragma once
// The `effects:` mapping of a model file (and of a synth spec's hidden effect) in YAML. Private
// to the .cpp files that read or write those files: no public header names yaml-cpp.
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/model/effects.h"

namespace touchdown::model {

// {id: {param_key: value, ...}, ...}; optional `interval_95` mappings ({key: [low, high]}) are
// informational and checked for shape. When `intervals` is given it receives, per effect, the
// [low, high] (SI) of every parameter in EffectInfo order, or nothing when the effect's
// interval_95 does not give them all. Throws InputError naming file and field.
std::vector<Effect> ParseEffects(const io::YamlFields& effects_mapping, EffectIntervals* intervals = nullptr);
// Writes `effects` as that mapping (file units), with intervals when given (same shape).
YAML::Node EffectsToYaml(const std::vector<Effect>& effects, const EffectIntervals& intervals = {});

}  // namespace touchdown::model
