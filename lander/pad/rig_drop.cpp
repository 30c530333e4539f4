#include "lander/pad/rig_drop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "lander/integ/hybrid_run.h"
#include "lander/pad/vertical_peaks.h"

namespace touchdown::pad {

namespace {
using S = RigStateLayout;

void RequireValid(const RigDropSetup& setup) {
  const RigDropInput& in = setup.initial;
  const RigDropOptions& options = setup.options;
  if (!setup.terrain) throw std::invalid_argument("RunRigDrop: no soil response");
  if (!(setup.body.mass_kg > 0.0 && std::isfinite(setup.body.mass_kg)))
    throw std::invalid_argument("RunRigDrop: mass must be positive and finite");
  if (!(in.gravity_m_s2 > 0.0 && std::isfinite(in.gravity_m_s2)))
    throw std::invalid_argument("RunRigDrop: gravity must be positive and finite");
  if (!(in.impact_speed_m_s >= 0.0 && std::isfinite(in.impact_speed_m_s)))
    throw std::invalid_argument("RunRigDrop: impact speed must be >= 0 and finite");
  if (!(options.sample_rate_hz > 0.0) || !(options.rest_duration_s >= 0.0) ||
      !(options.max_stroke_duration_s > 0.0) || !(options.approach_clearance_m >= 0.0))
    throw std::invalid_argument("RunRigDrop: invalid options");
}
}  // namespace

void Derivative(const RigDropSetup& model, RigData& data, const Eigen::Ref<const Eigen::VectorXd>& y,
                Eigen::Ref<Eigen::VectorXd> ydot) {
  const VerticalSoilResponse& response = *model.terrain;
  const double m = model.body.mass_kg, g = model.initial.gravity_m_s2;
  const double d = y[S::depth()];
  const double v = std::max(y[S::velocity_down()], 0.0);  // RFT resists only motion into the soil
  const bool in_soil = d > 0.0;
  const double force = in_soil ? response.Force(d, v) : 0.0;
  const double m_a = in_soil ? response.AddedMass(d) : 0.0;
  const double m_a_slope = in_soil ? response.AddedMassSlope(d) : 0.0;
  const double accretion = v * v * m_a_slope;  // momentum given per unit time to grains picked up
  data.soil_force_N = force;
  data.added_mass_kg = m_a;
  data.accretion_N = accretion;
  ydot[S::depth()] = y[S::velocity_down()];
  ydot[S::velocity_down()] = (m * g - force - accretion) / (m + m_a);
  ydot[S::work()] = force * v + 0.5 * accretion * v;
  if (ydot.size() > S::accretion()) ydot[S::accretion()] = 0.5 * accretion * v;
}

double RigContactForce(const RigDropSetup& setup, double d, double v) {
  const VerticalSoilResponse& response = *setup.terrain;
  if (!(d > 0.0)) return 0.0;
  v = std::max(v, 0.0);
  const double force = response.Force(d, v);
  const double m_a = response.AddedMass(d);
  if (m_a == 0.0) return force;  // exactly the soil force: no rounding from m (g - dv/dt)
  const double accretion = v * v * response.AddedMassSlope(d);
  const double m = setup.body.mass_kg, g = setup.initial.gravity_m_s2;
  const double dvdt = (m * g - force - accretion) / (m + m_a);
  return force + m_a * dvdt + accretion;
}

RigDropResult RunRigDrop(const RigDropSetup& setup) {
  RequireValid(setup);
  const VerticalSoilResponse& response = *setup.terrain;
  const RigDropOptions& options = setup.options;
  const double m = setup.body.mass_kg, g = setup.initial.gravity_m_s2, weight = m * g;
  bool resting = false;  // mode switch at the stop event

  RigData data;
  auto rhs = [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> ydot) {
    if (resting && response.StaticCapacity(std::max(y[S::depth()], 0.0)) >= weight) {
      ydot.setZero();  // static: the soil carries the weight, nothing moves
      return;
    }
    Derivative(setup, data, y, ydot);
  };
  integ::RootSpec roots;
  roots.count = 2;  // [0] touchdown: depth rises through 0; [1] stop: velocity falls through 0
  roots.directions = {+1, -1};
  roots.function = [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> gv) {
    gv[0] = y[S::depth()];
    gv[1] = y[S::velocity_down()];
  };
  integ::CvodeIntegrator integrator(S::size, rhs, options.integrator, roots);
  integ::HybridRun run(integrator);

  // Approach: free flight from a clearance chosen so the pad arrives at the requested speed.
  const double v_td = setup.initial.impact_speed_m_s;
  const double clearance = ReleaseClearance(options.approach_clearance_m, v_td, g);
  Eigen::VectorXd y(S::size);
  if (clearance > 0.0) {
    y << -clearance, ReleaseSpeed(v_td, g, clearance), 0.0, 0.0;
    run.Start(0.0, y);
    y = run.AdvanceToRoot(ApproachTimeLimit(clearance, g), 0, "touchdown was not reached during the approach");
  } else {
    y << 0.0, v_td, 0.0, 0.0;
  }
  // Touchdown defines t = 0; the depth root is exactly 0 there.
  y[S::depth()] = 0.0;
  y[S::work()] = 0.0;
  y[S::accretion()] = 0.0;
  run.Start(0.0, y);

  RigDropResult result;
  result.impact_energy_J = 0.5 * m * y[S::velocity_down()] * y[S::velocity_down()];
  auto record = [&](double t, const Eigen::VectorXd& s, double force) {
    result.trace.push_back({t, s[S::depth()], s[S::velocity_down()], force});
    result.peak_force_N = std::max(result.peak_force_N, force);
    if (!resting) result.max_deceleration_m_s2 = std::max(result.max_deceleration_m_s2, (force - weight) / m);
  };
  // The force just after contact (depth 0+): the velocity terms act on the first submerged face at
  // once (a flat pad's inertial drag lambda rho v^2 A, the plug's accretion), so the record starts
  // there rather than at the free fall's zero, which a recorder interpolating from it would smear
  // over the first sample period (found by an independent generator: 61 N recorded where 98 N acted).
  record(0.0, y, RigContactForce(setup, std::numeric_limits<double>::min(), y[S::velocity_down()]));

  // Stroke: sample until the velocity root.
  integ::HybridPhase stroke;
  stroke.sample_rate_hz = options.sample_rate_hz;
  stroke.end_s = options.max_stroke_duration_s;
  stroke.end = integ::RunEnd::kFailPastEnd;
  stroke.failure = "the pad did not stop within " + std::to_string(options.max_stroke_duration_s) + " s";
  integ::HybridCallbacks stroke_calls;
  stroke_calls.sample = [&](double t, const Eigen::VectorXd& s) {
    record(t, s, RigContactForce(setup, s[S::depth()], s[S::velocity_down()]));
  };
  stroke_calls.event = [&](double t, const std::vector<int>& found, Eigen::VectorXd& s) {
    if (found[1] == 0) return integ::EventAction::kContinue;  // the touchdown root again (grazing the surface)
    s[S::velocity_down()] = 0.0;  // the root: exactly at rest
    // At the stop v = 0: F_c = F + m_a dv/dt (the grains still push while the pad halts).
    record(t, s, RigContactForce(setup, s[S::depth()], 0.0));
    return integ::EventAction::kStop;
  };
  // Between samples too: a stiff soil stops the pad within one sample period.
  VerticalPeaks peaks(S::size, S::velocity_down(), -1.0, m, g);
  if (options.peaks_between_samples)
    stroke_calls.segment = [&](const integ::DenseSegment& segment) { peaks.Observe(segment); };
  const integ::HybridOutcome stop = run.Run(stroke, stroke_calls);
  result.peak_force_N = std::max(result.peak_force_N, peaks.peak_force_N());
  result.max_deceleration_m_s2 = std::max(result.max_deceleration_m_s2, peaks.max_deceleration_m_s2());
  const double t_stop = stop.t;
  y = stop.y;
  result.time_to_rest_s = t_stop;
  result.final_penetration_m = y[S::depth()];
  result.dissipated_energy_J = y[S::work()];
  result.accretion_loss_J = y[S::accretion()];
  result.gravity_work_J = weight * y[S::depth()];
  result.mean_conversion_rate_W = t_stop > 0.0 ? result.impact_energy_J / t_stop : 0.0;

  // Rest: the soil carries the weight; integrate on to show nothing creeps.
  resting = true;
  run.Restart(t_stop, y);
  const double dt = 1.0 / options.sample_rate_hz;
  integ::HybridPhase rest;
  rest.sample_rate_hz = options.sample_rate_hz;
  rest.first_sample = static_cast<long>(std::floor(t_stop / dt)) + 1;
  rest.end_s = t_stop + options.rest_duration_s;
  rest.end = integ::RunEnd::kIntegrateToEnd;
  integ::HybridCallbacks rest_calls;
  rest_calls.sample = [&](double t, const Eigen::VectorXd& s) {
    record(t, s, std::min(response.StaticCapacity(std::max(s[S::depth()], 0.0)), weight));
  };
  // A pad that loses its capacity sinks and stops again: the rest goes on through its events.
  rest_calls.event = [](double, const std::vector<int>&, Eigen::VectorXd&) { return integ::EventAction::kContinue; };
  const integ::HybridOutcome end = run.Run(rest, rest_calls);
  result.rest_creep_m = end.y[S::depth()] - result.final_penetration_m;
  result.solver = run.summary().solver;
  return result;
}

}  // namespace touchdown::pad
