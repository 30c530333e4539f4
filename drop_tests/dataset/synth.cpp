#include "drop_tests/dataset/synth.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "drop_tests/dataset/sensor_model.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/catalog/catalog.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/model/effects_yaml.h"
#include "lander/integ/cvode_integrator.h"
#include "lander/pad/effect_soil_response.h"
#include "rft/gravity_constants.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::dataset {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> StringList(const io::YamlFields& f, const std::string& key) {
  if (!f.Has(key)) f.Fail(key, "missing");
  const YAML::Node n = f.node()[key];
  std::vector<std::string> out;
  if (n.IsScalar()) out.push_back(n.Scalar());
  else if (n.IsSequence() && n.size() > 0)
    for (const YAML::Node& item : n) {
      if (!item.IsScalar() || item.Scalar().empty()) f.Fail(key, "must list non-empty names");
      out.push_back(item.Scalar());
    }
  else
    f.Fail(key, "must be a name or a non-empty list of names");
  return out;
}

// The out-of-library floor: multiplies the whole soil reaction (it is the only hidden term).
class FloorStiffenedResponse final : public pad::VerticalSoilResponse {
 public:
  FloorStiffenedResponse(const pad::VerticalSoilResponse& inner, const FloorStiffening& f) : inner_(inner), f_(f) {}
  double Force(double d, double v) const override { return inner_.Force(d, v) * Factor(d); }
  double AddedMass(double d) const override { return inner_.AddedMass(d); }
  double AddedMassSlope(double d) const override { return inner_.AddedMassSlope(d); }
  double StaticCapacity(double d) const override { return inner_.StaticCapacity(d) * Factor(d); }

 private:
  double Factor(double d) const { return 1.0 + std::exp((d + f_.bulb_depth_m - f_.bed_depth_m) / f_.influence_m); }
  const pad::VerticalSoilResponse& inner_;
  FloorStiffening f_;
};

std::string SpeedTag(double v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << v;
  return s.str();
}

double Quantise(double x, double step) { return step > 0.0 ? std::round(x / step) * step : x; }
}  // namespace

namespace {
// A synth spec's keys, a `drops` group's, and the `noise` block's fields (each optional).
// The spec's numbers read on their own, with SynthSpec's defaults.
const io::NumberKey kSynthSampleRate{"sample_rate_hz", io::Sign::kPositive, nullptr, nullptr, SynthSpec{}.sample_rate_hz};
const io::NumberKey kSynthRestDuration{"rest_duration_s", io::Sign::kNonNegative, nullptr, nullptr, SynthSpec{}.rest_duration_s};
const io::NumberKey kSynthMass{"mass_kg", io::Sign::kPositive, nullptr, "the pad's `mass_kg`"};
const io::NumberKey kSynthGravity{"gravity_m_s2", io::Sign::kPositive, nullptr, nullptr, rft::kEarthGravity_m_s2};
const std::vector<std::string> kSynthKeys{"schema_version", "type", "name", "description", "seed", "sample_rate_hz",
                                          "rest_duration_s", "trials", "drops", "true_zeta_N_cm3", "noise",
                                          "hidden_effect", "sensor_sampling", "provenance"};
const std::vector<std::string> kSynthDropKeys{"pads", "soils", "atmospheres", "impact_speeds_m_s", "mass_kg",
                                              "gravity_m_s2"};
const io::FieldTable<SynthNoise>& NoiseFields() {
  using N = SynthNoise;
  static const io::FieldTable<N> fields{
      {"force_sigma_N", &N::force_sigma_N, 1.0, io::Sign::kNonNegative},
      {"penetration_sigma_mm", &N::penetration_sigma_m, units::kMm, io::Sign::kNonNegative},
      {"force_drift_N_s", &N::force_drift_N_s, 1.0, io::Sign::kNonNegative},
      {"penetration_drift_mm_s", &N::penetration_drift_m_s, units::kMm, io::Sign::kNonNegative},
      {"force_resolution_N", &N::force_resolution_N, 1.0, io::Sign::kNonNegative},
      {"penetration_resolution_mm", &N::penetration_resolution_m, units::kMm, io::Sign::kNonNegative},
  };
  return fields;
}
}  // namespace

