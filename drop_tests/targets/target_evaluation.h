#pragma once
// The targets' simulated values for a set of parameter values: each distinct scenario runs once
// (drops and landers over the work pool, results stored by index, so threads never change a
// result), and again only when a parameter it depends on has changed (a scenario's result is
// kept per value of its own parameters: a lander is not rerun when only a pad it does not carry
// moves).
#include <array>
#include <map>
#include <vector>

#include "drop_tests/targets/object_edit.h"
#include "drop_tests/targets/targets_file.h"

namespace touchdown::targets {

struct ScenarioOutcome {
  // drops
  double final_penetration_m = 0.0, peak_force_N = 0.0, time_to_rest_s = 0.0;
  // landers
  double final_roll_deg = 0.0, final_pitch_deg = 0.0, max_tilt_deg = 0.0;
  std::array<double, 4> pad_depth_m{};
};

double MeasureValue(const Measure& m, const std::vector<ScenarioOutcome>& outcomes);
double Simulated(const Target& t, const std::vector<ScenarioOutcome>& outcomes);
// (simulated - value) / uncertainty; for bounds 0 inside and (simulated - bound) / uncertainty outside.
double Residual(const Target& t, double simulated);

class TargetEvaluator {
 public:
  TargetEvaluator(const TargetsFile& file, int threads);
  // Every scenario's outcome at `values` (one per parameter, in the file's units); only the
  // scenarios the targets selected by `fit_only` need are run (the others keep a default outcome).
  std::vector<ScenarioOutcome> Run(const std::vector<double>& values, bool fit_only);
  int scenario_runs() const { return scenario_runs_; }

 private:
  ScenarioOutcome RunScenario(size_t index, const std::vector<double>& values) const;
  // "zeta_lp = 3.48, curved_a1 = 0.0319": what an error names.
  std::string ParameterValuesText(const std::vector<double>& values) const;
  std::vector<double> OwnValues(size_t scenario, const std::vector<double>& values) const;

  const TargetsFile& file_;
  int threads_;
  ObjectEditor editor_;
  std::vector<std::vector<size_t>> depends_on_;  // per scenario: the parameters that change it
  std::vector<bool> needed_for_fit_;
  std::vector<std::map<std::vector<double>, ScenarioOutcome>> cache_;
  int scenario_runs_ = 0;
};

}  // namespace touchdown::targets
