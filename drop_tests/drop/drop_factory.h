#pragma once
// The one place a drop is made from a pad, a soil and the drop's conditions: the soil as the
// drop sees it (zeta override, atmosphere), zeta scaled to the drop's gravity, the rig's 2D law,
// the rig's soil response with the model's effect terms (the free pad's 3D contact model comes from
// model::MakeContactModel, as every 3D contact's does). ResolveDrop (drop_setup.h) resolves whole
// drops from these; calibrate, diagnose and synth, which need the rig's pieces (a regressor, a fitted
// zeta, a hidden effect around the response), take them from here too, so every drop of every
// command is built alike.
#include <memory>
#include <optional>
#include <string>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/model/effects.h"
#include "footpad_geom/axisymmetric_intrusion.h"
#include "rft/soil.h"
#include "lander/pad/effect_soil_response.h"
#include "lander/pad/free_drop.h"
#include "rft/law_kind.h"

namespace touchdown::drop {

// The soil as a drop runs on it: zeta replaced by `zeta_N_m3` (stated, like a catalogue zeta, at
// the soil's reference gravity) and the atmosphere by `atmosphere`, where given.
rft::SoilParameters DropSoil(const rft::SoilParameters& soil, const std::optional<double>& zeta_N_m3,
                             const std::optional<rft::Atmosphere>& atmosphere);

// zeta at the drop's gravity [N/m^3] (RFT stresses scale with rho g z: linear in gravity from
// the soil's reference gravity), before any gas cushion.
double ZetaAtGravity(const rft::SoilParameters& drop_soil, double gravity_m_s2);

// The rig's profile integral of an axisymmetric pad, under the rig's 2D law. Li 2013 is the only
// 2D law (rft/stress_law.h), and a soil names only its 3D law (rft_law_3d), so the rig uses Li
// 2013 on every soil: it is chosen here and nowhere else. (The integral is per pad, not per soil,
// as long as that holds.)
std::unique_ptr<geom::AxisymmetricIntrusion> MakeRigIntrusion(const geom::AxisymmetricProfile& profile);

// Whether a drop runs on the bekker law (rft/bekker_law.h): the law asked for (`law`, a drop's
// --law), else the soil's own. Li 2013 and Agarwal 2023 soils keep the rig's Li 2013 integral.
bool RunsOnBekker(const rft::SoilParameters& drop_soil, const std::optional<rft::LawKind>& law);

// The rig's profile integral under Bekker's pressure (rft::BekkerLaw2D: the footprint integral).
std::unique_ptr<geom::AxisymmetricIntrusion> MakeBekkerRigIntrusion(const geom::AxisymmetricProfile& profile);

// The rig's soil response on a Bekker soil for a pad's Bekker integral (MakeBekkerRigIntrusion):
// p = (k_c / b + k_phi) z^n with b the pad's radius (its footprint's equal-area radius, as
// rft::BekkerPlateB takes it for a mesh), no gravity scaling, and the effect terms in their rig
// form (depth_exponent excluded: n is the law's own). Throws InputError naming the soil's field.
pad::EffectSoilResponse MakeBekkerRigResponse(const geom::AxisymmetricIntrusion& intrusion,
                                              const rft::SoilParameters& drop_soil, const rft::EffectTerms& terms);

// The rig's vertical soil response for a pad's integral on `drop_soil` (DropSoil) at the drop's
// gravity, with the effect terms in their rig form (gas cushion only in air). Throws InputError
// if an effect needs the bulk density and the soil has none.
pad::EffectSoilResponse MakeRigResponse(const geom::AxisymmetricIntrusion& intrusion,
                                        const rft::SoilParameters& drop_soil, double gravity_m_s2,
                                        const rft::EffectTerms& terms);

// A free drop's model. kReference: the pad as its file meshes it and pad::FreeDropOptions'
// tolerances, what `touchdown drop --free` runs by default. kFast: the same drop at a coarser
// resolution, for studies of many drops (`--fast`): a revolved pad re-meshed at
// kFastFreeDropRimSegments rim segments with area-preserving rings (io::PadWithAngularSegments, the
// rim a lander scenario's simulation.pad_rim selects) and rtol kFastFreeDropRtol. On the free-drop
// benchmark drops (bench_free_drop, docs/lander_dynamics.md, "The free drops' fast model") it is
// within 0.4 % in final depth of the reference at rtol 1e-9, at 1.4-8 ms a drop; the flat pad's
// final tilt within 0.05 deg, inside the studies' contract (2 %, 0.1 deg), but the curved pad's, which
// converges slowly in the mesh, up to 0.15 deg off (tilted and sliding at 1.2 m/s; 0.12 deg
// spinning). A mesh pad has no fast model (its file fixes its mesh).
enum class FreeDropModel { kReference, kFast };
inline constexpr int kFastFreeDropRimSegments = 16;
inline constexpr double kFastFreeDropRtol = 1e-5;

// The pad a free drop of `model` runs on: `pad` itself (kReference), or re-meshed (kFast). A mesh
// pad under kFast throws InputError naming `context` and `field`.
io::PadSpec FreeDropPad(const io::PadSpec& pad, FreeDropModel model, const std::string& context,
                        const std::string& field);
// The free drop's integration options under `model`.
pad::FreeDropOptions FreeDropOptionsFor(FreeDropModel model);

}  // namespace touchdown::drop
