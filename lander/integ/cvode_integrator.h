#pragma once
// A generic wrapper around SUNDIALS CVODE. It owns every SUNDIALS object (context, vector,
// matrix, linear solver, integrator memory) and knows nothing about footpads or landers:
// the model is a right-hand side and optional root functions (house style: Chrono's
// ChIntegrable vs ChTimestepper). No SUNDIALS type appears in this header.
//
// Exceptions thrown by the callbacks never cross CVODE's C frames: they are caught in the
// callback, CVODE is told the evaluation failed, and the exception is re-thrown once
// CVode() has returned.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace touchdown::integ {

using RhsFunction = std::function<void(double t, Eigen::Ref<const Eigen::VectorXd> y,
                                       Eigen::Ref<Eigen::VectorXd> ydot)>;
using RootFunction = std::function<void(double t, Eigen::Ref<const Eigen::VectorXd> y,
                                        Eigen::Ref<Eigen::VectorXd> g)>;
// d(ydot)/dy at (t, y), given ydot = f(t, y), into a zeroed n x n matrix. A model that knows its
// Jacobian's structure forms it for far less than CVODE's difference quotients (one right-hand
// side per state); an approximate one is fine as long as it captures the stiff part: it only
// drives the Newton iteration, never the accuracy of the result.
using JacobianFunction = std::function<void(double t, Eigen::Ref<const Eigen::VectorXd> y,
                                            Eigen::Ref<const Eigen::VectorXd> ydot, Eigen::Ref<Eigen::MatrixXd> J)>;

// Stiff mode: who factors the Newton matrix. Both are dense LU with partial pivoting; they agree to
// rounding, not bit for bit (lander/integ/eigen_dense_solver.h says why Eigen's is the default).
enum class DenseSolver { kEigen, kSundials };

struct IntegratorOptions {
  double rtol = 1e-10;
  double atol = 1e-12;
  double max_step = 0.0;       // [s]; 0 = no limit
  long max_num_steps = 200000;  // per call to AdvanceTo
  bool stiff = false;          // BDF + dense Newton when true, Adams + fixed point otherwise
  // Stiff mode: most steps between Jacobian evaluations (CVodeSetJacEvalFrequency); 0 = CVODE's
  // default (51). Each difference-quotient Jacobian costs one right-hand side per state.
  long max_steps_between_jacobians = 0;
  DenseSolver dense_solver = DenseSolver::kEigen;
  // Stiff mode: the Newton iteration's convergence coefficient (CVodeSetNonlinConvCoef: it stops
  // when its estimated error is below this times the error test's tolerance); 0 = CVODE's default
  // (0.1).
  double nonlinear_convergence_coefficient = 0.0;
  // Wall-clock budget [s] for the integrator's whole life (construction, every Reset and
  // AdvanceTo: one drop); 0 = none. Checked in every right-hand-side and root evaluation, so a
  // stiff or chattering model cannot hang a sweep: the advance then fails with an
  // IntegrationFailure saying the limit was exceeded.
  double max_wall_time_s = 0.0;
  // Right-hand-side evaluations [count] for the integrator's whole life (every Reset included,
  // difference-quotient Jacobians too); 0 = none. The deterministic budget: unlike the
  // wall-clock one it gives the same outcome on any machine under any load, so a sweep's
  // results never depend on load. Exceeding it fails the advance with a LimitExceeded.
  long max_rhs_evaluations = 0;
  // Absolute tolerance per state component (its size must be the state size); empty: `atol` for
  // all. A model whose states have different scales (metres, radians per second, joules) needs
  // one: a state that stays near zero by symmetry is otherwise resolved to `atol` in its own unit.
  std::vector<double> component_atol;
  // Ceres-style validity check; fills *error and returns false on a bad option.
  bool IsValid(std::string* error) const;
};

// Root functions are only tracked in the given directions: +1 rising, -1 falling, 0 both.
struct RootSpec {
  int count = 0;
  RootFunction function;
  std::vector<int> directions;
};

enum class AdvanceStatus { kReachedTime, kFoundRoot };

struct AdvanceResult {
  AdvanceStatus status = AdvanceStatus::kReachedTime;
  double t = 0.0;
  std::vector<int> roots_found;  // per root function: +1/-1 crossed, 0 not
};

