#include "drop_tests/model/effects_yaml.h"

#include <cmath>
#include <string>

#include "rft/input_error.h"

namespace touchdown::model {

namespace {
// An effect's interval_95 mapping: checked for shape; the pairs (SI) in parameter order when
// every parameter has one.
std::vector<std::pair<double, double>> ReadIntervals(const io::YamlFields& iv, const EffectInfo& info) {
  std::vector<std::string> keys;
  for (const EffectParameterInfo& p : info.parameters) keys.push_back(p.key);
  iv.RequireOnly(keys);
  for (const auto& range : iv.node()) {
    const YAML::Node n = range.second;
    double lo = 0, hi = 0;
    if (!n.IsSequence() || n.size() != 2 || !YAML::convert<double>::decode(n[0], lo) ||
        !YAML::convert<double>::decode(n[1], hi) || !std::isfinite(lo) || !std::isfinite(hi) || lo > hi)
      iv.Fail(range.first.Scalar(), "must be [low, high] with low <= high");
  }
  std::vector<std::pair<double, double>> pairs;
  for (const EffectParameterInfo& p : info.parameters) {
    if (!iv.Has(p.key)) return {};
    const YAML::Node n = iv.node()[p.key];
    pairs.emplace_back(n[0].as<double>() * p.file_to_si, n[1].as<double>() * p.file_to_si);
  }
  return pairs;
}
}  // namespace

std::vector<Effect> ParseEffects(const io::YamlFields& f, EffectIntervals* intervals) {
  std::vector<Effect> out;
  if (intervals) intervals->clear();
  for (const auto& item : f.node()) {
    const std::string id = item.first.Scalar();
    try {
      FindEffect(id);
    } catch (const InputError&) {
      std::string known;  // the library's ids, in its order (docs/reference.md lists them)
      for (const EffectInfo& e : EffectLibrary()) known += (known.empty() ? "" : ", ") + e.id;
      f.Fail(id, "unknown effect (known: " + known + ")");
    }
    const EffectInfo& info = FindEffect(id);
    const io::YamlFields e = f.Child(id);
    std::vector<std::string> known{"interval_95"};
    for (const EffectParameterInfo& p : info.parameters) known.push_back(p.key);
    e.RequireOnly(known);
    Effect effect{id, {}};
    for (const EffectParameterInfo& p : info.parameters) {
      const double v = e.Number(p.key) * p.file_to_si;
      if (const std::string why = p.RangeProblem(v); !why.empty()) e.Fail(p.key, why);
      effect.values.push_back(v);
    }
    std::vector<std::pair<double, double>> pairs;
    if (e.Has("interval_95")) pairs = ReadIntervals(e.Child("interval_95"), info);
    if (intervals) intervals->push_back(std::move(pairs));
    out.push_back(std::move(effect));
  }
  MakeEffectTerms(out, f.file());  // ranges and repeats
  return out;
}

YAML::Node EffectsToYaml(const std::vector<Effect>& effects, const EffectIntervals& intervals) {
  YAML::Node root(YAML::NodeType::Map);
  for (size_t k = 0; k < effects.size(); ++k) {
    const EffectInfo& info = FindEffect(effects[k].id);
    YAML::Node e(YAML::NodeType::Map);
    for (size_t i = 0; i < info.parameters.size(); ++i)
      e[info.parameters[i].key] = effects[k].values[i] / info.parameters[i].file_to_si;
    if (k < intervals.size() && intervals[k].size() == info.parameters.size()) {
      YAML::Node iv(YAML::NodeType::Map);
      for (size_t i = 0; i < info.parameters.size(); ++i) {
        YAML::Node pair(YAML::NodeType::Sequence);
        pair.SetStyle(YAML::EmitterStyle::Flow);
        pair.push_back(intervals[k][i].first / info.parameters[i].file_to_si);
        pair.push_back(intervals[k][i].second / info.parameters[i].file_to_si);
        iv[info.parameters[i].key] = pair;
      }
      e["interval_95"] = iv;
    }
    root[effects[k].id] = e;
  }
  return root;
}

}  // namespace touchdown::model
