// The one hybrid-run loop (lander/integ/hybrid_run.h) on a bouncing ball: grid samples, events
// located by root-finding, state resets, stops, the three ways a run ends, and the counters.
#include "lander/integ/hybrid_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace touchdown::integ {
namespace {

constexpr double kG = 9.81;

// y = [height, upward velocity]; root 0: the ball reaches the floor (height falling through 0).
IntegratorOptions Tight() {
  IntegratorOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  return o;
}

struct Ball {
  CvodeIntegrator integrator{
      2, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) { d << y[1], -kG; }, Tight(),
      RootSpec{1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) { g[0] = y[0]; }, {-1}}};
};

Eigen::VectorXd State(double h, double v) { return (Eigen::VectorXd(2) << h, v).finished(); }

// A system whose rest shows in its samples (the lander's creep) ends the run after the sample that
// shows it: at that grid time and state, the next sample the first not taken, no event counted.
TEST(HybridRun, AStopAfterASampleEndsTheRunAtThatSample) {
  Ball ball;
  HybridRun run(ball.integrator);
  run.Start(0.0, State(10.0, 0.0));
  std::vector<double> sample_times;
  HybridCallbacks calls;
  calls.event = [](double, const std::vector<int>&, Eigen::VectorXd&) { return EventAction::kRestart; };
  // Stops at the first sample whose speed exceeds 5 m/s: t = 0.51 s on a 100 Hz grid (5 / 9.81 = 0.5097).
  double last_speed = 0.0;
  calls.sample = [&](double t, const Eigen::VectorXd& y) {
    sample_times.push_back(t);
    last_speed = -y[1];
  };
  calls.stop_after_sample = [&](double) { return last_speed > 5.0; };
  HybridPhase phase;
  phase.sample_rate_hz = 100.0;
  phase.end_s = 1.0;
  const HybridOutcome out = run.Run(phase, calls);
  ASSERT_TRUE(out.stopped);
  EXPECT_EQ(out.t, 51 * (1.0 / 100.0));
  EXPECT_EQ(out.next_sample, 52);
  ASSERT_EQ(sample_times.size(), 51u);  // 0.01, ..., 0.51 (the grid starts at k = 1)
  EXPECT_EQ(sample_times.back(), out.t);
  EXPECT_NEAR(out.y[1], -kG * out.t, 1e-9);
  EXPECT_NEAR(out.y[0], 10.0 - 0.5 * kG * out.t * out.t, 1e-9);
  EXPECT_EQ(run.summary().events, 0);
}

TEST(HybridRun, BouncesAreEventsWithResetsAndSamplesStayOnTheGrid) {
  Ball ball;
  HybridRun run(ball.integrator);
  const double h0 = 1.0, e = 0.5;
  run.Start(0.0, State(h0, 0.0));
  std::vector<double> sample_times, bounce_times;
  HybridCallbacks calls;
  calls.sample = [&](double t, const Eigen::VectorXd& y) {
    sample_times.push_back(t);
    EXPECT_GE(y[0], -1e-9);
  };
  calls.event = [&](double t, const std::vector<int>& found, Eigen::VectorXd& y) {
    EXPECT_EQ(found[0], -1);
    bounce_times.push_back(t);
    y[0] = 0.0;
    y[1] = -e * y[1];
    return bounce_times.size() < 3 ? EventAction::kRestart : EventAction::kStop;
  };
  HybridPhase phase;
  phase.sample_rate_hz = 100.0;
  phase.end_s = 10.0;
  const HybridOutcome out = run.Run(phase, calls);
  ASSERT_TRUE(out.stopped);
  // Bounce n at t1 (1 + 2 e + ... + 2 e^(n-1)), t1 = sqrt(2 h0 / g).
  const double t1 = std::sqrt(2.0 * h0 / kG);
  ASSERT_EQ(bounce_times.size(), 3u);
  EXPECT_NEAR(bounce_times[0], t1, 1e-9);
  EXPECT_NEAR(bounce_times[1], t1 * (1.0 + 2.0 * e), 1e-9);
  EXPECT_NEAR(bounce_times[2], t1 * (1.0 + 2.0 * e + 2.0 * e * e), 1e-9);
  EXPECT_EQ(out.t, bounce_times[2]);
  EXPECT_NEAR(out.y[1], e * e * e * std::sqrt(2.0 * kG * h0), 1e-8);
  // Every grid time before the stop, exactly k / rate, none skipped at an event.
  ASSERT_FALSE(sample_times.empty());
  for (size_t k = 0; k < sample_times.size(); ++k) EXPECT_EQ(sample_times[k], double(k + 1) * (1.0 / 100.0));
  EXPECT_LT(sample_times.back(), out.t);
  EXPECT_GT(sample_times.back() + 0.01, out.t);
  EXPECT_EQ(out.next_sample, long(sample_times.size()) + 1);
  const HybridSummary s = run.summary();
  EXPECT_EQ(s.events, 3);
  EXPECT_EQ(s.restarts, 2);
  EXPECT_EQ(s.samples, long(sample_times.size()));
  EXPECT_GT(s.solver.steps, 0);
  EXPECT_GE(s.solver.rhs_evaluations, s.solver.steps);
}

