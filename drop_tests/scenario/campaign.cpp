#include "drop_tests/scenario/campaign.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <unistd.h>

#include "drop_tests/io/output_path.h"
#include "drop_tests/scenario/campaign_plots.h"
#include "drop_tests/io/paths_in_outputs.h"
#include "drop_tests/io/yaml_fields.h"
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

PaperCheck ReadCheck(const io::YamlFields& f) {
  f.RequireOnly({"name", "quantity", "numerator", "denominator", "speed_m_s", "paper", "source"});
  PaperCheck c;
  c.name = f.String("name");
  c.quantity = f.String("quantity");
  if (c.quantity != "final_penetration_m" && c.quantity != "peak_force_N")
    f.Fail("quantity", "must be final_penetration_m or peak_force_N, got '" + c.quantity + "'");
  const io::YamlFields num = f.Child("numerator"), den = f.Child("denominator");
  c.numerator_pad = num.String("pad");
  c.numerator_soil = num.String("soil");
  c.denominator_pad = den.String("pad");
  c.denominator_soil = den.String("soil");
  c.speed_m_s = f.Positive("speed_m_s");
  if (f.Has("paper")) {
    const io::YamlFields p = f.Child("paper");
    p.RequireOnly({"experiment", "rft"});
    if (p.Has("experiment")) c.paper_experiment = p.Positive("experiment");
    if (p.Has("rft")) c.paper_rft = p.Positive("rft");
  }
  c.source = f.StringOr("source", "");
  return c;
}

const drop::PadDrop* FindDrop(const CampaignResult& r, const std::string& pad, const std::string& soil, double v) {
  for (const drop::PadDrop& d : r.drops)
    if (d.pad.name == pad && d.soil.name == soil && std::abs(d.conditions.impact_speed_m_s - v) < 1e-9) return &d;
  return nullptr;
}

double Quantity(const drop::PadDrop& d, const std::string& q) {
  return q == "peak_force_N" ? d.result.peak_force_N : d.result.final_penetration_m;
}
}  // namespace

CampaignScenario LoadCampaignScenario(const std::string& path) {
  const io::YamlFields f = io::YamlFields::LoadFile(path);
  f.RequireSchemaVersion(1);
  f.RequireOnly({"schema_version", "type", "name", "description", "gravity_m_s2", "reference_speed_m_s", "drops",
                 "paper_checks", "provenance"});
  if (f.Has("type") && f.String("type") != "campaign") f.Fail("type", "must be 'campaign'");
  CampaignScenario s;
  s.source = path;
  s.name = f.StringOr("name", fs::path(path).stem().string());
  s.description = f.StringOr("description", "");
  const double gravity = f.PositiveOr("gravity_m_s2", 9.81);
  std::map<std::string, std::shared_ptr<const io::PadSpec>> pads;
  std::map<std::string, rft::SoilParameters> soils;
  std::set<std::string> ids;
  auto load_pad = [](const std::string& name) { return std::make_shared<const io::PadSpec>(io::LoadPad(name)); };
  for (const io::YamlFields& entry : f.List("drops")) {
    entry.RequireOnly({"pad", "soil", "impact_speeds_m_s", "mass_kg", "zeta_N_cm3", "gravity_m_s2"});
    const std::shared_ptr<const io::PadSpec>& pad = Cached(pads, entry.String("pad"), entry, "pad", load_pad);
    const rft::SoilParameters& soil = Cached(soils, entry.String("soil"), entry, "soil", io::LoadSoil);
    for (double v : entry.NumberList("impact_speeds_m_s", /*allow_zero=*/true)) {
      CampaignCase c{pad->name + "_" + soil.name + "_v" + SpeedTag(v), pad, soil, {}};
      c.conditions.impact_speed_m_s = v;
      c.conditions.gravity_m_s2 = entry.PositiveOr("gravity_m_s2", gravity);
      if (entry.Has("mass_kg")) c.conditions.mass_kg = entry.Positive("mass_kg");
      if (entry.Has("zeta_N_cm3")) c.conditions.zeta_N_m3 = units::ZetaFromN_cm3(entry.Positive("zeta_N_cm3"));
      drop::ValidateConditions(c.conditions, f.file() + ": " + entry.prefix());  // ranges checked at load time
      if (!ids.insert(c.drop_id).second)
        entry.Fail("impact_speeds_m_s", "impact speed " + SpeedTag(v) + " m/s of pad " + pad->name + " on soil " +
                                            soil.name + " is listed twice (drop " + c.drop_id + ")");
      s.cases.push_back(std::move(c));
    }
  }
  s.reference_speed_m_s = f.PositiveOr("reference_speed_m_s", s.cases.front().conditions.impact_speed_m_s);
  if (f.Has("paper_checks"))
    for (const io::YamlFields& c : f.List("paper_checks")) s.checks.push_back(ReadCheck(c));
  return s;
}

