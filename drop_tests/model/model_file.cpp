#include "drop_tests/model/model_file.h"

#include <array>
#include <filesystem>
#include <sstream>
#include <nlohmann/json.hpp>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"
#include "drop_tests/model/effects.h"
#include "drop_tests/model/effects_yaml.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/catalog/paths_in_outputs.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::model {

namespace {

// A soil override's zeta and its reference gravity, read and written (always, both) from here.
const io::FieldTable<SoilOverride>& OverrideNumberFields() {
  static const io::FieldTable<SoilOverride> fields{
      {"zeta_N_cm3", &SoilOverride::zeta_N_m3, units::kN_m3_per_N_cm3, io::Sign::kPositive, /*optional=*/false, false,
       nullptr, "*required* (optional beside `dynamic_lambda` or `bekker`: the soil file's kept to the bit)"},
      {"reference_gravity_m_s2", &SoilOverride::reference_gravity_m_s2, 1.0, io::Sign::kPositive},
  };
  return fields;
}

// The override's `bekker:` block: any of the soil file's n, k_c_kN_m_n1, k_phi_kN_m_n2, in its units.
void ReadBekkerOverride(const io::YamlFields& f, SoilOverride& o) {
  const io::YamlFields b = f.Child("bekker");
  std::vector<std::string> keys;
  for (const BekkerOverrideField& e : BekkerOverrideFields()) keys.push_back(e.key);
  b.RequireOnly(keys);
  for (const BekkerOverrideField& e : BekkerOverrideFields()) {
    if (!b.Has(e.key)) continue;
    const double v = b.Number(e.key);
    limits::Require(*e.range, v, b.file(), b.Path(e.key));
    o.*e.member = v * e.si_per_unit;
  }
  if (!o.HasBekker()) f.Fail("bekker", "must give at least one of n, k_c_kN_m_n1, k_phi_kN_m_n2");
}

// What a model file's writer needs beside the model: the folder its paths are written relative to.
template <typename T>
struct ToWrite {
  const T& value;
  const std::string& directory;
};

const io::NumberKey kResidualRms{"residual_rms_N", io::Sign::kNonNegative, nullptr, nullptr, 0.0};

// An override's `fit` block's keys, in the order WriteModelFile writes them.
const io::KeyTable<ToWrite<SoilFit>>& FitKeys() {
  using W = ToWrite<SoilFit>;
  using Y = YAML::Emitter;
  static const io::KeyTable<W> keys{
      {"method", io::Always<W>, [](Y& y, const W& w) { y << w.value.method; }},
      {"drops", io::Always<W>, [](Y& y, const W& w) { y << w.value.drops; }},
      {"samples", io::Always<W>, [](Y& y, const W& w) { y << w.value.samples; }},
      {kResidualRms.key, io::Always<W>, [](Y& y, const W& w) { y << w.value.residual_rms_N; }, io::DocOf(kResidualRms)},
      {"dataset", [](const W& w) { return !w.value.dataset.empty(); },
       [](Y& y, const W& w) { y << io::PathForOutput(w.value.dataset, w.directory); }},
  };
  return keys;
}

// A soil override's keys, in the order WriteModelFile writes them.
const io::KeyTable<ToWrite<SoilOverride>>& OverrideKeys() {
  using W = ToWrite<SoilOverride>;
  using Y = YAML::Emitter;
  const auto interval = [](const W& w) { return w.value.zeta_low_N_m3 && w.value.zeta_high_N_m3; };
  static const io::KeyTable<W> keys = [&] {
    io::KeyTable<W> k;
    io::AppendNumberKeys<W, SoilOverride>(
        k, OverrideNumberFields(), [](const W& w) -> const SoilOverride& { return w.value; },
        [](const W& w) { return w.value.GivesZeta(); });
    k.push_back({"zeta_interval_N_cm3", interval, [](Y& y, const W& w) {
                   y << YAML::Flow << YAML::BeginSeq << units::ZetaToN_cm3(*w.value.zeta_low_N_m3)
                     << units::ZetaToN_cm3(*w.value.zeta_high_N_m3) << YAML::EndSeq;
                 }});
    k.push_back({"confidence", interval, [](Y& y, const W& w) { y << w.value.confidence; }});
    k.push_back({"dynamic_lambda", [](const W& w) { return w.value.dynamic_lambda.has_value(); },
                 [](Y& y, const W& w) { y << *w.value.dynamic_lambda; }});
    k.push_back({"bekker", [](const W& w) { return w.value.HasBekker(); }, [](Y& y, const W& w) {
                   y << YAML::BeginMap;
                   for (const BekkerOverrideField& e : BekkerOverrideFields())
                     if (w.value.*e.member) y << YAML::Key << e.key << YAML::Value << *(w.value.*e.member) / e.si_per_unit;
                   y << YAML::EndMap;
                 }});
    k.push_back({"fit", [](const W& w) { return w.value.fit.has_value(); }, [](Y& y, const W& w) {
                   io::WriteMap(y, FitKeys(), ToWrite<SoilFit>{*w.value.fit, w.directory});
                 }});
    return k;
  }();
  return keys;
}

// A model file's keys, in the order WriteModelFile writes them.
const io::KeyTable<ToWrite<ModelFile>>& ModelKeys() {
  using W = ToWrite<ModelFile>;
  using Y = YAML::Emitter;
  static const io::KeyTable<W> keys{
      {"schema_version", io::Always<W>, [](Y& y, const W&) { y << 1; }},
      {"type", io::Always<W>, [](Y& y, const W&) { y << "model"; }},
      {"name", [](const W& w) { return !w.value.name.empty(); }, [](Y& y, const W& w) { y << w.value.name; }},
      {"description", [](const W& w) { return !w.value.description.empty(); },
       [](Y& y, const W& w) { y << w.value.description; }},
      {"soils", io::Always<W>,
       [](Y& y, const W& w) {
         y << YAML::BeginMap;
         for (const auto& [name, o] : w.value.soils) {
           y << YAML::Key << name << YAML::Value;
           io::WriteMap(y, OverrideKeys(), ToWrite<SoilOverride>{o, w.directory});
         }
         y << YAML::EndMap;
       }},
      {"effects", io::Always<W>,
       [](Y& y, const W& w) {
         if (w.value.HasEffects()) y << EffectsToYaml(w.value.effects, w.value.effect_intervals);
         else y << YAML::Flow << YAML::BeginMap << YAML::EndMap;
       }},
      {"provenance", [](const W& w) { return !w.value.provenance_yaml.empty(); },
       [](Y& y, const W& w) { y << YAML::Load(w.value.provenance_yaml); }},
  };
  return keys;
}

SoilOverride ReadOverride(const io::YamlFields& f) {
  f.RequireOnly(io::Keys(OverrideKeys()));
  SoilOverride o;
  // An override that gives lambda or Bekker's fields may leave zeta out: the soil file's (none for
  // some Bekker soils) is kept to the last bit, which a written copy of it would not be.
  if (!f.Has("zeta_N_cm3") && !f.Has("dynamic_lambda") && !f.Has("bekker"))
    f.Fail("zeta_N_cm3", "is required when the override gives neither dynamic_lambda nor bekker");
  if (f.Has("bekker")) ReadBekkerOverride(f, o);
  if (f.Has("zeta_N_cm3")) {
    io::ReadFields(f, OverrideNumberFields(), o);
  } else {
    for (const char* key : {"reference_gravity_m_s2", "zeta_interval_N_cm3"})
      if (f.Has(key)) f.Fail(key, "belongs to a zeta_N_cm3, which this override does not give");
  }
  if (f.Has("dynamic_lambda")) {
    o.dynamic_lambda = f.Number("dynamic_lambda");
    limits::Require(limits::kDynamicLambda, *o.dynamic_lambda, f.file(), f.Path("dynamic_lambda"));
  }
  if (f.Has("zeta_interval_N_cm3")) {
    const YAML::Node n = f.node()["zeta_interval_N_cm3"];
    double lo = 0, hi = 0;
    if (!n.IsSequence() || n.size() != 2 || !YAML::convert<double>::decode(n[0], lo) ||
        !YAML::convert<double>::decode(n[1], hi) || !std::isfinite(lo) || !std::isfinite(hi) || !(lo <= hi))
      f.Fail("zeta_interval_N_cm3", "must be [low, high] with low <= high");
    o.zeta_low_N_m3 = lo * units::kN_m3_per_N_cm3;
    o.zeta_high_N_m3 = hi * units::kN_m3_per_N_cm3;
  }
  if (f.Has("confidence")) {
    o.confidence = f.Positive("confidence");
    if (o.confidence >= 1.0) f.Fail("confidence", "must be below 1");
  }
  if (f.Has("fit")) {
    const io::YamlFields fit = f.Child("fit");
    fit.RequireOnly(io::Keys(FitKeys()));
    SoilFit s;
    s.method = fit.StringOr("method", "");
    if (fit.Has("drops")) s.drops = fit.PositiveInt("drops");
    if (fit.Has("samples")) s.samples = fit.PositiveInt("samples");
    s.residual_rms_N = io::ReadNumberOr(fit, kResidualRms, s.residual_rms_N);
    s.dataset = fit.StringOr("dataset", "");
    o.fit = s;
  }
  return o;
}
}  // namespace

