#include "drop_tests/targets/targets_file.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/yaml_fields.h"
#include "drop_tests/scenario/campaign.h"
#include "drop_tests/scenario/lander_scenario_file.h"
#include "drop_tests/targets/object_edit.h"
#include "rft/gravity_constants.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace fs = std::filesystem;

namespace touchdown::targets {

namespace {
// A targets file's keys, block by block (docs/calibration_targets.md; docs/reference.md).
// A scenario's numbers (a rig drop's, a campaign row's).
const io::NumberKey kScenarioSpeed{"speed_m_s", io::Sign::kPositive};
const io::NumberKey kScenarioGravity{"gravity_m_s2", io::Sign::kPositive, nullptr, nullptr, rft::kEarthGravity_m_s2};
const std::vector<std::string> kTargetsKeys{"schema_version", "type", "name", "description", "parameters", "targets",
                                            "fit", "provenance"};
const std::vector<std::string> kParameterKeys{"name", "soil", "pad", "lander", "field", "lower", "upper", "start",
                                              "source", "prior"};
const std::vector<std::string> kPriorKeys{"value", "sd", "source"};
const std::vector<std::string> kTargetKeys{"name", "drop", "campaign", "lander", "quantity", "pad", "ratio", "value",
                                           "at_most", "at_least", "uncertainty", "use", "source"};
const std::vector<std::string> kRatioKeys{"numerator", "denominator"};
const std::vector<std::string> kDropKeys{"pad", "soil", "speed_m_s", "gravity_m_s2"};
const std::vector<std::string> kCampaignRowKeys{"file", "pad", "soil", "speed_m_s"};
const std::vector<std::string> kFitKeys{"relative_step", "max_iterations", "confidence"};
struct QuantityEntry {
  Quantity quantity;
  const char* name;
  bool lander;
  bool signed_value;  // roll and pitch take either sign; the others are magnitudes (>= 0)
  double largest;     // the largest magnitude a value may have (rft/physical_limits.h where it has one)
  const char* unit;
};
// Ratios of two quantities, and the pads' depth spread, are dimensionless.
constexpr double kLargestRatio = 1e6;
constexpr QuantityEntry kQuantities[] = {
    {Quantity::kFinalPenetration, "final_penetration_m", false, false, limits::kDepth_m.high, "m"},
    {Quantity::kPeakForce, "peak_force_N", false, false, limits::kForce_N.high, "N"},
    {Quantity::kTimeToRest, "time_to_rest_s", false, false, limits::kMaxLanderDuration_s, "s"},
    {Quantity::kFinalRoll, "final_roll_deg", true, true, 180.0, "deg"},
    {Quantity::kFinalPitch, "final_pitch_deg", true, true, 180.0, "deg"},
    {Quantity::kMaxTilt, "max_tilt_deg", true, false, 180.0, "deg"},
    {Quantity::kPadDepth, "pad_depth_m", true, false, limits::kDepth_m.high, "m"},
    {Quantity::kPadDepthSpread, "pad_depth_spread", true, false, kLargestRatio, "(dimensionless)"},
};
// An uncertainty divides its target's residual: below this share of the largest value its
// residuals and their squares leave the doubles (1e-320 is denormal; 1/1e-320 overflows).
constexpr double kSmallestUncertaintyShare = 1e-12;

const QuantityEntry& EntryOf(Quantity q) {
  for (const QuantityEntry& e : kQuantities)
    if (e.quantity == q) return e;
  throw std::logic_error("a quantity without an entry in kQuantities");
}

std::string Number(double v);

// A target on a magnitude, or on a ratio of two, that is negative can never be met: refused
// rather than fitted towards (a sign slip in a ratio otherwise drives the fit to a bound).
void RequireReachableSign(const io::YamlFields& t, const Target& out) {
  const QuantityEntry& q = EntryOf(out.measure.quantity);
  if (q.signed_value || (out.denominator && EntryOf(out.denominator->quantity).signed_value)) return;
  const std::string what = out.denominator ? "a ratio of " + std::string(q.name) + " to " +
                                                 EntryOf(out.denominator->quantity).name
                                           : std::string(q.name);
  const std::pair<const char*, const std::optional<double>*> given[] = {
      {"value", &out.value}, {"at_most", &out.at_most}, {"at_least", &out.at_least}};
  for (const auto& [key, v] : given)
    if (*v && **v < 0.0)
      t.Fail(key, "must be at least 0 (" + what + " is never negative), got " + Number(**v));
}

std::string KnownQuantities(bool lander) {
  std::string s;
  for (const QuantityEntry& q : kQuantities)
    if (q.lander == lander) s += (s.empty() ? "" : ", ") + std::string(q.name);
  return s;
}

std::string Number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

// A file a targets file names: beside the targets file when a relative path is found there, else
// as the catalogue resolves it (a bundled name, or a path from the working directory).
std::string ResolveNear(const io::YamlFields& f, const std::string& kind, const std::string& key) {
  try {
    return io::ResolveCatalogFileNear(f.file(), kind, f.String(key));
  } catch (const InputError& e) {
    f.Fail(key, e.what());
  }
}

void ReadBounds(const io::YamlFields& p, Parameter& out) {
  out.lower = p.Number("lower");
  out.upper = p.Number("upper");
  out.start = p.Number("start");
  if (!(out.lower < out.upper))
    p.Fail("upper", "must exceed lower (" + Number(out.lower) + "), got " + Number(out.upper));
  // The fit works on (x - lower) / (upper - lower): a range that overflows has no such scale.
  if (!std::isfinite(out.upper - out.lower))
    p.Fail("upper", "upper - lower must be a finite number (at most 1.8e308), got [" + Number(out.lower) + ", " +
                        Number(out.upper) + "]");
  if (out.start < out.lower || out.start > out.upper)
    p.Fail("start", "must lie within [lower, upper] = [" + Number(out.lower) + ", " + Number(out.upper) + "], got " +
                        Number(out.start));
}

ParameterPrior ReadPrior(const io::YamlFields& m, const Parameter& p) {
  m.RequireOnly(kPriorKeys);
  ParameterPrior out{m.Number("value"), m.Number("sd"), m.String("source")};
  if (out.value < p.lower || out.value > p.upper)
    m.Fail("value", "must lie within [lower, upper] = [" + Number(p.lower) + ", " + Number(p.upper) + "], got " +
                        Number(out.value));
  if (!(out.sd > 0.0) || !std::isfinite(out.sd)) m.Fail("sd", "must be a positive finite number, got " + Number(out.sd));
  return out;
}

Parameter ReadParameter(const io::YamlFields& p) {
  p.RequireOnly(kParameterKeys);
  Parameter out;
  out.name = p.Name("name");
  out.source = p.String("source");
  out.field = p.String("field");
  const int given = int(p.Has("soil")) + int(p.Has("pad")) + int(p.Has("lander"));
  if (given != 1) p.Fail("soil", "give exactly one of soil, pad, lander (what the parameter changes)");
  ReadBounds(p, out);
  if (p.Has("soil")) {
    out.object = p.String("soil");
    out.file = ResolveNear(p, "soils", "soil");
    const std::string bekker_prefix = "bekker.";
    if (out.field.rfind(bekker_prefix, 0) == 0) {
      out.bekker = model::FindBekkerOverrideField(out.field.substr(bekker_prefix.size()));
      if (!out.bekker)
        p.Fail("field", "a Bekker soil parameter is bekker.n, bekker.k_c_kN_m_n1 or bekker.k_phi_kN_m_n2, got '" + out.field + "'");
      out.kind = ParameterKind::kSoilBekker;
    } else if (out.field == "zeta_N_cm3" || out.field == "dynamic_lambda") {
      out.kind = out.field == "zeta_N_cm3" ? ParameterKind::kSoilZeta : ParameterKind::kSoilDynamicLambda;
    } else {
      p.Fail("field", "a soil parameter is zeta_N_cm3, dynamic_lambda or bekker.n, bekker.k_c_kN_m_n1, "
                      "bekker.k_phi_kN_m_n2, got '" + out.field + "'");
    }
    rft::SoilParameters soil;
    try {
      soil = io::LoadSoil(out.file);
    } catch (const InputError& e) {
      p.Fail("soil", e.what());
    }
    out.soil_name = soil.name;
    out.soil_reference_gravity_m_s2 = soil.reference_gravity_m_s2;
    // A lambda that no drop uses would be fitted to nothing: its interval would be the prior's.
    if (out.kind == ParameterKind::kSoilDynamicLambda && !soil.dynamic_term)
      p.Fail("field", "dynamic_lambda of soil '" + soil.name + "' acts only with its dynamic term on (dynamic_term: true in " +
                          out.file + ")");
    // The fitted lambda goes to a model file beside the soil's zeta, which a model file requires.
    if (out.kind == ParameterKind::kSoilDynamicLambda && !(soil.zeta_N_m3 > 0.0))
      p.Fail("field", "dynamic_lambda of soil '" + soil.name + "' needs the soil's zeta_N_cm3 (a bekker soil without one "
                          "has no model-file override to carry it)");
    // A Bekker field of a soil that runs on another law would be fitted to nothing.
    if (out.kind == ParameterKind::kSoilBekker && soil.rft_law_3d != rft::LawKind::kBekker)
      p.Fail("field", out.field + " of soil '" + soil.name + "' acts only on a soil whose law is bekker (law: bekker in " +
                          out.file + ")");
    // Every value between the bounds is simulated: both must be values a soil file may hold.
    const limits::Range& range = out.kind == ParameterKind::kSoilZeta    ? limits::kZeta_N_cm3
                                 : out.kind == ParameterKind::kSoilBekker ? *out.bekker->range
                                                                          : limits::kDynamicLambda;
    const std::string what = out.kind == ParameterKind::kSoilZeta ? "zeta " : out.field + " ";
    for (const char* bound : {"lower", "upper"}) {
      const double v = std::string(bound) == "lower" ? out.lower : out.upper;
      if (!limits::Within(range, v)) p.Fail(bound, what + limits::Describe(range, v));
    }
  } else {
    const bool pad = p.Has("pad");
    out.kind = pad ? ParameterKind::kPadField : ParameterKind::kLanderField;
    out.object = p.String(pad ? "pad" : "lander");
    out.file = Canonical(ResolveNear(p, pad ? "pads" : "landers", pad ? "pad" : "lander"));
    CheckEditable(out, p);  // the field exists, and the file loads at lower, start and upper
  }
  if (p.Has("prior")) out.prior = ReadPrior(p.Child("prior"), out);
  return out;
}

Quantity ReadQuantity(const io::YamlFields& m, bool lander) {
  const std::string name = m.String("quantity");
  for (const QuantityEntry& q : kQuantities)
    if (name == q.name) {
      if (q.lander != lander)
        m.Fail("quantity", "'" + name + "' is not a quantity of a " + (lander ? "lander" : "drop") + " (" +
                               KnownQuantities(lander) + ")");
      return q.quantity;
    }
  m.Fail("quantity", "unknown quantity '" + name + "' (drops: " + KnownQuantities(false) +
                         "; landers: " + KnownQuantities(true) + ")");
}
}  // namespace

std::string Canonical(const std::string& path) { return fs::weakly_canonical(path).string(); }

const char* QuantityName(Quantity q) {
  for (const QuantityEntry& e : kQuantities)
    if (e.quantity == q) return e.name;
  return "?";
}

bool IsLanderQuantity(Quantity q) {
  for (const QuantityEntry& e : kQuantities)
    if (e.quantity == q) return e.lander;
  return false;
}

std::string Parameter::Address() const {
  switch (kind) {
    case ParameterKind::kSoilZeta:
    case ParameterKind::kSoilDynamicLambda:
    case ParameterKind::kSoilBekker: return "soil " + object + ": " + field;
    case ParameterKind::kPadField: return "pad " + object + ": " + field;
    case ParameterKind::kLanderField: return "lander " + object + ": " + field;
  }
  return "";
}

namespace {
// Reads the scenarios of the targets, each distinct one once (keyed by what it runs).
class ScenarioReader {
 public:
  explicit ScenarioReader(std::vector<ScenarioRun>& runs) : runs_(runs) {}

