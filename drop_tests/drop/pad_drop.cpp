#include "drop_tests/drop/pad_drop.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <nlohmann/json.hpp>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/drop/drop_columns.h"
#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/drop/free_drop_output.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"
#include "rft/units.h"

namespace touchdown::drop {

using units::kDeg;

void ValidateConditions(const DropConditions& c, const std::string& context) {
  auto bad = [&](const std::string& field, double v, const std::string& rule) {
    std::ostringstream s;
    s << "must be " << rule << ", got " << v;
    throw MakeInputError(context, field, s.str());
  };
  limits::Require(limits::kSpeed_m_s, c.impact_speed_m_s, context, "impact_speed_m_s");
  if (c.mass_kg) limits::Require(limits::kMass_kg, *c.mass_kg, context, "mass_kg");
  limits::Require(limits::kGravity_m_s2, c.gravity_m_s2, context, "gravity_m_s2");
  if (c.zeta_N_m3) limits::Require(limits::kZeta_N_cm3, units::ZetaToN_cm3(*c.zeta_N_m3), context, "zeta_N_cm3");
  if (!(std::abs(c.tilt_rad) < limits::kDropTiltWithin_deg * kDeg))
    bad("tilt_deg", c.tilt_rad / kDeg,
        "between -" + std::to_string(limits::kDropTiltWithin_deg) + " and " + std::to_string(limits::kDropTiltWithin_deg));
  limits::Require(limits::kAbsSpeed_m_s, c.horizontal_speed_m_s, context, "horizontal_speed_m_s");
  if (!c.omega_W.allFinite()) throw MakeInputError(context, "omega", "must be finite");
  limits::Require(limits::kAngularSpeed_rad_s, c.omega_W.stableNorm(), context, "omega (its magnitude)");
}

double EffectiveZeta(const rft::SoilParameters& soil, const DropConditions& c) {
  return ZetaAtGravity(DropSoil(soil, c.zeta_N_m3, c.atmosphere), c.gravity_m_s2);
}

DropConditions DropConditionsFor(const DropRow& row, const rft::EffectTerms& effects, const std::string& effects_source,
                                 const std::string& context) {
  DropConditions c;
  static_cast<DropRow&>(c) = row;
  c.effects = effects;
  c.effects_source = effects_source;
  ValidateConditions(c, context);
  return c;
}

nlohmann::json SummaryJson(const PadDrop& d) {
  const pad::RigDropResult& r = d.result;
  // The result's numbers from its record's table (drop_columns.h), then the drop's conditions (the
  // keys are printed sorted, whatever the order they are set in).
  nlohmann::json j;
  if (d.free) {
    j = FreeDropJson(*d.free);
    j["law"] = d.contact_model;
    j["horizontal_speed_m_s"] = d.conditions.horizontal_speed_m_s;
  } else {
    for (const ResultNumber<pad::RigDropResult>& n : RigMetrics()) j[n.name] = r.*n.member;
    j["solver_steps"] = r.solver.steps;
    // RFT rig summaries name no law (they stay as they were); Bekker's do.
    if (d.law_3d == rft::LawKind::kBekker) j["law"] = rft::LawKindName(d.law_3d);
  }
  j["pad"] = d.pad.name;
  j["soil"] = d.soil.name;
  j["atmosphere"] = rft::AtmosphereName(d.soil.atmosphere);
  j["impact_speed_m_s"] = d.conditions.impact_speed_m_s;
  j["pad_mass_kg"] = d.mass_kg;
  j["gravity_m_s2"] = d.conditions.gravity_m_s2;
  j["zeta_N_cm3"] = units::ZetaToN_cm3(d.zeta_effective_N_m3);
  const std::vector<std::string> active = model::ActiveEffects(d.conditions.effects);
  if (!active.empty()) {
    const auto skipped = model::EffectsNotApplied(d.conditions.effects, d.in_air());
    nlohmann::json applied = nlohmann::json::array(), not_applied = nlohmann::json::object();
    for (const std::string& id : active) {
      bool skip = false;
      for (const auto& [sid, why] : skipped)
        if (sid == id) not_applied[id] = why, skip = true;
      if (!skip) applied.push_back(id);
    }
    j["effects"] = applied;
    j["effects_not_applied"] = not_applied;
    if (!d.conditions.effects_source.empty()) j["model"] = d.conditions.effects_source;
  }
  return j;
}

void WriteTraceCsv(const pad::RigDropResult& result, std::ostream& out) {
  WriteTraceCsv(RigTraceColumns(), result.trace, out);
}

void WriteTraceCsv(const pad::RigDropResult& result, const std::string& path) {
  io::WriteFileAtomically(path, [&](std::ostream& out) { WriteTraceCsv(result, out); });
}

namespace {

// The header lines of touchdown's traces, the rig's and a free drop's, as the writers print them. A
// file starting with one is a trace of touchdown's, which a rerun may replace: no other file starts
// so (datasets, comparisons and sweep exports order their columns t_s,penetration_m,force_N).
std::vector<std::string> TraceHeaders() {
  std::ostringstream rig, free;
  WriteTraceCsv(pad::RigDropResult{}, rig);
  WriteFreeDropTraceCsv(pad::FreeDropResult{}, free);
  auto first_line = [](const std::string& text) { return text.substr(0, text.find('\n')); };
  return {first_line(rig.str()), first_line(free.str())};
}

}  // namespace

void CheckTraceTarget(const io::OutputTarget& target) { io::CheckOutputFile(target, TraceHeaders()); }

void WriteTraceCsv(const PadDrop& drop, const io::OutputTarget& target) {
  io::WriteOutputFile(
      target,
      [&](std::ostream& out) {
        if (drop.free) WriteFreeDropTraceCsv(*drop.free, out);
        else WriteTraceCsv(drop.result, out);
      },
      TraceHeaders());
}

}  // namespace touchdown::drop