std::vector<io::BlockDoc> SynthSpecSchema() {
  const std::string read_by = "drop_tests/dataset/synth.cpp";
  return {io::MakeBlock("synth", read_by, io::DocsWith(kSynthKeys, {kSynthSampleRate, kSynthRestDuration})),
          io::MakeBlock("synth.drops", read_by, io::DocsWith(kSynthDropKeys, {kSynthMass, kSynthGravity})),
          io::MakeBlock("synth.noise", read_by, io::DocsOf(NoiseFields()))};
}

SynthSpec LoadSynthSpec(const std::string& path) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly(kSynthKeys);
  if (f.String("type") != "synth") f.Fail("type", "must be 'synth', got '" + f.String("type") + "'");
  SynthSpec s;
  s.source = path;
  s.name = f.Name("name", fs::path(path).stem().string());
  s.description = f.StringOr("description", "");
  if (f.Has("seed")) {
    // As a sweep's seed: a whole number a double holds exactly (a larger one would be rounded
    // or, from 2^64 on, not fit the generator's seed at all).
    const double seed = f.NonNegative("seed");
    if (seed != std::floor(seed) || seed > 9.0e15)
      f.Fail("seed", "must be a whole number from 0 to 9e15, got " + f.node()["seed"].Scalar());
    s.seed = static_cast<unsigned long long>(seed);
  }
  s.sample_rate_hz = io::ReadNumberOr(f, kSynthSampleRate, s.sample_rate_hz);
  s.rest_duration_s = io::ReadNumberOr(f, kSynthRestDuration, s.rest_duration_s);
  if (f.Has("sensor_sampling")) {
    const std::string sampling = f.String("sensor_sampling");
    const std::optional<pad::SensorSampling> parsed = ParseSensorSampling(sampling);
    if (!parsed) f.Fail("sensor_sampling", "must be " + SensorSamplingChoices() + ", got '" + sampling + "'");
    s.sensor_sampling = *parsed;
  }
  const int trials = f.Has("trials") ? f.PositiveInt("trials") : 1;
  // Resource caps: the dataset is built in memory (every trace) before it is written, so its size
  // is bounded here, at load, with the limit in the message.
  if (s.sample_rate_hz > limits::kMaxSynthSampleRate_Hz)
    f.Fail("sample_rate_hz", "must be at most " + io::FormatNumber(limits::kMaxSynthSampleRate_Hz) + " Hz, got " +
                                 io::FormatNumber(s.sample_rate_hz));
  if (s.rest_duration_s > limits::kMaxSynthRestDuration_s)
    f.Fail("rest_duration_s", "must be at most " + io::FormatNumber(limits::kMaxSynthRestDuration_s) + " s, got " +
                                  io::FormatNumber(s.rest_duration_s));
  if (trials > limits::kMaxSynthTrials)
    f.Fail("trials", "must be at most " + std::to_string(limits::kMaxSynthTrials) + ", got " + std::to_string(trials));
  int group = -1;
  for (const io::YamlFields& g : f.List("drops")) {
    ++group;
    g.RequireOnly(kSynthDropKeys);
    const std::vector<std::string> pads = StringList(g, "pads"), soils = StringList(g, "soils");
    std::vector<rft::Atmosphere> atmospheres;
    for (const std::string& a : g.Has("atmospheres") ? StringList(g, "atmospheres") : std::vector<std::string>{"vacuum"}) {
      const std::optional<rft::Atmosphere> parsed = rft::ParseAtmosphere(a);
      if (!parsed) g.Fail("atmospheres", "must be air or vacuum, got '" + a + "'");
      atmospheres.push_back(*parsed);
    }
    const std::vector<double> speeds = g.NumberList("impact_speeds_m_s", /*allow_zero=*/false);
    for (const std::string& pad : pads)
      if (!io::LoadPad(pad).is_axisymmetric())
        g.Fail("pads", "'" + pad + "' is a mesh pad; synth simulates rig drops, which need an axisymmetric pad");
    for (const std::string& pad : pads)
      for (const std::string& soil : soils)
        for (rft::Atmosphere atm : atmospheres)
          for (double v : speeds)
            for (int t = 0; t < trials; ++t) {
              if (s.drops.size() == limits::kMaxSynthDrops)
                f.Fail("drops", "more than " + std::to_string(limits::kMaxSynthDrops) + " drops (pads x soils x atmospheres x "
                                "impact speeds x trials)");
              SynthDrop d{pad, soil, atm, v, std::nullopt, io::ReadNumberOr(g, kSynthGravity, rft::kEarthGravity_m_s2), t, group};
              if (g.Has(kSynthMass.key)) d.mass_kg = io::ReadNumber(g, kSynthMass);
              s.drops.push_back(d);
            }
  }
  if (f.Has("true_zeta_N_cm3")) {
    const io::YamlFields z = f.Child("true_zeta_N_cm3");
    for (const auto& item : z.node()) s.true_zeta_N_m3.emplace_back(item.first.Scalar(), units::ZetaFromN_cm3(z.Positive(item.first.Scalar())));
  }
  if (f.Has("noise")) {
    const io::YamlFields n = f.Child("noise");
    n.RequireOnly(io::FieldKeys(NoiseFields()));
    io::ReadFields(n, NoiseFields(), s.noise);
  }
  if (f.Has("hidden_effect")) {
    const io::YamlFields h = f.Child("hidden_effect");
    const std::string id = h.String("id");
    if (id == "floor_stiffening") {
      h.RequireOnly({"id", "bed_depth_mm", "bulb_depth_mm", "influence_mm"});
      FloorStiffening fl;
      fl.bed_depth_m = h.PositiveOr("bed_depth_mm", 150.0) * units::kMm;
      fl.bulb_depth_m = h.PositiveOr("bulb_depth_mm", 100.0) * units::kMm;
      fl.influence_m = h.PositiveOr("influence_mm", 15.0) * units::kMm;
      s.floor = fl;
    } else {
      YAML::Node params(YAML::NodeType::Map);
      params[id] = YAML::Node(YAML::NodeType::Map);
      for (const auto& item : h.node())
        if (item.first.Scalar() != "id") params[id][item.first.Scalar()] = item.second;
      const std::vector<model::Effect> e = model::ParseEffects(io::YamlFields(params, path, "hidden_effect"));
      s.hidden_effect = e.front();
    }
  }
  if (s.drops.empty()) f.Fail("drops", "no drops");
  // The samples of the rest recorded after each stop, plus a stroke of about kSynthStrokeBoundS.
  const double samples = static_cast<double>(s.drops.size()) * (s.rest_duration_s + kSynthStrokeBoundS) * s.sample_rate_hz;
  if (samples > limits::kMaxSynthSamples)
    f.Fail("drops", "drops x (rest_duration_s + " + io::FormatNumber(kSynthStrokeBoundS) + " s) x sample_rate_hz is " +
                        io::FormatNumber(samples) + " samples, more than the " + io::FormatNumber(limits::kMaxSynthSamples) +
                        " a dataset may hold (" + std::to_string(s.drops.size()) + " drops)");
  return s;
}