TEST(HybridRun, RunEndsSampleIntegrateOrFailAtTheEnd) {
  auto run_to = [](RunEnd end, std::vector<double>* times) {
    Ball ball;
    HybridRun run(ball.integrator);
    run.Start(0.0, State(100.0, 0.0));  // no floor within the run
    HybridCallbacks calls;
    calls.sample = [&](double t, const Eigen::VectorXd&) { times->push_back(t); };
    calls.event = [](double, const std::vector<int>&, Eigen::VectorXd&) { return EventAction::kContinue; };
    HybridPhase phase;
    phase.sample_rate_hz = 10.0;
    phase.end_s = 0.25;
    phase.end = end;
    phase.failure = "did not stop";
    return run.Run(phase, calls);
  };
  std::vector<double> sampled, integrated, failed;
  const HybridOutcome a = run_to(RunEnd::kSampleAtEnd, &sampled);
  EXPECT_FALSE(a.stopped);
  EXPECT_EQ(a.t, 0.25);
  EXPECT_NEAR(a.y[0], 100.0 - 0.5 * kG * 0.25 * 0.25, 1e-9);
  EXPECT_EQ(sampled, (std::vector<double>{0.1, 0.2, 0.25}));
  const HybridOutcome b = run_to(RunEnd::kIntegrateToEnd, &integrated);
  EXPECT_EQ(b.t, 0.25);
  EXPECT_EQ(integrated, (std::vector<double>{0.1, 0.2}));
  try {
    run_to(RunEnd::kFailPastEnd, &failed);
    ADD_FAILURE() << "passing the end must fail";
  } catch (const IntegrationFailure& e) {
    EXPECT_STREQ(e.what(), "did not stop");
  }
  EXPECT_EQ(failed, (std::vector<double>{0.1, 0.2}));  // the failure comes before integrating past the end
}

TEST(HybridRun, ContinueGoesOnToTheSameOutputTimeAndEventsAreLimited) {
  Ball ball;
  HybridRun run(ball.integrator);
  run.Start(0.0, State(0.01, 0.0));
  std::vector<double> times;
  HybridCallbacks calls;
  calls.sample = [&](double t, const Eigen::VectorXd&) { times.push_back(t); };
  calls.event = [](double, const std::vector<int>&, Eigen::VectorXd& y) {
    y[1] = -y[1];  // an elastic bounce
    return EventAction::kRestart;
  };
  HybridPhase phase;
  phase.sample_rate_hz = 10.0;
  phase.end_s = 1.0;
  phase.max_events = 3;
  phase.name = "ball";
  try {
    run.Run(phase, calls);
    ADD_FAILURE() << "a fourth bounce must fail";
  } catch (const IntegrationFailure& e) {
    EXPECT_STREQ(e.what(), "ball: more than 3 events");
  }
  EXPECT_EQ(run.summary().events, 4);

  // An event that changes nothing: the same output time is reached after it.
  Ball other;
  HybridRun quiet(other.integrator);
  quiet.Start(0.0, State(0.01, 0.0));
  times.clear();
  calls.event = [](double, const std::vector<int>&, Eigen::VectorXd&) { return EventAction::kContinue; };
  phase.max_events = -1;
  phase.end_s = 0.1;
  const HybridOutcome out = quiet.Run(phase, calls);
  EXPECT_EQ(times, (std::vector<double>{0.1}));
  EXPECT_EQ(quiet.summary().events, 1);
  EXPECT_LT(out.y[0], 0.0);  // through the floor: nothing reset it
}