  Measure ReadMeasure(const io::YamlFields& m) {
    const int given = int(m.Has("drop")) + int(m.Has("campaign")) + int(m.Has("lander"));
    if (given != 1) m.Fail("drop", "give exactly one of drop, campaign, lander (the scenario)");
    Measure out;
    if (m.Has("lander")) {
      out.scenario = Lander(m);
      out.quantity = ReadQuantity(m, true);
      if (out.quantity == Quantity::kPadDepth) {
        out.pad = m.PositiveInt("pad");
        if (out.pad > lander::kNumLegs) m.Fail("pad", "must be 1..4, got " + std::to_string(out.pad));
      } else if (m.Has("pad")) {
        m.Fail("pad", "only pad_depth_m names a pad");
      }
      return out;
    }
    out.scenario = m.Has("drop") ? Drop(m.Child("drop")) : CampaignRow(m.Child("campaign"));
    out.quantity = ReadQuantity(m, false);
    if (m.Has("pad")) m.Fail("pad", "only a lander's pad_depth_m names a pad");
    return out;
  }

 private:
  size_t Add(const std::string& key, ScenarioRun run) {
    const auto [it, fresh] = index_.emplace(key, runs_.size());
    if (fresh) runs_.push_back(std::move(run));
    return it->second;
  }

