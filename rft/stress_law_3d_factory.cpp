#include "rft/stress_law_3d_factory.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "rft/agarwal2023.h"
#include "rft/bekker_law.h"
#include "rft/dynamic_term.h"
#include "rft/gas_cushion_term.h"
#include "rft/input_error.h"
#include "rft/li2013_3d.h"
#include "rft/physical_limits.h"
#include "rft/rate_damping_term.h"
#include "rft/registered_effects_law.h"
#include "rft/units.h"

namespace touchdown::rft {

namespace {

std::string Str(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string SoilLabel(const SoilParameters& soil) { return soil.name.empty() ? "soil" : "soil " + soil.name; }

void Require(bool ok, const SoilParameters& soil, const std::string& field, const std::string& message,
             double value) {
  if (!ok) throw MakeInputError(SoilLabel(soil), field, message + " (" + Str(value) + ")");
}

std::unique_ptr<StressLaw3D> MakeBekkerLaw(const SoilParameters& soil, double plate_b_m) {
  Require(std::isfinite(plate_b_m) && plate_b_m > 0.0, soil, "bekker",
          "the bekker law needs the pad's footprint dimension b > 0 [m]", plate_b_m);
  return std::make_unique<BekkerLaw3D>(soil.bekker, plate_b_m);
}

}  // namespace

void RequireBekkerParameters(const SoilParameters& soil) {
  const BekkerParameters& b = soil.bekker;
  Require(std::isfinite(b.n) && b.n > 0.0, soil, "bekker.n", "must be positive", b.n);
  Require(std::isfinite(b.k_c_N_m_n1) && b.k_c_N_m_n1 >= 0.0, soil, "bekker.k_c_kN_m_n1",
          "must be non-negative [N/m^(n+1)]", b.k_c_N_m_n1);
  Require(std::isfinite(b.k_phi_N_m_n2) && b.k_phi_N_m_n2 >= 0.0, soil, "bekker.k_phi_kN_m_n2",
          "must be non-negative [N/m^(n+2)]", b.k_phi_N_m_n2);
  Require(b.k_c_N_m_n1 + b.k_phi_N_m_n2 > 0.0, soil, "bekker.k_phi_kN_m_n2",
          "k_c and k_phi cannot both be 0 (the bekker law needs a bekker block)", b.k_phi_N_m_n2);
  Require(std::isfinite(b.cohesion_Pa) && b.cohesion_Pa >= 0.0, soil, "bekker.cohesion_kPa",
          "must be non-negative [Pa]", b.cohesion_Pa);
  Require(std::isfinite(b.friction_angle_rad) && b.friction_angle_rad >= 0.0 &&
              b.friction_angle_rad < std::numbers::pi / 2,
          soil, "bekker.friction_angle_deg", "must be in [0, 90) deg, in rad", b.friction_angle_rad);
  Require(std::isfinite(b.shear_modulus_K_m) && b.shear_modulus_K_m > 0.0, soil, "bekker.shear_modulus_K_mm",
          "must be positive [m]", b.shear_modulus_K_m);
}

void CheckSoilTakesLaw(LawKind law, const SoilParameters& soil, double gravity_m_s2) {
  if (!(std::isfinite(gravity_m_s2) && gravity_m_s2 > 0.0))
    throw MakeInputError(SoilLabel(soil), "gravity_m_s2", "must be positive (" + Str(gravity_m_s2) + ")");
  if (law == LawKind::kBekker) {
    RequireBekkerParameters(soil);
  } else if (law == LawKind::kLi2013) {
    // A Bekker soil file may leave zeta out: say that, not "zeta 0", when it meets an RFT law.
    if (soil.rft_law_3d == LawKind::kBekker && !(soil.zeta_N_m3 > 0.0))
      throw MakeInputError(SoilLabel(soil), "zeta_N_cm3",
                           "missing: it is a Bekker soil (law: bekker) and the law here is li2013, which needs "
                           "zeta_N_cm3; use the bekker law with it (a lander's ground.law: bekker) or an RFT soil");
    Require(std::isfinite(soil.zeta_N_m3) && soil.zeta_N_m3 > 0.0, soil, "zeta_N_cm3",
            "li2013 needs a positive zeta [N/cm^3]", soil.zeta_N_m3 * units::kN_cm3_per_N_m3);
    Require(std::isfinite(soil.reference_gravity_m_s2) && soil.reference_gravity_m_s2 > 0.0, soil,
            "reference_gravity_m_s2", "must be positive", soil.reference_gravity_m_s2);
  } else {  // LawKind::kAgarwal2023
    Require(std::isfinite(soil.bulk_density_kg_m3) && soil.bulk_density_kg_m3 > 0.0, soil,
            "bulk_density_kg_m3", "agarwal2023 needs the bulk density", soil.bulk_density_kg_m3);
    const double phi = soil.internal_friction_angle_rad;
    Require(std::isfinite(phi) && phi > 0.0 && phi < std::numbers::pi / 2, soil, "internal_friction_angle",
            "agarwal2023 needs an internal friction angle in (0, 90) deg, in rad", phi);
    Require(std::isfinite(soil.surface_friction_coefficient) && soil.surface_friction_coefficient >= 0.0,
            soil, "surface_friction", "must be non-negative", soil.surface_friction_coefficient);
    const double xi_n = AgarwalScalingXi(soil.bulk_density_kg_m3, gravity_m_s2, std::tan(phi));
    Require(xi_n > 0.0, soil, "internal_friction_angle", "gives a non-positive xi_n", xi_n);
    // The scaling is a cubic in tan(phi), unbounded as phi nears 90 deg: its xi_n meets the range a
    // given zeta must (N/cm^3 in the message, as a soil file gives it).
    Require(limits::Within(limits::kZeta_N_cm3, xi_n * units::kN_cm3_per_N_m3), soil, "internal_friction_angle",
            "the agarwal2023 scaling of this density and friction angle gives xi_n outside 0 to 1e4 N/cm^3",
            xi_n * units::kN_cm3_per_N_m3);
  }
}

std::unique_ptr<StressLaw3D> MakeStressLaw3D(LawKind law, const SoilParameters& soil,
                                             double gravity_m_s2, double bekker_plate_b_m) {
  CheckSoilTakesLaw(law, soil, gravity_m_s2);
  if (law == LawKind::kBekker) return MakeBekkerLaw(soil, bekker_plate_b_m);
  if (law == LawKind::kLi2013) return std::make_unique<Li2013TreersLaw>(soil.ZetaAtGravity(gravity_m_s2));
  const double xi_n =
      AgarwalScalingXi(soil.bulk_density_kg_m3, gravity_m_s2, std::tan(soil.internal_friction_angle_rad));
  return std::make_unique<Agarwal2023Law>(xi_n, soil.surface_friction_coefficient);
}

EffectTerms WithSoilDynamicTerm(const EffectTerms& terms, const SoilParameters& soil) {
  if (!soil.dynamic_term || terms.inertial_replaces_soil || terms.inertial_lambda > 0.0) return terms;
  Require(std::isfinite(soil.dynamic_lambda) && soil.dynamic_lambda >= 0.0, soil, "dynamic_lambda",
          "must be non-negative", soil.dynamic_lambda);
  Require(std::isfinite(soil.bulk_density_kg_m3) && soil.bulk_density_kg_m3 > 0.0, soil, "bulk_density_kg_m3",
          "the dynamic term needs the bulk density", soil.bulk_density_kg_m3);
  const double rho_c = soil.dynamic_density_kg_m3 > 0.0 ? soil.dynamic_density_kg_m3 : soil.bulk_density_kg_m3;
  EffectTerms out = terms;
  out.inertial_lambda = rho_c == soil.bulk_density_kg_m3 ? soil.dynamic_lambda
                                                         : soil.dynamic_lambda * rho_c / soil.bulk_density_kg_m3;
  return out;
}

SoilContactModel MakeSoilContactModel(LawKind law, const SoilParameters& soil, double gravity_m_s2,
                                      const EffectTerms& model_terms, const SurfaceElements* pad_surface) {
  const EffectTerms terms = WithSoilDynamicTerm(model_terms, soil);
  Require(std::isfinite(terms.inertial_lambda) && terms.inertial_lambda >= 0.0, soil, "inertial_drag.lambda",
          "must be non-negative", terms.inertial_lambda);
  Require(std::isfinite(terms.damping_c_N_s_m3) && terms.damping_c_N_s_m3 >= 0.0, soil, "rate_damping.c_N_s_m3",
          "must be non-negative", terms.damping_c_N_s_m3);
  Require(std::isfinite(terms.gas_chi) && terms.gas_chi >= 0.0 && terms.gas_chi < 1.0, soil, "gas_cushion.chi",
          "must be in [0, 1)", terms.gas_chi);
  Require(std::isfinite(terms.gas_c_N_s_m3) && terms.gas_c_N_s_m3 >= 0.0, soil, "gas_cushion.c_g_N_s_m3",
          "must be non-negative", terms.gas_c_N_s_m3);
  Require(std::isfinite(terms.depth_exponent) && terms.depth_exponent > 0.0, soil, "depth_exponent.p",
          "must be positive", terms.depth_exponent);
  Require(std::isfinite(terms.depth_reference_m) && terms.depth_reference_m > 0.0, soil, "depth_exponent.z_ref",
          "must be positive", terms.depth_reference_m);
  Require(std::isfinite(terms.compaction_k_kg_m3) && terms.compaction_k_kg_m3 >= 0.0, soil,
          "compaction_peak.k_c_kg_m3", "must be non-negative", terms.compaction_k_kg_m3);
  Require(std::isfinite(terms.compaction_depth_m) && terms.compaction_depth_m > 0.0, soil, "compaction_peak.d_c",
          "must be positive", terms.compaction_depth_m);
  Require(std::isfinite(terms.added_mass_ca) && terms.added_mass_ca >= 0.0, soil, "added_mass.c_a",
          "must be non-negative", terms.added_mass_ca);
  Require(std::isfinite(terms.added_mass_plug_cp) && terms.added_mass_plug_cp >= 0.0, soil, "added_mass_plug.c_p",
          "must be non-negative", terms.added_mass_plug_cp);
  const bool inertial = terms.inertial_lambda > 0.0;
  if (law == LawKind::kBekker)
    Require(terms.depth_exponent == 1.0, soil, "depth_exponent.p",
            "does not apply to the bekker law (its own exponent is bekker.n)", terms.depth_exponent);
  const double bekker_plate_b_m = law == LawKind::kBekker && pad_surface ? BekkerPlateB(*pad_surface) : 0.0;
  std::unique_ptr<StressLaw3D> out = MakeStressLaw3D(law, soil, gravity_m_s2, bekker_plate_b_m);
  // DynamicTermLaw replaces its inner law's dynamic stress, so it goes innermost; the other
  // decorators add theirs to their inner law's.
  if (inertial) {
    const double rho = soil.bulk_density_kg_m3;
    Require(std::isfinite(rho) && rho > 0.0, soil, "bulk_density_kg_m3",
            "inertial_drag needs the soil's bulk density", rho);
    out = std::make_unique<DynamicTermLaw>(std::move(out), terms.inertial_lambda, rho);
  }
  if (terms.gas_chi > 0.0 || terms.gas_c_N_s_m3 > 0.0)
    out = std::make_unique<GasCushionLaw>(std::move(out), terms.gas_chi, terms.gas_c_N_s_m3);
  if (terms.damping_c_N_s_m3 > 0.0) out = std::make_unique<RateDampingLaw>(std::move(out), terms.damping_c_N_s_m3);
  if (terms.HasRegistered()) {
    for (size_t i = 0; i < RegisteredEffects().size(); ++i) {
      const EffectDefinition& e = RegisteredEffects()[i];
      if (!terms.registered[i].active) continue;
      for (size_t k = 0; k < e.parameters.size(); ++k)
        if (const std::string why = e.parameters[k].RangeProblem(terms.registered[i].values[k]); !why.empty())
          throw MakeInputError(SoilLabel(soil), e.id + "." + e.parameters[k].key, why);
      if (e.needs_bulk_density)
        Require(std::isfinite(soil.bulk_density_kg_m3) && soil.bulk_density_kg_m3 > 0.0, soil, "bulk_density_kg_m3",
                e.id + " needs the soil's bulk density", soil.bulk_density_kg_m3);
    }
    out = std::make_unique<RegisteredEffectsLaw>(std::move(out), terms, soil.bulk_density_kg_m3);
  }
  SoilContactModel model;
  if (terms.depth_exponent != 1.0) model.pad_terms.depth = {terms.depth_exponent, terms.depth_reference_m};
  // Bekker's z^n: the depth law with z_ref = 1 m, so z_ref (z / z_ref)^n = z^n in SI.
  if (law == LawKind::kBekker && soil.bekker.n != 1.0) model.pad_terms.depth = {soil.bekker.n, 1.0};
  if (law == LawKind::kBekker && out->has_mobilised_shear())
    model.janosi_K_m = soil.bekker.shear_modulus_K_m;
  if (terms.compaction_k_kg_m3 > 0.0) {
    model.pad_terms.compaction_k_kg_m3 = terms.compaction_k_kg_m3;
    model.pad_terms.compaction_depth_m = terms.compaction_depth_m;
  }
  if (terms.added_mass_ca > 0.0) {
    Require(std::isfinite(soil.bulk_density_kg_m3) && soil.bulk_density_kg_m3 > 0.0, soil, "bulk_density_kg_m3",
            "added_mass needs the soil's bulk density", soil.bulk_density_kg_m3);
    model.pad_terms.added_mass_density_kg_m3 = terms.added_mass_ca * soil.bulk_density_kg_m3;
  }
  if (terms.added_mass_plug_cp > 0.0) {
    Require(std::isfinite(soil.bulk_density_kg_m3) && soil.bulk_density_kg_m3 > 0.0, soil, "bulk_density_kg_m3",
            "added_mass_plug needs the soil's bulk density", soil.bulk_density_kg_m3);
    model.pad_terms.plug_density_kg_m3 = terms.added_mass_plug_cp * soil.bulk_density_kg_m3;
  }
  model.law = std::move(out);
  return model;
}

}  // namespace touchdown::rft
