#include "lander/multibody/lander_simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace touchdown::lander {

namespace {
// Root functions per pad: [0] depth (touchdown, rising); free pad: [1] sink rate, [2] / [3] speed
// below the capture speed / the soil ramp speed while submerged (capture); held pad: [1..3] lift /
// sink / slide (release); all but [0] falling.
constexpr int kPadRoots = 4;
// Per leg: [0..1] crushable absorber events (falling).
constexpr int kLegRoots = 2;
constexpr int kNumRoots = kNumLegs * (kPadRoots + kLegRoots) + 1;
constexpr int kTipRoot = kNumRoots - 1;
int PadRoot(int leg, int k) { return kPadRoots * leg + k; }
int LegRoot(int leg, int k) { return kNumLegs * kPadRoots + kLegRoots * leg + k; }
// A pad whose joint centre moves slower than this is kinematically at rest (numerical zero,
// e.g. the fourth pad once three held pads have stopped a rigid-legged lander).
constexpr double kAtRestSpeed = 1e-10;

bool IsCrushable(const LanderModel& m, const StateLayout& L, int i) {
  return L.stroke_slot[i] >= 0 && m.legs[i].absorber->kind == ShockAbsorber::Kind::kCrushable;
}

Eigen::VectorXd Pack(const StateLayout& L, const LanderInitialState& s) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(L.size);
  auto put_quat = [&](int i, const Eigen::Matrix3d& R) {
    const Eigen::Quaterniond q(R);
    y.segment<4>(i) << q.w(), q.x(), q.y(), q.z();
  };
  y.segment<3>(L.p_B()) = s.p_WB;
  put_quat(L.quat_B(), s.R_WB);
  y.segment<3>(L.v_B()) = s.v_WB_W;
  y.segment<3>(L.w_B()) = s.w_WB_W;
  for (int i = 0; i < kNumLegs; ++i) {
    put_quat(L.quat_P(i), s.R_WP[i]);
    y.segment<3>(L.w_P(i)) = s.w_WB_W;  // the pads turn with the body at release
    if (L.stroke_slot[i] >= 0) y[L.stroke(i)] = s.stroke_m[i];
  }
  return y;
}

struct HoldCheck {
  double lift = 0.0;    // vertical reaction (>= 0 to hold)
  double sink = 0.0;    // vertical capacity - reaction (>= 0 to hold)
  double slide = 0.0;   // horizontal capacity - |horizontal reaction| (>= 0 to hold)
  Eigen::Vector3d slide_direction = Eigen::Vector3d::Zero();
};

HoldCheck CheckHold(const LanderModel& model, const rft::Terrain& terrain, int i, const PadFrame& f,
                    const rft::ContactWrench& reaction) {
  HoldCheck h;
  h.lift = reaction.force_W.z();
  h.sink = QuasiStaticWrench(model, terrain, i, f, Eigen::Vector3d(0, 0, -1)).force_W.z() - h.lift;
  Eigen::Vector3d horizontal(reaction.force_W.x(), reaction.force_W.y(), 0.0);
  const double load = horizontal.norm();
  if (load > 0.0) {
    h.slide_direction = -horizontal / load;  // the load pushes the pad against the reaction
    const rft::ContactWrench cap = QuasiStaticWrench(model, terrain, i, f, h.slide_direction);
    h.slide = -cap.force_W.dot(h.slide_direction) - load;
  } else {
    h.slide = QuasiStaticWrench(model, terrain, i, f, Eigen::Vector3d(1, 0, 0)).force_W.head<2>().norm();
  }
  return h;
}

// The absolute tolerance of each state: rtol times the landing's scale for that state (unless the
// options give component_atol or ask for the scalar atol). Why: states that stay near zero - a
// pad's spin about its ball joint, the roll rate of a symmetric landing - were resolved to 1e-11
// in their own unit, radians per second included (docs/lander_dynamics.md has the step counts).
//   length L: the largest distance of a ball joint from the body's centre of mass; pad size l:
//   the largest pad vertex distance from its joint; speed V: the initial speed plus sqrt(2 g L);
//   angles 1 rad; angular speeds V / L (body) and V / l (pads); energy M V^2 / 2 + M g L.
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
    o.component_atol[L.p_B() + k] = r * length;
    o.component_atol[L.v_B() + k] = r * V;
    o.component_atol[L.w_B() + k] = r * V / length;
    for (int i = 0; i < kNumLegs; ++i) o.component_atol[L.w_P(i) + k] = r * V / pad;
  }
  for (int i = 0; i < kNumLegs; ++i) {
    if (L.stroke_slot[i] < 0) continue;
    o.component_atol[L.stroke(i)] = r * length;
    o.component_atol[L.stroke_rate(i)] = r * V;
  }
  o.component_atol[L.work()] = r * E;
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