  std::shared_ptr<const io::PadSpec> Pad(const std::string& file) {
    auto& pad = pads_[file];
    if (!pad) pad = std::make_shared<const io::PadSpec>(io::LoadPad(file));
    return pad;
  }

  size_t Drop(const io::YamlFields& d) {
    d.RequireOnly(kDropKeys);
    ScenarioRun run;
    run.kind = ScenarioRun::Kind::kDrop;
    const std::string pad_file = Canonical(ResolveNear(d, "pads", "pad"));
    const std::string soil_file = Canonical(ResolveNear(d, "soils", "soil"));
    run.pad = Pad(pad_file);
    run.soil = io::LoadSoil(soil_file);
    drop::DropRow row;
    row.impact_speed_m_s = io::ReadNumber(d, kScenarioSpeed);
    row.gravity_m_s2 = io::ReadNumberOr(d, kScenarioGravity, rft::kEarthGravity_m_s2);
    run.conditions = drop::DropConditionsFor(row, {}, "", d.file() + ": " + d.prefix());
    run.label = "drop " + run.pad->name + " on " + run.soil.name + " at " + Number(row.impact_speed_m_s) + " m/s, g " +
                Number(row.gravity_m_s2);
    return Add("drop|" + pad_file + "|" + soil_file + "|" + Number(row.impact_speed_m_s) + "|" +
                   Number(row.gravity_m_s2),
               std::move(run));
  }

