#include "drop_tests/scenario/campaign.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/scenario/campaign_plots.h"
#include "drop_tests/formats/field_table.h"
#include "drop_tests/formats/key_table.h"
#include "drop_tests/catalog/paths_in_outputs.h"
#include "drop_tests/formats/yaml_fields.h"
#include "rft/gravity_constants.h"
#include "rft/input_error.h"
#include "rft/units.h"

namespace touchdown::scenario {

namespace fs = std::filesystem;

namespace {
// "1.00" for the speeds a campaign usually lists; a speed that two decimals would round (1.004)
// keeps its shortest exact form, so two different speeds never share a drop id.
std::string SpeedTag(double v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << v;
  if (std::stod(s.str()) == v) return s.str();
  std::ostringstream exact;
  exact << std::setprecision(17) << v;
  std::string shortest = exact.str();
  for (int digits = 1; digits <= 17; ++digits) {  // the fewest digits that read back as v
    std::ostringstream t;
    t << std::setprecision(digits) << v;
    if (std::stod(t.str()) == v) {
      shortest = t.str();
      break;
    }
  }
  return shortest;
}

// Pads and soils are loaded once per name; an error names the scenario field that used it.
template <typename T, typename Loader>
const T& Cached(std::map<std::string, T>& cache, const std::string& name, const io::YamlFields& f,
                const std::string& key, Loader load) {
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  try {
    return cache.emplace(name, load(name)).first->second;
  } catch (const InputError& e) {
    f.Fail(key, e.what());
  }
}

// A paper check's numbers and its `paper` figures (0 when the paper gives none: left out), read
// from a scenario and written into its resolved copy from the same tables.
const io::FieldTable<PaperCheck>& CheckFields() {
  static const io::FieldTable<PaperCheck> fields{
      {"speed_m_s", &PaperCheck::speed_m_s, 1.0, io::Sign::kPositive, false, false}};
  return fields;
}
const io::FieldTable<PaperCheck>& PaperFigureFields() {
  static const io::FieldTable<PaperCheck> fields{
      {"experiment", &PaperCheck::paper_experiment, 1.0, io::Sign::kPositive, true, true, nullptr, "none"},
      {"rft", &PaperCheck::paper_rft, 1.0, io::Sign::kPositive, true, true, nullptr, "none"}};
  return fields;
}

// A check's `numerator` and `denominator`: a pad and a soil by name.
struct PadSoil {
  const std::string& pad;
  const std::string& soil;
};
const io::KeyTable<PadSoil>& PadSoilKeys() {
  using Y = YAML::Emitter;
  static const io::KeyTable<PadSoil> keys{
      {"pad", io::Always<PadSoil>, [](Y& y, const PadSoil& p) { y << p.pad; }},
      {"soil", io::Always<PadSoil>, [](Y& y, const PadSoil& p) { y << p.soil; }},
  };
  return keys;
}
void WritePadSoil(YAML::Emitter& y, const PadSoil& p) {
  io::WriteMap(y, PadSoilKeys(), p, YAML::Flow);
}

// A paper check's keys, in the order a resolved copy writes them.
const io::KeyTable<PaperCheck>& CheckKeys() {
  using C = PaperCheck;
  using Y = YAML::Emitter;
  static const io::KeyTable<C> keys = [] {
    io::KeyTable<C> k{
        {"name", io::Always<C>, [](Y& y, const C& c) { y << c.name; }},
        {"quantity", io::Always<C>, [](Y& y, const C& c) { y << c.quantity; }},
        {"numerator", io::Always<C>, [](Y& y, const C& c) { WritePadSoil(y, {c.numerator_pad, c.numerator_soil}); }},
        {"denominator", io::Always<C>,
         [](Y& y, const C& c) { WritePadSoil(y, {c.denominator_pad, c.denominator_soil}); }},
    };
    io::AppendNumberKeys(k, CheckFields());
    k.push_back({"paper", [](const C& c) { return c.paper_experiment > 0 || c.paper_rft > 0; },
                 [](Y& y, const C& c) {
                   y << YAML::Flow << YAML::BeginMap;
                   io::WriteFields(y, PaperFigureFields(), c);
                   y << YAML::EndMap;
                 }});
    k.push_back({"source", [](const C& c) { return !c.source.empty(); }, [](Y& y, const C& c) { y << c.source; }});
    k.push_back({"used_for_fit", [](const C& c) { return c.used_for_fit; }, [](Y& y, const C&) { y << true; }});
    k.push_back({"fit_by", [](const C& c) { return c.used_for_fit; }, [](Y& y, const C& c) { y << c.fit_by; }});
    k.push_back({"reading", [](const C& c) { return c.reading.has_value(); },
                 [](Y& y, const C& c) { y << std::string(PaperReadingName(*c.reading)); }});
    return k;
  }();
  return keys;
}

PaperCheck ReadCheck(const io::YamlFields& f) {
  f.RequireOnly(io::Keys(CheckKeys()));
  PaperCheck c;
  c.name = f.Name("name");
  c.quantity = f.String("quantity");
  if (c.quantity != "final_penetration_m" && c.quantity != "peak_force_N")
    f.Fail("quantity", "must be final_penetration_m or peak_force_N, got '" + c.quantity + "'");
  const io::YamlFields num = f.Child("numerator"), den = f.Child("denominator");
  num.RequireOnly(io::Keys(PadSoilKeys()));
  den.RequireOnly(io::Keys(PadSoilKeys()));
  c.numerator_pad = num.String("pad");
  c.numerator_soil = num.String("soil");
  c.denominator_pad = den.String("pad");
  c.denominator_soil = den.String("soil");
  io::ReadFields(f, CheckFields(), c);
  if (f.Has("paper")) {
    const io::YamlFields p = f.Child("paper");
    p.RequireOnly(io::FieldKeys(PaperFigureFields()));
    io::ReadFields(p, PaperFigureFields(), c);
  }
  c.source = f.StringOr("source", "");
  if (f.Has("used_for_fit")) c.used_for_fit = f.Bool("used_for_fit");
  c.fit_by = f.StringOr("fit_by", "");
  if (c.used_for_fit && c.fit_by.empty()) f.Fail("fit_by", "missing (used_for_fit: true names the fit that used it)");
  if (!c.used_for_fit && !c.fit_by.empty()) f.Fail("fit_by", "only with used_for_fit: true");
  c.reading = ReadPaperReading(f);
  return c;
}

// What a resolved copy states about a case's pad and soil besides their files: derived from the
// files, written for its reader, and checked against the files when the copy is loaded (file
// units, as written).
struct PadSummary {
  double mass_kg = 0.0, radius_mm = 0.0, thickness_mm = 0.0, profile_points = 0.0;
};
PadSummary SummaryOf(const io::PadSpec& pad) {
  if (!pad.is_axisymmetric()) return {pad.mass_kg, 0.0, 0.0, 0.0};
  return {pad.mass_kg, pad.profile.radius_m() * units::kMmPerM, pad.profile.thickness_m() * units::kMmPerM,
          static_cast<double>(pad.profile.points.size())};
}
const io::FieldTable<PadSummary>& PadSummaryFields() {
  static const io::FieldTable<PadSummary> fields{
      {"mass_kg", &PadSummary::mass_kg, 1.0, io::Sign::kAny, false, false},
      {"radius_mm", &PadSummary::radius_mm, 1.0, io::Sign::kAny, false, false},
      {"thickness_mm", &PadSummary::thickness_mm, 1.0, io::Sign::kAny, false, false},
      {"profile_points", &PadSummary::profile_points, 1.0, io::Sign::kAny, false, false}};
  return fields;
}
const io::FieldTable<rft::SoilParameters>& SoilSummaryFields() {
  using S = rft::SoilParameters;
  static const io::FieldTable<S> fields{
      {"zeta_N_cm3", &S::zeta_N_m3, units::kN_m3_per_N_cm3, io::Sign::kAny, false, false},
      {"reference_gravity_m_s2", &S::reference_gravity_m_s2, 1.0, io::Sign::kAny, false, false}};
  return fields;
}

// The numbers of one case as run: the mass is the pad's when the scenario gives none, the zeta
// override 0 when there is none (then left out).
struct CaseNumbers {
  double impact_speed_m_s = 0.0, mass_kg = 0.0, gravity_m_s2 = 0.0, zeta_override_N_m3 = 0.0;
};
CaseNumbers NumbersOf(const CampaignCase& c) {
  return {c.conditions.impact_speed_m_s, c.conditions.mass_kg.value_or(c.pad->mass_kg), c.conditions.gravity_m_s2,
          c.conditions.zeta_N_m3.value_or(0.0)};
}
const io::FieldTable<CaseNumbers>& CaseFields() {
  static const io::FieldTable<CaseNumbers> fields{
      {"impact_speed_m_s", &CaseNumbers::impact_speed_m_s, 1.0, io::Sign::kNonNegative, false, false},
      {"mass_kg", &CaseNumbers::mass_kg, 1.0, io::Sign::kPositive, false, false},
      {"gravity_m_s2", &CaseNumbers::gravity_m_s2, 1.0, io::Sign::kPositive, false, false},
      {"zeta_override_N_cm3", &CaseNumbers::zeta_override_N_m3, units::kN_m3_per_N_cm3, io::Sign::kPositive, true,
       true}};
  return fields;
}

// One case of a resolved copy to write, with what it states besides its files.
struct CaseToWrite {
  const CampaignCase& c;
  PadSummary pad;
  CaseNumbers numbers;
  const std::string& dir;  // the folder the copy lives in (its files are written relative to it)
};

const io::KeyTable<CaseToWrite>& PadSummaryKeys() {
  using W = CaseToWrite;
  using Y = YAML::Emitter;
  static const io::KeyTable<W> keys = [] {
    io::KeyTable<W> k{
        {"name", io::Always<W>, [](Y& y, const W& w) { y << w.c.pad->name; }},
        {"file", io::Always<W>, [](Y& y, const W& w) { y << io::PathForOutput(w.c.pad->source, w.dir); }},
    };
    io::AppendNumberKeys<W, PadSummary>(k, PadSummaryFields(), [](const W& w) -> const PadSummary& { return w.pad; });
    return k;
  }();
  return keys;
}

const io::KeyTable<CaseToWrite>& SoilSummaryKeys() {
  using W = CaseToWrite;
  using Y = YAML::Emitter;
  static const io::KeyTable<W> keys = [] {
    io::KeyTable<W> k{
        {"name", io::Always<W>, [](Y& y, const W& w) { y << w.c.soil.name; }},
        {"file", io::Always<W>, [](Y& y, const W& w) { y << io::PathForOutput(w.c.soil_source, w.dir); }},
        {"atmosphere", io::Always<W>, [](Y& y, const W& w) { y << rft::AtmosphereName(w.c.soil.atmosphere); }},
    };
    io::AppendNumberKeys<W, rft::SoilParameters>(k, SoilSummaryFields(),
                                                 [](const W& w) -> const rft::SoilParameters& { return w.c.soil; });
    return k;
  }();
  return keys;
}

// A resolved copy's case (one entry of its `drops`).
const io::KeyTable<CaseToWrite>& CaseKeys() {
  using W = CaseToWrite;
  using Y = YAML::Emitter;
  static const io::KeyTable<W> keys = [] {
    io::KeyTable<W> k{
        {"drop_id", io::Always<W>, [](Y& y, const W& w) { y << w.c.drop_id; }},
        {"pad", io::Always<W>, io::MapOf(PadSummaryKeys)},
        {"soil", io::Always<W>, io::MapOf(SoilSummaryKeys)},
    };
    io::AppendNumberKeys<W, CaseNumbers>(k, CaseFields(), [](const W& w) -> const CaseNumbers& { return w.numbers; });
    return k;
  }();
  return keys;
}

// A campaign scenario's top-level keys (`source` only in a resolved copy, `gravity_m_s2` and
// `provenance` only in the user's: a resolved copy states each case's gravity).
struct CampaignToWrite {
  const CampaignScenario& s;
  const std::string& dir;
};
const io::KeyTable<CampaignToWrite>& CampaignKeys() {
  using W = CampaignToWrite;
  using Y = YAML::Emitter;
  static const io::KeyTable<W> keys{
      {"schema_version", io::Always<W>, [](Y& y, const W&) { y << 1; }},
      {"type", io::Always<W>, [](Y& y, const W&) { y << "campaign_resolved"; }},
      {"name", io::Always<W>, [](Y& y, const W& w) { y << w.s.name; }},
      {"description", [](const W& w) { return !w.s.description.empty(); }, [](Y& y, const W& w) { y << w.s.description; }},
      {"source", io::Always<W>, [](Y& y, const W& w) { y << io::PathForOutput(w.s.source, w.dir); }},
      {"gravity_m_s2"},
      {"reference_speed_m_s", io::Always<W>, [](Y& y, const W& w) { y << w.s.reference_speed_m_s; }},
      {"drops", io::Always<W>,
       [](Y& y, const W& w) {
         y << YAML::BeginSeq;
         for (const CampaignCase& c : w.s.cases) {
           io::WriteMap(y, CaseKeys(), CaseToWrite{c, SummaryOf(*c.pad), NumbersOf(c), w.dir});
         }
         y << YAML::EndSeq;
       }},
      {"model", [](const W& w) { return w.s.model.has_value(); },
       [](Y& y, const W& w) { y << io::PathForOutput(w.s.model_source, w.dir); }},
      {"paper_checks", [](const W& w) { return !w.s.checks.empty(); },
       [](Y& y, const W& w) {
         y << YAML::BeginSeq;
         for (const PaperCheck& c : w.s.checks) {
           io::WriteMap(y, CheckKeys(), c);
         }
         y << YAML::EndSeq;
       }},
      {"provenance"},
  };
  return keys;
}

const drop::PadDrop* FindDrop(const CampaignResult& r, const std::string& pad, const std::string& soil, double v) {
  for (const drop::PadDrop& d : r.drops)
    if (d.pad.name == pad && d.soil.name == soil && std::abs(d.conditions.impact_speed_m_s - v) < 1e-9) return &d;
  return nullptr;
}

double Quantity(const drop::PadDrop& d, const std::string& q) {
  return q == "peak_force_N" ? d.result.peak_force_N : d.result.final_penetration_m;
}

using PadCache = std::map<std::string, std::shared_ptr<const io::PadSpec>>;
using SoilCache = std::map<std::string, rft::SoilParameters>;

std::shared_ptr<const io::PadSpec> LoadSharedPad(const std::string& name) {
  return std::make_shared<const io::PadSpec>(io::LoadPad(name));
}

// Checked as every case is: its numbers in range at load time, its drop id unique.
void AddCase(CampaignScenario& s, std::set<std::string>& ids, const io::YamlFields& entry, const std::string& key,
             CampaignCase c) {
  drop::ValidateConditions(c.conditions, entry.file() + ": " + entry.prefix());
  if (!ids.insert(c.drop_id).second)
    entry.Fail(key, "impact speed " + SpeedTag(c.conditions.impact_speed_m_s) + " m/s of pad " + c.pad->name +
                        " on soil " + c.soil.name + " is listed twice (drop " + c.drop_id + ")");
  s.cases.push_back(std::move(c));
}

std::string DropId(const io::PadSpec& pad, const rft::SoilParameters& soil, double speed_m_s) {
  return pad.name + "_" + soil.name + "_v" + SpeedTag(speed_m_s);
}

// A scenario's numbers read on their own (each drop's are checked again as its conditions).
const io::NumberKey kCampaignGravity{"gravity_m_s2", io::Sign::kPositive, nullptr, nullptr, rft::kEarthGravity_m_s2};
const io::NumberKey kReferenceSpeed{"reference_speed_m_s", io::Sign::kPositive, nullptr, "the first drop's speed"};
const io::NumberKey kEntryGravity{"gravity_m_s2", io::Sign::kPositive, nullptr, "the campaign's"};
const io::NumberKey kEntryMass{"mass_kg", io::Sign::kPositive, nullptr, "the pad's `mass_kg`"};
const io::NumberKey kEntryZeta{"zeta_N_cm3", io::Sign::kPositive, nullptr, "the soil's"};

// A scenario's `drops` entry's keys: a pad and a soil by name or path, and its list of speeds.
const std::vector<std::string> kDropEntryKeys{"pad", "soil", "impact_speeds_m_s", "mass_kg", "zeta_N_cm3",
                                              "gravity_m_s2"};

// A scenario's `drops`: each entry a pad and a soil by name or path, and its list of speeds.
void ReadDropEntries(const io::YamlFields& f, CampaignScenario& s) {
  const double gravity = io::ReadNumberOr(f, kCampaignGravity, rft::kEarthGravity_m_s2);
  PadCache pads;
  SoilCache soils;
  std::set<std::string> ids;
  for (const io::YamlFields& entry : f.List("drops")) {
    entry.RequireOnly(kDropEntryKeys);
    const std::shared_ptr<const io::PadSpec>& pad = Cached(pads, entry.String("pad"), entry, "pad", LoadSharedPad);
    const rft::SoilParameters& soil = Cached(soils, entry.String("soil"), entry, "soil", io::LoadSoil);
    const std::string soil_source = io::ResolveCatalogFile("soils", entry.String("soil"));
    for (double v : entry.NumberList("impact_speeds_m_s", /*allow_zero=*/true)) {
      CampaignCase c{DropId(*pad, soil, v), pad, soil, soil_source, {}};
      c.conditions.impact_speed_m_s = v;
      c.conditions.gravity_m_s2 = io::ReadNumberOr(entry, kEntryGravity, gravity);
      if (entry.Has(kEntryMass.key)) c.conditions.mass_kg = io::ReadNumber(entry, kEntryMass);
      if (entry.Has(kEntryZeta.key)) c.conditions.zeta_N_m3 = units::ZetaFromN_cm3(io::ReadNumber(entry, kEntryZeta));
      AddCase(s, ids, entry, "impact_speeds_m_s", std::move(c));
    }
  }
}

// A resolved copy's `drops`: one entry a case, its pad and soil by file (as written into `dir`)
// with the values derived from them, which must still match the files.
void ReadResolvedCases(const io::YamlFields& f, const std::string& dir, CampaignScenario& s) {
  PadCache pads;
  SoilCache soils;
  std::set<std::string> ids;
  for (const io::YamlFields& entry : f.List("drops")) {
    entry.RequireOnly(io::Keys(CaseKeys()));
    const io::YamlFields pf = entry.Child("pad"), sf = entry.Child("soil");
    pf.RequireOnly(io::Keys(PadSummaryKeys()));
    sf.RequireOnly(io::Keys(SoilSummaryKeys()));
    const std::string pad_file = io::PathFromOutput(pf.String("file"), dir);
    const std::string soil_file = io::PathFromOutput(sf.String("file"), dir);
    const std::shared_ptr<const io::PadSpec>& pad = Cached(pads, pad_file, pf, "file", LoadSharedPad);
    const rft::SoilParameters& soil = Cached(soils, soil_file, sf, "file", io::LoadSoil);
    if (pf.String("name") != pad->name) pf.Fail("name", "is '" + pf.String("name") + "' but the pad file names '" + pad->name + "'");
    io::RequireFieldsMatch(pf, PadSummaryFields(), SummaryOf(*pad), "the pad file");
    if (sf.String("name") != soil.name) sf.Fail("name", "is '" + sf.String("name") + "' but the soil file names '" + soil.name + "'");
    const std::string atmosphere = rft::AtmosphereName(soil.atmosphere);
    if (sf.String("atmosphere") != atmosphere) sf.Fail("atmosphere", "differs from the soil file's '" + atmosphere + "'");
    io::RequireFieldsMatch(sf, SoilSummaryFields(), soil, "the soil file");
    CaseNumbers n;
    io::ReadFields(entry, CaseFields(), n);
    CampaignCase c{DropId(*pad, soil, n.impact_speed_m_s), pad, soil, soil_file, {}};
    if (entry.String("drop_id") != c.drop_id) entry.Fail("drop_id", "must be " + c.drop_id + " (pad_soil_vSPEED)");
    c.conditions.impact_speed_m_s = n.impact_speed_m_s;
    c.conditions.mass_kg = n.mass_kg;
    c.conditions.gravity_m_s2 = n.gravity_m_s2;
    if (n.zeta_override_N_m3 > 0.0) c.conditions.zeta_N_m3 = n.zeta_override_N_m3;
    AddCase(s, ids, entry, "impact_speed_m_s", std::move(c));
  }
}
}  // namespace

std::vector<io::BlockDoc> CampaignSchema() {
  const std::string read_by = "drop_tests/scenario/campaign.cpp";
  std::vector<io::KeyDoc> top = io::DocsOf(CampaignKeys(), {"source"});
  for (io::KeyDoc& k : top)
    for (const io::NumberKey& n : {kCampaignGravity, kReferenceSpeed})
      if (k.key == n.key) k = io::DocOf(n);
  return {io::MakeBlock("campaign", read_by, top),
          io::MakeBlock("campaign.drops", read_by,
                        io::DocsWith(kDropEntryKeys, {kEntryMass, kEntryZeta, kEntryGravity})),
          io::MakeBlock("campaign.paper_checks", read_by, io::DocsOf(CheckKeys())),
          io::MakeBlock("campaign.paper_checks.numerator", read_by, io::DocsOf(PadSoilKeys())),
          io::MakeBlock("campaign.paper_checks.paper", read_by, io::DocsOf(PaperFigureFields()))};
}

CampaignScenario LoadCampaignScenario(const std::string& path) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  const std::string type = f.StringOr("type", "campaign");
  if (type != "campaign" && type != "campaign_resolved") f.Fail("type", "must be 'campaign' or 'campaign_resolved'");
  const bool resolved = type == "campaign_resolved";
  f.RequireOnly(resolved ? io::Keys(CampaignKeys(), {"gravity_m_s2", "provenance"}) : io::Keys(CampaignKeys(), {"source"}));
  CampaignScenario s;
  const std::string dir = fs::path(path).parent_path().string();
  // A resolved copy names the scenario it was resolved from, and stands for it.
  s.source = resolved ? io::PathFromOutput(f.String("source"), dir) : path;
  s.name = f.Name("name", fs::path(path).stem().string());
  s.description = f.StringOr("description", "");
  if (resolved)
    ReadResolvedCases(f, dir, s);
  else
    ReadDropEntries(f, s);
  if (resolved)
    s.reference_speed_m_s = f.NonNegative("reference_speed_m_s");
  else
    s.reference_speed_m_s = io::ReadNumberOr(f, kReferenceSpeed, s.cases.front().conditions.impact_speed_m_s);
  if (f.Has("paper_checks"))
    for (const io::YamlFields& c : f.List("paper_checks")) s.checks.push_back(ReadCheck(c));
  if (f.Has("model")) {
    const fs::path given = f.String("model");
    const std::string model = resolved ? io::PathFromOutput(given.string(), dir)
                              : given.is_absolute() ? given.string() : (fs::path(dir) / given).string();
    try {
      SetCampaignModel(s, model);
    } catch (const InputError& e) {
      f.Fail("model", e.what());
    }
  }
  return s;
}