struct IntegratorSummary {
  long steps = 0;
  long rhs_evaluations = 0;
  long root_evaluations = 0;
  long error_test_failures = 0;
  long jacobian_evaluations = 0;        // stiff mode only
  long jacobian_rhs_evaluations = 0;    // right-hand sides spent on difference-quotient Jacobians
  long nonlinear_convergence_failures = 0;
  // Where the integrator stands after its last step: method order, step size, and the state
  // component with the largest weighted local error (the one that limits the step; -1: none yet).
  int last_order = 0;
  double last_step_s = 0.0;
  int limiting_component = -1;
};

// Raised when CVODE fails (too much work, convergence failure, non-finite state, the
// wall-clock limit): the message carries CVODE's own reason.
class IntegrationFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An IntegrationFailure because a work budget ran out, not because the model failed: which
// budget (`limit`: "max_rhs_evaluations" or "max_wall_time_s") and its value, so a caller can
// retry with a larger one.
class LimitExceeded : public IntegrationFailure {
 public:
  LimitExceeded(const std::string& message, std::string limit, double value)
      : IntegrationFailure(message), limit_(std::move(limit)), value_(value) {}
  const std::string& limit() const { return limit_; }
  double value() const { return value_; }

 private:
  std::string limit_;
  double value_;
};

// An IntegrationFailure at a root the integrator has just returned: a root function is still
// exactly zero there and a rounding step later (a lander's sink rate -v_z can round to 0.0 at its
// located root), so CVODE, asked to go on, reports the same root again instead (CV_ILL_INPUT, "root
// found at and very near t"). Nothing was integrated: time() and state() are still the root's, and
// a Reset there goes on (CVODE then sets such a function aside until it moves off zero).
class RootStillZero : public IntegrationFailure {
 public:
  using IntegrationFailure::IntegrationFailure;
};

// A piece of the solution, t_begin < t_end, inside one internal step of the integrator: CVODE's
// interpolating polynomial there (its dense output). A quantity that peaks between output times (a
// drop's force, which rises and falls within one sample period on stiff soil) is read from these
// pieces rather than from the samples. Valid only during the observer's call.
class DenseSegment {
 public:
  double t_begin() const { return t_begin_; }
  double t_end() const { return t_end_; }
  // The k-th time derivative of the state at t in [t_begin, t_end] (k = 0: the state; at most the
  // method's current order). At a step's end, k = 1 is the right-hand side there to the nonlinear
  // solver's tolerance (the Nordsieck history's first column after the corrector).
  void Derivative(double t, int k, Eigen::Ref<Eigen::VectorXd> out) const;

 private:
  friend class CvodeIntegrator;
  DenseSegment(double t_begin, double t_end, const void* impl) : t_begin_(t_begin), t_end_(t_end), impl_(impl) {}
  double t_begin_, t_end_;
  const void* impl_;  // the integrator's CVODE memory (no SUNDIALS type in this header)
};
using SegmentObserver = std::function<void(const DenseSegment& segment)>;

class CvodeIntegrator {
 public:
  CvodeIntegrator(int state_size, RhsFunction rhs, const IntegratorOptions& options,
                  RootSpec roots = {});
  // Stiff mode only: the Newton iteration's Jacobian comes from `jacobian` instead of difference
  // quotients.
  void SetJacobian(JacobianFunction jacobian);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  // (Re)starts the integration at t0 from y0; also after a discontinuity of the model.
  void Reset(double t0, const Eigen::VectorXd& y0);
  // Integrates towards t_out and stops there or at the first root, whichever comes first.
  AdvanceResult AdvanceTo(double t_out);
  // The same integration, bit for bit (every step, root and output: CVODE's own mode, handed back
  // control after each internal step), and `observer` sees the solution since the last return (or
  // the last Reset) in time order, without gaps, in pieces each inside one internal step. A piece
  // past a root is seen only when the integration goes on from it (the next AdvanceTo).
  AdvanceResult AdvanceTo(double t_out, const SegmentObserver& observer);
  // Time and state after the last Reset or AdvanceTo (at a root: the root's time).
  double time() const { return t_; }
  const Eigen::VectorXd& state() const { return y_; }
  IntegratorSummary summary() const;

 private:
  friend class DenseSegment;
  struct Impl;
  // The return of a CVode call that did not stop short (`flag`: success or a root), at t_reached.
  AdvanceResult Finish(int flag, double t_reached);
  std::unique_ptr<Impl> impl_;
  Eigen::VectorXd y_;
  double t_ = 0.0;
};

}  // namespace touchdown::integ
