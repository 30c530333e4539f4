#include "lander/multibody/lander_hybrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace touchdown::lander {

namespace {
// Root functions per pad: [0] depth (touchdown, rising); free pad: [1] sink rate, [2] / [3] speed
// below the capture speed / the soil ramp speed while submerged (capture); held pad: [1..3] lift /
// sink / slide (release); all but [0] falling.
constexpr int kPadRoots = 4;
// Per leg: [0..1] crushable absorber events; [2] the pad reaching its joint's stop, or leaving it
// (StopHysteresis below the rim) (all falling).
constexpr int kLegRoots = 3;
constexpr int kNumRoots = kNumLegs * (kPadRoots + kLegRoots) + 1;
constexpr int kTipRoot = kNumRoots - 1;
int PadRoot(int leg, int k) { return kPadRoots * leg + k; }
int LegRoot(int leg, int k) { return kNumLegs * kPadRoots + kLegRoots * leg + k; }
// How far inside the rim a pad at its joint's stop must swing back before the stop is off again
// (StopMode::kAtStop to kClear) [rad]: 100 times the run's rtol, at most 0.01 rad. Why: a pad
// pressed against its stop sits at the rim to within its attitude's integration error (about rtol),
// and with the stop off at the rim itself that error crossed it back and forth: events every few
// milliseconds, and where the root function was exactly zero at a restart CVODE counted it from the
// far side and the stop was lost (25 of the lunar study's 10,000 landings turned a pad past
// edge-on). Inside the rim the stop has no spring (ConeLimit); its damping acts there only on a pad
// that turns back out before it has left, as it would from the rim 100 rtol further in. As rtol goes
// to 0 the band closes.
double StopHysteresis(const LanderRunOptions& options) { return std::min(100.0 * options.integrator.rtol, 0.01); }

// A pad whose joint centre moves slower than this is kinematically at rest (numerical zero,
// e.g. the fourth pad once three held pads have stopped a rigid-legged lander).
constexpr double kAtRestSpeed = 1e-10;
// A capture is offered to every pad within this fraction above the capture speed. Why: pads that
// slow down together by symmetry (case B's pads 2 and 4) reach the capture speed at the same time
// up to the integration error; holding one and not its twin would turn that error into a
// different landing (0.015 mm of sinkage, 0.002 deg of roll and pitch).
constexpr double kCaptureTogether = 1e-3;

// The lander's own scales, for thresholds that must scale with it: a geometrically similar lander
// (lengths x k, masses x k^3, gravity / k) lands homologously (docs/lander_dynamics.md,
// "Similitude"), and a threshold in fixed newtons or metres would hold one of the two to a tighter
// or looser test than the other.
//   length: the largest distance of a ball joint from the body's centre of mass (as the
//   integrator's tolerances, lander_simulation.cpp); force: a pad's share of the lander's weight.
double LengthScale(const LanderModel& m) {
  double length = 0.0;
  for (const Leg& leg : m.legs) length = std::max(length, leg.joint_B.norm());
  return length;
}
double PadWeightShare(const LanderModel& m) { return m.TotalMass() * m.gravity_m_s2 / kNumLegs; }
// How long every joint must creep below the soil's ramp speed for the lander to be at rest: a
// quarter of its time scale sqrt(L / g). A rocking lander passes through the ramp speed at a turning
// point in 2 ramp / a; the dwell excludes every such passage with an acceleration a above
// 8 ramp / sqrt(L / g) (7e-4 m/s^2 for the full-scale lander on the Moon, whose rocking runs at
// 0.1-1 m/s^2).
double CreepDwell(const LanderModel& m) { return 0.25 * std::sqrt(LengthScale(m) / m.gravity_m_s2); }

bool IsCrushable(const LanderModel& m, const StateLayout& L, int i) {
  return L.stroke_slot[i] >= 0 && m.legs[i].absorber->kind == ShockAbsorber::Kind::kCrushable;
}

struct HoldCheck {
  double lift = 0.0;    // vertical reaction (>= 0 to hold)
  double sink = 0.0;    // vertical capacity - reaction (>= 0 to hold)
  double slide = 0.0;   // horizontal capacity - |horizontal reaction| (>= 0 to hold)
  Eigen::Vector3d slide_direction = Eigen::Vector3d::Zero();
};

// `sink_capacity` (optional): the pad's vertical capacity, NaN until known. A held pad does not
// move, so its capacity straight down is the same until the next event; the root functions keep it
// (on a slope, where pads stay held while the lander slides, the capacity checks would otherwise be
// half of all contact evaluations). `slide_capacity` (optional, with the root functions'): the
// pad's soil integrals at the pose it is held in, for its capacity in the direction of the load,
// which turns from step to step (HeldPadCapacity); the events' checks (none given) evaluate the
// contact at the pose they see.
// `contacts` (optional) counts the contacts evaluated.
HoldCheck CheckHold(const LanderModel& model, const rft::Terrain& terrain, int i, const PadFrame& f,
                    const rft::ContactWrench& reaction, double* sink_capacity = nullptr, long* contacts = nullptr,
                    HeldPadCapacity* slide_capacity = nullptr) {
  HoldCheck h;
  h.lift = reaction.force_W.z();
  const bool known = sink_capacity && !std::isnan(*sink_capacity);
  long evaluated = known ? 0 : 1;
  const double down = known ? *sink_capacity : QuasiStaticWrench(model, terrain, i, f, Eigen::Vector3d(0, 0, -1)).force_W.z();
  if (sink_capacity) *sink_capacity = down;
  h.sink = down - h.lift;
  Eigen::Vector3d horizontal(reaction.force_W.x(), reaction.force_W.y(), 0.0);
  const double load = horizontal.norm();
  if (load > 0.0) {
    h.slide_direction = -horizontal / load;  // the load pushes the pad against the reaction
    Eigen::Vector3d cap;
    if (slide_capacity) {
      cap = HeldPadCapacityForce(model, terrain, i, f, h.slide_direction, slide_capacity, &evaluated);
    } else {
      ++evaluated;
      cap = QuasiStaticWrench(model, terrain, i, f, h.slide_direction).force_W;
    }
    h.slide = -cap.dot(h.slide_direction) - load;
  } else {
    ++evaluated;
    h.slide = QuasiStaticWrench(model, terrain, i, f, Eigen::Vector3d(1, 0, 0)).force_W.head<2>().norm();
  }
  if (contacts) *contacts += evaluated;
  return h;
}

}  // namespace

