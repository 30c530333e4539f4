#include "lander/pad/free_drop.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "lander/integ/hybrid_run.h"
#include "lander/pad/free_pad_dynamics.h"
#include "lander/pad/pad_pose.h"
#include "lander/pad/vertical_peaks.h"
#include "rft/units.h"

namespace touchdown::pad {

namespace {
using S = FreePadStateLayout;

// The absolute tolerance of each state: rtol times the drop's own scale for that state (unless the
// caller gave component_atol). Why: a state that stays near zero - the rotation about an axis the
// drop is symmetric about, a level pad's spin - would be resolved to a scalar atol of 1e-11 in its
// own unit; the mesh's small asymmetries drive it, and the 5-degree tilted drop would spend 12 times
// the steps resolving 1e-4 rad/s of wobble to 1e-11 rad/s (the depth and tilt agree to 1e-6 with
// these scales; tests/lander/pad/free_drop_test.cpp).
//   length L: the pad's radius about its centre of mass; speed V: the largest of the impact speed,
//   the horizontal speed, spin times L and sqrt(g L); angle: 1 rad; angular speed V / L;
//   energy: m V^2 / 2 + m g L.
integ::IntegratorOptions WithScaledTolerances(integ::IntegratorOptions options, const geom::PadBody& body,
                                              const FreeDropInput& in, double radius, int size) {
  if (!options.component_atol.empty()) return options;
  const double L = radius > 0.0 ? radius : 1.0;
  const double V = std::max({in.impact_speed_m_s, std::abs(in.horizontal_speed_m_s), in.omega_W.norm() * L,
                             std::sqrt(in.gravity_m_s2 * L)});
  const double E = 0.5 * body.mass_kg * V * V + body.mass_kg * in.gravity_m_s2 * L;
  const double r = options.rtol;
  options.component_atol.assign(size, 0.0);
  for (int i = 0; i < 3; ++i) {
    options.component_atol[S::p_WC() + i] = r * L;
    options.component_atol[S::v_WC_W() + i] = r * V;
    options.component_atol[S::w_WB_B() + i] = r * V / L;
  }
  for (int i = 0; i < 4; ++i) options.component_atol[S::quat_WB() + i] = r;
  options.component_atol[S::work()] = r * E;
  if (size > S::shear()) options.component_atol[S::shear()] = r * L;
  return options;
}

void Validate(const geom::PadBody& body, const FreeDropInput& in) {
  if (!(body.mass_kg > 0.0) || body.surface.size() == 0 || body.vertices_B.cols() == 0)
    throw std::invalid_argument("RunFreeDrop: empty pad body");
  if (!(in.gravity_m_s2 > 0.0) || !(in.impact_speed_m_s >= 0.0) || !std::isfinite(in.horizontal_speed_m_s) ||
      !std::isfinite(in.tilt_rad) || !in.omega_W.allFinite())
    throw std::invalid_argument("RunFreeDrop: invalid input");
}

// Roots: [0] touchdown (depth rises through 0), looked for during the approach only (the stroke
// starts on the surface, depth 0 at t = 0, which CVODE would report as a root at its start; a pad
// that bounces off the soil flies on in the same stroke); [1] rest (speed falls below the threshold);
// only with Janosi's j as a state: [2] lift-off (the lowest point rises kLiftOffClearance above the
// surface: not at the stroke's start, where the depth is 0), which resets j.
constexpr double kLiftOffClearance = 1e-9;  // [m], a numerical margin
integ::RootSpec FreeDropRoots(const FreePadDynamics& pad, double rest_speed, const bool& approaching) {
  integ::RootSpec roots;
  const bool shear = pad.has_shear_state();
  roots.count = shear ? 3 : 2;
  roots.directions = {+1, -1};
  if (shear) roots.directions.push_back(-1);
  const double radius = pad.radius_m();
  roots.function = [&pad, rest_speed, radius, &approaching](double, Eigen::Ref<const Eigen::VectorXd> y,
                                                             Eigen::Ref<Eigen::VectorXd> gv) {
    const FreePadPose s = pad.PoseOf(y);
    gv[0] = approaching ? pad.Depth(s) : -1.0;
    gv[1] = s.v_WC.squaredNorm() + s.w_W.squaredNorm() * radius * radius - rest_speed * rest_speed;
    if (gv.size() > 2) gv[2] = approaching ? 1.0 : pad.Depth(s) + kLiftOffClearance;
  };
  return roots;
}

// The state at release: tilted, lowest point `clearance` above the surface, speed chosen to reach
// the requested vertical impact speed at touchdown.
Eigen::VectorXd ReleaseState(const FreePadDynamics& pad, const FreeDropInput& in, double clearance) {
  const double g = pad.gravity_m_s2(), v_td = in.impact_speed_m_s;
  const Eigen::Matrix3d R0 = TiltRotation(in.tilt_axis, in.tilt_rad);
  const Eigen::Quaterniond q0(R0);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(pad.size());
  y.segment<3>(S::p_WC()) = PlaceAtDepth(pad.body(), R0, -clearance) + R0 * pad.body().com_B;
  y.segment<4>(S::quat_WB()) << q0.w(), q0.x(), q0.y(), q0.z();
  y.segment<3>(S::v_WC_W()) << in.horizontal_speed_m_s, 0.0, -ReleaseSpeed(v_td, g, clearance);
  y.segment<3>(S::w_WB_B()) = R0.transpose() * in.omega_W;
  return y;
}

// Free flight to touchdown. Touchdown defines t = 0, with the lowest point on the surface, as in
// the rig drop: the root is located only to rounding, and a depth of +1e-18 m already submerges a
// flat bottom whole (a depth-independent term such as compaction_peak would then act on its full
// area in the sample at t = 0). A shift of that size, up to the last representable step.
Eigen::VectorXd Approach(integ::HybridRun& run, const FreePadDynamics& pad, const Eigen::VectorXd& release,
                         double clearance) {
  run.Start(0.0, release);
  Eigen::VectorXd y = run.AdvanceToRoot(ApproachTimeLimit(clearance, pad.gravity_m_s2()), 0,
                                        "touchdown was not reached during the approach");
  y[S::p_WC() + 2] += pad.Depth(pad.PoseOf(y));
  for (int i = 0; i < 8 && pad.Depth(pad.PoseOf(y)) > 0.0; ++i)
    y[S::p_WC() + 2] = std::nextafter(y[S::p_WC() + 2], std::numeric_limits<double>::infinity());
  return y;
}

// The stroke from touchdown (state y0 at t = 0): samples at the output rate until the rest event
// with enough static capacity, and the drop's summary.
FreeDropResult Stroke(integ::HybridRun& run, const FreePadDynamics& pad, const Eigen::VectorXd& y0,
                      const FreeDropOptions& options) {
  const double m = pad.mass_kg(), g = pad.gravity_m_s2();
  FreeDropResult result;
  const FreePadPose s0 = pad.PoseOf(y0);
  const double z_C0 = s0.p_WC.z();
  const Eigen::Vector2d xy_C0 = s0.p_WC.head<2>();
  result.impact_energy_J = pad.KineticEnergy(s0);
  result.touchdown_tilt_deg = units::RadToDeg(TiltFromVertical(s0.R_WB));
  auto record = [&](double t, const Eigen::VectorXd& state) {
    const FreePadPose s = pad.PoseOf(state);
    const bool moving = pad.Moving(s);
    // At rest the soil carries the weight: report the static reaction, as the rig drop does.
    Eigen::Vector3d f(0.0, 0.0, m * g);
    if (moving) {
      const rft::SoilContactModel& soil = pad.SoilUnder(s);
      const rft::ContactWrench w = pad.Wrench(s, soil);
      f = w.force_W;
      f.z() = pad.Vertical(s, w, soil).force_z;
    }
    result.trace.push_back({t, std::max(pad.Depth(s), 0.0), -s.v_WC.z(), f.z(), f.x(), s.p_WC.x() - xy_C0.x(),
                            units::RadToDeg(TiltFromVertical(s.R_WB))});
    FreeDropSample& pose = result.trace.back();
    pose.p_WB = s.p_WB;
    pose.q_WB = state.segment<4>(S::quat_WB()).normalized();
    pose.v_WB_W = s.v_WB;
    pose.w_W = s.w_W;
    pose.shear_displacement_m = s.shear_displacement_m;
    result.peak_force_N = std::max(result.peak_force_N, f.z());
    if (moving) result.max_deceleration_m_s2 = std::max(result.max_deceleration_m_s2, f.z() / m - g);
  };
  record(0.0, y0);

  integ::HybridPhase stroke;
  stroke.sample_rate_hz = options.sample_rate_hz;
  stroke.end_s = options.max_duration_s;
  stroke.end = integ::RunEnd::kFailPastEnd;
  stroke.failure = "the pad did not come to rest within " + std::to_string(options.max_duration_s) + " s";
  integ::HybridCallbacks calls;
  calls.sample = record;
  calls.event = [&](double t, const std::vector<int>& found, Eigen::VectorXd& s) {
    if (found.size() > 2 && found[2] != 0) {  // lift-off: the next contact shears fresh soil
      ++result.lift_offs;
      s[S::shear()] = 0.0;
      return integ::EventAction::kRestart;
    }
    if (found[1] == 0) return integ::EventAction::kContinue;  // not the rest event
    // Slow enough: rest if pushing straight down meets at least the weight.
    const FreePadPose probe = pad.PoseOf(s);
    if (pad.RestCapacity(probe) < m * g) return integ::EventAction::kContinue;
    result.final_kinetic_energy_J = pad.KineticEnergy(probe);
    s.segment<3>(S::v_WC_W()).setZero();
    s.segment<3>(S::w_WB_B()).setZero();
    record(t, s);
    return integ::EventAction::kStop;
  };
  // Between samples too: a stiff soil stops the pad within one sample period.
  VerticalPeaks peaks(pad.size(), S::v_WC_W() + 2, 1.0, m, g);
  calls.segment = [&](const integ::DenseSegment& segment) { peaks.Observe(segment); };
  const integ::HybridOutcome rest = run.Run(stroke, calls);
  result.peak_force_N = std::max(result.peak_force_N, peaks.peak_force_N());
  result.max_deceleration_m_s2 = std::max(result.max_deceleration_m_s2, peaks.max_deceleration_m_s2());
  const FreePadPose end = pad.PoseOf(rest.y);
  result.time_to_rest_s = rest.t;
  result.final_penetration_m = std::max(pad.Depth(end), 0.0);
  result.dissipated_energy_J = rest.y[S::work()];
  result.gravity_work_J = m * g * (z_C0 - end.p_WC.z());
  result.final_tilt_deg = units::RadToDeg(TiltFromVertical(end.R_WB));
  result.horizontal_travel_m = (end.p_WC.head<2>() - xy_C0).norm();
  if (pad.has_shear_state()) result.final_shear_displacement_m = rest.y[S::shear()];
  result.solver = run.summary().solver;
  return result;
}

}  // namespace

FreeDropResult RunFreeDrop(const FreeDropSetup& setup) {
  if (!setup.body) throw std::invalid_argument("RunFreeDrop: no pad body");
  const geom::PadBody& body = *setup.body;
  const FreeDropInput& in = setup.initial;
  const FreeDropOptions& options = setup.options;
  Validate(body, in);
  const FreePadDynamics pad(body, setup.terrain, in.gravity_m_s2);
  bool approaching = true;
  const integ::IntegratorOptions tolerances =
      WithScaledTolerances(options.integrator, body, in, pad.radius_m(), pad.size());
  FreePadData data;
  integ::CvodeIntegrator integrator(
      pad.size(),
      [&pad, &data](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot) { Derivative(pad, data, y, ydot); },
      tolerances, FreeDropRoots(pad, options.rest_speed_m_s, approaching));
  // Each state's typical size, atol / rtol, sizes the structured Jacobian's differences.
  const Eigen::VectorXd scale =
      Eigen::Map<const Eigen::VectorXd>(tolerances.component_atol.data(), pad.size()) / tolerances.rtol;
  if (tolerances.stiff && options.structured_jacobian)
    integrator.SetJacobian([&pad, &scale](double, Eigen::Ref<const Eigen::VectorXd> y,
                                          Eigen::Ref<const Eigen::VectorXd> ydot,
                                          Eigen::Ref<Eigen::MatrixXd> J) { pad.Jacobian(y, ydot, scale, J); });
  integ::HybridRun run(integrator);

  const double v_td = in.impact_speed_m_s, g = in.gravity_m_s2;
  const double clearance = ReleaseClearance(options.approach_clearance_m, v_td, g);
  Eigen::VectorXd y = ReleaseState(pad, in, clearance);
  if (clearance > 0.0) y = Approach(run, pad, y, clearance);
  y[S::work()] = 0.0;
  if (pad.has_shear_state()) y[S::shear()] = 0.0;  // j since touchdown (the approach may graze)
  approaching = false;
  run.Start(0.0, y);
  FreeDropResult result = Stroke(run, pad, y, options);
  if (tolerances.stiff && options.structured_jacobian)  // CVODE counts none of these
    result.solver.jacobian_rhs_evaluations = result.solver.jacobian_evaluations * pad.JacobianContacts();
  return result;
}

}  // namespace touchdown::pad