// The soil file's table (io::BekkerPressureSinkageFields), each row with its override member.
const std::vector<BekkerOverrideField>& BekkerOverrideFields() {
  static const std::vector<BekkerOverrideField> fields = [] {
    constexpr std::array<std::pair<const char*, std::optional<double> SoilOverride::*>, 3> own{{
        {"n", &SoilOverride::bekker_n},
        {"k_c", &SoilOverride::bekker_k_c_N_m_n1},
        {"k_phi", &SoilOverride::bekker_k_phi_N_m_n2},
    }};
    std::vector<BekkerOverrideField> f;
    for (size_t i = 0; i < own.size(); ++i) {
      const io::BekkerFileField& file = io::BekkerPressureSinkageFields()[i];
      f.push_back({file.key, own[i].first, io::UnitOfKey(file.key), file.file_to_si, file.range, own[i].second});
    }
    return f;
  }();
  return fields;
}

const BekkerOverrideField* FindBekkerOverrideField(std::string_view key) {
  for (const BekkerOverrideField& e : BekkerOverrideFields())
    if (key == e.key) return &e;
  return nullptr;
}

std::vector<io::BlockDoc> ModelFileSchema() {
  const std::string read_by = "drop_tests/model/model_file.cpp";
  std::vector<io::KeyDoc> bekker;
  for (const BekkerOverrideField& e : BekkerOverrideFields())
    bekker.push_back({e.key, e.unit, io::RangeText(io::Sign::kAny, e.range), "the soil file's"});
  // An effect's parameters, "id.key" (each required when the effect is listed), ranges in file units.
  std::vector<io::KeyDoc> effects;
  for (const EffectInfo& e : EffectLibrary())
    for (const EffectParameterInfo& p : e.parameters) {
      std::ostringstream range;
      range << "[" << p.lower / p.file_to_si << ", " << p.upper / p.file_to_si << "]";
      const std::string unit = p.FileUnit();
      effects.push_back({e.id + "." + p.key, unit.empty() || unit == "1" ? "-" : unit, range.str(), "*required*"});
    }
  return {io::MakeBlock("model", read_by, io::DocsOf(ModelKeys())),
          io::MakeBlock("model.effects.parameters", "drop_tests/model/effects_yaml.cpp", effects),
          io::MakeBlock("model.soil", read_by, io::DocsOf(OverrideKeys())),
          io::MakeBlock("model.soil.bekker", read_by, bekker),
          io::MakeBlock("model.soil.fit", read_by, io::DocsOf(FitKeys()))};
}

