#include "drop_tests/sweep/sweep_plan.h"


#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/util/splitmix.h"
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/model/contact_model.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/sweep/sweep_drop.h"
#include "drop_tests/sweep/sweep_file_keys.h"
#include "rft/bekker_law.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"
#include "drop_tests/sweep/sweep_param_table.h"

// Reading a sweep plan from its file (LoadSweepPlan, sweep_plan.h): the fixed, grid and random
// blocks, each value checked against its parameter's range, the lander block and the run options.
namespace touchdown::sweep {

namespace fs = std::filesystem;
using namespace param_table;

namespace {
// Range rules per parameter, checked on every value a file can produce (fixed, grid, random bounds).
void CheckValue(SweepParam p, double v, const std::string& file, const std::string& path) {
  auto fail = [&](const std::string& rule) {
    throw MakeInputError(file, path, "must be " + rule + ", got " + io::FormatNumber(v));
  };
  if (!std::isfinite(v)) fail("finite");
  switch (p) {
    // Physical ranges (rft/physical_limits.h), as for a single drop.
    case SweepParam::kImpactSpeed: limits::Require(limits::kSpeed_m_s, v, file, path); break;
    case SweepParam::kHorizontalSpeed: limits::Require(limits::kAbsSpeed_m_s, v, file, path); break;
    case SweepParam::kZeta: limits::Require(limits::kZeta_N_cm3, v, file, path); break;
    case SweepParam::kMass: limits::Require(limits::kMass_kg, v, file, path); break;
    case SweepParam::kGravity: limits::Require(limits::kGravity_m_s2, v, file, path); break;
    case SweepParam::kTilt:
      if (!(std::abs(v) < 90.0)) fail("strictly between -90 and 90 (on its side a pad does not land on its bottom)");
      break;
    case SweepParam::kRoll:
    case SweepParam::kPitch:
      if (!(std::abs(v) < 80.0)) fail("between -80 and 80");
      break;
    case SweepParam::kSlope:  // as the scenario's ground.slope_deg
      if (!(v >= 0.0 && v < 80.0)) fail("at least 0 and below 80");
      break;
    case SweepParam::kDownhillAzimuth:
    case SweepParam::kYawToSlope:
    case SweepParam::kHorizontalAzimuth: limits::Require(limits::kAzimuth_deg, v, file, path); break;
    case SweepParam::kRateX:
    case SweepParam::kRateY:
    case SweepParam::kRateZ: limits::Require(limits::kAngularRate_deg_s, v, file, path); break;
    default: break;
  }
}

class Loader {
 public:
  Loader(SweepPlan& plan, const std::string& base) : plan_(plan), base_(base) {}

  // A pad/soil name to an index into plan.pads / plan.soils (loaded once).
  double NameIndex(SweepParam p, const YAML::Node& n, const io::YamlFields& f, const std::string& path) {
    if (!n.IsScalar() || n.Scalar().empty())
      throw MakeInputError(f.file(), path, "must be a pad/soil name or YAML path");
    std::string ref = n.Scalar();
    const bool is_path = ref.find('/') != std::string::npos || ref.ends_with(".yaml") || ref.ends_with(".yml");
    if (is_path && fs::path(ref).is_relative()) ref = (fs::path(base_) / ref).lexically_normal().string();
    try {
      if (p == SweepParam::kPad) {
        for (size_t i = 0; i < pad_refs_.size(); ++i)
          if (pad_refs_[i] == ref) return static_cast<double>(i);
        // A mesh pad (no profile for the rig's integral) runs every drop as a free 6-DOF drop.
        plan_.pads.push_back(io::LoadPad(ref));
        pad_refs_.push_back(ref);
        return static_cast<double>(plan_.pads.size() - 1);
      }
      for (size_t i = 0; i < soil_refs_.size(); ++i)
        if (soil_refs_[i] == ref) return static_cast<double>(i);
      plan_.soils.push_back(io::LoadSoil(ref));
      plan_.soil_refs.push_back(ref);
      soil_refs_.push_back(ref);
      return static_cast<double>(plan_.soils.size() - 1);
    } catch (const InputError& e) {
      throw MakeInputError(f.file(), path, e.what());
    }
  }

