#include "lander/multibody/lander_jacobian.h"

#include <cmath>
#include <limits>

namespace touchdown::lander {

namespace {

Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

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
  J.block<3, 3>(L.p_B(), L.v_B()).setIdentity();
  QuaternionRateRows(y, L.quat_B(), L.w_B(), J);
  for (int i = 0; i < kNumLegs; ++i) {
    QuaternionRateRows(y, L.quat_P(i), L.w_P(i), J);
    if (L.stroke_slot[i] >= 0) J(L.stroke(i), L.stroke_rate(i)) = 1.0;
  }
}

// d(soil wrench)/d(joint position, joint velocity) of pad i, by difference quotients of its own
// contact (six evaluations): the body's states reach a pad's contact only through these two.
Eigen::Matrix<double, 6, 6> JointSensitivity(const LanderModel& model, const rft::Terrain& terrain, int i,
                                             const PadFrame& f, const rft::ContactWrench& w0, double h_p, double h_v) {
  const rft::SoilContactModel& contact = terrain.soils[terrain.SoilAt(f.p_WJ.x(), f.p_WJ.y())].contact;
  Eigen::Matrix<double, 6, 6> D;
  for (int k = 0; k < 6; ++k) {
    PadFrame g = f;
    const double h = k < 3 ? h_p : h_v;
    (k < 3 ? g.p_WJ : g.v_WJ_W)[k % 3] += h;
    const rft::ContactWrench w = FreePadSoilWrench(model, contact, i, g, *terrain.surface);
    D.col(k) << (w.force_W - w0.force_W) / h, (w.moment_W - w0.moment_W) / h;
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
  void Column(int j, const GivenSoil* given) {
    const double h = Step(j);
    const int rows = L.size - L.nq;  // speeds, work and the pads' shear displacements
    w.y = y;
    w.y[j] += h;
    EvaluateLander(model, L, terrain, modes, w.y, &w.probe, data, given);
    StateDerivative(L, w.y, w.probe, w.ydot);
    J.block(L.nq, j, rows, 1) = (w.ydot.segment(L.nq, rows) - w.f0.segment(L.nq, rows)) / h;
  }

  // The body's columns: each pad's wrench predicted from its joint's motion (chain rule through
  // JointSensitivity), so no contact is evaluated again.
  void BodyColumns() {
    std::array<Eigen::Matrix<double, 6, 6>, kNumLegs> D;
    for (int i = 0; i < kNumLegs; ++i)
      if (touching[i]) {
        D[i] = JointSensitivity(model, terrain, i, w.base.pose.pads[i], w.base.soil[i], Step(L.p_B()), Step(L.v_B()));
        w.contact_evaluations += 6;
      }
    std::array<int, StateLayout::kBodyPositions + StateLayout::kBodySpeeds> columns{};
    for (int c = 0; c < StateLayout::kBodyPositions; ++c) columns[c] = c;
    for (int c = 0; c < StateLayout::kBodySpeeds; ++c) columns[StateLayout::kBodyPositions + c] = L.nq + c;
    for (int j : columns) {
      w.y = y;  // Column() perturbs it the same way again
      w.y[j] += Step(j);
      const LanderPose moved = ComputePose(model, L, w.y);
      GivenSoil given;
      for (int i = 0; i < kNumLegs; ++i) {
        if (!touching[i]) continue;
        const PadFrame &now = moved.pads[i], &base = w.base.pose.pads[i];
        Eigen::Matrix<double, 6, 1> dx;
        dx << now.p_WJ - base.p_WJ, now.v_WJ_W - base.v_WJ_W;
        const Eigen::Matrix<double, 6, 1> dw = D[i] * dx;
        w.predicted[i] = w.base.soil[i];
        w.predicted[i].force_W += dw.head<3>();
        w.predicted[i].moment_W += dw.tail<3>();
        given.wrench[i] = &w.predicted[i];
      }
      Column(j, &given);
    }
  }

  // A pad's own columns (attitude, spin, stroke): only its contact is evaluated again.
  void PadColumns(int i) {
    GivenSoil given;
    for (int k = 0; k < kNumLegs; ++k)
      if (k != i && touching[k]) given.wrench[k] = &w.base.soil[k];
    std::array<int, StateLayout::kPadPositions + StateLayout::kPadSpeeds + 3> columns{};
    int n = 0;
    for (int c = 0; c < StateLayout::kPadPositions; ++c) columns[n++] = L.quat_P(i) + c;
    for (int c = 0; c < StateLayout::kPadSpeeds; ++c) columns[n++] = L.w_P(i) + c;
    if (L.stroke_slot[i] >= 0) columns[n++] = L.stroke(i), columns[n++] = L.stroke_rate(i);
    if (L.has_shear) columns[n++] = L.shear(i);  // Janosi's j reaches the pad's own contact only
    for (int c = 0; c < n; ++c) Column(columns[c], &given);
    if (touching[i]) w.contact_evaluations += n;
  }
};

}  // namespace

void LanderJacobian(const LanderModel& model, const StateLayout& L, const rft::Terrain& terrain,
                    const LanderModes& modes, const Eigen::Ref<const Eigen::VectorXd>& y, const Eigen::VectorXd& scale,
                    LanderData* data, LanderJacobianData* work, Eigen::Ref<Eigen::MatrixXd> J) {
  PositionRows(L, y, J);
  LanderJacobianData& w = *work;
  EvaluateLander(model, L, terrain, modes, y, &w.base, data);
  w.f0.resize(L.size);
  w.ydot.resize(L.size);
  StateDerivative(L, y, w.base, w.f0);
  w.contact_evaluations += kNumLegs;
  JacobianPass pass{model, L, terrain, modes, y, scale, data, w, J};
  for (int i = 0; i < kNumLegs; ++i)
    pass.touching[i] = modes.pad[i] == PadMode::kFree && PadDepth(model, terrain, i, w.base.pose.pads[i]) > 0.0;
  pass.BodyColumns();
  for (int i = 0; i < kNumLegs; ++i) pass.PadColumns(i);
}

}  // namespace touchdown::lander
