#include "lander/integ/cvode_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <utility>

#include "lander/integ/eigen_dense_solver.h"

namespace touchdown::integ {

bool IntegratorOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& what) {
    if (error) *error = what;
    return false;
  };
  if (!(rtol > 0.0 && rtol < 1.0)) return fail("rtol must be in (0, 1)");
  if (!(atol > 0.0 && std::isfinite(atol))) return fail("atol must be positive and finite");
  for (double a : component_atol)
    if (!(a > 0.0 && std::isfinite(a))) return fail("every component_atol must be positive and finite");
  if (!(max_step >= 0.0 && std::isfinite(max_step))) return fail("max_step must be >= 0");
  if (max_num_steps <= 0) return fail("max_num_steps must be positive");
  if (max_steps_between_jacobians < 0) return fail("max_steps_between_jacobians must be >= 0");
  if (!(nonlinear_convergence_coefficient >= 0.0 && nonlinear_convergence_coefficient < 1.0))
    return fail("nonlinear_convergence_coefficient must be in [0, 1)");
  if (!(max_wall_time_s >= 0.0 && std::isfinite(max_wall_time_s)))
    return fail("max_wall_time_s must be >= 0 and finite");
  if (max_rhs_evaluations < 0) return fail("max_rhs_evaluations must be >= 0");
  return true;
}

struct CvodeIntegrator::Impl {
  int n = 0;
  RhsFunction rhs;
  RootSpec roots;
  JacobianFunction jacobian;
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  N_Vector dky = nullptr;  // DenseSegment's scratch
  long max_num_steps = 0;  // per AdvanceTo
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  SUNNonlinearSolver nonlinear_solver = nullptr;
  void* cvode = nullptr;
  std::exception_ptr pending;  // exception caught inside a C callback
  std::string last_error;      // CVODE's own message for the last failure
  bool initialised = false;
  bool returned_root = false;    // the last AdvanceTo stopped at a root (and no Reset since)
  double max_wall_time_s = 0.0;  // 0: no limit
  long max_rhs_evaluations = 0;  // 0: no limit
  long rhs_calls = 0;            // over the integrator's life (CVODE's own counter restarts at each Reset)
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();

  // True (and the failure pending) once the wall-clock budget is spent. Called first in every
  // callback: returning -1 there makes CVode return at once, and AdvanceTo re-throws.
  bool OutOfTime() {
    if (max_wall_time_s <= 0.0) return false;
    const std::chrono::duration<double> used = std::chrono::steady_clock::now() - started;
    if (used.count() <= max_wall_time_s) return false;
    std::ostringstream s;
    s << "wall-clock limit exceeded: more than " << max_wall_time_s
      << " s (max_wall_time_s; load-dependent: a busier machine fails more drops)";
    pending = std::make_exception_ptr(LimitExceeded(s.str(), "max_wall_time_s", max_wall_time_s));
    return true;
  }

  // True (and the failure pending) once the right-hand-side budget is spent; counts this call.
  bool OutOfEvaluations() {
    if (max_rhs_evaluations <= 0 || ++rhs_calls <= max_rhs_evaluations) return false;
    std::ostringstream s;
    s << "evaluation limit exceeded: more than " << max_rhs_evaluations
      << " right-hand-side evaluations (max_rhs_evaluations)";
    pending = std::make_exception_ptr(
        LimitExceeded(s.str(), "max_rhs_evaluations", static_cast<double>(max_rhs_evaluations)));
    return true;
  }

  ~Impl() {
    if (cvode) CVodeFree(&cvode);
    if (nonlinear_solver) SUNNonlinSolFree(nonlinear_solver);
    if (linear_solver) SUNLinSolFree(linear_solver);
    if (matrix) SUNMatDestroy(matrix);
    if (y) N_VDestroy(y);
    if (dky) N_VDestroy(dky);
    if (context) SUNContext_Free(&context);
  }

