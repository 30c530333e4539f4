#pragma once
// One loop for every hybrid simulation (rig, free pad, lander): continuous motion integrated by
// CvodeIntegrator between events, output sampled on a fixed grid t_k = k / rate, events found by
// CVODE's root functions and handled by the model (house style: Drake's Simulator with witness
// functions and unrestricted updates). The model says what to sample, what an event does to the
// state and the modes, and when the run stops; the loop owns the grid, the restarts after a
// discontinuity and the counters, so the three bodies cannot drift apart in how they step.
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "lander/integ/cvode_integrator.h"

namespace touchdown::integ {

// What a root means to the model.
enum class EventAction {
  kContinue,  // nothing changed: integrate on to the same output time
  kRestart,   // the state or the modes changed: restart the integrator from the updated state
  kStop,      // the run ends here, with the (possibly updated) state
};

// What happens when the next output time passes the end of the run.
enum class RunEnd {
  kSampleAtEnd,     // the end time itself is the last output (sampled even off the grid)
  kIntegrateToEnd,  // outputs on the grid only; then on to the end time without a sample
  kFailPastEnd,     // the run must stop at an event before: passing the end is a failure
};

struct HybridPhase {
  double sample_rate_hz = 1000.0;  // output grid t_k = k / rate
  long first_sample = 1;           // k of the first output
  double end_s = 0.0;
  RunEnd end = RunEnd::kSampleAtEnd;
  std::string failure;  // kFailPastEnd: the IntegrationFailure's message
  // More roots returned (events) than this fail the run, against Zeno behaviour; < 0: no limit.
  int max_events = -1;
  std::string name = "hybrid run";  // prefixes the max_events failure
};

struct HybridCallbacks {
  // A grid output: the state at t_k.
  std::function<void(double t, const Eigen::VectorXd& y)> sample;
  // A root: which functions crossed (CvodeIntegrator's roots_found); y is the state there and
  // may be updated (kRestart, kStop).
  std::function<EventAction(double t, const std::vector<int>& roots_found, Eigen::VectorXd& y)> event;
  // Optional, after each grid output: true ends the run there (HybridOutcome::stopped, at that
  // output's time and state), for a system whose rest shows in its samples rather than in a root.
  std::function<bool(double t)> stop_after_sample;
  // Optional: the solution between outputs, piece by piece (CvodeIntegrator's observed advance, the
  // same trajectory bit for bit), for what peaks between samples (a drop's peak force).
  SegmentObserver segment;
};

struct HybridOutcome {
  bool stopped = false;  // ended by kStop (else at the end time)
  double t = 0.0;
  Eigen::VectorXd y;
  long next_sample = 0;  // k of the first output not taken
};

// Counters since the last Start: the integrator's, summed over every restart (CVODE restarts its
// own at each one), and the loop's.
struct HybridSummary {
  IntegratorSummary solver;  // last_order, last_step_s, limiting_component: of the last segment
  long samples = 0;          // grid outputs
  long events = 0;           // roots returned
  long restarts = 0;         // restarts after an event
};

class HybridRun {
 public:
  explicit HybridRun(CvodeIntegrator& integrator) : integrator_(integrator) {}

  // (Re)starts at (t0, y0) and the counters from zero: what came before (an approach to
  // touchdown) is a preparation, not part of the run the summary describes.
  void Start(double t0, const Eigen::VectorXd& y0);
  // Restarts the integrator at (t, y) after a discontinuity; the counters go on.
  void Restart(double t, const Eigen::VectorXd& y);
  // Integrates until the first root before t_limit, which must be root `root`; the state there.
  // Anything else throws IntegrationFailure(failure).
  Eigen::VectorXd AdvanceToRoot(double t_limit, int root, const std::string& failure);
  // Samples and events from the current time until a kStop or the phase's end.
  HybridOutcome Run(const HybridPhase& phase, const HybridCallbacks& callbacks);
  HybridSummary summary() const;

 private:
  void Accumulate();
  CvodeIntegrator& integrator_;
  HybridSummary totals_;  // solver: finished segments only
};

}  // namespace touchdown::integ
