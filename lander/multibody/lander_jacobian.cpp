#include "lander/multibody/lander_jacobian.h"

#include <cmath>
#include <limits>

#include "rft/ground.h"

namespace touchdown::lander {

namespace {

// dq/dt = 1/2 [0, w] (x) q (world-frame w): its derivatives with respect to q and w.
void QuaternionRateRows(const Eigen::Ref<const Eigen::VectorXd>& y, int qi, int wi, Eigen::Ref<Eigen::MatrixXd> J) {
  const double qw = y[qi];
  const Eigen::Vector3d qv = y.segment<3>(qi + 1), w = y.segment<3>(wi);
  J.block<1, 3>(qi, qi + 1) = -0.5 * w.transpose();
  J.block<3, 1>(qi + 1, qi) = 0.5 * w;
  J.block<3, 3>(qi + 1, qi + 1) = 0.5 * Skew(w);
  J.block<1, 3>(qi, wi) = -0.5 * qv.transpose();
  J.block<3, 3>(qi + 1, wi) = 0.5 * (qw * Eigen::Matrix3d::Identity() - Skew(qv));
}

void PositionRows(const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y, Eigen::Ref<Eigen::MatrixXd> J) {
  J.block<3, 3>(L.p_WB(), L.v_WB_W()).setIdentity();
  QuaternionRateRows(y, L.quat_WB(), L.w_WB_W(), J);
  for (int i = 0; i < kNumLegs; ++i) {
    QuaternionRateRows(y, L.quat_WP(i), L.w_WP_W(i), J);
    if (L.stroke_slot[i] >= 0) J(L.stroke(i), L.stroke_rate(i)) = 1.0;
  }
}

// Small rotation (world frame) taking R0 to R1: vee of the skew part of R1 R0^T.
Eigen::Vector3d RotationBetween(const Eigen::Matrix3d& R0, const Eigen::Matrix3d& R1) {
  const Eigen::Matrix3d A = R1 * R0.transpose();
  return 0.5 * Eigen::Vector3d(A(2, 1) - A(1, 2), A(0, 2) - A(2, 0), A(1, 0) - A(0, 1));
}

// How far a pad moved between two poses, as the contact sees it: joint position, attitude (small
// world-frame rotation), joint velocity, spin.
PadMotion MotionBetween(const PadFrame& from, const PadFrame& to) {
  PadMotion dx;
  dx << to.p_WJ - from.p_WJ, RotationBetween(from.R_WP, to.R_WP), to.v_WJ_W - from.v_WJ_W, to.w_WP_W - from.w_WP_W;
  return dx;
}

// d(soil wrench)/d(pad motion) of pad i by one-sided difference quotients of its own contact: the
// wrench depends on the pad's state only through its joint's position and velocity, its attitude
// and its spin (and Janosi's j), so twelve contacts give every column of the Jacobian by the chain
// rule. `attitude` false: without the three attitude columns (see lander_jacobian.h).
struct SensitivitySteps {
  double position, angle, velocity, spin;
};
// Over a plane the contact sees the joint's position only through its depth below the surface: moving
// the pad along the plane changes nothing. So the x and y columns are the z column times the depth's
// gradient over dz (-slope_x, -slope_y): one contact instead of three (on level ground they were
// exactly zero already).
ContactSensitivity PadSensitivity(const LanderModel& model, const rft::Terrain& terrain, int i, const PadFrame& f,
                                  const rft::ContactWrench& w0, const SensitivitySteps& h, bool attitude,
                                  long* contacts) {
  const rft::SoilContactModel& contact = terrain.soils[terrain.SoilAt(f.p_WJ.x(), f.p_WJ.y())].contact;
  const auto* plane = terrain.surface->ExactPlane();
  ContactSensitivity D = ContactSensitivity::Zero();
  for (int k = 0; k < 12; ++k) {
    if (k / 3 == 1 && !attitude) continue;
    if (plane && k < 2) continue;  // from the z column, below
    PadFrame g = f;
    const int axis = k % 3;
    double step = 0.0;
    switch (k / 3) {
      case 0: step = h.position, g.p_WJ[axis] += step; break;
      case 1:
        step = h.angle;
        g.R_WP = Eigen::AngleAxisd(step, Eigen::Vector3d::Unit(axis)).toRotationMatrix() * f.R_WP;
        break;
      case 2: step = h.velocity, g.v_WJ_W[axis] += step; break;
      default: step = h.spin, g.w_WP_W[axis] += step; break;
    }
    const rft::ContactWrench w = FreePadSoilWrench(model, contact, i, g, *terrain.surface);
    D.col(k) << (w.force_W - w0.force_W) / step, (w.moment_W - w0.moment_W) / step;
    ++*contacts;
  }
  if (plane) {
    D.col(0) = -plane->slope_x() * D.col(2);
    D.col(1) = -plane->slope_y() * D.col(2);
  }
  return D;
}

// One Jacobian's evaluation: the base point and the difference quotients around it.
struct JacobianPass {
  const LanderModel& model;
  const StateLayout& L;
  const rft::Terrain& terrain;
  const LanderModes& modes;
  const Eigen::Ref<const Eigen::VectorXd>& y;
  const Eigen::VectorXd& scale;
  LanderData* data;
  LanderJacobianData& w;
  Eigen::Ref<Eigen::MatrixXd> J;
  // Free pads in contact: their wrench moves with the state; the others' does not (a held pad's is
  // a constraint force, formed in every evaluation).
  std::array<bool, kNumLegs> touching{};