  static int Rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      if (self->OutOfEvaluations() || self->OutOfTime()) return -1;
      Eigen::Map<const Eigen::VectorXd> ym(N_VGetArrayPointer(y), self->n);
      Eigen::Map<Eigen::VectorXd> dm(N_VGetArrayPointer(ydot), self->n);
      self->rhs(t, ym, dm);
      // A non-finite derivative is recoverable: CVODE retries with a smaller step.
      return dm.allFinite() ? 0 : 1;
    } catch (...) {
      self->pending = std::current_exception();
      return -1;
    }
  }

  static int Jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(user);
    try {
      if (self->OutOfTime()) return -1;
      Eigen::Map<const Eigen::VectorXd> ym(N_VGetArrayPointer(y), self->n);
      Eigen::Map<const Eigen::VectorXd> fm(N_VGetArrayPointer(fy), self->n);
      // SUNDIALS' dense matrix is column-major and contiguous, as Eigen's default.
      Eigen::Map<Eigen::MatrixXd> jm(SM_DATA_D(J), self->n, self->n);
      jm.setZero();
      self->jacobian(t, ym, fm, jm);
      return jm.allFinite() ? 0 : 1;
    } catch (...) {
      self->pending = std::current_exception();
      return -1;
    }
  }

  static int Roots(realtype t, N_Vector y, realtype* g, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      if (self->OutOfTime()) return -1;
      Eigen::Map<const Eigen::VectorXd> ym(N_VGetArrayPointer(y), self->n);
      Eigen::Map<Eigen::VectorXd> gm(g, self->roots.count);
      self->roots.function(t, ym, gm);
      return 0;
    } catch (...) {
      self->pending = std::current_exception();
      return -1;
    }
  }

  static void ErrorHandler(int, const char* module, const char* function, char* msg, void* user) {
    auto* self = static_cast<Impl*>(user);
    std::ostringstream s;
    s << module << "::" << function << ": " << msg;
    self->last_error = s.str();
  }

  void Check(int flag, const char* what) const {
    if (flag < 0) {
      std::ostringstream s;
      // CVodeGetReturnFlagName returns a malloc'd string the caller owns (found by LeakSanitizer).
      char* name = CVodeGetReturnFlagName(flag);
      s << what << " failed: " << (name ? name : "unknown flag");
      std::free(name);
      if (!last_error.empty()) s << " (" << last_error << ")";
      throw IntegrationFailure(s.str());
    }
  }
};

CvodeIntegrator::CvodeIntegrator(int state_size, RhsFunction rhs, const IntegratorOptions& options,
                                 RootSpec roots)
    : impl_(std::make_unique<Impl>()), y_(Eigen::VectorXd::Zero(state_size)) {
  std::string why;
  if (!options.IsValid(&why)) throw std::invalid_argument("IntegratorOptions: " + why);
  if (state_size <= 0) throw std::invalid_argument("CvodeIntegrator: state size must be positive");
  if (roots.count > 0 && (!roots.function || (!roots.directions.empty() &&
                                              int(roots.directions.size()) != roots.count)))
    throw std::invalid_argument("CvodeIntegrator: inconsistent RootSpec");
  Impl& m = *impl_;
  m.n = state_size;
  m.rhs = std::move(rhs);
  m.roots = std::move(roots);
  m.max_wall_time_s = options.max_wall_time_s;
  m.max_rhs_evaluations = options.max_rhs_evaluations;
  m.started = std::chrono::steady_clock::now();
  if (SUNContext_Create(nullptr, &m.context) != 0) throw IntegrationFailure("SUNContext_Create failed");
  m.y = N_VNew_Serial(state_size, m.context);
  m.dky = N_VNew_Serial(state_size, m.context);
  N_VConst(0.0, m.y);
  m.max_num_steps = options.max_num_steps;
  m.cvode = CVodeCreate(options.stiff ? CV_BDF : CV_ADAMS, m.context);
  if (!m.cvode || !m.y) throw IntegrationFailure("CVodeCreate failed");
  m.Check(CVodeSetErrHandlerFn(m.cvode, &Impl::ErrorHandler, &m), "CVodeSetErrHandlerFn");
  m.Check(CVodeInit(m.cvode, &Impl::Rhs, 0.0, m.y), "CVodeInit");
  m.Check(CVodeSetUserData(m.cvode, &m), "CVodeSetUserData");
  if (options.component_atol.empty()) {
    m.Check(CVodeSStolerances(m.cvode, options.rtol, options.atol), "CVodeSStolerances");
  } else {
    if (static_cast<int>(options.component_atol.size()) != state_size)
      throw std::invalid_argument("CvodeIntegrator: component_atol has " + std::to_string(options.component_atol.size()) +
                                  " entries for a state of " + std::to_string(state_size));
    // CVODE copies the tolerance vector.
    std::vector<double> atol = options.component_atol;
    N_Vector a = N_VMake_Serial(state_size, atol.data(), m.context);
    const int flag = CVodeSVtolerances(m.cvode, options.rtol, a);
    N_VDestroy(a);
    m.Check(flag, "CVodeSVtolerances");
  }
  m.Check(CVodeSetMaxNumSteps(m.cvode, options.max_num_steps), "CVodeSetMaxNumSteps");
  if (options.max_step > 0) m.Check(CVodeSetMaxStep(m.cvode, options.max_step), "CVodeSetMaxStep");
  if (options.stiff) {
    m.matrix = SUNDenseMatrix(state_size, state_size, m.context);
    m.linear_solver = options.dense_solver == DenseSolver::kEigen ? MakeEigenDenseSolver(state_size, m.context)
                                                                  : SUNLinSol_Dense(m.y, m.matrix, m.context);
    m.Check(CVodeSetLinearSolver(m.cvode, m.linear_solver, m.matrix), "CVodeSetLinearSolver");
    if (options.max_steps_between_jacobians > 0)
      m.Check(CVodeSetJacEvalFrequency(m.cvode, options.max_steps_between_jacobians), "CVodeSetJacEvalFrequency");
    if (options.nonlinear_convergence_coefficient > 0.0)
      m.Check(CVodeSetNonlinConvCoef(m.cvode, options.nonlinear_convergence_coefficient), "CVodeSetNonlinConvCoef");
  } else {
    m.nonlinear_solver = SUNNonlinSol_FixedPoint(m.y, 0, m.context);
    m.Check(CVodeSetNonlinearSolver(m.cvode, m.nonlinear_solver), "CVodeSetNonlinearSolver");
  }
  if (m.roots.count > 0) {
    m.Check(CVodeRootInit(m.cvode, m.roots.count, &Impl::Roots), "CVodeRootInit");
    if (!m.roots.directions.empty())
      m.Check(CVodeSetRootDirection(m.cvode, m.roots.directions.data()), "CVodeSetRootDirection");
    m.Check(CVodeSetNoInactiveRootWarn(m.cvode), "CVodeSetNoInactiveRootWarn");
  }
}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::SetJacobian(JacobianFunction jacobian) {
  Impl& m = *impl_;
  if (!m.linear_solver) throw std::logic_error("CvodeIntegrator::SetJacobian: only the stiff (BDF) mode uses a Jacobian");
  m.jacobian = std::move(jacobian);
  m.Check(CVodeSetJacFn(m.cvode, m.jacobian ? &Impl::Jacobian : nullptr), "CVodeSetJacFn");
}

