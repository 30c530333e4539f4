#pragma once
// The penetration-depth law Durian's group fitted to spheres dropped from rest into dry,
// non-cohesive grains (Uehara et al., PRL 90, 194301, 2003; Ambroso et al., PRE 71, 051305, 2005):
//   d = (c / mu) (rho_b / rho_g)^(1/2) D^(2/3) H^(1/3),   H = h + d the total drop distance,
// c the fitted prefactor, mu the medium's friction coefficient (tan of its repose angle), rho_b
// and D the sphere's density and diameter, rho_g the medium's bulk density. With L the length
// (c / mu) (rho_b / rho_g)^(1/2) D^(2/3) [m^(2/3)] and a = L^3, d solves d^3 - a d - a h = 0, a
// depressed cubic whose largest root is the depth (trigonometric form when it has three real
// roots, Cardano's otherwise). Pure functions, no state.

namespace touchdown::validation {

struct ShallowImpactParameters {
  double prefactor = 0.0;             // c
  double friction_coefficient = 0.0;  // mu
  double sphere_density_kg_m3 = 0.0;
  double medium_density_kg_m3 = 0.0;
  double sphere_diameter_m = 0.0;
};

// L = (c / mu) (rho_b / rho_g)^(1/2) D^(2/3) [m^(2/3)]. Throws std::invalid_argument on a
// non-positive parameter.
double ShallowImpactLength(const ShallowImpactParameters& p);
// The depth [m] for a sphere released from rest at height h above the surface (h = 0: touching
// it, d = L^(3/2)). Throws std::invalid_argument on a negative h.
double ShallowImpactDepth(const ShallowImpactParameters& p, double drop_height_m);

}  // namespace touchdown::validation