Dataset Synthesize(const SynthSpec& spec) {
  Dataset ds;
  ds.extra_columns = {"trial", "data_origin"};
  std::map<std::string, io::PadSpec> pads;
  std::map<std::string, rft::SoilParameters> soils;
  std::map<std::string, std::unique_ptr<geom::AxisymmetricIntrusion>> intrusions;
  const rft::EffectTerms terms = spec.hidden_effect ? model::MakeEffectTerms({*spec.hidden_effect}, spec.source) : rft::EffectTerms{};
  std::map<std::string, int> made_by;  // drop id -> the drops[] group that made it
  for (size_t i = 0; i < spec.drops.size(); ++i) {
    const SynthDrop& sd = spec.drops[i];
    const std::string group = "drops[" + std::to_string(sd.group) + "]";
    try {
      if (!pads.count(sd.pad)) {
        pads[sd.pad] = io::LoadPad(sd.pad);
        intrusions[sd.pad] = drop::MakeRigIntrusion(pads[sd.pad].profile);
      }
    } catch (const InputError& e) {
      throw MakeInputError(spec.source, group + ".pads", e.what());
    }
    try {
      if (!soils.count(sd.soil)) soils[sd.soil] = io::LoadSoil(sd.soil);
    } catch (const InputError& e) {
      throw MakeInputError(spec.source, group + ".soils", e.what());
    }
    const io::PadSpec& pad = pads[sd.pad];
    // A Bekker soil's drops run on its own law (its profile integral, kept beside the Li 2013 one).
    const bool bekker = drop::RunsOnBekker(soils[sd.soil], std::nullopt);
    const std::string bekker_key = sd.pad + "\n(bekker)";
    if (bekker && !intrusions.count(bekker_key)) intrusions[bekker_key] = drop::MakeBekkerRigIntrusion(pad.profile);
    // The true zeta, where the spec states one, overrides the catalogue's.
    std::optional<double> true_zeta;
    for (const auto& [name, zeta] : spec.true_zeta_N_m3)
      if (name == sd.soil) true_zeta = zeta;
    const rft::SoilParameters soil = drop::DropSoil(soils[sd.soil], true_zeta, sd.atmosphere);
    const double mass = sd.mass_kg.value_or(pad.mass_kg);
    const pad::EffectSoilResponse response =
        bekker ? drop::MakeBekkerRigResponse(*intrusions[bekker_key], soil, terms)
               : drop::MakeRigResponse(*intrusions[sd.pad], soil, sd.gravity_m_s2, terms);
    pad::RigDropSetup setup{{mass}, &response, {sd.gravity_m_s2, sd.impact_speed_m_s}, {}};
    std::optional<FloorStiffenedResponse> floored;
    if (spec.floor) setup.terrain = &floored.emplace(response, *spec.floor);
    setup.options.rest_duration_s = spec.rest_duration_s + std::abs(terms.sensor_dt_s) + 2.0 / spec.sample_rate_hz;
    setup.options.sample_rate_hz = SimulationRateFor_Hz(spec.sample_rate_hz);  // as compare and diagnose record
    pad::RigDropResult sim;
    try {
      sim = pad::RunRigDrop(setup);
    } catch (const integ::IntegrationFailure& e) {
      throw integ::IntegrationFailure(spec.source + ": " + group + ": the drop of pad " + sd.pad + " on soil " +
                                      sd.soil + " at " + io::FormatNumber(sd.impact_speed_m_s) + " m/s (trial " +
                                      std::to_string(sd.trial) + "): " + e.what());
    }

    // The recorder: a seeded stream per drop, so adding drops never changes the others.
    std::mt19937_64 rng(spec.seed * 0x9E3779B97F4A7C15ULL + i + 1);
    std::normal_distribution<double> normal(0.0, 1.0);
    const SynthNoise& n = spec.noise;
    const double force_drift = n.force_drift_N_s * normal(rng);
    const double pen_drift = n.penetration_drift_m_s * normal(rng);
    DatasetDrop d;
    std::ostringstream id;
    id << pad.name << '_' << soil.name << '_' << rft::AtmosphereName(sd.atmosphere) << "_v" << SpeedTag(sd.impact_speed_m_s) << "_t" << sd.trial;
    d.drop_id = id.str();
    // The dataset's rules on ids and names, checked here so a refusal names the spec's field, not
    // the output directory (WriteDatasetFiles checks them again).
    if (const std::string problem = DropIdProblem(d.drop_id); !problem.empty())
      throw MakeInputError(spec.source, group, "the drop of pad " + sd.pad + " on soil " + sd.soil + ": " + problem);
    for (const auto& [key, name] : {std::pair<const char*, const std::string&>{"pads", sd.pad}, {"soils", sd.soil}})
      if (name.find_first_of(",\n\r") != std::string::npos)
        throw MakeInputError(spec.source, group + "." + key,
                             "'" + name + "' contains a comma or a line break, which drops.csv cannot hold");
    if (const auto [it, inserted] = made_by.emplace(d.drop_id, sd.group); !inserted)
      throw MakeInputError(spec.source, group,
                           "makes drop '" + d.drop_id + "' again (drops[" + std::to_string(it->second) +
                               "] made it already): a pad, soil, atmosphere, speed and trial may appear once");
    d.pad = sd.pad;
    d.soil = sd.soil;
    d.atmosphere = sd.atmosphere;
    d.impact_speed_m_s = sd.impact_speed_m_s;
    d.pad_mass_kg = mass;
    d.gravity_m_s2 = sd.gravity_m_s2;
    d.trace_file = "traces/" + d.drop_id + ".csv";
    d.extra = {std::to_string(sd.trial), "synthetic"};
    const double t_end = sim.time_to_rest_s - terms.sensor_dt_s + spec.rest_duration_s;
    for (long k = 0; k / spec.sample_rate_hz <= t_end + 1e-12; ++k) {
      const double t = k / spec.sample_rate_hz;
      const pad::RecordedSample r =
          pad::RecordedSampleOf(sim, sd.gravity_m_s2, terms, t, spec.sensor_sampling, 1.0 / spec.sample_rate_hz);
      d.trace.t_s.push_back(t);
      d.trace.force_N.push_back(Quantise(r.force_N + force_drift * t + n.force_sigma_N * normal(rng), n.force_resolution_N));
      d.trace.penetration_m.push_back(
          Quantise(r.penetration_m + pen_drift * t + n.penetration_sigma_m * normal(rng), n.penetration_resolution_m));
    }
    ds.drops.push_back(std::move(d));
  }
  return ds;
}

