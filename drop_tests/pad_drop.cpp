#include "drop_tests/pad_drop.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <nlohmann/json.hpp>

#include "drop_tests/atomic_file.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "rft/input_error.h"
#include "rft/stress_law.h"

namespace touchdown::drop {

void ValidateConditions(const DropConditions& c, const std::string& context) {
  auto bad = [&](const std::string& field, double v, const std::string& rule) {
    std::ostringstream s;
    s << "must be " << rule << ", got " << v;
    throw MakeInputError(context, field, s.str());
  };
  if (!(c.impact_speed_m_s >= 0.0 && std::isfinite(c.impact_speed_m_s)))
    bad("impact_speed_m_s", c.impact_speed_m_s, ">= 0 and finite");
  if (c.mass_kg && !(*c.mass_kg > 0.0 && std::isfinite(*c.mass_kg))) bad("mass_kg", *c.mass_kg, "positive and finite");
  if (!(c.gravity_m_s2 > 0.0 && std::isfinite(c.gravity_m_s2))) bad("gravity_m_s2", c.gravity_m_s2, "positive and finite");
  if (c.zeta_N_m3 && !(*c.zeta_N_m3 > 0.0 && std::isfinite(*c.zeta_N_m3)))
    bad("zeta_N_cm3", *c.zeta_N_m3 / 1e6, "positive and finite");
  if (c.atmosphere && *c.atmosphere != "vacuum" && *c.atmosphere != "air")
    throw MakeInputError(context, "atmosphere", "must be vacuum or air, got '" + *c.atmosphere + "'");
}

PadDrop RunPadDrop(const PadSpec& pad, const rft::SoilParameters& soil, const DropConditions& conditions,
                   const RigDropOptions& options) {
  ValidateConditions(conditions, pad.name + " on " + soil.name);
  // The rig drop integrates the exact axisymmetric profile; a mesh pad needs the 3D contact
  // wrench (rft/contact_wrench.h) and the free-pad dynamics.
  if (!pad.is_axisymmetric())
    throw MakeInputError(pad.source, "", "rig drop of mesh pads needs the 3D contact; use --free");
  // The record keeps the pad's description but not its 3D body (megabytes for a fine mesh,
  // unused by the rig drop): copying it per drop would cost more than the drop itself.
  PadSpec described{pad.name, pad.source, pad.kind, pad.profile, pad.mass_kg, {}, pad.mesh_file};
  PadDrop drop{std::move(described), soil, conditions, conditions.mass_kg.value_or(pad.mass_kg), 0.0, {}};
  rft::SoilParameters effective = soil;
  if (conditions.zeta_N_m3) effective.zeta_N_m3 = *conditions.zeta_N_m3;
  if (conditions.atmosphere) drop.soil.atmosphere = *conditions.atmosphere;
  drop.zeta_effective_N_m3 = effective.ZetaAtGravity(conditions.gravity_m_s2);

  const geom::AxisymmetricIntrusion intrusion(pad.profile, rft::Li2013Law{});
  // With no effect terms this is exactly the quasi-static RFT force F_z(d; zeta).
  SoilResponseInputs inputs{drop.zeta_effective_N_m3, soil.bulk_density_kg_m3, drop.soil.atmosphere == "air",
                            conditions.effects};
  std::optional<EffectSoilResponse> response;
  try {
    response.emplace(intrusion, inputs);
  } catch (const InputError& e) {
    throw MakeInputError(soil.name, "", e.what());
  }
  drop.result = RunRigDrop({drop.mass_kg, conditions.gravity_m_s2, conditions.impact_speed_m_s}, *response, options);
  return drop;
}

nlohmann::json SummaryJson(const PadDrop& d) {
  const RigDropResult& r = d.result;
  return nlohmann::json{
      {"pad", d.pad.name},
      {"soil", d.soil.name},
      {"atmosphere", d.soil.atmosphere},
      {"impact_speed_m_s", d.conditions.impact_speed_m_s},
      {"pad_mass_kg", d.mass_kg},
      {"gravity_m_s2", d.conditions.gravity_m_s2},
      {"zeta_N_cm3", d.zeta_effective_N_m3 / 1e6},
      {"final_penetration_m", r.final_penetration_m},
      {"peak_force_N", r.peak_force_N},
      {"time_to_rest_s", r.time_to_rest_s},
      {"max_deceleration_m_s2", r.max_deceleration_m_s2},
      {"impact_energy_J", r.impact_energy_J},
      {"gravity_work_J", r.gravity_work_J},
      {"dissipated_energy_J", r.dissipated_energy_J},
      {"mean_conversion_rate_W", r.mean_conversion_rate_W},
      {"rest_creep_m", r.rest_creep_m},
      {"solver_steps", r.solver.steps},
  };
}

void WriteTraceCsv(const RigDropResult& result, const std::string& path) {
  WriteFileAtomically(path, [&](std::ostream& out) {
    out << "t_s,penetration_m,velocity_m_s,force_N\n" << std::setprecision(10);
    for (const DropSample& s : result.trace)
      out << s.t_s << ',' << s.penetration_m << ',' << s.velocity_m_s << ',' << s.force_N << '\n';
  });
}

}  // namespace touchdown::drop