void CvodeIntegrator::Reset(double t0, const Eigen::VectorXd& y0) {
  Impl& m = *impl_;
  if (y0.size() != m.n) throw std::invalid_argument("CvodeIntegrator::Reset: wrong state size");
  if (!y0.allFinite()) throw IntegrationFailure("CvodeIntegrator::Reset: non-finite initial state");
  Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(m.y), m.n) = y0;
  m.last_error.clear();
  m.Check(CVodeReInit(m.cvode, t0, m.y), "CVodeReInit");
  y_ = y0;
  t_ = t0;
  m.initialised = true;
  m.returned_root = false;
}

AdvanceResult CvodeIntegrator::AdvanceTo(double t_out) {
  Impl& m = *impl_;
  if (!m.initialised) throw std::logic_error("CvodeIntegrator::AdvanceTo before Reset");
  realtype t_reached = 0.0;
  m.pending = nullptr;
  const int flag = CVode(m.cvode, t_out, m.y, &t_reached, CV_NORMAL);
  if (m.pending) std::rethrow_exception(std::exchange(m.pending, nullptr));
  return Finish(flag, t_reached);
}

AdvanceResult CvodeIntegrator::Finish(int flag, double t_reached) {
  Impl& m = *impl_;
  // Right after a root, with a valid t_out, CVODE's only bad-input return is its close-root check.
  if (flag == CV_ILL_INPUT && std::exchange(m.returned_root, false))
    throw RootStillZero("CVode: a root function is still exactly zero at the root just returned (" + m.last_error +
                        ")");
  m.Check(flag, "CVode");
  y_ = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(m.y), m.n);
  if (!y_.allFinite()) throw IntegrationFailure("CVode produced a non-finite state");
  t_ = t_reached;
  AdvanceResult result;
  result.t = t_reached;
  m.returned_root = flag == CV_ROOT_RETURN;
  if (flag == CV_ROOT_RETURN) {
    result.status = AdvanceStatus::kFoundRoot;
    result.roots_found.assign(m.roots.count, 0);
    m.Check(CVodeGetRootInfo(m.cvode, result.roots_found.data()), "CVodeGetRootInfo");
  }
  return result;
}

