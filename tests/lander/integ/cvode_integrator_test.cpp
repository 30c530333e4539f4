// The generic CVODE wrapper: accuracy on closed forms, root-finding, option checks, and
// exceptions carried across the C callbacks.
#include "lander/integ/cvode_integrator.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace touchdown::integ {
namespace {

TEST(CvodeIntegrator, HarmonicOscillatorMatchesClosedForm) {
  for (bool stiff : {false, true}) {
    IntegratorOptions options;
    options.stiff = stiff;
    CvodeIntegrator integ(2, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
      d[0] = y[1];
      d[1] = -4.0 * y[0];
    }, options);
    integ.Reset(0.0, Eigen::Vector2d(1.0, 0.0));
    integ.AdvanceTo(3.0);
    EXPECT_NEAR(integ.state()[0], std::cos(6.0), 1e-8) << "stiff " << stiff;
    EXPECT_NEAR(integ.state()[1], -2.0 * std::sin(6.0), 1e-8);
    EXPECT_GT(integ.summary().steps, 0);
  }
}

TEST(CvodeIntegrator, FindsRootOfFreeFallExactly) {
  // Fall from 1 m: the ground is reached at t = sqrt(2 / g).
  RootSpec roots{1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) { g[0] = y[0]; },
                 {-1}};
  CvodeIntegrator integ(2, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
    d[0] = y[1];
    d[1] = -9.81;
  }, IntegratorOptions{}, roots);
  integ.Reset(0.0, Eigen::Vector2d(1.0, 0.0));
  const AdvanceResult r = integ.AdvanceTo(10.0);
  ASSERT_EQ(r.status, AdvanceStatus::kFoundRoot);
  EXPECT_EQ(r.roots_found[0], -1);
  EXPECT_NEAR(r.t, std::sqrt(2.0 / 9.81), 1e-9);
  EXPECT_NEAR(integ.time(), r.t, 0.0);
}

TEST(CvodeIntegrator, RootDirectionFilters) {
  // sin(t) rises through 0 at 2 pi, falls at pi; only the rising crossing is asked for.
  RootSpec roots{1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) { g[0] = y[0]; },
                 {+1}};
  CvodeIntegrator integ(2, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
    d[0] = y[1];
    d[1] = -y[0];
  }, IntegratorOptions{}, roots);
  integ.Reset(0.0, Eigen::Vector2d(0.0, 1.0));
  const AdvanceResult r = integ.AdvanceTo(10.0);
  ASSERT_EQ(r.status, AdvanceStatus::kFoundRoot);
  EXPECT_NEAR(r.t, 2 * M_PI, 1e-7);
}

TEST(CvodeIntegrator, ExceptionInRightHandSideIsRethrownAfterCvodeReturns) {
  CvodeIntegrator integ(1, [](double t, Eigen::Ref<const Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> d) {
    if (t > 0.5) throw std::domain_error("model refused");
    d[0] = 1.0;
  }, IntegratorOptions{});
  integ.Reset(0.0, Eigen::VectorXd::Zero(1));
  EXPECT_THROW(integ.AdvanceTo(1.0), std::domain_error);
}

TEST(CvodeIntegrator, SolverFailureComesBackWithReason) {
  IntegratorOptions options;
  options.max_num_steps = 5;
  CvodeIntegrator integ(1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
    d[0] = -1000.0 * y[0] + std::sin(1000.0 * y[0]);
  }, options);
  integ.Reset(0.0, Eigen::VectorXd::Ones(1));
  try {
    integ.AdvanceTo(100.0);
    FAIL() << "expected IntegrationFailure";
  } catch (const IntegrationFailure& e) {
    EXPECT_NE(std::string(e.what()).find("CV_TOO_MUCH_WORK"), std::string::npos) << e.what();
  }
}

