#include "lander/integ/hybrid_run.h"

#include <stdexcept>

namespace touchdown::integ {

void HybridRun::Start(double t0, const Eigen::VectorXd& y0) {
  totals_ = HybridSummary{};
  integrator_.Reset(t0, y0);
}

void HybridRun::Accumulate() {
  const IntegratorSummary s = integrator_.summary();
  IntegratorSummary& t = totals_.solver;
  t.steps += s.steps;
  t.rhs_evaluations += s.rhs_evaluations;
  t.root_evaluations += s.root_evaluations;
  t.error_test_failures += s.error_test_failures;
  t.jacobian_evaluations += s.jacobian_evaluations;
  t.jacobian_rhs_evaluations += s.jacobian_rhs_evaluations;
  t.nonlinear_convergence_failures += s.nonlinear_convergence_failures;
}

void HybridRun::Restart(double t, const Eigen::VectorXd& y) {
  Accumulate();
  ++totals_.restarts;
  integrator_.Reset(t, y);
}

Eigen::VectorXd HybridRun::AdvanceToRoot(double t_limit, int root, const std::string& failure) {
  const AdvanceResult r = integrator_.AdvanceTo(t_limit);
  if (r.status != AdvanceStatus::kFoundRoot || r.roots_found[root] == 0) throw IntegrationFailure(failure);
  return integrator_.state();
}

HybridOutcome HybridRun::Run(const HybridPhase& phase, const HybridCallbacks& callbacks) {
  if (!(phase.sample_rate_hz > 0.0)) throw std::invalid_argument("HybridRun: sample rate must be positive");
  const double dt = 1.0 / phase.sample_rate_hz;
  HybridOutcome out;
  long k = phase.first_sample;
  long events = 0;
  while (phase.end == RunEnd::kFailPastEnd || integrator_.time() < phase.end_s) {
    double t_out = k * dt;
    bool sampled = true;
    if (t_out > phase.end_s) {
      if (phase.end == RunEnd::kFailPastEnd) throw IntegrationFailure(phase.failure);
      t_out = phase.end_s;
      sampled = phase.end == RunEnd::kSampleAtEnd;
    }
    // An event restarted the integrator exactly at this output time: CVODE cannot start towards
    // its own start time (CV_TOO_CLOSE), and the state there is the output.
    AdvanceResult r{AdvanceStatus::kReachedTime, t_out, {}};
    if (integrator_.time() != t_out) {
      try {
        r = callbacks.segment ? integrator_.AdvanceTo(t_out, callbacks.segment) : integrator_.AdvanceTo(t_out);
      } catch (const RootStillZero&) {  // after a kContinue: restart where CVODE stopped (at the root)
        Restart(integrator_.time(), integrator_.state());
        continue;
      }
    }
    if (r.status == AdvanceStatus::kReachedTime) {
      if (sampled) {
        callbacks.sample(t_out, integrator_.state());
        ++totals_.samples;
      }
      ++k;
      if (sampled && callbacks.stop_after_sample && callbacks.stop_after_sample(t_out)) {
        out.stopped = true;
        out.t = t_out;
        out.y = integrator_.state();
        out.next_sample = k;
        return out;
      }
      continue;
    }
    ++totals_.events;
    if (phase.max_events >= 0 && ++events > phase.max_events)
      throw IntegrationFailure(phase.name + ": more than " + std::to_string(phase.max_events) + " events");
    Eigen::VectorXd y = integrator_.state();
    const EventAction action = callbacks.event(r.t, r.roots_found, y);
    if (action == EventAction::kStop) {
      out.stopped = true;
      out.t = r.t;
      out.y = std::move(y);
      out.next_sample = k;
      return out;
    }
    if (action == EventAction::kRestart) Restart(r.t, y);
  }
  out.t = integrator_.time();
  out.y = integrator_.state();
  out.next_sample = k;
  return out;
}

HybridSummary HybridRun::summary() const {
  HybridSummary s = totals_;
  const IntegratorSummary now = integrator_.summary();
  s.solver.steps += now.steps;
  s.solver.rhs_evaluations += now.rhs_evaluations;
  s.solver.root_evaluations += now.root_evaluations;
  s.solver.error_test_failures += now.error_test_failures;
  s.solver.jacobian_evaluations += now.jacobian_evaluations;
  s.solver.jacobian_rhs_evaluations += now.jacobian_rhs_evaluations;
  s.solver.nonlinear_convergence_failures += now.nonlinear_convergence_failures;
  s.solver.last_order = now.last_order;
  s.solver.last_step_s = now.last_step_s;
  s.solver.limiting_component = now.limiting_component;
  return s;
}

}  // namespace touchdown::integ