void DenseSegment::Derivative(double t, int k, Eigen::Ref<Eigen::VectorXd> out) const {
  const auto& m = *static_cast<const CvodeIntegrator::Impl*>(impl_);
  if (out.size() != m.n) throw std::invalid_argument("DenseSegment::Derivative: wrong output size");
  const int flag = CVodeGetDky(m.cvode, t, k, m.dky);
  if (flag != CV_SUCCESS) throw std::logic_error("DenseSegment::Derivative: t or k outside the step's polynomial");
  out = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(m.dky), m.n);
}

// CVODE's CV_NORMAL mode with a budget of one internal step per call: each call steps once and
// returns (CV_TOO_MUCH_WORK, the state at the step's end) unless the step reached t_out or a root,
// which it returns as an uninterrupted call would. Its root search and its output at t_out are
// those of the uninterrupted call (CV_ONE_STEP would search roots over whole steps instead of up to
// t_out, and locate them differently in the last bits); a call after a step only repeats the error
// weights' computation from the same history. So the trajectory is the same, bit for bit.
AdvanceResult CvodeIntegrator::AdvanceTo(double t_out, const SegmentObserver& observer) {
  if (!observer) return AdvanceTo(t_out);
  Impl& m = *impl_;
  if (!m.initialised) throw std::logic_error("CvodeIntegrator::AdvanceTo before Reset");
  double seen = t_;  // observed up to here
  auto observe = [&](double until) {
    if (until > seen) observer(DenseSegment(seen, until, &m));
    seen = std::max(seen, until);
  };
  // The rest of the current step, where the last return (an output or a root the run goes on
  // from) lay inside it: the next step's polynomial no longer covers it.
  realtype t_n = 0.0;
  m.Check(CVodeGetCurrentTime(m.cvode, &t_n), "CVodeGetCurrentTime");
  observe(std::min(t_n, t_out));
  struct StepBudget {  // one step per call while here; the caller's budget back on every exit
    Impl& m;
    ~StepBudget() { CVodeSetMaxNumSteps(m.cvode, m.max_num_steps); }
  } budget{m};
  m.Check(CVodeSetMaxNumSteps(m.cvode, 1), "CVodeSetMaxNumSteps");
  const std::string error_before = m.last_error;
  for (long steps = 0;; ++steps) {
    realtype t_reached = 0.0;
    m.pending = nullptr;
    const int flag = CVode(m.cvode, t_out, m.y, &t_reached, CV_NORMAL);
    if (m.pending) std::rethrow_exception(std::exchange(m.pending, nullptr));
    if (flag == CV_TOO_MUCH_WORK) {  // one step taken, short of t_out and of any root
      m.last_error = error_before;
      observe(t_reached);
      if (steps + 1 >= m.max_num_steps) {
        std::ostringstream s;
        s << "CVode failed: CV_TOO_MUCH_WORK (at t = " << t_reached << ", " << m.max_num_steps
          << " steps taken before reaching tout)";
        throw IntegrationFailure(s.str());
      }
      continue;
    }
    AdvanceResult result = Finish(flag, t_reached);
    observe(t_reached);
    return result;
  }
}

IntegratorSummary CvodeIntegrator::summary() const {
  IntegratorSummary s;
  CVodeGetNumSteps(impl_->cvode, &s.steps);
  CVodeGetNumRhsEvals(impl_->cvode, &s.rhs_evaluations);
  CVodeGetNumGEvals(impl_->cvode, &s.root_evaluations);
  CVodeGetNumErrTestFails(impl_->cvode, &s.error_test_failures);
  CVodeGetNumNonlinSolvConvFails(impl_->cvode, &s.nonlinear_convergence_failures);
  if (impl_->linear_solver) {
    CVodeGetNumJacEvals(impl_->cvode, &s.jacobian_evaluations);
    CVodeGetNumLinRhsEvals(impl_->cvode, &s.jacobian_rhs_evaluations);
  }
  CVodeGetLastOrder(impl_->cvode, &s.last_order);
  CVodeGetLastStep(impl_->cvode, &s.last_step_s);
  // The state that limits the step: largest |local error| x error weight of the last step.
  const int n = static_cast<int>(y_.size());
  if (n > 0 && s.steps > 0) {
    Eigen::VectorXd weights(n), errors(n);
    N_Vector w = N_VMake_Serial(n, weights.data(), impl_->context);
    N_Vector e = N_VMake_Serial(n, errors.data(), impl_->context);
    if (CVodeGetErrWeights(impl_->cvode, w) == CV_SUCCESS && CVodeGetEstLocalErrors(impl_->cvode, e) == CV_SUCCESS)
      (errors.cwiseAbs().cwiseProduct(weights)).maxCoeff(&s.limiting_component);
    N_VDestroy(w);
    N_VDestroy(e);
  }
  return s;
}

}  // namespace touchdown::integ