TEST(CvodeIntegrator, WallClockLimitFailsTheAdvanceWithItsReason) {
  // A right-hand side that costs 2 ms per evaluation and a 50 ms budget: the advance must stop
  // with an IntegrationFailure naming the limit, well before the 10^4 s it was asked for.
  IntegratorOptions options;
  options.max_wall_time_s = 0.05;
  options.max_num_steps = 100000000;
  CvodeIntegrator integ(1, [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    d[0] = std::cos(y[0]);
  }, options);
  integ.Reset(0.0, Eigen::VectorXd::Zero(1));
  const auto start = std::chrono::steady_clock::now();
  try {
    integ.AdvanceTo(1e4);
    FAIL() << "expected IntegrationFailure";
  } catch (const IntegrationFailure& e) {
    EXPECT_NE(std::string(e.what()).find("wall-clock limit exceeded"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(CvodeIntegrator, WallClockLimitIsCheckedInRootFunctionsToo) {
  // A cheap right-hand side, a slow root function, and steps capped at 1 ms so that reaching
  // t = 1000 s takes a million root evaluations.
  IntegratorOptions options;
  options.max_wall_time_s = 0.05;
  options.max_num_steps = 100000000;
  options.max_step = 1e-3;
  RootSpec roots;
  roots.count = 1;
  roots.function = [](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> g) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    g[0] = y[0] + 1.0;  // never crosses
  };
  CvodeIntegrator integ(1, [](double, Eigen::Ref<const Eigen::VectorXd>, Eigen::Ref<Eigen::VectorXd> d) {
    d[0] = 1.0;
  }, options, roots);
  integ.Reset(0.0, Eigen::VectorXd::Zero(1));
  try {
    integ.AdvanceTo(1e3);
    FAIL() << "expected IntegrationFailure";
  } catch (const IntegrationFailure& e) {
    EXPECT_NE(std::string(e.what()).find("wall-clock limit exceeded"), std::string::npos) << e.what();
  }
}

// The deterministic work limit. It counts every right-hand side over the
// integrator's life (across Resets, whose CVODE counters restart), so the same model fails at
// the same evaluation on any machine; the failure names the limit and its value.
TEST(CvodeIntegrator, EvaluationLimitFailsAtTheSameEvaluationAcrossResets) {
  IntegratorOptions options;
  EXPECT_EQ(options.max_rhs_evaluations, 0);  // none by default
  options.max_rhs_evaluations = 300;
  options.max_step = 1e-2;
  long calls = 0;
  auto run = [&] {
    calls = 0;
    CvodeIntegrator integ(1, [&](double, Eigen::Ref<const Eigen::VectorXd> y, Eigen::Ref<Eigen::VectorXd> d) {
      ++calls;
      d[0] = std::cos(y[0]);
    }, options);
    for (int k = 0;; ++k) {  // restarts every 0.5 s: the budget is not renewed
      integ.Reset(0.5 * k, Eigen::VectorXd::Zero(1));
      integ.AdvanceTo(0.5 * (k + 1));
    }
  };
  for (int attempt = 0; attempt < 2; ++attempt) {
    try {
      run();
      FAIL() << "expected LimitExceeded";
    } catch (const LimitExceeded& e) {
      EXPECT_EQ(e.limit(), "max_rhs_evaluations");
      EXPECT_EQ(e.value(), 300.0);
      EXPECT_NE(std::string(e.what()).find("more than 300 right-hand-side evaluations"), std::string::npos) << e.what();
      EXPECT_EQ(calls, 300);  // the 301st evaluation is refused before the model runs
    }
  }
  options.max_rhs_evaluations = -1;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
}

TEST(CvodeIntegrator, NoWallClockLimitByDefault) {
  IntegratorOptions options;
  EXPECT_EQ(options.max_wall_time_s, 0.0);
  options.max_wall_time_s = -1.0;
  std::string why;
  EXPECT_FALSE(options.IsValid(&why));
  EXPECT_NE(why.find("max_wall_time_s"), std::string::npos);
  options.max_wall_time_s = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(options.IsValid(&why));
}

TEST(CvodeIntegrator, OptionsAreValidated) {
  std::string why;
  IntegratorOptions bad;
  bad.rtol = 0.0;
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_NE(why.find("rtol"), std::string::npos);
  bad = {};
  bad.atol = -1;
  EXPECT_FALSE(bad.IsValid(&why));
  EXPECT_TRUE(IntegratorOptions{}.IsValid(&why));
  EXPECT_THROW(CvodeIntegrator(1, [](double, auto, auto) {}, bad), std::invalid_argument);
  // Newton's convergence coefficient: 0 keeps CVODE's 0.1; a value of 1 or more, or negative, or
  // not a number, is refused.
  for (double c : {-0.01, 1.0, std::nan("")}) {
    bad = {};
    bad.nonlinear_convergence_coefficient = c;
    EXPECT_FALSE(bad.IsValid(&why)) << c;
    EXPECT_NE(why.find("nonlinear_convergence_coefficient"), std::string::npos);
  }
  IntegratorOptions tight;
  tight.nonlinear_convergence_coefficient = 0.03;
  EXPECT_TRUE(tight.IsValid(&why));
}

}  // namespace
}  // namespace touchdown::integ
