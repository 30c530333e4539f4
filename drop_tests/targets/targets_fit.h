#pragma once
// The fit of a targets file: bounded least squares (Ceres: Levenberg-Marquardt, central-difference
// derivatives, the parameters' bounds) of the residuals (simulated - value) / uncertainty of the
// targets marked `use: fit` (a bound target is 0 inside its bound) and (x - value) / sd of each
// parameter's prior, then every target, fitted or predicted, evaluated at the result. Intervals:
// the covariance of the normalised residuals, (J^T J)^-1 at the solution (the targets'
// uncertainties taken as one standard deviation, not rescaled by the residuals; with priors, the
// posterior's Laplace approximation), over the parameters not at a bound; a parameter at a bound
// gets none.
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "drop_tests/model/model_file.h"
#include "drop_tests/targets/targets_file.h"
#include "rft/enum_names.h"

namespace touchdown::targets {

struct ParameterResult {
  double value = 0.0;
  enum class Bound { kNone, kLower, kUpper } at_bound = Bound::kNone;
  std::optional<double> sigma;                // one standard deviation (file units)
  std::optional<double> low, high;            // value -+ z sigma at the file's confidence
  std::string interval_note;                  // why there is none, when there is none
  std::optional<double> prior_residual;       // (value - prior) / prior sd, when it has a prior
};
// The bound names a report gives (at_bound).
inline constexpr std::array<EnumName<ParameterResult::Bound>, 3> kBoundNames{{{ParameterResult::Bound::kNone, "none"},
                                                                          {ParameterResult::Bound::kLower, "lower"},
                                                                          {ParameterResult::Bound::kUpper, "upper"}}};


struct TargetResult {
  double simulated = 0.0;
  double residual = 0.0;
};

struct TargetsFitResult {
  std::vector<ParameterResult> parameters;
  std::vector<TargetResult> targets;
  double cost = 0.0;            // 0.5 * sum of the squared residuals: fitted targets' and priors'
  int iterations = 0;
  int scenario_runs = 0;        // simulations run (drops and landers; repeats are not rerun)
  std::string termination;      // Ceres' message ("no fit" when nothing is fitted)
  bool converged = false;
  // The joint covariance of the parameters that got an interval (file units, one standard
  // deviation squared on the diagonal): `covariance[a][b]` between parameters
  // covariance_parameters[a] and [b] (indices into `parameters`). What a study draws the
  // parameters from (drop_tests/stability/soil_uncertainty.h).
  std::vector<size_t> covariance_parameters;
  std::vector<std::vector<double>> covariance;
};

struct TargetsFitOptions {
  int threads = 1;  // scenarios of one evaluation run side by side; results do not depend on it
  // Called with the parameters (file units) of every evaluation the fit makes, derivatives'
  // included: every one lies within the parameters' [lower, upper].
  std::function<void(const std::vector<double>&)> on_evaluation = {};
};

// Throws integ::IntegrationFailure when a simulation fails.
TargetsFitResult FitTargets(const TargetsFile& file, const TargetsFitOptions& options = {});

// The report (docs/calibration_targets.md): per parameter its value, bounds, bound flag and
// interval; per target its value or bounds, simulated value, residual, fitted or predicted.
nlohmann::json TargetsReportJson(const TargetsFile& file, const TargetsFitResult& fit);
// A short fixed-width table of the same.
std::string TargetsReportTable(const TargetsFile& file, const TargetsFitResult& fit);
// The fitted zeta per soil as a model file (`--model`), with the fit's provenance and the other
// parameters' values and how to apply them. The targets file is named as seen from `output_dir`,
// the directory the model file lives in (drop_tests/catalog/paths_in_outputs.h).
model::ModelFile TargetsModel(const TargetsFile& file, const TargetsFitResult& fit, const std::string& name,
                              const std::string& output_dir);

}  // namespace touchdown::targets