  size_t CampaignRow(const io::YamlFields& c) {
    c.RequireOnly(kCampaignRowKeys);
    const std::string file = Canonical(ResolveNear(c, "scenarios", "file"));
    auto& campaign = campaigns_[file];
    if (!campaign) {
      try {
        campaign = std::make_shared<scenario::CampaignScenario>(scenario::LoadCampaignScenario(file));
      } catch (const InputError& e) {
        c.Fail("file", e.what());
      }
    }
    const std::string pad = c.String("pad"), soil = c.String("soil");
    const double speed = io::ReadNumber(c, kScenarioSpeed);
    for (size_t i = 0; i < campaign->cases.size(); ++i) {
      const scenario::CampaignCase& k = campaign->cases[i];
      if (k.pad->name != pad || k.soil.name != soil || std::abs(k.conditions.impact_speed_m_s - speed) > 1e-12) continue;
      ScenarioRun run;
      run.kind = ScenarioRun::Kind::kCampaign;
      run.pad = k.pad;
      run.soil = k.soil;
      run.conditions = k.conditions;
      run.label = "campaign " + campaign->name + " row " + k.drop_id;
      return Add("campaign|" + file + "|" + k.drop_id, std::move(run));
    }
    c.Fail("pad", "campaign " + file + " has no row with pad '" + pad + "', soil '" + soil + "' and speed " +
                      Number(speed) + " m/s");
  }