namespace {
void WriteSpecYaml(const SynthSpec& s, YAML::Emitter& y, bool with_truth) {
  y << YAML::BeginMap << YAML::Key << "schema_version" << YAML::Value << 1;
  y << YAML::Key << "synthetic" << YAML::Value << true;
  y << YAML::Key << "name" << YAML::Value << s.name << YAML::Key << "spec_file" << YAML::Value << s.source;
  y << YAML::Key << "seed" << YAML::Value << s.seed << YAML::Key << "sample_rate_hz" << YAML::Value << s.sample_rate_hz
    << YAML::Key << "rest_duration_s" << YAML::Value << s.rest_duration_s << YAML::Key << "drops" << YAML::Value
    << s.drops.size();
  y << YAML::Key << "sensor_sampling" << YAML::Value << SensorSamplingName(s.sensor_sampling);
  y << YAML::Key << "noise" << YAML::Value << YAML::BeginMap << YAML::Key << "force_sigma_N" << YAML::Value
    << s.noise.force_sigma_N << YAML::Key << "penetration_sigma_mm" << YAML::Value << s.noise.penetration_sigma_m * units::kMmPerM
    << YAML::Key << "force_drift_N_s" << YAML::Value << s.noise.force_drift_N_s << YAML::Key
    << "penetration_drift_mm_s" << YAML::Value << s.noise.penetration_drift_m_s * units::kMmPerM << YAML::Key
    << "force_resolution_N" << YAML::Value << s.noise.force_resolution_N << YAML::Key << "penetration_resolution_mm"
    << YAML::Value << s.noise.penetration_resolution_m * units::kMmPerM << YAML::EndMap;
  if (with_truth) {
    y << YAML::Key << "true_zeta_N_cm3" << YAML::Value << YAML::BeginMap;
    for (const auto& [soil, zeta] : s.true_zeta_N_m3) y << YAML::Key << soil << YAML::Value << units::ZetaToN_cm3(zeta);
    y << YAML::EndMap << YAML::Key << "hidden_effect" << YAML::Value;
    if (s.hidden_effect) y << model::EffectsToYaml({*s.hidden_effect});
    else if (s.floor)
      y << YAML::BeginMap << YAML::Key << "floor_stiffening (outside the library)" << YAML::Value << YAML::BeginMap
        << YAML::Key << "bed_depth_mm" << YAML::Value << s.floor->bed_depth_m * units::kMmPerM << YAML::Key << "bulb_depth_mm"
        << YAML::Value << s.floor->bulb_depth_m * units::kMmPerM << YAML::Key << "influence_mm" << YAML::Value
        << s.floor->influence_m * units::kMmPerM << YAML::EndMap << YAML::EndMap;
    else y << "none";
  }
  y << YAML::EndMap;
}
}  // namespace

