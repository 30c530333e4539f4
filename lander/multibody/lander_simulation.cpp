#include "lander/multibody/lander_simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "lander/integ/hybrid_run.h"
#include "lander/multibody/lander_hybrid.h"

namespace touchdown::lander {

namespace {

Eigen::VectorXd Pack(const StateLayout& L, const LanderInitialState& s) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(L.size);
  auto put_quat = [&](int i, const Eigen::Matrix3d& R) {
    const Eigen::Quaterniond q(R);
    y.segment<4>(i) << q.w(), q.x(), q.y(), q.z();
  };
  y.segment<3>(L.p_WB()) = s.p_WB;
  put_quat(L.quat_WB(), s.R_WB);
  y.segment<3>(L.v_WB_W()) = s.v_WB_W;
  y.segment<3>(L.w_WB_W()) = s.w_WB_W;
  for (int i = 0; i < kNumLegs; ++i) {
    put_quat(L.quat_WP(i), s.R_WP[i]);
    y.segment<3>(L.w_WP_W(i)) = s.w_WB_W;  // the pads turn with the body at release
    if (L.stroke_slot[i] >= 0) y[L.stroke(i)] = s.stroke_m[i];
  }
  return y;
}

// The absolute tolerance of each state: rtol times the landing's scale for that state (unless the
// options give component_atol or ask for the scalar atol). Why: states that stay near zero - a
// pad's spin about its ball joint, the roll rate of a symmetric landing - would be resolved to a
// scalar 1e-11 in their own unit, radians per second included (docs/lander_dynamics.md has the
// step counts).
//   length L: the largest distance of a ball joint from the body's centre of mass; pad size l:
//   the largest pad vertex distance from its joint; speed V: the initial speed plus sqrt(2 g L);
//   angles 1 rad; angular speeds V / L (body) and V / l (pads, times options.
//   pad_spin_tolerance_factor); energy M V^2 / 2 + M g L.
integ::IntegratorOptions ScaledTolerances(const LanderModel& model, const StateLayout& L,
                                          const LanderInitialState& initial, const LanderRunOptions& options) {
  integ::IntegratorOptions o = options.integrator;
  if (!o.component_atol.empty() || !options.scale_tolerances) return o;
  double length = 0.0, pad = 0.0;
  for (const Leg& leg : model.legs) {
    length = std::max(length, leg.joint_B.norm());
    if (leg.pad->vertices_B.cols() > 0) pad = std::max(pad, leg.pad->vertices_B.colwise().norm().maxCoeff());
  }
  if (!(length > 0.0)) length = 1.0;
  if (!(pad > 0.0)) pad = length;
  const double g = model.gravity_m_s2;
  const double V = initial.v_WB_W.norm() + std::sqrt(2.0 * g * length) + 1e-3;
  const double M = model.TotalMass(), E = 0.5 * M * V * V + M * g * length;
  const double r = o.rtol;
  o.component_atol.assign(L.size, r);  // quaternions
  for (int k = 0; k < 3; ++k) {
    o.component_atol[L.p_WB() + k] = r * length;
    o.component_atol[L.v_WB_W() + k] = r * V;
    o.component_atol[L.w_WB_W() + k] = r * V / length;
    for (int i = 0; i < kNumLegs; ++i)
      o.component_atol[L.w_WP_W(i) + k] = r * V / pad * options.pad_spin_tolerance_factor;
  }
  for (int i = 0; i < kNumLegs; ++i) {
    if (L.stroke_slot[i] < 0) continue;
    o.component_atol[L.stroke(i)] = r * length;
    o.component_atol[L.stroke_rate(i)] = r * V;
  }
  o.component_atol[L.work()] = r * E;
  if (L.has_shear)
    for (int i = 0; i < kNumLegs; ++i) o.component_atol[L.shear(i)] = r * length;
  return o;
}

}  // namespace

double BodyHeightForClearance(const LanderModel& model, const rft::Terrain& terrain, const LanderInitialState& state,
                              double clearance_m) {
  const StateLayout L(model);
  LanderInitialState s = state;
  s.p_WB.z() = 0.0;
  const Eigen::VectorXd y = Pack(L, s);
  const LanderPose p = ComputePose(model, L, y);
  double depth = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < kNumLegs; ++i) depth = std::max(depth, PadDepth(model, terrain, i, p.pads[i]));
  return depth + clearance_m;
}

LanderRunResult SimulateLander(const LanderSetup& setup) {
  const LanderModel& model = setup.model;
  const LanderInitialState& initial = setup.initial;
  const LanderRunOptions& options = setup.options;
  if (!(options.duration_s > 0.0) || !(options.sample_rate_hz > 0.0) || !(options.capture_speed_m_s >= 0.0))
    throw std::invalid_argument("SimulateLander: invalid options");
  LanderRunResult result;
  LanderHybrid lander(model, setup.terrain, options, result);
  const StateLayout& L = lander.layout();
  const integ::IntegratorOptions tolerances = ScaledTolerances(model, L, initial, options);
  integ::CvodeIntegrator integrator(
      L.size,
      [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot) { lander.Derivative(y, ydot); },
      tolerances, lander.RootFunctions());
  // Each state's typical size, atol / rtol, sizes the Jacobian's difference quotients.
  Eigen::VectorXd scale = Eigen::VectorXd::Constant(L.size, tolerances.atol / tolerances.rtol);
  if (!tolerances.component_atol.empty())
    scale = Eigen::Map<const Eigen::VectorXd>(tolerances.component_atol.data(), L.size) / tolerances.rtol;
  if (tolerances.stiff)
    integrator.SetJacobian([&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<const Eigen::VectorXd>,
                               Eigen::Ref<Eigen::MatrixXd> J) { lander.Jacobian(y, scale, J); });

  const Eigen::VectorXd y0 = Pack(L, initial);
  result.initial_energy_J = KineticEnergy(model, L, y0) + PotentialEnergy(model, L, y0);
  lander.StopsAtRelease(y0);
  integ::HybridRun run(integrator);
  run.Start(0.0, y0);
  const bool over_at_release = lander.TouchdownsAtRelease(y0);
  lander.Record(0.0, y0);
  if (over_at_release) {
    lander.Finish(0.0, y0);
    result.solver = run.summary().solver;
    return result;
  }

  integ::HybridPhase phase;
  phase.sample_rate_hz = options.sample_rate_hz;
  phase.end_s = options.duration_s;
  phase.end = integ::RunEnd::kSampleAtEnd;
  phase.max_events = options.max_events;
  phase.name = "lander";
  integ::HybridCallbacks calls;
  calls.sample = [&](double t, const Eigen::VectorXd& y) { lander.Record(t, y); };
  calls.event = [&](double t, const std::vector<int>& found, Eigen::VectorXd& y) { return lander.OnEvent(t, found, y); };
  calls.stop_after_sample = [&](double t) { return lander.RestsAtCreep(t); };
  const integ::HybridOutcome end = run.Run(phase, calls);

  double t_end = end.t;
  if (lander.at_rest()) {
    // The remaining samples repeat the one just recorded from the rest state (same state, same
    // evaluation): nothing is integrated.
    const double dt = 1.0 / options.sample_rate_hz;
    const LanderSample at_rest = result.trace.back();
    for (long k = end.next_sample; k * dt <= options.duration_s + 1e-12; ++k) {
      result.trace.push_back(at_rest);
      result.trace.back().t_s = k * dt;
    }
    t_end = options.duration_s;
  }
  lander.Finish(t_end, end.y);
  result.solver = run.summary().solver;
  return result;
}

}  // namespace touchdown::lander