  double Step(int j) const {
    return std::sqrt(std::numeric_limits<double>::epsilon()) * std::max(std::abs(y[j]), scale[j]);
  }

  // Column j of the speed and work rows from an evaluation at y + h e_j.
  void Column(int j, const GivenSoil* given, PositionTerms positions = PositionTerms::kForm) {
    const double h = Step(j);
    const int rows = L.size - L.nq;  // speeds, work and the pads' shear displacements
    w.y = y;
    w.y[j] += h;
    EvaluateLander(model, L, terrain, modes, w.y, &w.probe, data, given, positions);
    StateDerivative(L, w.y, w.probe, w.ydot);
    J.block(L.nq, j, rows, 1) = (w.ydot.segment(L.nq, rows) - w.f0.segment(L.nq, rows)) / h;
  }

  void Sensitivities() {
    for (int i = 0; i < kNumLegs; ++i)
      if (touching[i]) {
        const SensitivitySteps h{Step(L.p_WB()), Step(L.quat_WP(i)), Step(L.v_WB_W()), Step(L.w_WP_W(i))};
        w.sensitivity[i] = PadSensitivity(model, terrain, i, w.base.pose.pads[i], w.base.soil[i], h, w.attitude_sensitivity,
                                          &w.contact_evaluations);
      }
  }

  // The base point's position terms (mass matrix factor, constraint decomposition) into `data`,
  // for the speed columns, which move u only. An evaluation at y with the base's wrenches given.
  void KeepPositionTerms() {
    GivenSoil given;
    for (int i = 0; i < kNumLegs; ++i)
      if (touching[i]) given.wrench[i] = &w.base.soil[i];
    EvaluateLander(model, L, terrain, modes, y, &w.probe, data, &given, PositionTerms::kKeep);
  }

  // Column j with every touching pad's wrench predicted to first order from its motion (chain rule
  // through the sensitivities): no contact is evaluated again. `positions`: kReuse for a speed
  // column after KeepPositionTerms.
  void PredictedColumn(int j, PositionTerms positions = PositionTerms::kForm) {
    w.y = y;  // Column() perturbs it the same way again
    w.y[j] += Step(j);
    const LanderPose moved = ComputePose(model, L, w.y);
    GivenSoil given;
    for (int i = 0; i < kNumLegs; ++i) {
      if (!touching[i]) continue;
      const Eigen::Matrix<double, 6, 1> dw = w.sensitivity[i] * MotionBetween(w.base.pose.pads[i], moved.pads[i]);
      w.predicted[i] = w.base.soil[i];
      w.predicted[i].force_W += dw.head<3>();
      w.predicted[i].moment_W += dw.tail<3>();
      given.wrench[i] = &w.predicted[i];
    }
    Column(j, &given, positions);
  }

  // Janosi's j reaches only its own pad's contact (not through the pad's motion): evaluated again.
  void ShearColumn(int i) {
    GivenSoil given;
    for (int k = 0; k < kNumLegs; ++k)
      if (k != i && touching[k]) given.wrench[k] = &w.base.soil[k];
    Column(L.shear(i), &given);
    if (touching[i]) ++w.contact_evaluations;
  }
};

}  // namespace

void LanderJacobian(const LanderModel& model, const StateLayout& L, const rft::Terrain& terrain,
                    const LanderModes& modes, const Eigen::Ref<const Eigen::VectorXd>& y, const Eigen::VectorXd& scale,
                    LanderData* data, LanderJacobianData* work, Eigen::Ref<Eigen::MatrixXd> J,
                    const LanderEvaluation* at_y) {
  PositionRows(L, y, J);
  LanderJacobianData& w = *work;
  if (at_y != nullptr) {
    w.base = *at_y;
  } else {
    EvaluateLander(model, L, terrain, modes, y, &w.base, data);
    w.contact_evaluations += w.base.pad_contacts;
  }
  w.f0.resize(L.size);
  w.ydot.resize(L.size);
  StateDerivative(L, y, w.base, w.f0);
  JacobianPass pass{model, L, terrain, modes, y, scale, data, w, J};
  for (int i = 0; i < kNumLegs; ++i)
    pass.touching[i] = modes.pad[i] == PadMode::kFree && PadDepth(model, terrain, i, w.base.pose.pads[i]) > 0.0;
  pass.Sensitivities();
  for (int j = 0; j < L.nq; ++j) pass.PredictedColumn(j);
  // The speed columns leave q, and so the mass matrix and the holds' constraint Jacobian, as they
  // are at y: their factorisations are formed once (not with added mass, whose mass moves with the
  // contact and so with the speeds' predicted wrenches).
  bool added_mass = false;
  for (const rft::TerrainSoil& soil : terrain.soils) added_mass |= soil.contact.pad_terms.has_added_mass();
  if (!added_mass) pass.KeepPositionTerms();
  for (int j = L.nq; j < L.nq + L.nu; ++j)
    pass.PredictedColumn(j, added_mass ? PositionTerms::kForm : PositionTerms::kReuse);
  if (L.has_shear)
    for (int i = 0; i < kNumLegs; ++i) pass.ShearColumn(i);
}

}  // namespace touchdown::lander