  // A `pad_soils` value (a Table II letter or four soils) to an index into plan.pad_soil_sets.
  double PadSoils(const YAML::Node& n, const io::YamlFields& f, const std::string& path) {
    PadSoilSet set;
    if (n.IsScalar()) {
      const PaperCase* found = nullptr;
      for (const PaperCase& c : kPaperCases)
        if (n.Scalar() == c.label) found = &c;
      if (!found)
        throw MakeInputError(f.file(), path, "must be a ground case of the paper's Table II (A, B or C) or a list "
                                             "of four soils, got '" + n.Scalar() + "'");
      set.label = found->label;
      for (int i = 0; i < 4; ++i) set.soil[i] = static_cast<int>(NameIndex(SweepParam::kSoil, YAML::Node(found->soils[i]), f, path));
    } else if (n.IsSequence() && n.size() == 4) {
      for (int i = 0; i < 4; ++i)
        set.soil[i] = static_cast<int>(NameIndex(SweepParam::kSoil, n[i], f, path + "[" + std::to_string(i) + "]"));
    } else {
      throw MakeInputError(f.file(), path, "must be a ground case of the paper's Table II (A, B or C) or a list of "
                                           "four soils (pads 1..4, clockwise from front-left), got " +
                                           (n.IsSequence() ? "a list of " + std::to_string(n.size())
                                                           : std::string("a mapping")));
    }
    for (size_t i = 0; i < plan_.pad_soil_sets.size(); ++i)
      if (plan_.pad_soil_sets[i].label == set.label && plan_.pad_soil_sets[i].soil == set.soil)
        return static_cast<double>(i);
    plan_.pad_soil_sets.push_back(set);
    return static_cast<double>(plan_.pad_soil_sets.size() - 1);
  }

  double Scalar(SweepParam p, const YAML::Node& n, const io::YamlFields& f, const std::string& path) {
    if (p == SweepParam::kPadSoils) return PadSoils(n, f, path);
    if (IsName(p)) return NameIndex(p, n, f, path);
    double v = 0.0;
    if (!n.IsScalar() || !YAML::convert<double>::decode(n, v))
      throw MakeInputError(f.file(), path, "must be a number");
    CheckValue(p, v, f.file(), path);
    return ToSi(p, v);
  }

  std::vector<double> List(SweepParam p, const YAML::Node& n, const io::YamlFields& f, const std::string& path) {
    std::vector<double> out;
    if (!n.IsSequence() || n.size() == 0) throw MakeInputError(f.file(), path, "must be a non-empty list");
    for (size_t i = 0; i < n.size(); ++i) out.push_back(Scalar(p, n[i], f, path + "[" + std::to_string(i) + "]"));
    return out;
  }

