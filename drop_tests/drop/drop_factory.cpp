#include "drop_tests/drop/drop_factory.h"

#include <stdexcept>

#include "rft/bekker_law.h"
#include "rft/input_error.h"
#include "rft/stress_law.h"
#include "rft/stress_law_3d_factory.h"

namespace touchdown::drop {

rft::SoilParameters DropSoil(const rft::SoilParameters& soil, const std::optional<double>& zeta_N_m3,
                             const std::optional<rft::Atmosphere>& atmosphere) {
  rft::SoilParameters out = soil;
  if (zeta_N_m3) out.zeta_N_m3 = *zeta_N_m3;
  if (atmosphere) out.atmosphere = *atmosphere;
  return out;
}

double ZetaAtGravity(const rft::SoilParameters& drop_soil, double gravity_m_s2) {
  return drop_soil.ZetaAtGravity(gravity_m_s2);
}

std::unique_ptr<geom::AxisymmetricIntrusion> MakeRigIntrusion(const geom::AxisymmetricProfile& profile) {
  // A mesh pad has no profile; its callers refuse it at load, naming the input (a bug otherwise).
  if (profile.points.empty()) throw std::invalid_argument("MakeRigIntrusion: a pad without a profile (a mesh pad)");
  return std::make_unique<geom::AxisymmetricIntrusion>(profile, rft::Li2013Law{});
}

bool RunsOnBekker(const rft::SoilParameters& drop_soil, const std::optional<rft::LawKind>& law) {
  return law.value_or(drop_soil.rft_law_3d) == rft::LawKind::kBekker;
}

std::unique_ptr<geom::AxisymmetricIntrusion> MakeBekkerRigIntrusion(const geom::AxisymmetricProfile& profile) {
  if (profile.points.empty()) throw std::invalid_argument("MakeBekkerRigIntrusion: a pad without a profile (a mesh pad)");
  return std::make_unique<geom::AxisymmetricIntrusion>(profile, rft::BekkerLaw2D{});
}

pad::EffectSoilResponse MakeBekkerRigResponse(const geom::AxisymmetricIntrusion& intrusion,
                                              const rft::SoilParameters& drop_soil, const rft::EffectTerms& terms) {
  rft::RequireBekkerParameters(drop_soil);
  if (terms.HasDepthExponent())
    throw MakeInputError(drop_soil.name, "depth_exponent", "does not apply to the bekker law (its exponent is bekker.n)");
  rft::EffectTerms bekker_terms = rft::WithSoilDynamicTerm(terms, drop_soil);
  // Bekker's z^n as the rig's depth law, z_ref = 1 m: z_ref (z / z_ref)^n = z^n in SI.
  bekker_terms.depth_exponent = drop_soil.bekker.n;
  bekker_terms.depth_reference_m = 1.0;
  const pad::SoilResponseInputs in{rft::BekkerModulus(drop_soil.bekker, intrusion.radius_m()),
                                   drop_soil.bulk_density_kg_m3, drop_soil.atmosphere == rft::Atmosphere::kAir,
                                   bekker_terms};
  return pad::EffectSoilResponse(intrusion, in);
}

pad::EffectSoilResponse MakeRigResponse(const geom::AxisymmetricIntrusion& intrusion,
                                        const rft::SoilParameters& drop_soil, double gravity_m_s2,
                                        const rft::EffectTerms& terms) {
  const pad::SoilResponseInputs in{ZetaAtGravity(drop_soil, gravity_m_s2), drop_soil.bulk_density_kg_m3,
                                   drop_soil.atmosphere == rft::Atmosphere::kAir,
                                   rft::WithSoilDynamicTerm(terms, drop_soil)};
  return pad::EffectSoilResponse(intrusion, in);
}

io::PadSpec FreeDropPad(const io::PadSpec& pad, FreeDropModel model, const std::string& context,
                        const std::string& field) {
  if (model == FreeDropModel::kReference) return pad;
  if (!pad.is_axisymmetric())
    throw MakeInputError(context, field,
                         "pad '" + pad.name + "' is a mesh: the fast model re-meshes revolved pads only");
  return io::PadWithAngularSegments(pad, kFastFreeDropRimSegments, geom::RimPolygon::kAreaPreserving);
}

pad::FreeDropOptions FreeDropOptionsFor(FreeDropModel model) {
  pad::FreeDropOptions options;
  if (model == FreeDropModel::kFast) options.integrator.rtol = kFastFreeDropRtol;
  return options;
}

}  // namespace touchdown::drop
