#include "drop_tests/targets/targets_fit.h"

#include <cmath>
#include <algorithm>
#include <exception>
#include <limits>
#include <memory>

#include <Eigen/Dense>
#include <boost/math/distributions/normal.hpp>
#include <ceres/ceres.h>
#include <glog/logging.h>

#include "drop_tests/targets/target_evaluation.h"
#include "rft/input_error.h"

namespace touchdown::targets {

namespace {
// The fit runs on u = 1 + (x - lower) / (upper - lower), in [1, 2] for every parameter: the
// trust region and the difference steps (relative_step * u) then mean the same share of every
// parameter's range, whatever its unit (N/cm^3, 1/mm, mm). (Not [0, 1]: a relative step at 0
// would vanish.)
double ToFit(const Parameter& p, double x) { return 1.0 + (x - p.lower) / (p.upper - p.lower); }
double FromFit(const Parameter& p, double u) {
  const double range = p.upper - p.lower;
  if (u >= 2.0) return p.upper;  // exactly the bound at u = 2 (and at u = 1 below)
  return std::clamp(p.lower + (u - 1.0) * range, p.lower, p.upper);  // not past a bound by a rounding
}

// Ceres logs through glog: without InitGoogleLogging, glog prefixes its first message with
// "WARNING: Logging before InitGoogleLogging()", and Ceres logs warnings (a failed evaluation,
// trust_region_minimizer.cc) whatever Solver::Options::logging_type says. touchdown reports the
// fit itself (its termination, the report), so nothing of Ceres' reaches the user: every glog
// message below FATAL is dropped before it is formatted, and nothing goes to log files.
void SilenceCeresLogging() {
  FLAGS_logtostderr = false;
  FLAGS_alsologtostderr = false;
  FLAGS_stderrthreshold = google::GLOG_FATAL;
  FLAGS_minloglevel = google::GLOG_FATAL;
}

double PriorResidual(const ParameterPrior& prior, double x) { return (x - prior.value) / prior.sd; }

// The fitted targets' residuals (and the priors') for Ceres. Ceres is C code at heart for errors: an exception of a
// simulation is kept and rethrown after Solve (Ceres sees a failed evaluation and stops).
class FitResiduals {
 public:
  FitResiduals(const TargetsFile& file, TargetEvaluator& evaluator, const TargetsFitOptions& options,
               std::exception_ptr& failure)
      : file_(file), evaluator_(evaluator), options_(options), failure_(failure) {}

  bool operator()(const double* u, double* residuals) const {
    if (failure_) return false;
    try {
      std::vector<double> values(file_.parameters.size());
      for (size_t i = 0; i < values.size(); ++i) values[i] = FromFit(file_.parameters[i], u[i]);
      if (options_.on_evaluation) options_.on_evaluation(values);
      const std::vector<ScenarioOutcome> outcomes = evaluator_.Run(values, true);
      int k = 0;
      for (const Target& t : file_.targets)
        if (t.fit) residuals[k++] = Residual(t, Simulated(t, outcomes));
      for (size_t i = 0; i < values.size(); ++i)
        if (file_.parameters[i].prior) residuals[k++] = PriorResidual(*file_.parameters[i].prior, values[i]);
      return true;
    } catch (...) {
      failure_ = std::current_exception();
      return false;
    }
  }

 private:
  const TargetsFile& file_;
  TargetEvaluator& evaluator_;
  const TargetsFitOptions& options_;
  std::exception_ptr& failure_;
};

// The residuals and their Jacobian by differences that never leave the box u in [1, 2]: a
// parameter's bounds are the user's statement of where the model is meaningful (a zeta below its
// lower bound may be negative), so no simulation may run outside them. Inside the box by at least
// one step this is Ceres' central difference, operation for operation (step |u| * relative_step,
// at least sqrt(epsilon); (r(u + h) - r(u - h)) * (1 / h / 2)); within a step of a bound it is the
// one-sided difference on the inner side. (ceres::NumericDiffCostFunction steps across bounds: it
// does not know them.)
class BoundedDifferenceCost : public ceres::CostFunction {
 public:
  BoundedDifferenceCost(const FitResiduals& residuals, int parameters, int outputs, double relative_step)
      : residuals_(residuals), relative_step_(relative_step) {
    mutable_parameter_block_sizes()->push_back(parameters);
    set_num_residuals(outputs);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    if (!residuals_(parameters[0], residuals)) return false;
    if (jacobians == nullptr || jacobians[0] == nullptr) return true;
    const int n = parameter_block_sizes()[0], m = num_residuals();
    std::vector<double> u(parameters[0], parameters[0] + n), plus(size_t(m), 0.0), minus(size_t(m), 0.0);
    const double min_step = std::sqrt(std::numeric_limits<double>::epsilon());
    for (int j = 0; j < n; ++j) {
      const double centre = u[size_t(j)];
      const double h = std::max(min_step, std::abs(centre) * relative_step_);
      const bool up = centre + h <= kHigh, down = centre - h >= kLow;
      double one_over_h = 1.0 / h;
      if (up) {
        u[size_t(j)] = centre + h;
        if (!residuals_(u.data(), plus.data())) return false;
      } else {
        plus.assign(residuals, residuals + m);
      }
      if (down) {
        u[size_t(j)] = centre - h;
        if (!residuals_(u.data(), minus.data())) return false;
      } else {
        minus.assign(residuals, residuals + m);
      }
      if (up && down) one_over_h /= 2;
      u[size_t(j)] = centre;
      for (int i = 0; i < m; ++i) jacobians[0][i * n + j] = (plus[size_t(i)] - minus[size_t(i)]) * one_over_h;
    }
    return true;
  }

