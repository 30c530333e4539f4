#include "lander/pad/free_pad_dynamics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "rft/deepest_point.h"
#include "rft/entrained_mass.h"

namespace touchdown::pad {

namespace {
using L = FreePadStateLayout;

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
  if (const auto* plane = ground_.ExactPlane()) {
    depth_only_ = true;
    g_W_ = Eigen::Vector3d(plane->slope_x(), plane->slope_y(), -1.0);
  }
}

FreePadPose FreePadDynamics::PoseOf(const Eigen::Ref<const Eigen::VectorXd>& y) const {
  FreePadPose s;
  const Eigen::Quaterniond q(y[L::quat_WB()], y[L::quat_WB() + 1], y[L::quat_WB() + 2], y[L::quat_WB() + 3]);
  s.R_WB = q.normalized().toRotationMatrix();
  s.p_WC = y.segment<3>(L::p_WC());
  s.v_WC = y.segment<3>(L::v_WC_W());
  s.w_B = y.segment<3>(L::w_WB_B());
  s.w_W = s.R_WB * s.w_B;
  s.p_WB = s.p_WC - s.R_WB * body_.com_B;
  s.v_WB = s.v_WC + s.w_W.cross(s.p_WB - s.p_WC);
  if (shear_state_) s.shear_displacement_m = y[L::shear()];
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

// added_mass and added_mass_plug (rft/entrained_mass.h): the entrained cone and plug move with the
// centre of mass's vertical velocity v_z. Grains join at rest (dm_a/dt > 0) or leave with the pad's velocity (< 0), so
// m a_z + m_a a_z = F_z - m g - max(dm_a/dt, 0) v_z (the grains' weight rests on the bed); the
// kinetic energy lost, |dm_a/dt| v_z^2 / 2 (accretion, or carried off by shed grains), counts as
// dissipated with the soil's work. Horizontal motion and rotation keep the pad's own inertia:
// the cone is defined by the vertical stroke.
FreePadVertical FreePadDynamics::Vertical(const FreePadPose& s, const rft::ContactWrench& w,
                                          const rft::SoilContactModel& soil) const {
  FreePadVertical out;
  if (soil.pad_terms.has_added_mass()) {
    const rft::EntrainedMass e = rft::EntrainedGrains(soil.pad_terms, w.penetration_m, w.penetration_rate_m_s,
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

void Derivative(const FreePadDynamics& model, FreePadData& data, const Eigen::Ref<const Eigen::VectorXd>& y,
                Eigen::Ref<Eigen::VectorXd> ydot) {
  const FreePadPose s = model.PoseOf(y);
  const rft::SoilContactModel& soil = model.SoilUnder(s);
  const rft::ContactWrench w = model.Moving(s) ? model.Wrench(s, soil) : rft::ContactWrench{};
  const Eigen::Vector3d M_C = w.moment_W + (s.p_WB - s.p_WC).cross(w.force_W);
  ydot.segment<3>(L::p_WC()) = s.v_WC;
  const Eigen::Vector4d q = y.segment<4>(L::quat_WB());
  const Eigen::Vector3d& wb = s.w_B;
  ydot.segment<4>(L::quat_WB()) << -0.5 * (q[1] * wb.x() + q[2] * wb.y() + q[3] * wb.z()),
      0.5 * (q[0] * wb.x() + q[2] * wb.z() - q[3] * wb.y()), 0.5 * (q[0] * wb.y() + q[3] * wb.x() - q[1] * wb.z()),
      0.5 * (q[0] * wb.z() + q[1] * wb.y() - q[2] * wb.x());
  ydot.segment<3>(L::v_WC_W()) = w.force_W / model.m_ - Eigen::Vector3d(0.0, 0.0, model.g_);
  ydot.segment<3>(L::w_WB_B()) = model.I_inv_ * (s.R_WB.transpose() * M_C - wb.cross(model.I_ * wb));
  ydot[L::work()] = -(w.force_W.dot(s.v_WB) + w.moment_W.dot(s.w_W));
  if (soil.pad_terms.has_added_mass()) {
    const FreePadVertical vz = model.Vertical(s, w, soil);
    ydot[L::v_WC_W() + 2] = vz.a_z;
    ydot[L::work()] += vz.accretion_W;
  }
  // Janosi's j: the horizontal slip of the contact's reference point while the pad is in the soil.
  if (model.shear_state_) ydot[L::shear()] = w.submerged_area_m2 > 0.0 ? std::hypot(s.v_WB.x(), s.v_WB.y()) : 0.0;
  data.pose = s;
  data.soil = w;
}

int FreePadDynamics::JacobianContacts() const { return (depth_only_ ? 1 : 3) + 3 + 3 + 3 + (shear_state_ ? 1 : 0); }

void FreePadDynamics::Jacobian(const Eigen::Ref<const Eigen::VectorXd>& y, const Eigen::Ref<const Eigen::VectorXd>& f0,
                               const Eigen::Ref<const Eigen::VectorXd>& scale, Eigen::Ref<Eigen::MatrixXd> J) const {
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, L::kMaxSize, 1>;  // on the stack
  const int n = size(), soil_rows = n - L::v_WC_W();
  const double root_eps = std::sqrt(std::numeric_limits<double>::epsilon());
  State yp = y, fp(n);
  FreePadData probe;
  J.setZero();
  // The soil's rows (v, w, work, j) of one column: a forward difference of step h along yp - y.
  auto difference = [&](double h) -> Eigen::Ref<const Eigen::VectorXd> {
    Derivative(*this, probe, yp, fp);
    fp.tail(soil_rows) = (fp.tail(soil_rows) - f0.tail(soil_rows)) / h;
    yp = y;
    return fp.tail(soil_rows);
  };
  auto step = [&](int i) { return root_eps * std::max(std::abs(y[i]), scale[i]); };
  // Position: dp/dt = v; the soil's columns.
  for (int i = 0; i < 3; ++i) J(L::p_WC() + i, L::v_WC_W() + i) = 1.0;
  if (depth_only_) {  // d/dp = g_W d/d(depth); the difference along -z (depth grows by h)
    const double h = step(L::p_WC() + 2);
    yp[L::p_WC() + 2] -= h;
    const Eigen::Ref<const Eigen::VectorXd> dF = difference(h);
    for (int i = 0; i < 3; ++i) J.col(L::p_WC() + i).tail(soil_rows) = g_W_[i] * dF;
  } else {
    for (int i = 0; i < 3; ++i) {
      const double h = step(L::p_WC() + i);
      yp[L::p_WC() + i] += h;
      J.col(L::p_WC() + i).tail(soil_rows) = difference(h);
    }
  }
  // Attitude: dq/dt = q (x) (0, w) / 2 is linear in q and w. The soil's rows depend on q / |q|
  // alone: differences along body-frame rotations theta_k, q' = q (x) (cos h/2, sin h/2 e_k) (same
  // norm); then d/dq_i = (2 / |q|) sum_k (q^ (x) e_k)_i d/dtheta_k, the tangent part of e_i.
  const Eigen::Vector4d q = y.segment<4>(L::quat_WB());
  const Eigen::Vector3d w = y.segment<3>(L::w_WB_B());
  Eigen::Matrix4d dqdot_dq;
  dqdot_dq << 0.0, -w.x(), -w.y(), -w.z(), w.x(), 0.0, w.z(), -w.y(), w.y(), -w.z(), 0.0, w.x(), w.z(), w.y(), -w.x(), 0.0;
  J.block<4, 4>(L::quat_WB(), L::quat_WB()) = 0.5 * dqdot_dq;
  Eigen::Matrix<double, 4, 3> qe;  // column k: q (x) (0, e_k)
  qe << -q[1], -q[2], -q[3], q[0], -q[3], q[2], q[3], q[0], -q[1], -q[2], q[1], q[0];
  J.block<4, 3>(L::quat_WB(), L::w_WB_B()) = 0.5 * qe;
  const double norm = q.norm(), h_rot = root_eps;
  for (int k = 0; k < 3; ++k) {
    yp.segment<4>(L::quat_WB()) = std::cos(0.5 * h_rot) * q + std::sin(0.5 * h_rot) * qe.col(k);
    const Eigen::Ref<const Eigen::VectorXd> dF = difference(h_rot);
    for (int i = 0; i < 4; ++i) J.col(L::quat_WB() + i).tail(soil_rows) += (2.0 * qe(i, k) / (norm * norm)) * dF;
  }
  // Velocity, angular velocity and (with Janosi's shear) j: plain differences; work: no column.
  for (const int i : {L::v_WC_W(), L::v_WC_W() + 1, L::v_WC_W() + 2, L::w_WB_B(), L::w_WB_B() + 1, L::w_WB_B() + 2}) {
    const double h = step(i);
    yp[i] += h;
    J.col(i).tail(soil_rows) = difference(h);
  }
  if (shear_state_) {
    const double h = step(L::shear());
    yp[L::shear()] += h;
    J.col(L::shear()).tail(soil_rows) = difference(h);
  }
}

double FreePadDynamics::RestCapacity(const FreePadPose& s) const {
  rft::PadKinematics down{s.R_WB, s.p_WB, Eigen::Vector3d(0.0, 0.0, -rft::kQuasiStaticProbeSpeed_m_s),
                            Eigen::Vector3d::Zero()};
  const rft::SoilContactModel& soil = SoilUnder(s);
  return rft::ComputeContactWrench(body_.surface, down, ground_, *soil.law, soil.pad_terms).force_W.z();
}

double FreePadDynamics::KineticEnergy(const FreePadPose& s) const {
  return 0.5 * m_ * s.v_WC.squaredNorm() + 0.5 * s.w_B.dot(I_ * s.w_B);
}

}  // namespace touchdown::pad
