#include "lander/multibody/lander_simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "lander/integ/hybrid_run.h"

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

Eigen::VectorXd Pack(const LanderModel& model, const StateLayout& L, const LanderInitialState& s) {
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
  (void)model;
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
  const Eigen::VectorXd y = Pack(model, L, s);
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

namespace {
// One lander run as the hybrid loop sees it (integ::HybridRun): the modes, the right-hand side and
// root functions in those modes, the trace, and what each event does to the modes and the state.
class LanderHybrid {
 public:
  LanderHybrid(const LanderModel& model, const rft::Terrain& terrain, const LanderRunOptions& options,
               LanderRunResult& result)
      : model_(model), L_(model), terrain_(terrain), options_(options), result_(result) {
    for (int i = 0; i < kNumLegs; ++i) modes_.stroke[i] = StrokeMode::kLocked;
    eval_.u_dot = Eigen::VectorXd::Zero(L_.nu);
  }
  const StateLayout& layout() const { return L_; }
  void Derivative(Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot);
  void Roots(Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g);
  integ::RootSpec RootFunctions();
  void Record(double t, const Eigen::VectorXd& s);
  void TouchdownsAtRelease(const Eigen::VectorXd& y);
  integ::EventAction OnEvent(double t, const std::vector<int>& found, Eigen::VectorXd& y);
  bool at_rest() const { return result_.rest_time_s.has_value(); }
  void Finish(double t, const Eigen::VectorXd& y);

 private:
  void Touchdowns(double t, const std::vector<int>& found);
  bool SwitchModes(double t, const std::vector<int>& found, const LanderPose& pose, std::array<bool, kNumLegs>& fresh);
  void OfferCaptures(const LanderPose& pose, std::array<bool, kNumLegs>& fresh);
  void HoldStoppedPads(Eigen::VectorXd& y, std::array<bool, kNumLegs>& fresh);
  void SettleHolds(double t, Eigen::VectorXd& s, const std::array<bool, kNumLegs>& fresh, const Eigen::VectorXd& before);
  bool RecordCaptures(double t, const Eigen::VectorXd& y, const std::array<bool, kNumLegs>& fresh);

  const LanderModel& model_;
  const StateLayout L_;
  const rft::Terrain& terrain_;
  const LanderRunOptions& options_;
  LanderRunResult& result_;
  LanderModes modes_;
  LanderData data_;  // scratch of the right-hand side and the root functions
  LanderEvaluation eval_, root_eval_;
  std::array<Eigen::Vector3d, kNumLegs> held_at_;
};

void LanderHybrid::Derivative(Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot) {
  EvaluateLander(model_, L_, terrain_, modes_, y, &eval_, &data_);
  StateDerivative(L_, y, eval_, ydot);
}

void LanderHybrid::Roots(Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) {
  g.setOnes();
  bool need_forces = false;
  for (int i = 0; i < kNumLegs; ++i)
    need_forces |= modes_.pad[i] == PadMode::kHeld || (IsCrushable(model_, L_, i) && modes_.stroke[i] == StrokeMode::kLocked);
  if (need_forces) EvaluateLander(model_, L_, terrain_, modes_, y, &root_eval_, &data_);
  const LanderPose pose = need_forces ? root_eval_.pose : ComputePose(model_, L_, y);
  for (int i = 0; i < kNumLegs; ++i) {
    const PadFrame& f = pose.pads[i];
    g[PadRoot(i, 0)] = PadDepth(model_, terrain_, i, f);
    if (modes_.pad[i] == PadMode::kFree) {
      g[PadRoot(i, 1)] = -f.v_WJ_W.z();  // sink rate
      // Slow capture: a submerged pad whose joint centre has slowed below the capture speed.
      g[PadRoot(i, 2)] = g[PadRoot(i, 0)] > 0.0 ? f.v_WJ_W.norm() - options_.capture_speed_m_s : 1.0;
      // ... and again at the soil's ramp speed, where a pad whose earlier capture was undone
      // has slowed down once more.
      g[PadRoot(i, 3)] = g[PadRoot(i, 0)] > 0.0 ? f.v_WJ_W.norm() - kSoilRampSpeed : 1.0;
    } else {
      const HoldCheck h = CheckHold(model_, terrain_, i, f, root_eval_.soil[i]);
      g[PadRoot(i, 1)] = h.lift;
      g[PadRoot(i, 2)] = h.sink;
      g[PadRoot(i, 3)] = h.slide;
    }
    if (IsCrushable(model_, L_, i)) {
      const ShockAbsorber& ab = *model_.legs[i].absorber;
      if (modes_.stroke[i] == StrokeMode::kFree) {
        g[LegRoot(i, 0)] = y[L_.stroke_rate(i)];
        g[LegRoot(i, 1)] = ab.stroke_limit_m - y[L_.stroke(i)];
      } else if (modes_.stroke[i] == StrokeMode::kLocked) {
        g[LegRoot(i, 0)] = ab.crush_force_N - root_eval_.leg_force_N[i];
      }
    }
  }
  g[kTipRoot] = StabilityMargin(model_, L_, y);
}

integ::RootSpec LanderHybrid::RootFunctions() {
  integ::RootSpec roots;
  roots.count = kNumRoots;
  roots.function = [this](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) { Roots(y, g); };
  roots.directions.assign(kNumRoots, -1);
  for (int i = 0; i < kNumLegs; ++i) roots.directions[PadRoot(i, 0)] = +1;
  return roots;
}

void LanderHybrid::Record(double t, const Eigen::VectorXd& s) {
  LanderEvaluation e;
  EvaluateLander(model_, L_, terrain_, modes_, s, &e);
  LanderSample x;
  x.t_s = t;
  x.p_WB = e.pose.p_WB;
  x.v_WB_W = e.pose.v_WB_W;
  x.w_WB_W = e.pose.w_WB_W;
  x.attitude = BodyAttitude(e.pose.R_WB);
  x.a_WB_W = e.u_dot.head<3>();
  for (int i = 0; i < kNumLegs; ++i) {
    x.pad_depth_m[i] = PadDepth(model_, terrain_, i, e.pose.pads[i]);
    x.pad_force_W[i] = e.soil[i].force_W;
    x.stroke_m[i] = L_.stroke_slot[i] >= 0 ? s[L_.stroke(i)] : 0.0;
    x.leg_force_N[i] = e.leg_force_N[i];
    x.pad_held[i] = modes_.pad[i] == PadMode::kHeld;
    result_.peak_pad_force_N[i] = std::max(result_.peak_pad_force_N[i], e.soil[i].force_W.norm());
    if (modes_.pad[i] == PadMode::kHeld)
      result_.max_held_drift_m = std::max(result_.max_held_drift_m, (e.pose.pads[i].p_WJ - held_at_[i]).norm());
  }
  x.kinetic_J = KineticEnergy(model_, L_, s);
  x.potential_J = PotentialEnergy(model_, L_, s);
  x.dissipated_J = s[L_.work()];
  result_.max_tilt_rad = std::max(result_.max_tilt_rad, x.attitude.tilt_rad);
  if (result_.first_touchdown_s)
    result_.max_body_deceleration_m_s2 = std::max(result_.max_body_deceleration_m_s2, x.a_WB_W.z());
  result_.trace.push_back(x);
}

// A pad already on the surface at release (touchdown_speed_m_s: 0 places the lowest pad there)
// touches down at t = 0: CVODE never reports a root that holds at the start.
void LanderHybrid::TouchdownsAtRelease(const Eigen::VectorXd& y) {
  constexpr double kTouchingAtRelease_m = 1e-9;  // rounding of the placement, far below any sinkage
  const LanderPose pose = ComputePose(model_, L_, y);
  for (int i = 0; i < kNumLegs; ++i)
    if (PadDepth(model_, terrain_, i, pose.pads[i]) >= -kTouchingAtRelease_m) {
      result_.events.push_back({0.0, "touchdown", i});
      result_.touchdown_time_s[i] = 0.0;
      result_.first_touchdown_s = 0.0;
    }
}

void LanderHybrid::Touchdowns(double t, const std::vector<int>& found) {
  for (int i = 0; i < kNumLegs; ++i)
    if (found[PadRoot(i, 0)] != 0) {
      result_.events.push_back({t, "touchdown", i});
      if (!result_.touchdown_time_s[i]) result_.touchdown_time_s[i] = t;
      if (!result_.first_touchdown_s) result_.first_touchdown_s = t;
    }
}

// The mode changes the roots ask for: captures, releases, crushing, lock and bottoming. Returns
// true if any mode changed; `fresh` marks the pads just captured.
bool LanderHybrid::SwitchModes(double t, const std::vector<int>& found, const LanderPose& pose,
                               std::array<bool, kNumLegs>& fresh) {
  bool changed = false;
  for (int i = 0; i < kNumLegs; ++i) {
    const PadFrame& f = pose.pads[i];
    const bool stops_sinking = found[PadRoot(i, 1)] != 0 && f.v_WJ_W.head<2>().norm() <= options_.capture_speed_m_s;
    const bool slowed_down = found[PadRoot(i, 2)] != 0 || found[PadRoot(i, 3)] != 0;
    if (modes_.pad[i] == PadMode::kFree && (stops_sinking || slowed_down) && PadDepth(model_, terrain_, i, f) > 0.0) {
      modes_.pad[i] = PadMode::kHeld;
      fresh[i] = changed = true;
    } else if (modes_.pad[i] == PadMode::kHeld &&
               (found[PadRoot(i, 1)] != 0 || found[PadRoot(i, 2)] != 0 || found[PadRoot(i, 3)] != 0)) {
      // The reaction left the capacity: the pad starts to move in the direction the load
      // pushes it (lift-off up, sinking down, sliding along the horizontal load).
      modes_.pad[i] = PadMode::kFree;
      if (found[PadRoot(i, 1)] != 0) {
        result_.events.push_back({t, "release_liftoff", i});
      } else if (found[PadRoot(i, 2)] != 0) {
        result_.events.push_back({t, "release_sink", i});
      } else {
        result_.events.push_back({t, "release_slide", i});
      }
      changed = true;
    }
    if (IsCrushable(model_, L_, i)) {
      if (modes_.stroke[i] == StrokeMode::kLocked && found[LegRoot(i, 0)] != 0) {
        modes_.stroke[i] = StrokeMode::kFree;
        result_.events.push_back({t, "crush", i});
        changed = true;
      } else if (modes_.stroke[i] == StrokeMode::kFree && found[LegRoot(i, 1)] != 0) {
        modes_.stroke[i] = StrokeMode::kBottomed;
        result_.events.push_back({t, "bottom", i});
        changed = true;
      } else if (modes_.stroke[i] == StrokeMode::kFree && found[LegRoot(i, 0)] != 0) {
        modes_.stroke[i] = StrokeMode::kLocked;
        result_.events.push_back({t, "lock", i});
        changed = true;
      }
    }
  }
  return changed;
}

// A capture is offered to every slow submerged pad at once: the pads share the body's load, so
// one pad alone may fail its hold check (and be released) where all of them together hold.
void LanderHybrid::OfferCaptures(const LanderPose& pose, std::array<bool, kNumLegs>& fresh) {
  if (std::none_of(fresh.begin(), fresh.end(), [](bool b) { return b; })) return;
  for (int i = 0; i < kNumLegs; ++i)
    if (modes_.pad[i] == PadMode::kFree && PadDepth(model_, terrain_, i, pose.pads[i]) > 0.0 &&
        pose.pads[i].v_WJ_W.norm() <= options_.capture_speed_m_s) {
      modes_.pad[i] = PadMode::kHeld;
      fresh[i] = true;
    }
}

// Projects the speeds onto the holds; pads kinematically stopped by the others' holds are held too.
void LanderHybrid::HoldStoppedPads(Eigen::VectorXd& y, std::array<bool, kNumLegs>& fresh) {
  for (int pass = 0; pass < kNumLegs; ++pass) {
    y[L_.work()] += ProjectOntoConstraints(model_, L_, modes_, y);
    const LanderPose p = ComputePose(model_, L_, y);
    bool more = false;
    for (int i = 0; i < kNumLegs; ++i)
      if (modes_.pad[i] == PadMode::kFree && PadDepth(model_, terrain_, i, p.pads[i]) > 0.0 &&
          p.pads[i].v_WJ_W.norm() < kAtRestSpeed) {
        modes_.pad[i] = PadMode::kHeld;
        fresh[i] = more = true;
      }
    if (!more) break;
  }
}

// Holds every captured pad can keep; releases the others, worst first.
void LanderHybrid::SettleHolds(double t, Eigen::VectorXd& s, const std::array<bool, kNumLegs>& fresh,
                               const Eigen::VectorXd& before) {
  for (int iter = 0; iter < 3 * kNumLegs; ++iter) {
    LanderEvaluation e;
    EvaluateLander(model_, L_, terrain_, modes_, s, &e);
    int worst = -1;
    double worst_value = 0.0;
    HoldCheck worst_check;
    for (int i = 0; i < kNumLegs; ++i) {
      if (modes_.pad[i] != PadMode::kHeld) continue;
      const HoldCheck h = CheckHold(model_, terrain_, i, e.pose.pads[i], e.soil[i]);
      const double scale = std::max(1.0, std::abs(e.soil[i].force_W.z()));
      const double v = std::min({h.lift, h.sink, h.slide}) / scale;
      if (v < -1e-9 && v < worst_value) worst = i, worst_value = v, worst_check = h;
    }
    if (worst < 0) return;
    modes_.pad[worst] = PadMode::kFree;
    const double m_check = std::min({worst_check.lift, worst_check.sink, worst_check.slide});
    if (fresh[worst]) {
      // The capture cannot hold: undo it (the pad goes on moving under RFT).
      s.segment(L_.nq, L_.nu) = before.segment(L_.nq, L_.nu);
      s[L_.work()] = before[L_.work()] + ProjectOntoConstraints(model_, L_, modes_, s);
    } else {
      const char* kind = m_check == worst_check.lift   ? "release_liftoff"
                         : m_check == worst_check.sink ? "release_sink"
                                                       : "release_slide";
      result_.events.push_back({t, kind, worst});
    }
  }
  throw integ::IntegrationFailure("lander: pad holds did not settle at t = " + std::to_string(t));
}

// The capture events of the pads that stay held; true if every pad is held.
bool LanderHybrid::RecordCaptures(double t, const Eigen::VectorXd& y, const std::array<bool, kNumLegs>& fresh) {
  const LanderPose after = ComputePose(model_, L_, y);
  bool all_held = true;
  for (int i = 0; i < kNumLegs; ++i) {
    if (modes_.pad[i] == PadMode::kHeld && fresh[i]) {
      held_at_[i] = after.pads[i].p_WJ;
      result_.events.push_back({t, "capture", i});
    }
    all_held &= modes_.pad[i] == PadMode::kHeld;
  }
  return all_held;
}

integ::EventAction LanderHybrid::OnEvent(double t, const std::vector<int>& found, Eigen::VectorXd& y) {
  Record(t, y);  // the state at the event, in the old modes (peak forces before a capture)
  const LanderPose pose = ComputePose(model_, L_, y);
  Touchdowns(t, found);
  if (found[kTipRoot] != 0) {
    result_.tipped_over = true;
    result_.events.push_back({t, "tip_over", -1});
    return integ::EventAction::kStop;
  }
  const Eigen::VectorXd before = y;
  std::array<bool, kNumLegs> fresh{};
  if (!SwitchModes(t, found, pose, fresh)) return integ::EventAction::kContinue;
  OfferCaptures(pose, fresh);
  NormalizeQuaternions(L_, y);
  HoldStoppedPads(y, fresh);
  SettleHolds(t, y, fresh, before);
  result_.capture_loss_J += y[L_.work()] - before[L_.work()];
  const bool all_held = RecordCaptures(t, y, fresh);
  Record(t, y);
  if (!(all_held && options_.stop_at_rest)) return integ::EventAction::kRestart;
  // Static from here on: the loads no longer change, so the holds stay valid.
  result_.rest_time_s = t;
  result_.events.push_back({t, "rest", -1});
  return integ::EventAction::kStop;
}

void LanderHybrid::Finish(double t, const Eigen::VectorXd& y) {
  const LanderPose fin = ComputePose(model_, L_, y);
  for (int i = 0; i < kNumLegs; ++i) result_.final_penetration_m[i] = PadDepth(model_, terrain_, i, fin.pads[i]);
  result_.final_attitude = BodyAttitude(fin.R_WB);
  result_.final_kinetic_J = KineticEnergy(model_, L_, y);
  result_.final_potential_J = PotentialEnergy(model_, L_, y);
  result_.dissipated_J = y[L_.work()];
  result_.end_time_s = t;
  result_.final_state = y;
}
}  // namespace

LanderRunResult SimulateLander(const LanderModel& model, const rft::Terrain& terrain, const LanderInitialState& initial,
                               const LanderRunOptions& options) {
  if (!(options.duration_s > 0.0) || !(options.sample_rate_hz > 0.0) || !(options.capture_speed_m_s >= 0.0))
    throw std::invalid_argument("SimulateLander: invalid options");
  LanderRunResult result;
  LanderHybrid lander(model, terrain, options, result);
  const StateLayout& L = lander.layout();
  integ::CvodeIntegrator integrator(
      L.size,
      [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot) { lander.Derivative(y, ydot); },
      ScaledTolerances(model, L, initial, options), lander.RootFunctions());

  const Eigen::VectorXd y0 = Pack(model, L, initial);
  result.initial_energy_J = KineticEnergy(model, L, y0) + PotentialEnergy(model, L, y0);
  integ::HybridRun run(integrator);
  run.Start(0.0, y0);
  lander.TouchdownsAtRelease(y0);
  lander.Record(0.0, y0);

  integ::HybridPhase phase;
  phase.sample_rate_hz = options.sample_rate_hz;
  phase.end_s = options.duration_s;
  phase.end = integ::RunEnd::kSampleAtEnd;
  phase.max_events = options.max_events;
  phase.name = "lander";
  integ::HybridCallbacks calls;
  calls.sample = [&](double t, const Eigen::VectorXd& y) { lander.Record(t, y); };
  calls.event = [&](double t, const std::vector<int>& found, Eigen::VectorXd& y) { return lander.OnEvent(t, found, y); };
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