void LanderHybrid::Derivative(Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot) {
  lander::Derivative(LanderSystem{model_, L_, terrain_, modes_}, data_, y, ydot);
  last_rhs_y_ = y;
  last_rhs_valid_ = true;
  rhs_contacts_ += data_.evaluation.pad_contacts;
}

void LanderHybrid::Roots(Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) {
  g.setOnes();
  bool need_forces = false;
  for (int i = 0; i < kNumLegs; ++i)
    need_forces |= modes_.pad[i] == PadMode::kHeld || (IsCrushable(model_, L_, i) && modes_.stroke[i] == StrokeMode::kLocked);
  if (need_forces) {
    EvaluateLander(model_, L_, terrain_, modes_, y, &root_eval_, &data_);
    root_contacts_ += root_eval_.pad_contacts;
  }
  const LanderPose pose = need_forces ? root_eval_.pose : ComputePose(model_, L_, y);
  for (int i = 0; i < kNumLegs; ++i) {
    const PadFrame& f = pose.pads[i];
    g[PadRoot(i, 0)] = PadDepth(model_, terrain_, i, f);
    if (modes_.pad[i] == PadMode::kFree) {
      // Sink rate. A pad whose capture was refused and that rides on with its vertical speed at
      // zero (sliding through the soil's trailing band) would cross it again within a step, and
      // each offer restarts the integrator at its smallest steps: thousands of refused captures in
      // a few milliseconds were seen on sliding landings at loose tolerances.
      g[PadRoot(i, 1)] = capture_refused_[i] ? 1.0 : -f.v_WJ_W.z();
      // Slow capture: a submerged pad whose joint centre has slowed below the capture speed.
      g[PadRoot(i, 2)] = g[PadRoot(i, 0)] > 0.0 ? f.v_WJ_W.norm() - options_.capture_speed_m_s : 1.0;
      // ... and again at the soil's ramp speed, where a pad whose earlier capture was undone
      // has slowed down once more.
      g[PadRoot(i, 3)] = g[PadRoot(i, 0)] > 0.0 ? f.v_WJ_W.norm() - model_.soil_ramp_speed_m_s : 1.0;
    } else {
      const HoldCheck h =
          CheckHold(model_, terrain_, i, f, root_eval_.soil[i], &sink_capacity_[i], &root_contacts_,
                    options_.held_capacity_from_integrals ? &slide_capacity_[i] : nullptr);
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
    if (const std::optional<ConeLimit>& cone = model_.legs[i].cone; cone && modes_.stop[i] != StopMode::kByAngle) {
      const double swing = JointSwingAngle(pose.R_WB, f.R_WP);
      g[LegRoot(i, 2)] = modes_.stop[i] == StopMode::kClear ? cone->half_angle_rad - swing
                                                             : swing - (cone->half_angle_rad - StopHysteresis(options_));
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
  x.q_WB = s.segment<4>(L_.quat_WB()).normalized();
  x.a_WB_W = e.u_dot.head<3>();
  for (int i = 0; i < kNumLegs; ++i) {
    x.pad_depth_m[i] = PadDepth(model_, terrain_, i, e.pose.pads[i]);
    x.pad_force_W[i] = e.soil[i].force_W;
    x.stroke_m[i] = L_.stroke_slot[i] >= 0 ? s[L_.stroke(i)] : 0.0;
    x.leg_force_N[i] = e.leg_force_N[i];
    x.pad_held[i] = modes_.pad[i] == PadMode::kHeld;
    x.q_WP[i] = s.segment<4>(L_.quat_WP(i)).normalized();
    x.p_WJ[i] = e.pose.pads[i].p_WJ;
    x.v_WJ_W[i] = e.pose.pads[i].v_WJ_W;
    x.w_WP_W[i] = e.pose.pads[i].w_WP_W;
    x.shear_displacement_m[i] = e.pose.pads[i].shear_displacement_m;
    result_.max_joint_swing_rad =
        std::max(result_.max_joint_swing_rad, JointSwingAngle(e.pose.R_WB, e.pose.pads[i].R_WP));
    result_.peak_pad_force_N[i] = std::max(result_.peak_pad_force_N[i], e.soil[i].force_W.norm());
    if (modes_.pad[i] == PadMode::kHeld)
      result_.max_held_drift_m = std::max(result_.max_held_drift_m, (e.pose.pads[i].p_WJ - held_at_[i]).norm());
  }
  x.kinetic_J = KineticEnergy(model_, L_, s);
  x.potential_J = PotentialEnergy(model_, L_, s);
  x.dissipated_J = s[L_.work()];
  result_.max_tilt_rad = std::max(result_.max_tilt_rad, x.attitude.tilt_rad);
  const Eigen::Vector3d com = LanderCentreOfMass(model_, e.pose);
  for (int i = 0; i < kNumLegs; ++i)
    result_.min_stability_margin_m = std::min(result_.min_stability_margin_m, InsideEdgeDistance(e.pose, i, com));
  if (result_.first_touchdown_s)
    result_.max_body_deceleration_m_s2 = std::max(result_.max_body_deceleration_m_s2, x.a_WB_W.z());
  result_.trace.push_back(x);
  TrackCreep(t, e.pose);
}

void LanderHybrid::TrackCreep(double t, const LanderPose& pose) {
  bool creeping = options_.rest_at_creep && options_.stop_at_rest && result_.first_touchdown_s.has_value() &&
                  model_.soil_ramp_speed_m_s > 0.0;
  for (int i = 0; i < kNumLegs && creeping; ++i) creeping = pose.pads[i].v_WJ_W.norm() < model_.soil_ramp_speed_m_s;
  if (!creeping) {
    creeping_since_ = kUnknown;
  } else if (std::isnan(creeping_since_)) {
    creeping_since_ = t;
  }
}

bool LanderHybrid::RestsAtCreep(double t) {
  if (std::isnan(creeping_since_) || at_rest() || t - creeping_since_ < CreepDwell(model_)) return false;
  result_.rest_time_s = t;
  result_.events.push_back({t, LanderEventKind::kRest, -1});
  return true;
}

void LanderHybrid::TipOver(double t, const Eigen::VectorXd& y) {
  const CriticalEdge edge = CriticalSupportEdge(model_, L_, y);
  result_.tipped_over = true;
  result_.tip_over_edge = edge.from_leg;
  result_.tip_over_azimuth_rad = edge.outward_azimuth_rad;
  result_.events.push_back({t, LanderEventKind::kTipOver, -1});
}

void LanderHybrid::StopsAtRelease(const Eigen::VectorXd& y) {
  if (!options_.joint_stops_as_modes) return;
  const LanderPose pose = ComputePose(model_, L_, y);
  for (int i = 0; i < kNumLegs; ++i)
    if (const std::optional<ConeLimit>& cone = model_.legs[i].cone)
      modes_.stop[i] = JointSwingAngle(pose.R_WB, pose.pads[i].R_WP) > cone->half_angle_rad ? StopMode::kAtStop
                                                                                              : StopMode::kClear;
}

// A pad already on the surface at release (touchdown_speed_m_s: 0 places the lowest pad there)
// touches down at t = 0: CVODE never reports a root that holds at the start.
bool LanderHybrid::TouchdownsAtRelease(const Eigen::VectorXd& y) {
  // Rounding of the placement, far below any sinkage: 1e-9 of the lander's size.
  const double touching = 1e-9 * LengthScale(model_);
  const LanderPose pose = ComputePose(model_, L_, y);
  for (int i = 0; i < kNumLegs; ++i)
    if (PadDepth(model_, terrain_, i, pose.pads[i]) >= -touching) {
      result_.events.push_back({0.0, LanderEventKind::kTouchdown, i});
      result_.touchdown_time_s[i] = 0.0;
      result_.first_touchdown_s = 0.0;
    }
  // Standing at release with the centre of mass outside the support polygon: over at once (OnEvent).
  if (!result_.first_touchdown_s || StabilityMargin(model_, L_, y) >= 0.0) return false;
  TipOver(0.0, y);
  return true;
}

bool LanderHybrid::Touchdowns(double t, const std::vector<int>& found, Eigen::VectorXd& y) {
  bool reset = false;
  for (int i = 0; i < kNumLegs; ++i)
    if (found[PadRoot(i, 0)] != 0) {
      // Janosi's j counts the slip since this touchdown: it grows only in contact, so setting it
      // to 0 here is the reset at the last lift-off.
      if (L_.has_shear && y[L_.shear(i)] != 0.0) y[L_.shear(i)] = 0.0, reset = true;
      result_.events.push_back({t, LanderEventKind::kTouchdown, i});
      if (!result_.touchdown_time_s[i]) result_.touchdown_time_s[i] = t;
      if (!result_.first_touchdown_s) result_.first_touchdown_s = t;
    }
  return reset;
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
        result_.events.push_back({t, LanderEventKind::kReleaseLiftoff, i});
      } else if (found[PadRoot(i, 2)] != 0) {
        result_.events.push_back({t, LanderEventKind::kReleaseSink, i});
      } else {
        result_.events.push_back({t, LanderEventKind::kReleaseSlide, i});
      }
      changed = true;
    }
    if (IsCrushable(model_, L_, i)) {
      if (modes_.stroke[i] == StrokeMode::kLocked && found[LegRoot(i, 0)] != 0) {
        modes_.stroke[i] = StrokeMode::kFree;
        result_.events.push_back({t, LanderEventKind::kCrush, i});
        changed = true;
      } else if (modes_.stroke[i] == StrokeMode::kFree && found[LegRoot(i, 1)] != 0) {
        modes_.stroke[i] = StrokeMode::kBottomed;
        result_.events.push_back({t, LanderEventKind::kBottom, i});
        changed = true;
      } else if (modes_.stroke[i] == StrokeMode::kFree && found[LegRoot(i, 0)] != 0) {
        modes_.stroke[i] = StrokeMode::kLocked;
        result_.events.push_back({t, LanderEventKind::kLock, i});
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
        pose.pads[i].v_WJ_W.norm() <= options_.capture_speed_m_s * (1.0 + kCaptureTogether)) {
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
      // Relative to the pad's load, and to its share of the weight for a pad that carries (almost)
      // nothing, so that rounding in the margins never releases a hold.
      const double scale = std::max({PadWeightShare(model_), std::abs(e.soil[i].force_W.z()),
                                     std::numeric_limits<double>::min()});
      const double v = std::min({h.lift, h.sink, h.slide}) / scale;
      if (v < -1e-9 && v < worst_value) worst = i, worst_value = v, worst_check = h;
    }
    if (worst < 0) return;
    modes_.pad[worst] = PadMode::kFree;
    const double m_check = std::min({worst_check.lift, worst_check.sink, worst_check.slide});
    if (fresh[worst]) {
      // The capture cannot hold: undo it (the pad goes on moving under RFT).
      capture_refused_[worst] = true;
      s.segment(L_.nq, L_.nu) = before.segment(L_.nq, L_.nu);
      s[L_.work()] = before[L_.work()] + ProjectOntoConstraints(model_, L_, modes_, s);
    } else {
      const LanderEventKind kind = m_check == worst_check.lift   ? LanderEventKind::kReleaseLiftoff
                         : m_check == worst_check.sink ? LanderEventKind::kReleaseSink
                                                       : LanderEventKind::kReleaseSlide;
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
      result_.events.push_back({t, LanderEventKind::kCapture, i});
    }
    all_held &= modes_.pad[i] == PadMode::kHeld;
  }
  return all_held;
}

integ::EventAction LanderHybrid::OnEvent(double t, const std::vector<int>& found, Eigen::VectorXd& y) {
  sink_capacity_.fill(std::numeric_limits<double>::quiet_NaN());  // holds and poses may change here
  for (HeldPadCapacity& c : slide_capacity_) c.formed = false;
  last_rhs_valid_ = false;
  Record(t, y);  // the state at the event, in the old modes (peak forces before a capture)
  const LanderPose pose = ComputePose(model_, L_, y);
  const bool shear_reset = Touchdowns(t, found, y);
  // The tip-over root fires when the margin falls through zero; a lander whose centre of mass is
  // already outside its support polygon when a pad touches (aligned to a slope steeper than its
  // static angle) would never see it fall.
  bool touched = false;
  bool stopped = false;
  for (int i = 0; i < kNumLegs; ++i) {
    touched |= found[PadRoot(i, 0)] != 0;
    if (found[LegRoot(i, 2)] == 0) continue;
    const bool reached = modes_.stop[i] == StopMode::kClear;  // the other root function reports leaving
    modes_.stop[i] = reached ? StopMode::kAtStop : StopMode::kClear;
    result_.events.push_back({t, reached ? LanderEventKind::kStopReached : LanderEventKind::kStopLeft, i});
    stopped = true;
  }
  if (found[kTipRoot] != 0 || (touched && StabilityMargin(model_, L_, y) < 0.0)) {
    TipOver(t, y);
    return integ::EventAction::kStop;
  }
  for (int i = 0; i < kNumLegs; ++i)
    if (pose.pads[i].v_WJ_W.head<2>().norm() > options_.capture_speed_m_s || found[PadRoot(i, 0)] != 0)
      capture_refused_[i] = false;
  const Eigen::VectorXd before = y;
  std::array<bool, kNumLegs> fresh{};
  // A touchdown restarts the integrator. With a soil's dynamic term it is a discontinuity of the
  // right-hand side (a level pad's whole bottom meets the soil at once, and lambda rho v^2 A with
  // it), and after a restart CVODE sets aside a root function that is exactly zero there (a level
  // pad's depth is 0 to rounding at its touchdown); continuing instead, CVODE reported that zero
  // as the same touchdown again and again (20,000 events at one instant in a calibrate --targets run).
  if (!SwitchModes(t, found, pose, fresh))
    return shear_reset || touched || stopped ? integ::EventAction::kRestart : integ::EventAction::kContinue;
  OfferCaptures(pose, fresh);
  NormalizeQuaternions(L_, y);
  HoldStoppedPads(y, fresh);
  SettleHolds(t, y, fresh, before);
  result_.capture_loss_J += y[L_.work()] - before[L_.work()];
  const bool all_held = RecordCaptures(t, y, fresh);
  // At rest when every pad is held, or when the holds fix the body and every joint: a pad left
  // free (lifted, or touching without load) could only swing about its fixed ball joint, a
  // pendulum of a few grams-metres that moves nothing else (on slopes such a pad dangled and
  // brushed the soil for the rest of the run).
  const bool at_rest = all_held || HoldsFixTheStance(model_, L_, modes_, y);
  if (at_rest && !all_held) StopFreePads(y);
  Record(t, y);
  if (!(at_rest && options_.stop_at_rest)) return integ::EventAction::kRestart;
  // Static from here on: the loads no longer change, so the holds stay valid.
  result_.rest_time_s = t;
  result_.events.push_back({t, LanderEventKind::kRest, -1});
  return integ::EventAction::kStop;
}

// The free pads' spin about their fixed joints set to zero at rest; its kinetic energy is counted as
// dissipated, as a capture's.
void LanderHybrid::StopFreePads(Eigen::VectorXd& y) {
  const double before = KineticEnergy(model_, L_, y);
  for (int i = 0; i < kNumLegs; ++i)
    if (modes_.pad[i] == PadMode::kFree) y.segment<3>(L_.w_WP_W(i)).setZero();
  const double removed = before - KineticEnergy(model_, L_, y);
  y[L_.work()] += removed;
  result_.capture_loss_J += removed;
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
  result_.jacobian_pad_contacts = jacobian_data_.contact_evaluations;
  result_.rhs_pad_contacts = rhs_contacts_;
  result_.root_pad_contacts = root_contacts_;
}

}  // namespace touchdown::lander