void SetCampaignModel(CampaignScenario& scenario, const std::string& model_path) {
  scenario.model = model::LoadModelFile(model_path);
  scenario.model_source = model_path;
}

void WriteResolvedScenario(const CampaignScenario& s, const std::string& path, const std::string& output_dir) {
  YAML::Emitter y;
  io::WriteMap(y, CampaignKeys(), CampaignToWrite{s, output_dir});
  io::WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

namespace {
// A case as it runs: with the scenario's model, as `drop --model` runs one drop.
drop::PadDrop RunCase(const CampaignScenario& s, const CampaignCase& c) {
  if (!s.model) return drop::RunDrop(drop::ResolveDrop(*c.pad, c.soil, c.conditions));
  drop::DropConditions conditions = c.conditions;
  conditions.effects = model::ModelEffectTerms(*s.model);
  conditions.effects_source = s.model_source;
  return drop::RunDrop(drop::ResolveDrop(*c.pad, model::ApplyModel(*s.model, c.soil), conditions));
}
}  // namespace

CampaignResult RunCampaign(const CampaignScenario& scenario) {
  CampaignResult result{scenario, {}};
  for (const CampaignCase& c : scenario.cases) result.drops.push_back(RunCase(scenario, c));
  return result;
}

std::vector<CheckOutcome> EvaluateChecks(const CampaignResult& r) {
  std::vector<CheckOutcome> out;
  for (const PaperCheck& c : r.scenario.checks) {
    const drop::PadDrop* num = FindDrop(r, c.numerator_pad, c.numerator_soil, c.speed_m_s);
    const drop::PadDrop* den = FindDrop(r, c.denominator_pad, c.denominator_soil, c.speed_m_s);
    if (!num || !den)
      throw MakeInputError(r.scenario.source, "paper_checks", "check '" + c.name + "' names a drop the campaign does not run");
    out.push_back({c, Quantity(*num, c.quantity) / Quantity(*den, c.quantity)});
  }
  return out;
}

namespace {
// Everything but the traces (traces/ already written): summary.csv and .json, the resolved
// scenario and the plots, from the drops' summaries.
void WriteCampaignSummaries(const CampaignResult& r, const fs::path& staging, const std::string& out_dir) {
  nlohmann::json drops = nlohmann::json::array();
  for (size_t i = 0; i < r.drops.size(); ++i) {
    const std::string id = r.scenario.cases[i].drop_id;
    nlohmann::json j = drop::SummaryJson(r.drops[i]);
    j["drop_id"] = id;
    j["trace"] = "traces/" + id + ".csv";
    drops.push_back(j);
  }
  // summary.csv uses the dataset column names, so a campaign reads as a simulated dataset: each
  // column is the drop summary's value of that name (drop::SummaryJson, from the drop's record table).
  static const std::vector<std::string> kColumns = {
      "drop_id",        "pad",          "soil",  "atmosphere",          "impact_speed_m_s", "pad_mass_kg",
      "gravity_m_s2",   "trace",        "final_penetration_m", "peak_force_N", "time_to_rest_s",
      "max_deceleration_m_s2", "impact_energy_J", "dissipated_energy_J", "mean_conversion_rate_W", "zeta_N_cm3"};
  io::WriteFileAtomically((staging / "summary.csv").string(), [&](std::ostream& out) {
    for (size_t c = 0; c < kColumns.size(); ++c) out << (c ? "," : "") << kColumns[c];
    out << '\n' << std::setprecision(10);
    for (const nlohmann::json& j : drops) {
      for (size_t c = 0; c < kColumns.size(); ++c) {
        const nlohmann::json& v = j.at(kColumns[c]);
        out << (c ? "," : "");
        if (v.is_string()) out << v.get<std::string>();
        else out << v.get<double>();
      }
      out << '\n';
    }
  });
  nlohmann::json checks = nlohmann::json::array();
  for (const CheckOutcome& c : EvaluateChecks(r)) checks.push_back(CheckOutcomeJson(c));
  const nlohmann::json summary{{"scenario", r.scenario.name}, {"drops", drops}, {"paper_checks", checks}};
  io::WriteFileAtomically((staging / "summary.json").string(), [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
  WriteResolvedScenario(r.scenario, (staging / "scenario_resolved.yaml").string(), out_dir);
  WriteCampaignPlots(r, staging.string());
}

std::string TracePath(const fs::path& staging, const CampaignCase& c) {
  return (staging / "traces" / (c.drop_id + ".csv")).string();
}
}  // namespace

void WriteCampaignOutputs(const CampaignResult& r, const io::OutputTarget& out) {
  io::WriteOutputDirectory(out, io::OutputKind::kCampaign, [&](const std::string& staging_dir) {
    const fs::path staging = staging_dir;
    fs::create_directories(staging / "traces");
    for (size_t i = 0; i < r.drops.size(); ++i) drop::WriteTraceCsv(r.drops[i].result, TracePath(staging, r.scenario.cases[i]));
    WriteCampaignSummaries(r, staging, out.path);
  });
}

CampaignResult RunCampaignToDirectory(const CampaignScenario& scenario, const io::OutputTarget& out,
                                      const io::ProgressOptions& progress_options) {
  CampaignResult r{scenario, {}};
  io::Progress progress("campaign", "drops", static_cast<int64_t>(scenario.cases.size()), progress_options);
  io::WriteOutputDirectory(out, io::OutputKind::kCampaign, [&](const std::string& staging_dir) {
    const fs::path staging = staging_dir;
    fs::create_directories(staging / "traces");
    r.drops.clear();
    r.drops.reserve(scenario.cases.size());
    for (const CampaignCase& c : scenario.cases) {
      drop::PadDrop d = RunCase(scenario, c);
      drop::WriteTraceCsv(d.result, TracePath(staging, c));
      std::vector<pad::DropSample>().swap(d.result.trace);  // released: the file holds it
      if (d.free) std::vector<pad::FreeDropSample>().swap(d.free->trace);
      r.drops.push_back(std::move(d));
      progress.Add(1);
    }
    progress.Finish();
    WriteCampaignSummaries(r, staging, out.path);
  });
  return r;
}

nlohmann::json CheckOutcomeJson(const CheckOutcome& c) {
  nlohmann::json j{{"name", c.check.name}, {"quantity", c.check.quantity}, {"speed_m_s", c.check.speed_m_s},
                   {"simulated", c.simulated}, {"source", c.check.source}};
  if (c.check.paper_experiment > 0) j["paper_experiment"] = c.check.paper_experiment;
  if (c.check.paper_rft > 0) j["paper_rft"] = c.check.paper_rft;
  j["used_for_fit"] = c.check.used_for_fit;
  if (c.check.used_for_fit) j["fit_by"] = c.check.fit_by;
  if (c.check.reading) j["reading"] = std::string(PaperReadingName(*c.check.reading));
  return j;
}

}  // namespace touchdown::scenario