void WriteResolvedScenario(const CampaignScenario& s, const std::string& path, const std::string& output_dir) {
  YAML::Emitter y;
  y << YAML::BeginMap << YAML::Key << "schema_version" << YAML::Value << 1 << YAML::Key << "type" << YAML::Value
    << "campaign_resolved" << YAML::Key << "name" << YAML::Value << s.name << YAML::Key << "source" << YAML::Value
    << io::PathForOutput(s.source, output_dir) << YAML::Key << "reference_speed_m_s" << YAML::Value << s.reference_speed_m_s << YAML::Key << "drops"
    << YAML::Value << YAML::BeginSeq;
  for (const CampaignCase& c : s.cases) {
    const rft::SoilParameters& soil = c.soil;
    y << YAML::BeginMap << YAML::Key << "drop_id" << YAML::Value << c.drop_id;
    const io::PadSpec& pad = *c.pad;
    y << YAML::Key << "pad" << YAML::Value << YAML::BeginMap << YAML::Key << "name" << YAML::Value << pad.name
      << YAML::Key << "file" << YAML::Value << io::PathForOutput(pad.source, output_dir) << YAML::Key << "mass_kg"
      << YAML::Value << pad.mass_kg << YAML::Key << "radius_mm" << YAML::Value << pad.profile.radius_m() * 1e3
      << YAML::Key << "thickness_mm" << YAML::Value << pad.profile.thickness_m() * 1e3 << YAML::Key
      << "profile_points" << YAML::Value << pad.profile.points.size() << YAML::EndMap;
    y << YAML::Key << "soil" << YAML::Value << YAML::BeginMap << YAML::Key << "name" << YAML::Value << soil.name
      << YAML::Key << "atmosphere" << YAML::Value << rft::AtmosphereName(soil.atmosphere) << YAML::Key << "zeta_N_cm3" << YAML::Value
      << units::ZetaToN_cm3(soil.zeta_N_m3) << YAML::Key << "reference_gravity_m_s2" << YAML::Value << soil.reference_gravity_m_s2
      << YAML::EndMap;
    y << YAML::Key << "impact_speed_m_s" << YAML::Value << c.conditions.impact_speed_m_s << YAML::Key << "mass_kg"
      << YAML::Value << c.conditions.mass_kg.value_or(pad.mass_kg) << YAML::Key << "gravity_m_s2" << YAML::Value
      << c.conditions.gravity_m_s2;
    if (c.conditions.zeta_N_m3) y << YAML::Key << "zeta_override_N_cm3" << YAML::Value << units::ZetaToN_cm3(*c.conditions.zeta_N_m3);
    y << YAML::EndMap;
  }
  y << YAML::EndSeq << YAML::EndMap;
  io::WriteFileAtomically(path, [&](std::ostream& out) { out << y.c_str() << '\n'; });
}

CampaignResult RunCampaign(const CampaignScenario& scenario) {
  CampaignResult result{scenario, {}};
  for (const CampaignCase& c : scenario.cases) result.drops.push_back(drop::RunPadDrop(*c.pad, c.soil, c.conditions));
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
  // summary.csv uses the dataset column names, so a campaign reads as a simulated dataset.
  io::WriteFileAtomically((staging / "summary.csv").string(), [&](std::ostream& out) {
    out << "drop_id,pad,soil,atmosphere,impact_speed_m_s,pad_mass_kg,gravity_m_s2,trace,final_penetration_m,"
           "peak_force_N,time_to_rest_s,max_deceleration_m_s2,impact_energy_J,dissipated_energy_J,"
           "mean_conversion_rate_W,zeta_N_cm3\n"
        << std::setprecision(10);
    for (const auto& j : drops)
      out << j["drop_id"].get<std::string>() << ',' << j["pad"].get<std::string>() << ','
          << j["soil"].get<std::string>() << ',' << j["atmosphere"].get<std::string>() << ','
          << j["impact_speed_m_s"].get<double>() << ',' << j["pad_mass_kg"].get<double>() << ','
          << j["gravity_m_s2"].get<double>() << ',' << j["trace"].get<std::string>() << ','
          << j["final_penetration_m"].get<double>() << ',' << j["peak_force_N"].get<double>() << ','
          << j["time_to_rest_s"].get<double>() << ',' << j["max_deceleration_m_s2"].get<double>() << ','
          << j["impact_energy_J"].get<double>() << ',' << j["dissipated_energy_J"].get<double>() << ','
          << j["mean_conversion_rate_W"].get<double>() << ',' << j["zeta_N_cm3"].get<double>() << '\n';
  });
  nlohmann::json checks = nlohmann::json::array();
  for (const CheckOutcome& c : EvaluateChecks(r)) {
    nlohmann::json j{{"name", c.check.name}, {"quantity", c.check.quantity}, {"speed_m_s", c.check.speed_m_s},
                     {"simulated", c.simulated}, {"source", c.check.source}};
    if (c.check.paper_experiment > 0) j["paper_experiment"] = c.check.paper_experiment;
    if (c.check.paper_rft > 0) j["paper_rft"] = c.check.paper_rft;
    checks.push_back(j);
  }
  const nlohmann::json summary{{"scenario", r.scenario.name}, {"drops", drops}, {"paper_checks", checks}};
  io::WriteFileAtomically((staging / "summary.json").string(), [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
  WriteResolvedScenario(r.scenario, (staging / "scenario_resolved.yaml").string(), out_dir);
  std::vector<std::string> drop_ids;
  for (const CampaignCase& c : r.scenario.cases) drop_ids.push_back(c.drop_id);
  WriteCampaignPlots(r.drops, drop_ids, r.scenario.reference_speed_m_s, staging.string());
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

CampaignResult RunCampaignToDirectory(const CampaignScenario& scenario, const io::OutputTarget& out) {
  CampaignResult r{scenario, {}};
  io::WriteOutputDirectory(out, io::OutputKind::kCampaign, [&](const std::string& staging_dir) {
    const fs::path staging = staging_dir;
    fs::create_directories(staging / "traces");
    r.drops.clear();
    r.drops.reserve(scenario.cases.size());
    for (const CampaignCase& c : scenario.cases) {
      drop::PadDrop d = drop::RunPadDrop(*c.pad, c.soil, c.conditions);
      drop::WriteTraceCsv(d.result, TracePath(staging, c));
      std::vector<pad::DropSample>().swap(d.result.trace);  // released: the file holds it
      if (d.free) std::vector<pad::FreeDropSample>().swap(d.free->trace);
      r.drops.push_back(std::move(d));
    }
    WriteCampaignSummaries(r, staging, out.path);
  });
  return r;
}

}  // namespace touchdown::scenario
