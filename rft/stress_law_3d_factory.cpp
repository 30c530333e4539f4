#include "rft/stress_law_3d_factory.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "rft/agarwal2023.h"
#include "rft/dynamic_term.h"
#include "rft/input_error.h"
#include "rft/li2013_3d.h"

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

}  // namespace

std::unique_ptr<StressLaw3D> MakeStressLaw3D(std::string_view law, const SoilParameters& soil,
                                             double gravity_m_s2) {
  if (!(std::isfinite(gravity_m_s2) && gravity_m_s2 > 0.0))
    throw MakeInputError(SoilLabel(soil), "gravity_m_s2", "must be positive (" + Str(gravity_m_s2) + ")");

  std::unique_ptr<StressLaw3D> quasi_static;
  if (law == "li2013") {
    Require(std::isfinite(soil.zeta_N_m3) && soil.zeta_N_m3 > 0.0, soil, "zeta",
            "li2013 needs a positive zeta", soil.zeta_N_m3);
    Require(std::isfinite(soil.reference_gravity_m_s2) && soil.reference_gravity_m_s2 > 0.0, soil,
            "reference_gravity_m_s2", "must be positive", soil.reference_gravity_m_s2);
    quasi_static = std::make_unique<Li2013TreersLaw>(soil.ZetaAtGravity(gravity_m_s2));
  } else if (law == "agarwal2023") {
    Require(std::isfinite(soil.bulk_density_kg_m3) && soil.bulk_density_kg_m3 > 0.0, soil,
            "bulk_density_kg_m3", "agarwal2023 needs the bulk density", soil.bulk_density_kg_m3);
    const double phi = soil.internal_friction_angle_rad;
    Require(std::isfinite(phi) && phi > 0.0 && phi < std::numbers::pi / 2, soil, "internal_friction_angle",
            "agarwal2023 needs an internal friction angle in (0, 90) deg, in rad", phi);
    Require(std::isfinite(soil.surface_friction_coefficient) && soil.surface_friction_coefficient >= 0.0,
            soil, "surface_friction", "must be non-negative", soil.surface_friction_coefficient);
    const double xi_n = AgarwalScalingXi(soil.bulk_density_kg_m3, gravity_m_s2, std::tan(phi));
    Require(xi_n > 0.0, soil, "internal_friction_angle", "gives a non-positive xi_n", xi_n);
    quasi_static = std::make_unique<Agarwal2023Law>(xi_n, soil.surface_friction_coefficient);
  } else {
    throw MakeInputError(SoilLabel(soil), "law",
                         "unknown 3D stress law '" + std::string(law) + "' (expected li2013 or agarwal2023)");
  }

  if (!soil.dynamic_term) return quasi_static;
  const double rho_c =
      soil.dynamic_density_kg_m3 > 0.0 ? soil.dynamic_density_kg_m3 : soil.bulk_density_kg_m3;
  Require(std::isfinite(soil.dynamic_lambda) && soil.dynamic_lambda >= 0.0, soil, "dynamic_lambda",
          "must be non-negative", soil.dynamic_lambda);
  Require(std::isfinite(rho_c) && rho_c > 0.0, soil, "dynamic_density_kg_m3",
          "the dynamic term needs a density (dynamic_density_kg_m3 or bulk_density_kg_m3)", rho_c);
  return std::make_unique<DynamicTermLaw>(std::move(quasi_static), soil.dynamic_lambda, rho_c);
}

}  // namespace touchdown::rft