 private:
  SweepPlan& plan_;
  std::string base_;
  std::vector<std::string> pad_refs_, soil_refs_;
};

}  // namespace

namespace {
// The scenario a lander sweep starts every drop from, the digest of the files it reads, and the
// half width of the patches `pad_soils` lays; options only single-pad sweeps take are refused.
void ReadLanderBlock(const io::YamlFields& f, const std::string& base, SweepPlan& plan) {
  const io::YamlFields l = f.Child("lander");
  l.RequireOnly(io::Keys(LanderBlockKeys()));
  std::string ref = l.String("scenario");
  const bool is_path = ref.find('/') != std::string::npos || ref.ends_with(".yaml") || ref.ends_with(".yml");
  if (is_path && fs::path(ref).is_relative()) ref = (fs::path(base) / ref).lexically_normal().string();
  try {
    plan.lander = scenario::LoadLanderScenario(io::ResolveCatalogFile("scenarios", ref));
  } catch (const InputError& e) {
    l.Fail("scenario", e.what());
  }
  // The digest covers every file the scenario reads: scenario, lander, pad (and mesh), soils.
  const scenario::LanderSpec& spec = plan.lander->lander;
  std::string files = FileText(plan.lander->source) + '\0' + FileText(spec.source) + '\0' +
                      FileText(spec.pad.source) + '\0' + FileText(spec.pad.mesh_file);
  files += '\0' + FileText(io::ResolveCatalogFile("soils", plan.lander->ground.default_soil));
  for (const scenario::LanderPatchSpec& patch : plan.lander->ground.patches)
    files += '\0' + FileText(io::ResolveCatalogFile("soils", patch.soil));
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, Fnv1a64(files));
  plan.lander_digest = hex;
  // The half width of the patches `pad_soils` lays under the pads: given, or the scenario's own
  // under_pad patches', or 0.08 m as the shipped scenarios.
  for (const scenario::LanderPatchSpec& patch : plan.lander->ground.patches)
    if (const auto* square = std::get_if<scenario::UnderPadSquare>(&patch.area))
      plan.pad_patch_half_width_m = square->half_width_m;
  if (l.Has("pad_patch_half_width_m")) {
    plan.pad_patch_half_width_m = io::ReadNumber(l, kPadPatchHalfWidthKey);
    if (plan.pad_patch_half_width_m > 1.0)
      l.Fail("pad_patch_half_width_m", "must be at most 1 m, got " + io::FormatNumber(plan.pad_patch_half_width_m));
  }
  for (const char* key : {"rest_duration_s", "trace_max_samples"})
    if (f.Has(key)) f.Fail(key, "a lander sweep runs the scenario's simulation options; remove it");
  if (f.Has("traces") && f.String("traces") != TraceStorageName(TraceStorage::kNone))
    f.Fail("traces", "a lander sweep stores summaries only (traces: none); run `touchdown lander` for a trace");
}

// Trace storage and the per-drop options and work limits.
void ReadRunOptions(const io::YamlFields& f, SweepPlan& plan) {
  const std::string traces =
      f.StringOr("traces", TraceStorageName(plan.lander ? TraceStorage::kNone : TraceStorage::kDecimated));
  if (const std::optional<TraceStorage> t = FindName(kTraceStorageNames, traces)) plan.traces = *t;
  else f.Fail("traces", "must be " + NameChoices(kTraceStorageNames) + ", got '" + traces + "'");
  if (f.Has("trace_max_samples")) plan.trace_max_samples = f.PositiveInt("trace_max_samples");
  if (plan.trace_max_samples < 3) f.Fail("trace_max_samples", "must be at least 3");
  plan.rig.rest_duration_s = io::ReadNumberOr(f, kRestDurationKey, kRestDurationKey.default_value);
  if (plan.rig.rest_duration_s > limits::kMaxRigRestDuration_s)
    f.Fail("rest_duration_s", "must be at most " + io::FormatNumber(limits::kMaxRigRestDuration_s) + " s");
  plan.rig.integrator.max_wall_time_s =
      io::ReadNumberOr(f, kMaxDropWallTimeKey, kDefaultMaxDropWallTimeS);
  if (!std::isfinite(plan.rig.integrator.max_wall_time_s))
    f.Fail("max_drop_wall_time_s", "must be a finite number of seconds (0: no limit)");
  plan.rig.integrator.max_rhs_evaluations = kDefaultMaxDropEvaluations;
  if (f.Has("max_drop_evaluations")) {
    const double n = f.NonNegative("max_drop_evaluations");
    if (n != std::floor(n) || n > 1e15)
      f.Fail("max_drop_evaluations", "must be a whole number of evaluations between 0 (no limit) and 1e15, got " +
                                         io::FormatNumber(n));
    plan.rig.integrator.max_rhs_evaluations = static_cast<long>(n);
  }
}

// The free drops' model (`simulation: {free_drop_model: reference | fast}`), checked against every
// pad: the fast model re-meshes revolved pads and refuses a mesh pad, naming it.
void ReadSimulation(const io::YamlFields& f, SweepPlan& plan) {
  if (!f.Has("simulation")) return;
  if (plan.lander) f.Fail("simulation", "a lander sweep runs the scenario's simulation options; remove it");
  const io::YamlFields sim = f.Child("simulation");
  sim.RequireOnly(io::Keys(SimulationBlockKeys()));
  const std::string model = sim.StringOr("free_drop_model", "reference");
  if (model == "fast") plan.free_drop_model = drop::FreeDropModel::kFast;
  else if (model != "reference") sim.Fail("free_drop_model", "must be 'reference' or 'fast', got '" + model + "'");
  for (const io::PadSpec& pad : plan.pads)
    drop::FreeDropPad(pad, plan.free_drop_model, sim.file(), sim.Path("free_drop_model"));
}

// Every parameter's key, the lander sweeps' after theirs: "pad, soil, ...; lander sweeps: roll_deg, ..."
// (docs/reference.md lists them; tests/python/test_reference.py reads this list).
std::string KnownParams() {
  std::string single, lander;
  for (int i = 0; i < kSweepParamCount; ++i) {
    const SweepParam p = static_cast<SweepParam>(i);
    std::string& list = IsLanderParam(p) ? lander : single;
    list += (list.empty() ? "" : ", ") + std::string(SweepParamKey(p));
  }
  return single + "; lander sweeps: " + lander;
}

// Which parameters the blocks set: each at most once, and only where the sweep's kind takes it.
class ParamClaims {
 public:
  explicit ParamClaims(bool lander) : lander_(lander) {}
  bool Seen(SweepParam p) const { return seen_[static_cast<int>(p)]; }
  SweepParam Claim(const io::YamlFields& block, const std::string& key) {
    const std::optional<SweepParam> p = ParamFromKey(key);
    if (!p) block.Fail(key, "unknown parameter (" + KnownParams() + ")");
    if (Seen(*p)) block.Fail(key, "set in more than one of fixed, grid and random");
    if (lander_ && IsSinglePadOnly(*p) && *p != SweepParam::kPad)
      block.Fail(key, "a single-pad parameter; a lander sweep varies impact_speed_m_s, horizontal_speed_m_s, "
                      "horizontal_azimuth_deg, roll_deg, pitch_deg, yaw_relative_to_slope_deg, the angular rates, "
                      "slope_deg, downhill_azimuth_deg, gravity_m_s2, soil, pad_soils and pad (the pad design)");
    if (!lander_ && IsLanderParam(*p))
      block.Fail(key, "a lander parameter: it needs a `lander: {scenario: ...}` block (single pads take tilt_deg)");
    const SweepParam other = *p == SweepParam::kSoil ? SweepParam::kPadSoils : SweepParam::kSoil;
    if ((*p == SweepParam::kSoil || *p == SweepParam::kPadSoils) && Seen(other))
      block.Fail(key, "soil (the whole ground) and pad_soils (the soil under each pad) exclude each other; keep one");
    seen_[static_cast<int>(*p)] = true;
    return *p;
  }

