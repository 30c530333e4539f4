#include "lander/pad/free_pad_dynamics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "rft/deepest_point.h"
#include "rft/entrained_mass.h"

namespace touchdown::pad {

namespace {
double BodyRadius(const geom::PadBody& body) {
  return body.vertices_B.cols() > 0 ? (body.vertices_B.colwise() - body.com_B).colwise().norm().maxCoeff() : 0.0;
}
}  // namespace

FreePadDynamics::FreePadDynamics(const geom::PadBody& body, const rft::Terrain& terrain, double gravity_m_s2)
    : body_(body),
      terrain_(terrain),
      ground_(*terrain.surface),
      m_(body.mass_kg),
      g_(gravity_m_s2),
      I_(body.inertia_com_B),
      I_inv_(body.inertia_com_B.inverse()),
      radius_(BodyRadius(body)) {
  for (const rft::TerrainSoil& soil : terrain.soils) shear_state_ |= soil.contact.has_janosi_shear();
}

FreePadPose FreePadDynamics::PoseOf(const Eigen::Ref<const Eigen::VectorXd>& y) const {
  FreePadPose s;
  const Eigen::Quaterniond q(y[kQ], y[kQ + 1], y[kQ + 2], y[kQ + 3]);
  s.R_WB = q.normalized().toRotationMatrix();
  s.p_WC = y.segment<3>(kP);
  s.v_WC = y.segment<3>(kV);
  s.w_B = y.segment<3>(kW);
  s.w_W = s.R_WB * s.w_B;
  s.p_WB = s.p_WC - s.R_WB * body_.com_B;
  s.v_WB = s.v_WC + s.w_W.cross(s.p_WB - s.p_WC);
  if (shear_state_) s.shear_displacement_m = y[kShearDisplacement];
  return s;
}

double FreePadDynamics::Depth(const FreePadPose& s) const {
  return rft::DeepestVertexDepth(geom::DeepestPointCandidates(body_, ground_), s.R_WB, s.p_WB, ground_);
}

bool FreePadDynamics::Moving(const FreePadPose& s) const {
  return s.v_WB.squaredNorm() + s.w_W.squaredNorm() * radius_ * radius_ > 0.0;
}

const rft::SoilContactModel& FreePadDynamics::SoilUnder(const FreePadPose& s) const {
  return terrain_.soils[terrain_.SoilAt(s.p_WB.x(), s.p_WB.y())].contact;
}

rft::ContactWrench FreePadDynamics::Wrench(const FreePadPose& s, const rft::SoilContactModel& soil) const {
  rft::PadKinematics k{s.R_WB, s.p_WB, s.v_WB, s.w_W};
  if (soil.has_janosi_shear()) k.shear_mobilisation = soil.ShearMobilisation(s.shear_displacement_m);
  return rft::ComputeContactWrench(body_.surface, k, ground_, *soil.law, soil.pad_terms);
}

// added_mass (rft/entrained_mass.h): the entrained cone moves with the centre of mass's vertical
// velocity v_z. Grains join at rest (dm_a/dt > 0) or leave with the pad's velocity (< 0), so
// m a_z + m_a a_z = F_z - m g - max(dm_a/dt, 0) v_z (the grains' weight rests on the bed); the
// kinetic energy lost, |dm_a/dt| v_z^2 / 2 (accretion, or carried off by shed grains), counts as
// dissipated with the soil's work. Horizontal motion and rotation keep the pad's own inertia:
// the cone is defined by the vertical stroke.
FreePadVertical FreePadDynamics::Vertical(const FreePadPose& s, const rft::ContactWrench& w,
                                          const rft::SoilContactModel& soil) const {
  FreePadVertical out;
  const double added_density = soil.pad_terms.added_mass_density_kg_m3;
  if (added_density > 0.0) {
    const rft::EntrainedMass e = rft::EntrainedCone(added_density, w.penetration_m, w.penetration_rate_m_s,
                                                    w.footprint_area_m2, w.footprint_area_rate_m2_s);
    const double v_z = s.v_WC.z();
    const double accretion = -std::max(e.rate_kg_s, 0.0) * v_z;  // upward while sinking
    out.a_z = (w.force_W.z() - m_ * g_ + accretion) / (m_ + e.mass_kg);
    out.accretion_W = 0.5 * std::abs(e.rate_kg_s) * v_z * v_z;
    out.force_z = m_ * (out.a_z + g_);
    if (e.mass_kg == 0.0 && accretion == 0.0) out.force_z = w.force_W.z();
  } else {
    out.a_z = w.force_W.z() / m_ - g_;
    out.force_z = w.force_W.z();
  }
  return out;
}

void FreePadDynamics::Derivative(const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::VectorXd> ydot) const {
  const FreePadPose s = PoseOf(y);
  const rft::SoilContactModel& soil = SoilUnder(s);
  const rft::ContactWrench w = Moving(s) ? Wrench(s, soil) : rft::ContactWrench{};
  const Eigen::Vector3d M_C = w.moment_W + (s.p_WB - s.p_WC).cross(w.force_W);
  ydot.segment<3>(kP) = s.v_WC;
  const Eigen::Vector4d q = y.segment<4>(kQ);
  const Eigen::Vector3d& wb = s.w_B;
  ydot.segment<4>(kQ) << -0.5 * (q[1] * wb.x() + q[2] * wb.y() + q[3] * wb.z()),
      0.5 * (q[0] * wb.x() + q[2] * wb.z() - q[3] * wb.y()), 0.5 * (q[0] * wb.y() + q[3] * wb.x() - q[1] * wb.z()),
      0.5 * (q[0] * wb.z() + q[1] * wb.y() - q[2] * wb.x());
  ydot.segment<3>(kV) = w.force_W / m_ - Eigen::Vector3d(0.0, 0.0, g_);
  ydot.segment<3>(kW) = I_inv_ * (s.R_WB.transpose() * M_C - wb.cross(I_ * wb));
  ydot[kWork] = -(w.force_W.dot(s.v_WB) + w.moment_W.dot(s.w_W));
  if (soil.pad_terms.added_mass_density_kg_m3 > 0.0) {
    const FreePadVertical vz = Vertical(s, w, soil);
    ydot[kV + 2] = vz.a_z;
    ydot[kWork] += vz.accretion_W;
  }
  // Janosi's j: the horizontal slip of the contact's reference point while the pad is in the soil.
  if (shear_state_) ydot[kShearDisplacement] = w.submerged_area_m2 > 0.0 ? std::hypot(s.v_WB.x(), s.v_WB.y()) : 0.0;
}

double FreePadDynamics::RestCapacity(const FreePadPose& s) const {
  rft::PadKinematics down{s.R_WB, s.p_WB, Eigen::Vector3d(0.0, 0.0, -1e-6), Eigen::Vector3d::Zero()};
  const rft::SoilContactModel& soil = SoilUnder(s);
  return rft::ComputeContactWrench(body_.surface, down, ground_, *soil.law, soil.pad_terms).force_W.z();
}

double FreePadDynamics::KineticEnergy(const FreePadPose& s) const {
  return 0.5 * m_ * s.v_WC.squaredNorm() + 0.5 * s.w_B.dot(I_ * s.w_B);
}

}  // namespace touchdown::pad