  static constexpr double kLow = 1.0, kHigh = 2.0;  // the box of ToFit

 private:
  const FitResiduals& residuals_;
  double relative_step_;
};

int FittedTargets(const TargetsFile& file) {
  int n = 0;
  for (const Target& t : file.targets) n += t.fit ? 1 : 0;
  return n;
}

// The residuals the fit minimises: the fitted targets', then one per prior.
int FitResidualCount(const TargetsFile& file) {
  int n = FittedTargets(file);
  for (const Parameter& p : file.parameters) n += p.prior ? 1 : 0;
  return n;
}

ParameterResult::Bound AtBound(const Parameter& p, double v) {
  const double tolerance = 1e-9 * (p.upper - p.lower);
  if (v <= p.lower + tolerance) return ParameterResult::Bound::kLower;
  if (v >= p.upper - tolerance) return ParameterResult::Bound::kUpper;
  return ParameterResult::Bound::kNone;
}

// Whether each parameter moves a fitted residual at the solution (a zero column of the Jacobian:
// every target it changes is inside its bound there).
// The Jacobian of the fitted residuals at the solution (m x n, dense: n is a handful).
Eigen::MatrixXd DenseJacobian(ceres::Problem& problem, size_t n) {
  ceres::CRSMatrix crs;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), nullptr, nullptr, nullptr, &crs);
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(crs.num_rows, Eigen::Index(n));
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[size_t(r)]; k < crs.rows[size_t(r) + 1]; ++k) jacobian(r, crs.cols[size_t(k)]) = crs.values[size_t(k)];
  return jacobian;
}

