#pragma once
// The lander as a hybrid system, for the hybrid-run loop (lander/integ/hybrid_run.h): its modes,
// the right-hand side and root functions in those modes, the trace it records, and what each
// event does to the modes and the state (lander_simulation.h lists the events). Internal to
// SimulateLander.
#include <Eigen/Core>
#include <array>
#include <limits>
#include <vector>

#include "lander/integ/hybrid_run.h"
#include "lander/multibody/lander_dynamics.h"
#include "lander/multibody/lander_jacobian.h"
#include "lander/multibody/lander_run.h"

namespace touchdown::lander {

// One lander run as the hybrid loop sees it (integ::HybridRun): the modes, the right-hand side and
// root functions in those modes, the trace, and what each event does to the modes and the state.
class LanderHybrid {
 public:
  LanderHybrid(const LanderModel& model, const rft::Terrain& terrain, const LanderRunOptions& options,
               LanderRunResult& result)
      : model_(model), L_(RunStateLayout(model, terrain)), terrain_(terrain), options_(options), result_(result) {
    for (int i = 0; i < kNumLegs; ++i) modes_.stroke[i] = StrokeMode::kLocked;
    data_.evaluation.u_dot = Eigen::VectorXd::Zero(L_.nu);
    last_rhs_y_ = Eigen::VectorXd::Zero(L_.size);
    jacobian_data_.attitude_sensitivity = options.jacobian_attitude_sensitivity;
    // The slide checks form their integrals inside the root functions: their storage, reserved here.
    for (int i = 0; i < kNumLegs; ++i)
      slide_capacity_[i].integrals.runs.reserve(static_cast<size_t>(model.legs[i].pad->surface.size()));
  }
  const StateLayout& layout() const { return L_; }
  void Derivative(Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot);
  void Roots(Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g);
  // BDF's Newton Jacobian (lander_jacobian.h); `scale`: each state's typical size.
  void Jacobian(Eigen::Ref<const Eigen::VectorXd> y, const Eigen::VectorXd& scale, Eigen::Ref<Eigen::MatrixXd> J) {
    // CVODE forms its Jacobian at the predicted state, where it has just evaluated the right-hand side.
    const bool at_last_rhs = last_rhs_valid_ && y == last_rhs_y_;
    LanderJacobian(model_, L_, terrain_, modes_, y, scale, &data_, &jacobian_data_, J,
                   at_last_rhs ? &data_.evaluation : nullptr);
  }
  long jacobian_contact_evaluations() const { return jacobian_data_.contact_evaluations; }
  integ::RootSpec RootFunctions();
  void Record(double t, const Eigen::VectorXd& s);
  // The joints' stops' modes at release (LanderRunOptions::joint_stops_as_modes): at the stop where a
  // pad starts beyond its cone, clear of it elsewhere. Before the first step.
  void StopsAtRelease(const Eigen::VectorXd& y);
  // Touchdowns of pads touching at release; true if the lander is over already (it stands with
  // its centre of mass outside the support polygon).
  bool TouchdownsAtRelease(const Eigen::VectorXd& y);
  integ::EventAction OnEvent(double t, const std::vector<int>& found, Eigen::VectorXd& y);
  // After each grid sample: true, and the rest recorded, once every ball joint has crept slower
  // than the soil's ramp speed for the creep dwell (LanderRunOptions::rest_at_creep).
  bool RestsAtCreep(double t);
  bool at_rest() const { return result_.rest_time_s.has_value(); }
  void Finish(double t, const Eigen::VectorXd& y);

 private:
  // Whether every ball joint moves slower than the soil's ramp speed at this record, and since when
  // (creeping_since_; RestsAtCreep).
  void TrackCreep(double t, const LanderPose& pose);
  // Records a tip-over at t: the event and the support edge the lander goes over.
  void TipOver(double t, const Eigen::VectorXd& y);
  // Records the touchdowns; resets their pads' j (true if any changed: the run must restart).
  bool Touchdowns(double t, const std::vector<int>& found, Eigen::VectorXd& y);
  bool SwitchModes(double t, const std::vector<int>& found, const LanderPose& pose, std::array<bool, kNumLegs>& fresh);
  void OfferCaptures(const LanderPose& pose, std::array<bool, kNumLegs>& fresh);
  void HoldStoppedPads(Eigen::VectorXd& y, std::array<bool, kNumLegs>& fresh);
  void SettleHolds(double t, Eigen::VectorXd& s, const std::array<bool, kNumLegs>& fresh, const Eigen::VectorXd& before);
  void StopFreePads(Eigen::VectorXd& y);
  bool RecordCaptures(double t, const Eigen::VectorXd& y, const std::array<bool, kNumLegs>& fresh);

  const LanderModel& model_;
  const StateLayout L_;
  const rft::Terrain& terrain_;
  const LanderRunOptions& options_;
  LanderRunResult& result_;
  LanderModes modes_;
  LanderData data_;  // the right-hand side's (its last evaluation in data_.evaluation), and the root functions' scratch
  LanderEvaluation root_eval_;
  // The state of data_.evaluation, the last right-hand side (false after an event: the modes may have changed).
  Eigen::VectorXd last_rhs_y_;
  bool last_rhs_valid_ = false;
  LanderJacobianData jacobian_data_;
  std::array<Eigen::Vector3d, kNumLegs> held_at_;
  // Pads whose capture was offered and undone (the soil could not hold them) and that have not
  // been faster than the capture speed since: their stopping to sink no longer offers a capture
  // (only slowing down to the soil's ramp speed does, or speeding up and slowing down again).
  std::array<bool, kNumLegs> capture_refused_{};
  long rhs_contacts_ = 0, root_contacts_ = 0;  // pad contacts evaluated (LanderRunResult)
  // Vertical capacity of each held pad since the last event (NaN: not yet evaluated).
  std::array<double, kNumLegs> sink_capacity_{kUnknown, kUnknown, kUnknown, kUnknown};
  // Each held pad's soil integrals at its pose since the last event, for its slide checks.
  std::array<HeldPadCapacity, kNumLegs> slide_capacity_;
  // The time since which every recorded sample had its joints below the soil's ramp speed (NaN: the
  // last one did not).
  double creeping_since_ = kUnknown;
  static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace touchdown::lander