void WriteSyntheticDataset(const SynthSpec& spec, const Dataset& dataset, const io::OutputTarget& out) {
  io::WriteOutputDirectory(out, io::OutputKind::kDataset, [&](const std::string& staging) {
    WriteDatasetFiles(dataset, staging);
    const fs::path dir = staging;
    io::WriteFileAtomically((dir / "README.md").string(), [&](std::ostream& out) {
      out << "# SYNTHETIC dataset: " << spec.name << "\n\n"
          << "**These are not measurements.** Every trace was made by `touchdown synth` from the spec `"
          << fs::path(spec.source).filename().string() << "`: a simulated axisymmetric rig drop (RFT on the soils as given, each with its own dynamic term if it carries one"
          << (spec.hidden_effect || spec.floor ? ", plus a hidden effect" : "") << "), recorded with simulated "
          << "sensor noise, drift and quantisation. drops.csv marks every row `data_origin = synthetic`.\n\n"
          << (spec.description.empty() ? "" : spec.description + "\n\n") << "- drops: " << dataset.drops.size()
          << "\n- sampling: " << spec.sample_rate_hz << " Hz, seed " << spec.seed
          << "\n- noise: load cell sigma " << spec.noise.force_sigma_N << " N, drift sigma "
          << spec.noise.force_drift_N_s << " N/s, resolution " << spec.noise.force_resolution_N
          << " N; displacement sigma " << spec.noise.penetration_sigma_m * units::kMmPerM << " mm, drift sigma "
          << spec.noise.penetration_drift_m_s * units::kMmPerM << " mm/s, resolution " << spec.noise.penetration_resolution_m * units::kMmPerM
          << " mm\n\nsynthetic.yaml holds the generator settings; synthetic_truth.yaml the hidden effect and "
          << "true soils (for checking a diagnosis; `touchdown diagnose` never reads it).\n";
    });
    YAML::Emitter meta, truth;
    WriteSpecYaml(spec, meta, false);
    WriteSpecYaml(spec, truth, true);
    io::WriteFileAtomically((dir / "synthetic.yaml").string(), [&](std::ostream& o) { o << meta.c_str() << '\n'; });
    io::WriteFileAtomically((dir / "synthetic_truth.yaml").string(), [&](std::ostream& o) { o << truth.c_str() << '\n'; });
  });
}

SynthRun SynthesizeToDirectory(const std::string& spec_path, const io::OutputTarget& out) {
  io::CheckOutputDirectory(out, io::OutputKind::kDataset);
  SynthRun run{LoadSynthSpec(spec_path), 0};
  const Dataset dataset = Synthesize(run.spec);
  WriteSyntheticDataset(run.spec, dataset, out);
  run.drops = dataset.drops.size();
  return run;
}

}  // namespace touchdown::dataset