// The covariance (J_f^T J_f)^-1 of the parameters free at the solution (not at a bound, moving a
// residual), J_f their columns of the normalised residuals' Jacobian: the Gauss-Newton covariance
// ceres::Covariance computes. Formed here with Eigen: ceres::Covariance on the parameter block, with
// a SubsetManifold set on it after the solve to hold the other parameters, aborted with a corrupted
// heap in a joint lander fit (Ceres 2.1, Debian 12).
void AddIntervals(ceres::Problem& problem, std::vector<double>& x, const TargetsFile& file, TargetsFitResult& result) {
  std::vector<ParameterResult>& out = result.parameters;
  const size_t n = x.size();
  const Eigen::MatrixXd jacobian = DenseJacobian(problem, n);
  std::vector<Eigen::Index> free;
  for (size_t i = 0; i < n; ++i) {
    if (out[i].at_bound != ParameterResult::Bound::kNone)
      out[i].interval_note = "at a bound: no symmetric interval";
    else if (jacobian.col(Eigen::Index(i)).isZero(0.0))
      out[i].interval_note = "not determined: every fitted target it changes is inside its bound";
    else
      free.push_back(Eigen::Index(i));
  }
  if (free.empty()) return;
  Eigen::MatrixXd jf(jacobian.rows(), Eigen::Index(free.size()));
  for (size_t k = 0; k < free.size(); ++k) jf.col(Eigen::Index(k)) = jacobian.col(free[k]);
  const Eigen::MatrixXd normal = jf.transpose() * jf;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(normal, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sv = svd.singularValues();
  if (!(sv(sv.size() - 1) > 1e-12 * sv(0))) {
    for (ParameterResult& p : out)
      if (p.interval_note.empty()) p.interval_note = "not determined: the fitted targets do not fix these parameters jointly";
    return;
  }
  const Eigen::MatrixXd c = svd.matrixV() * sv.cwiseInverse().asDiagonal() * svd.matrixU().transpose();
  const double z = boost::math::quantile(boost::math::normal(), 0.5 + 0.5 * file.settings.confidence);
  for (size_t k = 0; k < free.size(); ++k) {
    const size_t i = size_t(free[k]);
    out[i].sigma = std::sqrt(c(Eigen::Index(k), Eigen::Index(k))) * (file.parameters[i].upper - file.parameters[i].lower);
    out[i].low = out[i].value - z * *out[i].sigma;
    out[i].high = out[i].value + z * *out[i].sigma;
  }
  // The same matrix in file units: the fit's coordinates are each parameter's range scaled to [0, 1].
  const auto range = [&](size_t k) { return file.parameters[size_t(free[k])].upper - file.parameters[size_t(free[k])].lower; };
  result.covariance.assign(free.size(), std::vector<double>(free.size(), 0.0));
  for (size_t a = 0; a < free.size(); ++a) {
    result.covariance_parameters.push_back(size_t(free[a]));
    for (size_t b = 0; b < free.size(); ++b)
      result.covariance[a][b] = c(Eigen::Index(a), Eigen::Index(b)) * range(a) * range(b);
  }
}

// Stops the solve once every fitted target is reproduced to a millionth of its uncertainty. Ceres'
// own criteria are relative (to the cost, the parameters and the gradient), and an exactly
// solvable file drives the cost to the simulations' rounding level (about 1e-18), where each
// step's relative change in cost is of order one: without this it runs to its iteration cap.
class ExactFitStop : public ceres::IterationCallback {
 public:
  static constexpr double kResidual = 1e-6;
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    return s.cost <= 0.5 * kResidual * kResidual ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
};

void Solve(const TargetsFile& file, TargetEvaluator& evaluator, const TargetsFitOptions& fit_options,
           std::vector<double>& x, TargetsFitResult& result) {
  SilenceCeresLogging();
  std::exception_ptr failure;
  const FitResiduals residuals(file, evaluator, fit_options, failure);
  auto* cost = new BoundedDifferenceCost(residuals, int(x.size()), FitResidualCount(file), file.settings.relative_step);
  ceres::Problem problem;  // owns `cost`
  problem.AddResidualBlock(cost, nullptr, x.data());
  for (size_t i = 0; i < x.size(); ++i) {
    problem.SetParameterLowerBound(x.data(), int(i), BoundedDifferenceCost::kLow);
    problem.SetParameterUpperBound(x.data(), int(i), BoundedDifferenceCost::kHigh);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  // A trust region in u: the first step moves at most a tenth of each range (Ceres' default, 1e4,
  // lets the first step jump to a corner of the box, where the projected steps then stall).
  options.trust_region_strategy_type = ceres::DOGLEG;
  options.jacobi_scaling = false;
  options.initial_trust_region_radius = 0.1;
  options.max_num_iterations = file.settings.max_iterations;
  options.num_threads = 1;
  options.logging_type = ceres::SILENT;
  options.function_tolerance = 1e-12;
  options.parameter_tolerance = 1e-10;
  options.gradient_tolerance = 1e-14;
  ExactFitStop exact_fit_stop;
  options.callbacks.push_back(&exact_fit_stop);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (failure) std::rethrow_exception(failure);
  // A cost Ceres could not evaluate (not finite) is a failed fit, not a result: no model is written.
  if (summary.termination_type == ceres::FAILURE || !std::isfinite(summary.final_cost))
    throw SolverFailure("calibrate --targets: the fit failed after " + std::to_string(summary.iterations.size()) +
                        " evaluations of the targets: " + summary.message);
  result.iterations = int(summary.iterations.size()) - 1;
  result.converged = summary.termination_type == ceres::CONVERGENCE || summary.termination_type == ceres::USER_SUCCESS;
  result.termination = summary.termination_type == ceres::USER_SUCCESS
                           ? "exact: every fitted target reproduced to 1e-6 of its uncertainty"
                           : summary.message;
  for (size_t i = 0; i < x.size(); ++i) {
    result.parameters[i].value = FromFit(file.parameters[i], x[i]);
    result.parameters[i].at_bound = AtBound(file.parameters[i], result.parameters[i].value);
  }
  AddIntervals(problem, x, file, result);
  if (failure) std::rethrow_exception(failure);
  for (size_t i = 0; i < x.size(); ++i) x[i] = result.parameters[i].value;
}
}  // namespace

TargetsFitResult FitTargets(const TargetsFile& file, const TargetsFitOptions& options) {
  TargetEvaluator evaluator(file, options.threads);
  TargetsFitResult result;
  std::vector<double> x;
  for (const Parameter& p : file.parameters) {
    x.push_back(ToFit(p, p.start));
    result.parameters.push_back({p.start, AtBound(p, p.start), {}, {}, {}, "", {}});
  }
  if (x.empty() || FittedTargets(file) == 0) {
    result.termination = "no fit: " + std::string(x.empty() ? "no free parameters" : "no target has use: fit");
    for (ParameterResult& p : result.parameters) p.interval_note = "not fitted";
    for (size_t i = 0; i < x.size(); ++i) x[i] = file.parameters[i].start;
  } else {
    Solve(file, evaluator, options, x, result);
  }
  const std::vector<ScenarioOutcome> outcomes = evaluator.Run(x, false);
  for (const Target& t : file.targets) {
    const double simulated = Simulated(t, outcomes);
    const double r = Residual(t, simulated);
    result.targets.push_back({simulated, r});
    if (t.fit) result.cost += 0.5 * r * r;
  }
  for (size_t i = 0; i < x.size(); ++i)
    if (const std::optional<ParameterPrior>& prior = file.parameters[i].prior) {
      result.parameters[i].prior_residual = PriorResidual(*prior, x[i]);
      result.cost += 0.5 * *result.parameters[i].prior_residual * *result.parameters[i].prior_residual;
    }
  result.scenario_runs = evaluator.scenario_runs();
  return result;
}

}  // namespace touchdown::targets