// A root function that is exactly zero where its root was found and stays zero just after it (a
// lander's sink rate -v_z that rounds to 0.0 at the located root): CVODE, continuing, would find
// the root "at and very near" that time again and fail (CV_ILL_INPUT). The loop restarts there
// instead, where CVODE sets such a function aside until it moves off zero.
TEST(HybridRun, ContinueAtARootFunctionStillExactlyZeroRestartsInstead) {
  CvodeIntegrator integrator{
      1, [](double, Eigen::Ref<const Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> d) { d[0] = 1.0; }, Tight(),
      RootSpec{1,
               [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) {
                 g[0] = std::max(0.5 - y[0], 0.0);  // falls to zero at y = 0.5 and stays there
               },
               {-1}}};
  HybridRun run(integrator);
  run.Start(0.0, Eigen::VectorXd::Zero(1));
  std::vector<double> events, samples;
  HybridCallbacks calls;
  calls.sample = [&](double t, const Eigen::VectorXd&) { samples.push_back(t); };
  calls.event = [&](double t, const std::vector<int>&, Eigen::VectorXd&) {
    events.push_back(t);
    return EventAction::kContinue;
  };
  HybridPhase phase;
  phase.sample_rate_hz = 4.0;
  phase.end_s = 1.0;
  const HybridOutcome out = run.Run(phase, calls);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0], 0.5, 1e-9);
  EXPECT_EQ(samples, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
  EXPECT_NEAR(out.y[0], 1.0, 1e-9);
  EXPECT_EQ(run.summary().restarts, 1);  // the continue became a restart
}

// An event exactly on the output grid whose handler restarts the integrator: the output there is
// the state after the event (CVODE, asked to integrate towards its own start time, would fail).
TEST(HybridRun, RestartExactlyAtAnOutputTimeSamplesThere) {
  CvodeIntegrator integrator{
      1, [](double, Eigen::Ref<const Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> d) { d[0] = 1.0; }, Tight(),
      RootSpec{1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) { g[0] = 0.5 - y[0]; },
               {-1}}};
  HybridRun run(integrator);
  run.Start(0.0, Eigen::VectorXd::Zero(1));
  std::vector<double> events, samples, values;
  HybridCallbacks calls;
  calls.sample = [&](double t, const Eigen::VectorXd& y) {
    samples.push_back(t);
    values.push_back(y[0]);
  };
  calls.event = [&](double t, const std::vector<int>&, Eigen::VectorXd& y) {
    events.push_back(t);
    y[0] += 1.0;  // a jump: the output at the event's time is the state after it
    return EventAction::kRestart;
  };
  HybridPhase phase;
  phase.sample_rate_hz = 4.0;
  phase.end_s = 1.0;
  run.Run(phase, calls);
  ASSERT_EQ(events, (std::vector<double>{0.5}));  // exactly on the grid (y = t is integrated exactly)
  EXPECT_EQ(samples, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
  ASSERT_EQ(values.size(), 4u);
  EXPECT_NEAR(values[1], 1.5, 1e-12);
  EXPECT_NEAR(values[3], 2.0, 1e-9);
}

TEST(HybridRun, AdvanceToRootNeedsThatRootAndStartClearsTheCounters) {
  Ball ball;
  HybridRun run(ball.integrator);
  run.Start(0.0, State(0.5, 0.0));
  const Eigen::VectorXd at_floor = run.AdvanceToRoot(10.0, 0, "no floor");
  EXPECT_NEAR(at_floor[0], 0.0, 1e-12);
  EXPECT_GT(run.summary().solver.steps, 0);
  run.Start(0.0, State(100.0, 0.0));
  EXPECT_EQ(run.summary().solver.steps, 0);
  EXPECT_THROW(run.AdvanceToRoot(0.1, 0, "no floor"), IntegrationFailure);
}

}  // namespace
}  // namespace touchdown::integ