 private:
  bool lander_;
  bool seen_[kSweepParamCount] = {};
};

void ReadFixed(const io::YamlFields& block, ParamClaims& claims, Loader& loader, SweepPlan& plan) {
  for (const auto& item : block.node()) {
    const std::string key = item.first.Scalar();
    const SweepParam p = claims.Claim(block, key);
    plan.fixed[static_cast<int>(p)] = loader.Scalar(p, item.second, block, block.Path(key));
  }
}

// A grid axis given as a range.
const std::vector<std::string> kGridRangeKeys{"from", "to", "count"};

// Grid axes: a list of values or {from, to, count}; the first-listed axis varies slowest.
void ReadGrid(const io::YamlFields& block, ParamClaims& claims, Loader& loader, SweepPlan& plan) {
  for (const auto& item : block.node()) {
    const std::string key = item.first.Scalar();
    const SweepParam p = claims.Claim(block, key);
    SweepAxis axis{p, {}};
    if (item.second.IsMap() && !IsName(p)) {
      const io::YamlFields range = block.Child(key);
      range.RequireOnly(kGridRangeKeys);
      const double from = range.Number("from"), to = range.Number("to");
      const int count = range.PositiveInt("count");
      if (count < 2 && from != to) range.Fail("count", "must be at least 2 when from != to");
      if (count > kMaxGridCount)
        range.Fail("count", "must be at most " + std::to_string(kMaxGridCount) + ", got " + std::to_string(count));
      for (int i = 0; i < count; ++i) {
        // Ends exact: from and to appear as written.
        const double v = i == count - 1 ? to : from + (to - from) * i / (count - 1 > 0 ? count - 1 : 1);
        CheckValue(p, v, block.file(), range.Path(i == count - 1 ? "to" : "from"));
        axis.values.push_back(ToSi(p, v));
      }
    } else {
      axis.values = loader.List(p, item.second, block, block.Path(key));
    }
    plan.grid.push_back(std::move(axis));
  }
}

// What a YAML node holds, for a message: 'text' for a scalar, else "a list of N" or "a mapping".
std::string GivenAs(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list of " + std::to_string(n.size());
  return n.IsMap() ? "a mapping" : "nothing";
}

// `probabilities: [...]` of a choice: one per value, each in [0, 1], summing to 1 (to 1e-9).
std::vector<double> ReadProbabilities(const io::YamlFields& spec, size_t count) {
  const YAML::Node n = spec.node()["probabilities"];
  if (!n.IsSequence() || n.size() != count)
    spec.Fail("probabilities", "must be a list of " + std::to_string(count) + " numbers, one per choice, got " +
                                   GivenAs(n));
  std::vector<double> out;
  double sum = 0.0;
  for (size_t i = 0; i < count; ++i) {
    double v = 0.0;
    const std::string path = spec.Path("probabilities") + "[" + std::to_string(i) + "]";
    if (!n[i].IsScalar() || !YAML::convert<double>::decode(n[i], v) || !(v >= 0.0 && v <= 1.0))
      throw MakeInputError(spec.file(), path, "must be a probability between 0 and 1, got " + GivenAs(n[i]));
    out.push_back(v);
    sum += v;
  }
  if (!(std::abs(sum - 1.0) <= 1e-9))
    spec.Fail("probabilities", "must sum to 1, got " + io::FormatNumber(sum));
  return out;
}

// `per_pad_choice`: every combination of the soils under the four pads becomes a pad_soils set
// (k^4 of them), so a drop's draw is an index like any other pad_soils value.
void AddPerPadSets(SweepRandom& r, const io::YamlFields& spec, SweepPlan& plan) {
  const size_t k = r.values.size();
  if (k > 8) spec.Fail("per_pad_choice", "at most 8 soils, got " + std::to_string(k));
  r.first_set = static_cast<int>(plan.pad_soil_sets.size());
  const size_t combinations = k * k * k * k;
  for (size_t c = 0; c < combinations; ++c) {
    PadSoilSet set;
    size_t rest = c;
    for (int pad = 0; pad < 4; ++pad, rest /= k) set.soil[pad] = static_cast<int>(r.values[rest % k]);
    plan.pad_soil_sets.push_back(set);
  }
}

// Seeded random samples: `uniform: [low, high]` or `choice: [...]` per parameter (pad_soils also
// `per_pad_choice: [...]`), a choice optionally with `probabilities: [...]`.
void ReadRandom(const io::YamlFields& block, ParamClaims& claims, Loader& loader, SweepPlan& plan) {
  // The bound --samples has too (rft/physical_limits.h).
  limits::Require(limits::kSamples, block.Number("samples"), block.file(), block.Path("samples"));
  plan.samples = block.PositiveInt("samples");
  if (!block.Has("seed")) block.Fail("seed", "missing (random samples need a seed to be reproducible)");
  const double seed = block.Number("seed");
  if (seed < 0 || seed != std::floor(seed) || seed > 9.0e15)
    block.Fail("seed", "must be a whole number from 0 to 9e15, got " + block.node()["seed"].Scalar());
  plan.seed = static_cast<uint64_t>(seed);
  for (const auto& item : block.node()) {
    const std::string key = item.first.Scalar();
    if (key == "samples" || key == "seed") continue;
    const SweepParam p = claims.Claim(block, key);
    const io::YamlFields spec = block.Child(key);
    spec.RequireOnly(io::Keys(RandomSpecKeys()));
    SweepRandom r;
    r.param = p;
    const int given = int(spec.Has("uniform")) + int(spec.Has("choice")) + int(spec.Has("per_pad_choice"));
    if (given != 1) spec.Fail("uniform", "give exactly one of uniform, choice and per_pad_choice");
    if (spec.Has("per_pad_choice")) {
      if (p != SweepParam::kPadSoils) spec.Fail("per_pad_choice", "only pad_soils draws a value per pad");
      r.choice = r.per_pad = true;
      r.values = loader.List(SweepParam::kSoil, spec.node()["per_pad_choice"], spec, spec.Path("per_pad_choice"));
      AddPerPadSets(r, spec, plan);
    } else if (spec.Has("choice")) {
      r.choice = true;
      r.values = loader.List(p, spec.node()["choice"], spec, spec.Path("choice"));
    } else {
      if (IsName(p)) spec.Fail("uniform", "pads and soils take `choice`, not `uniform`");
      if (spec.Has("probabilities")) spec.Fail("probabilities", "only a choice takes probabilities");
      const YAML::Node u = spec.node()["uniform"];
      if (!u.IsSequence() || u.size() != 2) spec.Fail("uniform", "must be [low, high]");
      const double lo = loader.Scalar(p, u[0], spec, spec.Path("uniform") + "[0]");
      const double hi = loader.Scalar(p, u[1], spec, spec.Path("uniform") + "[1]");
      if (!(lo < hi)) spec.Fail("uniform", "needs low < high");
      r.low = lo;
      r.high = hi;
    }
    if (spec.Has("probabilities")) r.probabilities = ReadProbabilities(spec, r.values.size());
    plan.random.push_back(std::move(r));
  }
}

}  // namespace