ModelFile LoadModelFile(const std::string& path) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly(io::Keys(ModelKeys()));
  if (f.String("type") != "model") f.Fail("type", "must be 'model', got '" + f.String("type") + "'");
  ModelFile m;
  m.source = path;
  m.name = f.Name("name", std::filesystem::path(path).stem().string());
  m.description = f.StringOr("description", "");
  if (f.Has("soils")) {
    const io::YamlFields soils = f.Child("soils");
    for (const auto& item : soils.node()) {
      const std::string name = item.first.Scalar();
      m.soils[name] = ReadOverride(soils.Child(name));
    }
  }
  if (f.Has("effects")) {
    if (!f.node()["effects"].IsMap()) f.Fail("effects", "must be a mapping of effect terms");
    m.effects = ParseEffects(f.Child("effects"), &m.effect_intervals);  // ids, parameters and ranges
  }
  if (f.Has("provenance")) m.provenance_yaml = YAML::Dump(f.node()["provenance"]);
  return m;
}

void WriteModelFile(const ModelFile& m, const io::OutputTarget& target, const std::string& output_dir) {
  const std::string directory =
      output_dir.empty() ? std::filesystem::path(target.path).parent_path().string() : output_dir;
  YAML::Emitter y;
  y.SetDoublePrecision(10);
  io::WriteMap(y, ModelKeys(), ToWrite<ModelFile>{m, directory});
  io::WriteOutputFile(target, [&](std::ostream& out) { out << kModelFileMark << '\n' << y.c_str() << '\n'; }, kModelFileMark);
}

