#include "rft/bekker_law.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace touchdown::rft {

double BekkerModulus(const BekkerParameters& soil, double plate_b_m) {
  return soil.k_c_N_m_n1 / plate_b_m + soil.k_phi_N_m_n2;
}

double BekkerPressure(const BekkerParameters& soil, double plate_b_m, double depth_m) {
  if (!(depth_m > 0.0)) return 0.0;
  return BekkerModulus(soil, plate_b_m) * std::pow(depth_m, soil.n);
}

double JanosiShearStress(const BekkerParameters& soil, double pressure_Pa, double shear_displacement_m) {
  const double strength = soil.cohesion_Pa + pressure_Pa * std::tan(soil.friction_angle_rad);
  // -expm1(-x) = 1 - exp(-x), accurate for the small displacements right after touchdown.
  return strength * -std::expm1(-shear_displacement_m / soil.shear_modulus_K_m);
}

double BekkerStaticSinkage(const BekkerParameters& soil, double plate_b_m, double area_m2, double weight_N) {
  return std::pow(weight_N / (area_m2 * BekkerModulus(soil, plate_b_m)), 1.0 / soil.n);
}

double FootprintArea(const SurfaceElements& elements) {
  double area = 0.0;
  for (int i = 0; i < elements.size(); ++i) area += elements.area_m2(i) * std::max(0.0, -elements.n_B(2, i));
  return area;
}

double BekkerPlateB(const SurfaceElements& elements) { return std::sqrt(FootprintArea(elements) / std::numbers::pi); }

namespace {
// The direction of the shear per unit of its magnitude on an element: against the horizontal slip,
// weighted by the element's footprint fraction -n_z (0 on walls and upward faces), with the slip
// regularised below kBekkerShearRegularisationSpeed_m_s.
Eigen::Vector3d ShearDirection(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) {
  const double footprint = -n_W.z();
  if (!(footprint > 0.0)) return Eigen::Vector3d::Zero();
  const double slip = std::hypot(v_W.x(), v_W.y());
  if (slip == 0.0) return Eigen::Vector3d::Zero();
  const double scale = footprint / std::max(slip, kBekkerShearRegularisationSpeed_m_s);
  return Eigen::Vector3d(-v_W.x() * scale, -v_W.y() * scale, 0.0);
}
}  // namespace

BekkerLaw3D::BekkerLaw3D(const BekkerParameters& soil, double plate_b_m)
    : modulus_(BekkerModulus(soil, plate_b_m)),
      tan_phi_(std::tan(soil.friction_angle_rad)),
      cohesion_(soil.cohesion_Pa),
      b_(plate_b_m) {}

Eigen::Vector3d BekkerLaw3D::StressPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const {
  Eigen::Vector3d s = -modulus_ * n_W;
  if (tan_phi_ > 0.0) s += (modulus_ * tan_phi_) * ShearDirection(n_W, v_W);
  return s;
}

Eigen::Vector3d BekkerLaw3D::MobilisedShearPerDepth(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const {
  if (!(tan_phi_ > 0.0)) return Eigen::Vector3d::Zero();
  return (modulus_ * tan_phi_) * ShearDirection(n_W, v_W);
}

Eigen::Vector3d BekkerLaw3D::MobilisedShearStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const {
  return cohesion_ * ShearDirection(n_W, v_W);
}

Eigen::Vector3d BekkerLaw3D::DynamicStress(const Eigen::Vector3d& n_W, const Eigen::Vector3d& v_W) const {
  return cohesion_ * ShearDirection(n_W, v_W);
}

Alpha2 BekkerLaw2D::Alpha(double beta_rad, double /*gamma_rad*/) const {
  // A vertical wall (|beta| = pi/2) carries no vertical pressure: exactly 0, not cos(pi/2) ~ 6e-17.
  if (std::abs(beta_rad) >= std::numbers::pi / 2) return {0.0, 0.0};
  return {std::cos(beta_rad), 0.0};
}

}  // namespace touchdown::rft