std::vector<io::BlockDoc> SweepPlanSchema() {
  const std::string read_by = "drop_tests/sweep/sweep_plan_file.cpp";
  return {io::MakeBlock("sweep", read_by, io::DocsOf(SweepKeys())),
          io::MakeBlock("sweep.lander", read_by, io::DocsOf(LanderBlockKeys())),
          io::MakeBlock("sweep.simulation", read_by, io::DocsOf(SimulationBlockKeys())),
          io::MakeBlock("sweep.grid.range", read_by, io::PlainKeyDocs(kGridRangeKeys)),
          io::MakeBlock("sweep.random.draw", read_by, io::DocsOf(RandomSpecKeys()))};
}

SweepPlan LoadSweepPlan(const std::string& path, const std::string& model_override) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly(io::Keys(SweepKeys()));
  // A stability study (docs/stability_studies.md) is a lander sweep whose `study` block says how
  // `touchdown stability` analyses its landings; the sweep itself ignores that block.
  const std::string type = f.String("type");
  if (type != "sweep" && type != "stability") f.Fail("type", "must be 'sweep' or 'stability', got '" + type + "'");
  if (type == "stability" && !f.Has("lander"))
    f.Fail("lander", "missing: a stability study lands a lander scenario (lander: {scenario: ...})");
  if (f.Has("study") && type != "stability") f.Fail("study", "only a stability study (type: stability) takes it");
  // The design limits of `touchdown trade` (trade.h); the sweep itself ignores them.
  if (f.Has("trade") && f.Has("lander")) f.Fail("trade", "trade limits are for single-pad sweeps, not a lander sweep");
  const std::string base = fs::path(path).parent_path().string();
  SweepPlan plan;
  plan.source = path;
  plan.name = f.Name("name", fs::path(path).stem().string());
  if (f.Has("lander")) ReadLanderBlock(f, base, plan);
  ReadRunOptions(f, plan);

  // The model first: the soils are loaded through it.
  std::string model_path;
  if (f.Has("model")) {
    if (!model_override.empty()) f.Fail("model", "given both here and with --model; keep one");
    model_path = f.String("model");
    if (fs::path(model_path).is_relative()) model_path = (fs::path(base) / model_path).lexically_normal().string();
  } else {
    model_path = model_override;
  }
  if (!model_path.empty()) plan.model = model::LoadModelFile(model_path);

  Loader loader(plan, base);
  ParamClaims claims(plan.lander.has_value());
  if (f.Has("fixed")) ReadFixed(f.Child("fixed"), claims, loader, plan);
  if (f.Has("grid")) ReadGrid(f.Child("grid"), claims, loader, plan);
  if (f.Has("random")) ReadRandom(f.Child("random"), claims, loader, plan);
  if (!plan.lander)
    for (SweepParam required : {SweepParam::kPad, SweepParam::kSoil, SweepParam::kImpactSpeed})
      if (!claims.Seen(required))
        f.Fail(SweepParamKey(required), "not set in fixed, grid or random");
  ReadSimulation(f, plan);
  // Counted in floating point first: the int64 product could overflow.
  double drops = static_cast<double>(plan.samples);
  for (const SweepAxis& a : plan.grid) drops *= static_cast<double>(a.values.size());
  if (!(drops <= static_cast<double>(kMaxSweepDrops)) || plan.size() <= 0)
    f.Fail("grid", "the sweep has too many drops (" + io::FormatNumber(drops) + ", at most 2^40)");
  if (plan.lander && plan.lander->ground.soil_field && claims.Seen(SweepParam::kPadSoils))
    f.Fail("lander", "the scenario's ground.soil_field and pad_soils both set the soil under the pads; keep one");
  if (plan.model)
    for (rft::SoilParameters& soil : plan.soils) soil = model::ApplyModel(*plan.model, soil);

  // A lander sweep checks its model against the scenario's soils now, not drop by drop.
  const model::ModelFile* model = plan.model ? &*plan.model : nullptr;
  if (plan.lander) {
    plan.lander->model = plan.model;
    try {
      // Every soil the landings can stand on (the scenario's own and the sweep's), under the model,
      // as a landing's setup builds its contact (scenario::ResolveLander), without building one.
      for (const auto& [ref, soil] : scenario::LoadLanderSoils(*plan.lander, plan.soil_refs))
        model::MakeContactModel({.law = plan.lander->ground.law, .soil = soil,
                                 .gravity_m_s2 = plan.lander->gravity_m_s2, .model = model,
                                 .pad_surface = &plan.lander->lander.pad.body.surface});
    } catch (const InputError& e) {
      f.Fail("lander", e.what());
    }
    // A pad design the study varies must fit the lander (its mass and joint height place the legs).
    for (const io::PadSpec& pad : plan.pads) {
      try {
        scenario::LanderSpecWithPad(plan.lander->lander, pad);
      } catch (const InputError& e) {
        f.Fail("pad", e.what());
      }
    }
  }
  return plan;
}


}  // namespace touchdown::sweep

