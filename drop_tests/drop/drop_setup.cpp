#include "drop_tests/drop/drop_setup.h"

#include <utility>

#include "drop_tests/drop/drop_factory.h"
#include "drop_tests/model/contact_model.h"
#include "rft/input_error.h"
#include "rft/soil_map.h"

namespace touchdown::drop {

namespace {

// A free pad of another mass keeps its shape and uniform density: inertia scales with the mass.
geom::PadBody WithMass(const geom::PadBody& body, double mass_kg) {
  geom::PadBody out = body;
  out.inertia_com_B *= mass_kg / body.mass_kg;
  out.mass_kg = mass_kg;
  return out;
}

// A free drop's result in the rig's terms (summary and trace), for sweeps, datasets and plots.
pad::RigDropResult AsRigResult(const pad::FreeDropResult& f) {
  pad::RigDropResult r;
  r.final_penetration_m = f.final_penetration_m;
  r.peak_force_N = f.peak_force_N;
  r.time_to_rest_s = f.time_to_rest_s;
  r.max_deceleration_m_s2 = f.max_deceleration_m_s2;
  r.impact_energy_J = f.impact_energy_J;
  r.gravity_work_J = f.gravity_work_J;
  r.dissipated_energy_J = f.dissipated_energy_J;
  r.mean_conversion_rate_W = f.time_to_rest_s > 0.0 ? f.impact_energy_J / f.time_to_rest_s : 0.0;
  r.rest_creep_m = 0.0;  // the free drop ends at rest: no rest phase is simulated
  r.trace.reserve(f.trace.size());
  for (const pad::FreeDropSample& s : f.trace) r.trace.push_back({s.t_s, s.penetration_m, s.velocity_m_s, s.force_N});
  r.solver = f.solver;
  return r;
}

pad::FreeDropSetup ResolveFree(DropSetup& setup, const io::PadSpec& pad, const rft::SoilParameters& soil,
                               const rft::SoilParameters& drop_soil, const DropConditions& c,
                               const DropRunOptions& options) {
  const rft::SoilContactModel law =
      model::MakeContactModel({.law = c.law_3d, .soil = drop_soil, .gravity_m_s2 = c.gravity_m_s2, .effects = c.effects,
                               .effects_source = c.effects_source, .pad_surface = &pad.body.surface});
  setup.record.law_3d = law.law->kind();
  setup.record.contact_model = law.name();
  pad::FreeDropSetup free;
  if (setup.record.mass_kg == pad.body.mass_kg) {
    free.body = &pad.body;
  } else {
    setup.body = std::make_unique<geom::PadBody>(WithMass(pad.body, setup.record.mass_kg));
    free.body = setup.body.get();
  }
  free.terrain = rft::UniformTerrain(soil.name, law);
  free.initial.impact_speed_m_s = c.impact_speed_m_s;
  free.initial.horizontal_speed_m_s = c.horizontal_speed_m_s;
  free.initial.tilt_rad = c.tilt_rad;
  free.initial.tilt_axis = c.tilt_axis;
  free.initial.omega_W = c.omega_W;
  free.initial.gravity_m_s2 = c.gravity_m_s2;
  free.options = options.free;
  return free;
}

pad::RigDropSetup ResolveRig(DropSetup& setup, const io::PadSpec& pad, const rft::SoilParameters& soil,
                             const rft::SoilParameters& drop_soil, const DropConditions& c,
                             const DropRunOptions& options) {
  // A Bekker drop has its own integral (a caller's cached one is Li 2013's).
  const bool bekker = RunsOnBekker(drop_soil, c.law_3d);
  if (bekker) setup.intrusion = MakeBekkerRigIntrusion(pad.profile);
  else if (!options.intrusion) setup.intrusion = MakeRigIntrusion(pad.profile);
  const geom::AxisymmetricIntrusion& intrusion = setup.intrusion ? *setup.intrusion : *options.intrusion;
  // With no effect terms this is exactly the quasi-static RFT force F_z(d; zeta) (or Bekker's).
  try {
    setup.response = std::make_unique<pad::EffectSoilResponse>(
        bekker ? MakeBekkerRigResponse(intrusion, drop_soil, c.effects)
               : MakeRigResponse(intrusion, drop_soil, c.gravity_m_s2, c.effects));
  } catch (const InputError& e) {
    throw MakeInputError(soil.name, "", e.what());
  }
  if (bekker) setup.record.law_3d = rft::LawKind::kBekker;
  return {{setup.record.mass_kg}, setup.response.get(), {c.gravity_m_s2, c.impact_speed_m_s}, options.rig};
}

}  // namespace

DropSetup ResolveDrop(const io::PadSpec& pad, const rft::SoilParameters& soil, const DropConditions& conditions,
                      const DropRunOptions& options) {
  const bool free = conditions.IsFree();
  // The rig drop integrates the exact axisymmetric profile; a mesh pad needs the 3D contact
  // wrench (rft/contact_wrench.h) and the free-pad dynamics.
  if (!free && !pad.is_axisymmetric())
    throw MakeInputError(pad.source, "", "a mesh pad drops only as a free pad (touchdown drop --free, or a sweep), not on the paper's rig, which drops axisymmetric pads");
  // The record keeps the pad's description but not its 3D body (megabytes for a fine mesh,
  // unused by the rig drop): copying it per drop would cost more than the drop itself.
  io::PadSpec described{pad.name, pad.source, pad.kind, pad.profile, pad.mass_kg, {}, pad.mesh_file, pad.file};
  const rft::SoilParameters drop_soil = DropSoil(soil, conditions.zeta_N_m3, conditions.atmosphere);
  DropSetup setup{PadDrop{std::move(described), DropSoil(soil, std::nullopt, conditions.atmosphere), conditions,
                          conditions.mass_kg.value_or(pad.mass_kg), ZetaAtGravity(drop_soil, conditions.gravity_m_s2),
                          {}, {}, rft::LawKind::kLi2013, {}},
                  pad::RigDropSetup{}, nullptr, nullptr, nullptr};
  if (free) setup.run = ResolveFree(setup, pad, soil, drop_soil, conditions, options);
  else setup.run = ResolveRig(setup, pad, soil, drop_soil, conditions, options);
  return setup;
}

PadDrop RunDrop(const DropSetup& setup) {
  PadDrop drop = setup.record;
  if (const auto* free = std::get_if<pad::FreeDropSetup>(&setup.run)) {
    pad::FreeDropResult r = pad::RunFreeDrop(*free);
    drop.result = AsRigResult(r);
    drop.free = std::move(r);
  } else {
    drop.result = pad::RunRigDrop(std::get<pad::RigDropSetup>(setup.run));
  }
  return drop;
}

}  // namespace touchdown::drop