double StabilityMargin(const LanderModel& model, const StateLayout& L, const Eigen::Ref<const Eigen::VectorXd>& y) {
  const LanderPose p = ComputePose(model, L, y);
  Eigen::Vector3d com = model.body_mass_kg * p.p_WB;
  for (int i = 0; i < kNumLegs; ++i)
    com += model.legs[i].pad->mass_kg * (p.pads[i].p_WJ + p.pads[i].c_JC_W);
  com /= model.TotalMass();
  double margin = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kNumLegs; ++i) {
    const Eigen::Vector2d a = p.pads[i].p_WJ.head<2>(), b = p.pads[(i + 1) % kNumLegs].p_WJ.head<2>();
    const Eigen::Vector2d e = b - a, r = com.head<2>() - a;
    // Clockwise polygon seen from above: the inside is on the right of each edge.
    margin = std::min(margin, -(e.x() * r.y() - e.y() * r.x()) / e.norm());
  }
  return margin;
}

LanderRunResult SimulateLander(const LanderModel& model, const rft::Terrain& terrain, const LanderInitialState& initial,
                               const LanderRunOptions& options) {
  if (!(options.duration_s > 0.0) || !(options.sample_rate_hz > 0.0) || !(options.capture_speed_m_s >= 0.0))
    throw std::invalid_argument("SimulateLander: invalid options");
  const StateLayout L(model);
  LanderModes modes;
  for (int i = 0; i < kNumLegs; ++i) modes.stroke[i] = StrokeMode::kLocked;
  LanderEvaluation eval;
  eval.u_dot = Eigen::VectorXd::Zero(L.nu);

  auto rhs = [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot) {
    EvaluateLander(model, L, terrain, modes, y, &eval);
    StateDerivative(L, y, eval, ydot);
  };
  LanderEvaluation root_eval;
  auto roots_fn = [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) {
    g.setOnes();
    bool need_forces = false;
    for (int i = 0; i < kNumLegs; ++i)
      need_forces |= modes.pad[i] == PadMode::kHeld || (IsCrushable(model, L, i) && modes.stroke[i] == StrokeMode::kLocked);
    if (need_forces) EvaluateLander(model, L, terrain, modes, y, &root_eval);
    const LanderPose pose = need_forces ? root_eval.pose : ComputePose(model, L, y);
    for (int i = 0; i < kNumLegs; ++i) {
      const PadFrame& f = pose.pads[i];
      g[PadRoot(i, 0)] = PadDepth(model, terrain, i, f);
      if (modes.pad[i] == PadMode::kFree) {
        g[PadRoot(i, 1)] = -f.v_WJ_W.z();  // sink rate
        // Slow capture: a submerged pad whose joint centre has slowed below the capture speed.
        g[PadRoot(i, 2)] = g[PadRoot(i, 0)] > 0.0 ? f.v_WJ_W.norm() - options.capture_speed_m_s : 1.0;
        // ... and again at the soil's ramp speed, where a pad whose earlier capture was undone
        // has slowed down once more.
        g[PadRoot(i, 3)] = g[PadRoot(i, 0)] > 0.0 ? f.v_WJ_W.norm() - kSoilRampSpeed : 1.0;
      } else {
        const HoldCheck h = CheckHold(model, terrain, i, f, root_eval.soil[i]);
        g[PadRoot(i, 1)] = h.lift;
        g[PadRoot(i, 2)] = h.sink;
        g[PadRoot(i, 3)] = h.slide;
      }
      if (IsCrushable(model, L, i)) {
        const ShockAbsorber& ab = *model.legs[i].absorber;
        if (modes.stroke[i] == StrokeMode::kFree) {
          g[LegRoot(i, 0)] = y[L.stroke_rate(i)];
          g[LegRoot(i, 1)] = ab.stroke_limit_m - y[L.stroke(i)];
        } else if (modes.stroke[i] == StrokeMode::kLocked) {
          g[LegRoot(i, 0)] = ab.crush_force_N - root_eval.leg_force_N[i];
        }
      }
    }
    g[kTipRoot] = StabilityMargin(model, L, y);
  };
  integ::RootSpec roots;
  roots.count = kNumRoots;
  roots.function = roots_fn;
  roots.directions.assign(kNumRoots, -1);
  for (int i = 0; i < kNumLegs; ++i) roots.directions[PadRoot(i, 0)] = +1;
  integ::CvodeIntegrator integrator(L.size, rhs, ScaledTolerances(model, L, initial, options), roots);

  LanderRunResult result;
  Eigen::VectorXd y = Pack(L, initial);
  result.initial_energy_J = KineticEnergy(model, L, y) + PotentialEnergy(model, L, y);
  std::array<Eigen::Vector3d, kNumLegs> held_at;

  auto record = [&](double t, const Eigen::VectorXd& s) {
    LanderEvaluation e;
    EvaluateLander(model, L, terrain, modes, s, &e);
    LanderSample x;
    x.t_s = t;
    x.p_WB = e.pose.p_WB;
    x.v_WB_W = e.pose.v_WB_W;
    x.w_WB_W = e.pose.w_WB_W;
    x.attitude = BodyAttitude(e.pose.R_WB);
    x.a_WB_W = e.u_dot.head<3>();
    for (int i = 0; i < kNumLegs; ++i) {
      x.pad_depth_m[i] = PadDepth(model, terrain, i, e.pose.pads[i]);
      x.pad_force_W[i] = e.soil[i].force_W;
      x.stroke_m[i] = L.stroke_slot[i] >= 0 ? s[L.stroke(i)] : 0.0;
      x.leg_force_N[i] = e.leg_force_N[i];
      x.pad_held[i] = modes.pad[i] == PadMode::kHeld;
      result.peak_pad_force_N[i] = std::max(result.peak_pad_force_N[i], e.soil[i].force_W.norm());
      if (modes.pad[i] == PadMode::kHeld)
        result.max_held_drift_m = std::max(result.max_held_drift_m, (e.pose.pads[i].p_WJ - held_at[i]).norm());
    }
    x.kinetic_J = KineticEnergy(model, L, s);
    x.potential_J = PotentialEnergy(model, L, s);
    x.dissipated_J = s[L.work()];
    result.max_tilt_rad = std::max(result.max_tilt_rad, x.attitude.tilt_rad);
    if (result.first_touchdown_s)
      result.max_body_deceleration_m_s2 = std::max(result.max_body_deceleration_m_s2, x.a_WB_W.z());
    result.trace.push_back(x);
  };

  // Holds every captured pad can keep; releases the others. Returns true if modes changed.
  auto settle_holds = [&](double t, Eigen::VectorXd& s, const std::array<bool, kNumLegs>& fresh,
                          const Eigen::VectorXd& before) {
    for (int iter = 0; iter < 3 * kNumLegs; ++iter) {
      LanderEvaluation e;
      EvaluateLander(model, L, terrain, modes, s, &e);
      int worst = -1;
      double worst_value = 0.0;
      HoldCheck worst_check;
      for (int i = 0; i < kNumLegs; ++i) {
        if (modes.pad[i] != PadMode::kHeld) continue;
        const HoldCheck h = CheckHold(model, terrain, i, e.pose.pads[i], e.soil[i]);
        const double scale = std::max(1.0, std::abs(e.soil[i].force_W.z()));
        const double v = std::min({h.lift, h.sink, h.slide}) / scale;
        if (v < -1e-9 && v < worst_value) worst = i, worst_value = v, worst_check = h;
      }
      if (worst < 0) return;
      modes.pad[worst] = PadMode::kFree;
      const double m_check = std::min({worst_check.lift, worst_check.sink, worst_check.slide});
      if (fresh[worst]) {
        // The capture cannot hold: undo it (the pad goes on moving under RFT).
        s.segment(L.nq, L.nu) = before.segment(L.nq, L.nu);
        s[L.work()] = before[L.work()] + ProjectOntoConstraints(model, L, modes, s);
      } else {
        const char* kind = m_check == worst_check.lift   ? "release_liftoff"
                           : m_check == worst_check.sink ? "release_sink"
                                                         : "release_slide";
        result.events.push_back({t, kind, worst});
      }
    }
    throw integ::IntegrationFailure("lander: pad holds did not settle at t = " + std::to_string(t));
  };

  integ::IntegratorSummary totals;
  auto accumulate = [&] {
    const integ::IntegratorSummary s = integrator.summary();
    totals.steps += s.steps;
    totals.rhs_evaluations += s.rhs_evaluations;
    totals.root_evaluations += s.root_evaluations;
    totals.error_test_failures += s.error_test_failures;
    totals.jacobian_evaluations += s.jacobian_evaluations;
    totals.jacobian_rhs_evaluations += s.jacobian_rhs_evaluations;
    totals.nonlinear_convergence_failures += s.nonlinear_convergence_failures;
  };
  const double dt = 1.0 / options.sample_rate_hz;
  double t = 0.0;
  long k = 1;
  int events = 0;
  integrator.Reset(0.0, y);
  {
    // A pad already on the surface at release (touchdown_speed_m_s: 0 places the lowest pad
    // there) touches down at t = 0: CVODE never reports a root that holds at the start.
    constexpr double kTouchingAtRelease_m = 1e-9;  // rounding of the placement, far below any sinkage
    const LanderPose pose = ComputePose(model, L, y);
    for (int i = 0; i < kNumLegs; ++i)
      if (PadDepth(model, terrain, i, pose.pads[i]) >= -kTouchingAtRelease_m) {
        result.events.push_back({0.0, "touchdown", i});
        result.touchdown_time_s[i] = 0.0;
        result.first_touchdown_s = 0.0;
      }
  }
  record(0.0, y);
  while (t < options.duration_s) {
    const double t_out = std::min(k * dt, options.duration_s);
    const integ::AdvanceResult r = integrator.AdvanceTo(t_out);
    y = integrator.state();
    t = r.t;
    if (r.status == integ::AdvanceStatus::kReachedTime) {
      record(t, y);
      ++k;
      continue;
    }
    if (++events > options.max_events)
      throw integ::IntegrationFailure("lander: more than " + std::to_string(options.max_events) + " events");
    record(t, y);  // the state at the event, in the old modes (peak forces before a capture)
    const std::vector<int>& found = r.roots_found;
    const LanderPose pose = ComputePose(model, L, y);
    for (int i = 0; i < kNumLegs; ++i)
      if (found[PadRoot(i, 0)] != 0) {
        result.events.push_back({t, "touchdown", i});
        if (!result.touchdown_time_s[i]) result.touchdown_time_s[i] = t;
        if (!result.first_touchdown_s) result.first_touchdown_s = t;
      }
    if (found[kTipRoot] != 0) {
      result.tipped_over = true;
      result.events.push_back({t, "tip_over", -1});
      break;
    }
    bool changed = false;
    const Eigen::VectorXd before = y;
    std::array<bool, kNumLegs> fresh{};
    for (int i = 0; i < kNumLegs; ++i) {
      const PadFrame& f = pose.pads[i];
      const bool stops_sinking = found[PadRoot(i, 1)] != 0 && f.v_WJ_W.head<2>().norm() <= options.capture_speed_m_s;
      const bool slowed_down = found[PadRoot(i, 2)] != 0 || found[PadRoot(i, 3)] != 0;
      if (modes.pad[i] == PadMode::kFree && (stops_sinking || slowed_down) && PadDepth(model, terrain, i, f) > 0.0) {
        modes.pad[i] = PadMode::kHeld;
        fresh[i] = changed = true;
      } else if (modes.pad[i] == PadMode::kHeld &&
                 (found[PadRoot(i, 1)] != 0 || found[PadRoot(i, 2)] != 0 || found[PadRoot(i, 3)] != 0)) {
        // The reaction left the capacity: the pad starts to move in the direction the load
        // pushes it (lift-off up, sinking down, sliding along the horizontal load).
        modes.pad[i] = PadMode::kFree;
        if (found[PadRoot(i, 1)] != 0) {
          result.events.push_back({t, "release_liftoff", i});
        } else if (found[PadRoot(i, 2)] != 0) {
          result.events.push_back({t, "release_sink", i});
        } else {
          result.events.push_back({t, "release_slide", i});
        }
        changed = true;
      }
      if (IsCrushable(model, L, i)) {
        if (modes.stroke[i] == StrokeMode::kLocked && found[LegRoot(i, 0)] != 0) {
          modes.stroke[i] = StrokeMode::kFree;
          result.events.push_back({t, "crush", i});
          changed = true;
        } else if (modes.stroke[i] == StrokeMode::kFree && found[LegRoot(i, 1)] != 0) {
          modes.stroke[i] = StrokeMode::kBottomed;
          result.events.push_back({t, "bottom", i});
          changed = true;
        } else if (modes.stroke[i] == StrokeMode::kFree && found[LegRoot(i, 0)] != 0) {
          modes.stroke[i] = StrokeMode::kLocked;
          result.events.push_back({t, "lock", i});
          changed = true;
        }
      }
    }
    if (!changed) continue;
    // A capture is offered to every slow submerged pad at once: the pads share the body's load,
    // so one pad alone may fail its hold check (and be released) where all of them together hold.
    if (std::any_of(fresh.begin(), fresh.end(), [](bool b) { return b; }))
      for (int i = 0; i < kNumLegs; ++i)
        if (modes.pad[i] == PadMode::kFree && PadDepth(model, terrain, i, pose.pads[i]) > 0.0 &&
            pose.pads[i].v_WJ_W.norm() <= options.capture_speed_m_s) {
          modes.pad[i] = PadMode::kHeld;
          fresh[i] = true;
        }
    NormalizeQuaternions(L, y);
    // Pads kinematically stopped by the others' holds are held too.
    for (int pass = 0; pass < kNumLegs; ++pass) {
      y[L.work()] += ProjectOntoConstraints(model, L, modes, y);
      const LanderPose p = ComputePose(model, L, y);
      bool more = false;
      for (int i = 0; i < kNumLegs; ++i)
        if (modes.pad[i] == PadMode::kFree && PadDepth(model, terrain, i, p.pads[i]) > 0.0 &&
            p.pads[i].v_WJ_W.norm() < kAtRestSpeed) {
          modes.pad[i] = PadMode::kHeld;
          fresh[i] = more = true;
        }
      if (!more) break;
    }
    settle_holds(t, y, fresh, before);
    result.capture_loss_J += y[L.work()] - before[L.work()];
    const LanderPose after = ComputePose(model, L, y);
    bool all_held = true;
    for (int i = 0; i < kNumLegs; ++i) {
      if (modes.pad[i] == PadMode::kHeld && fresh[i]) {
        held_at[i] = after.pads[i].p_WJ;
        result.events.push_back({t, "capture", i});
      }
      all_held &= modes.pad[i] == PadMode::kHeld;
    }
    accumulate();
    integrator.Reset(t, y);
    record(t, y);
    if (all_held && options.stop_at_rest) {
      result.rest_time_s = t;
      result.events.push_back({t, "rest", -1});
      // Static from here on: the loads no longer change, so the holds stay valid. The remaining
      // samples repeat the one just recorded from this state (same state, same evaluation).
      const LanderSample at_rest = result.trace.back();
      for (; k * dt <= options.duration_s + 1e-12; ++k) {
        result.trace.push_back(at_rest);
        result.trace.back().t_s = k * dt;
      }
      t = options.duration_s;
      break;
    }
  }
  const LanderPose fin = ComputePose(model, L, y);
  for (int i = 0; i < kNumLegs; ++i) result.final_penetration_m[i] = PadDepth(model, terrain, i, fin.pads[i]);
  result.final_attitude = BodyAttitude(fin.R_WB);
  result.final_kinetic_J = KineticEnergy(model, L, y);
  result.final_potential_J = PotentialEnergy(model, L, y);
  result.dissipated_J = y[L.work()];
  result.end_time_s = t;
  result.final_state = y;
  accumulate();
  result.solver = totals;
  return result;
}

}  // namespace touchdown::lander