rft::SoilParameters ApplyModel(const ModelFile& m, const rft::SoilParameters& soil) {
  rft::SoilParameters out = soil;
  const auto it = m.soils.find(soil.name);
  if (it == m.soils.end()) return out;
  const SoilOverride& o = it->second;
  // The model's zeta holds at its own reference gravity; the soil keeps its reference. The soil's
  // own zeta (a model that calibrates only lambda carries it) is kept without a round trip.
  if (o.zeta_N_m3 > 0.0 && (o.zeta_N_m3 != soil.zeta_N_m3 || o.reference_gravity_m_s2 != soil.reference_gravity_m_s2))
    out.SetZetaAtGravity(o.zeta_N_m3, o.reference_gravity_m_s2);
  if (o.dynamic_lambda) out.dynamic_lambda = *o.dynamic_lambda;
  if (o.bekker_n) out.bekker.n = *o.bekker_n;
  if (o.bekker_k_c_N_m_n1) out.bekker.k_c_N_m_n1 = *o.bekker_k_c_N_m_n1;
  if (o.bekker_k_phi_N_m_n2) out.bekker.k_phi_N_m_n2 = *o.bekker_k_phi_N_m_n2;
  return out;
}

rft::EffectTerms ModelEffectTerms(const ModelFile& m) {
  return MakeEffectTerms(m.effects, m.source.empty() ? "model " + m.name : m.source);
}

nlohmann::json ModelEffectsJson(const ModelFile& m) {
  const rft::EffectTerms terms = ModelEffectTerms(m);
  nlohmann::json applied = nlohmann::json::array(), skipped = nlohmann::json::object();
  for (const auto& [id, why] : EffectsNotApplied(terms, /*in_air=*/true)) skipped[id] = why;
  for (const EffectId kind : ActiveEffectIds(terms)) {
    const EffectInfo& e = FindEffect(kind);
    if (!skipped.contains(e.id)) applied.push_back(e.air_only ? e.id + " (soils in air only)" : e.id);
  }
  return {{"file", m.source}, {"effects", applied}, {"effects_not_applied", skipped}};
}

std::string ModelDigestText(const ModelFile& m) {
  std::string s = "model:" + m.name + ";";
  for (const auto& [name, o] : m.soils)
  {
    if (o.GivesZeta())
      s += name + "=" + io::FormatNumber(o.zeta_N_m3) + "@" + io::FormatNumber(o.reference_gravity_m_s2) + ";";
    if (o.dynamic_lambda) s += name + ".dynamic_lambda=" + io::FormatNumber(*o.dynamic_lambda) + ";";
    for (const BekkerOverrideField& e : BekkerOverrideFields())
      if (o.*e.member) s += name + ".bekker." + e.key + "=" + io::FormatNumber(*(o.*e.member)) + ";";
  }
  if (m.HasEffects()) s += "effects:" + YAML::Dump(EffectsToYaml(m.effects, m.effect_intervals));
  return s;
}

}  // namespace touchdown::model
