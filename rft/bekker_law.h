#pragma once
// Classical terramechanics beside RFT: Bekker's pressure-sinkage law and the Janosi-Hanamoto shear
// law (Bekker 1969; Wong, Theory of Ground Vehicles, ch. 2), as pure functions and as a 3D stress
// law for the element contact (rft/contact_wrench.h). docs/bekker_soil.md argues the choices.
//
//   pressure   p = (k_c / b + k_phi) z^n     on elements that press into the soil (z their depth)
//   shear      tau = (c + p tan phi)(1 - exp(-j / K))   against the tangential motion
//
// b is a dimension of the pad, not of the soil: BekkerPlateB takes it from the pad's footprint
// (the radius of the circle of the footprint's area; a circular plate's radius exactly). It is
// fixed per pad, so the modulus k_c / b + k_phi is a constant of a drop and the pressure is the
// depth power law of rft/pad_level_terms.h with z_ref = 1 m.
//
// Bekker's moduli carry no gravity: the same soil gives the same pressure on the Moon and on Earth
// (RFT's zeta scales with g). Plastic, as RFT: only elements that lead the motion are loaded.
#include <Eigen/Core>
#include <string_view>

#include "rft/bekker_parameters.h"
#include "rft/stress_law.h"
#include "rft/stress_law_3d.h"
#include "rft/surface_elements.h"

namespace touchdown::rft {

// k_c / b + k_phi [N/m^(n+2)] for a plate of smaller dimension (radius) b [m] > 0.
double BekkerModulus(const BekkerParameters& soil, double plate_b_m);
// Bekker's pressure [Pa] at depth z >= 0 (0 above the surface).
double BekkerPressure(const BekkerParameters& soil, double plate_b_m, double depth_m);
// Janosi-Hanamoto shear stress [Pa] under normal pressure p [Pa] after a shear displacement j >= 0 [m].
double JanosiShearStress(const BekkerParameters& soil, double pressure_Pa, double shear_displacement_m);
// The static sinkage [m] of a flat plate of area A [m^2] and dimension b under a weight W [N]:
// z = (W / (A (k_c / b + k_phi)))^(1/n).
double BekkerStaticSinkage(const BekkerParameters& soil, double plate_b_m, double area_m2, double weight_N);

// The footprint of a pad: the horizontal projection of its downward-facing surface (n_z < 0) in the
// pad frame [m^2], and b = sqrt(A / pi), the radius of the circle of that area.
double FootprintArea(const SurfaceElements& elements);
double BekkerPlateB(const SurfaceElements& elements);

// Below this tangential slip speed the fully mobilised shear grows linearly with the speed, so the
// force stays Lipschitz in the velocity (CVODE) and a pad at rest feels no shear direction. A
// numerical regularisation [m/s], not soil data.
inline constexpr double kBekkerShearRegularisationSpeed_m_s = 1e-3;

// The 3D law of a Bekker soil for a pad of dimension b. On an element that leads (the contact
// decides): the pressure (k_c / b + k_phi) against the outward normal, per unit depth^n (the
// contact weights it by z^n through PadLevelTerms::depth = {n, 1 m}; MakeSoilContactModel sets it),
// and, on the element's footprint (its downward-facing part, -n_z dA), the Janosi shear against the
// horizontal slip: tan(phi) times the pressure per unit depth^n here, the cohesion c as the
// depth-independent DynamicStress, both fully mobilised; the contact scales them by
// 1 - exp(-j / K) for the pad's shear displacement j (a state of the free pad and of the lander's
// pads, docs/bekker_soil.md), through MobilisedShearPerDepth / MobilisedShearStress.
class BekkerLaw3D final : public StressLaw3D {
 public:
  BekkerLaw3D(const BekkerParameters& soil, double plate_b_m);
  std::string_view name() const override { return "bekker"; }
  LawKind kind() const override { return LawKind::kBekker; }
  Eigen::Vector3d StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  bool has_dynamic_stress() const override { return cohesion_ > 0.0; }
  Eigen::Vector3d DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  // The Janosi shear of the two stresses above (tan phi p and c on the footprint), which the
  // contact scales by 1 - exp(-j / K) (PadKinematics::shear_mobilisation).
  bool has_mobilised_shear() const override { return tan_phi_ > 0.0 || cohesion_ > 0.0; }
  Eigen::Vector3d MobilisedShearPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  Eigen::Vector3d MobilisedShearStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const override;
  double modulus() const { return modulus_; }
  double plate_b_m() const { return b_; }

 private:
  double modulus_, tan_phi_, cohesion_, b_;
};

// The rig's 2D form (footpad_geom/axisymmetric_intrusion.h): a normal pressure on an element of
// attack angle beta pushes up with cos(beta) per unit area, whatever the intrusion angle, so
// alpha_z = cos(beta) (0 on a vertical wall) and the profile integral is the footprint integral of
// p. The intrusion's zeta is then the modulus k_c / b + k_phi and its depth law z^n.
class BekkerLaw2D final : public StressLaw2D {
 public:
  std::string_view name() const override { return "bekker"; }
  Alpha2 Alpha(double beta_rad, double gamma_rad) const override;
};

}  // namespace touchdown::rft