  size_t Lander(const io::YamlFields& m) {
    const std::string file = Canonical(ResolveNear(m, "scenarios", "lander"));
    ScenarioRun run;
    run.kind = ScenarioRun::Kind::kLander;
    try {
      run.lander = std::make_shared<const scenario::LanderScenario>(scenario::LoadLanderScenario(file));
    } catch (const InputError& e) {
      m.Fail("lander", e.what());
    }
    run.label = "lander " + run.lander->name;
    return Add("lander|" + file, std::move(run));
  }

  std::vector<ScenarioRun>& runs_;
  std::map<std::string, size_t> index_;
  std::map<std::string, std::shared_ptr<const io::PadSpec>> pads_;
  std::map<std::string, std::shared_ptr<scenario::CampaignScenario>> campaigns_;
};

Target ReadTarget(const io::YamlFields& t, ScenarioReader& reader) {
  t.RequireOnly(kTargetKeys);
  Target out;
  out.name = t.Name("name");
  out.source = t.String("source");
  if (t.Has("ratio")) {
    for (const char* k : {"drop", "campaign", "lander", "quantity", "pad"})
      if (t.Has(k)) t.Fail(k, "a ratio target gives its scenarios in ratio.numerator and ratio.denominator");
    const io::YamlFields r = t.Child("ratio");
    r.RequireOnly(kRatioKeys);
    out.measure = reader.ReadMeasure(r.Child("numerator"));
    out.denominator = reader.ReadMeasure(r.Child("denominator"));
  } else {
    out.measure = reader.ReadMeasure(t);
  }
  if (t.Has("value")) out.value = t.Number("value");
  if (t.Has("at_most")) out.at_most = t.Number("at_most");
  if (t.Has("at_least")) out.at_least = t.Number("at_least");
  if (out.value && (out.at_most || out.at_least)) t.Fail("value", "give a value or bounds (at_most, at_least), not both");
  if (!out.value && !out.at_most && !out.at_least) t.Fail("value", "missing (a value, or at_most and/or at_least)");
  if (out.at_most && out.at_least && !(*out.at_least < *out.at_most))
    t.Fail("at_most", "must exceed at_least (" + Number(*out.at_least) + "), got " + Number(*out.at_most));
  RequireReachableSign(t, out);
  // Every number within what the quantity can be, so that residuals and the fit's cost stay finite
  // (a value of 1e308 made the cost infinite and the fit "fail" with exit 0).
  const QuantityEntry& entry = EntryOf(out.measure.quantity);
  const double largest = out.denominator ? kLargestRatio : entry.largest;
  const char* unit = out.denominator ? "(dimensionless)" : entry.unit;
  const limits::Range values{unit, -largest, largest, false};
  for (const char* key : {"value", "at_most", "at_least"})
    if (t.Has(key)) limits::Require(values, t.Number(key), t.file(), t.Path(key));
  out.uncertainty = t.Positive("uncertainty");
  limits::Require({unit, kSmallestUncertaintyShare * largest, largest, false}, out.uncertainty, t.file(),
                  t.Path("uncertainty"));
  const std::string use = t.String("use");
  if (use != "fit" && use != "predict") t.Fail("use", "must be 'fit' or 'predict', got '" + use + "'");
  out.fit = use == "fit";
  return out;
}

void ReadSettings(const io::YamlFields& f, FitSettings& s) {
  f.RequireOnly(kFitKeys);
  if (f.Has("relative_step")) s.relative_step = f.Positive("relative_step");
  if (s.relative_step > 0.1) f.Fail("relative_step", "must be at most 0.1, got " + Number(s.relative_step));
  if (f.Has("max_iterations")) s.max_iterations = f.PositiveInt("max_iterations");
  if (f.Has("confidence")) s.confidence = f.Positive("confidence");
  if (s.confidence < 0.5 || s.confidence >= 1.0) f.Fail("confidence", "must be in [0.5, 1), got " + Number(s.confidence));
}

void CheckUnique(const io::YamlFields& f, const std::vector<std::string>& names, const char* list) {
  std::set<std::string> seen;
  for (size_t i = 0; i < names.size(); ++i)
    if (!seen.insert(names[i]).second)
      f.Fail(std::string(list) + "[" + std::to_string(i) + "].name", "'" + names[i] + "' is given twice");
}
// Two parameters may not free the same field of the same file (`addresses`: file and field, one
// per parameter); the message names both as the user wrote them.
void CheckSameFieldOnce(const io::YamlFields& f, const std::vector<Parameter>& parameters,
                        const std::vector<std::string>& addresses) {
  std::map<std::string, size_t> seen;
  for (size_t i = 0; i < addresses.size(); ++i) {
    const auto [it, inserted] = seen.emplace(addresses[i], i);
    if (!inserted)
      f.Fail("parameters[" + std::to_string(i) + "]",
             "'" + parameters[i].name + "' frees " + parameters[i].Address() + ", which parameters[" +
                 std::to_string(it->second) + "] ('" + parameters[it->second].name + "') frees already");
  }
}
}  // namespace

std::vector<io::BlockDoc> TargetsFileSchema() {
  const std::string read_by = "drop_tests/targets/targets_file.cpp";
  // The fit's settings take FitSettings' defaults.
  const FitSettings defaults;
  std::vector<io::KeyDoc> fit = io::PlainKeyDocs(kFitKeys);
  fit[0].default_value = Number(defaults.relative_step);
  fit[1].default_value = std::to_string(defaults.max_iterations);
  fit[2].default_value = Number(defaults.confidence);
  return {io::MakeBlock("targets", read_by, io::PlainKeyDocs(kTargetsKeys)),
          io::MakeBlock("targets.parameters", read_by, io::PlainKeyDocs(kParameterKeys)),
          io::MakeBlock("targets.parameters.prior", read_by, io::PlainKeyDocs(kPriorKeys)),
          io::MakeBlock("targets.targets", read_by, io::PlainKeyDocs(kTargetKeys)),
          io::MakeBlock("targets.targets.ratio", read_by, io::PlainKeyDocs(kRatioKeys)),
          io::MakeBlock("targets.targets.drop", read_by, io::DocsWith(kDropKeys, {kScenarioSpeed, kScenarioGravity})),
          io::MakeBlock("targets.targets.campaign", read_by, io::DocsWith(kCampaignRowKeys, {kScenarioSpeed})),
          io::MakeBlock("targets.fit", read_by, fit)};
}

TargetsFile LoadTargetsFile(const std::string& path) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly(kTargetsKeys);
  if (f.String("type") != "targets") f.Fail("type", "must be 'targets', got '" + f.String("type") + "'");
  TargetsFile out;
  out.source = path;
  out.name = f.Name("name", fs::path(path).stem().string());
  out.description = f.StringOr("description", "");
  if (f.Has("fit")) ReadSettings(f.Child("fit"), out.settings);
  std::vector<std::string> names, addresses;
  if (f.Has("parameters"))
    for (const io::YamlFields& p : f.List("parameters")) {
      out.parameters.push_back(ReadParameter(p));
      names.push_back(out.parameters.back().name);
      addresses.push_back(out.parameters.back().file + "|" + out.parameters.back().field);
    }
  CheckUnique(f, names, "parameters");
  CheckSameFieldOnce(f, out.parameters, addresses);
  ScenarioReader reader(out.scenarios);
  names.clear();
  for (const io::YamlFields& t : f.List("targets")) {
    out.targets.push_back(ReadTarget(t, reader));
    names.push_back(out.targets.back().name);
  }
  CheckUnique(f, names, "targets");
  for (size_t i = 0; i < out.parameters.size(); ++i)
    if (!ChangesAnyScenario(out.parameters[i], out.scenarios))
      f.Fail("parameters[" + std::to_string(i) + "]", "'" + out.parameters[i].Address() +
                                                           "' changes none of the targets' scenarios");
  return out;
}

std::string Target::Describe(const std::vector<ScenarioRun>& scenarios) const {
  auto one = [&](const Measure& m) {
    std::string s = std::string(QuantityName(m.quantity));
    if (m.quantity == Quantity::kPadDepth) s += " of pad " + std::to_string(m.pad);
    return s + " (" + scenarios[m.scenario].label + ")";
  };
  return denominator ? one(measure) + " / " + one(*denominator) : one(measure);
}

}  // namespace touchdown::targets
