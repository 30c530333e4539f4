#include "drop_tests/targets/target_evaluation.h"

#include <sstream>

#include <algorithm>
#include <cmath>

#include "drop_tests/drop/drop_setup.h"
#include "drop_tests/util/work_pool.h"
#include "drop_tests/scenario/lander_setup.h"
#include "rft/units.h"

namespace touchdown::targets {

namespace {
using units::kDeg;

ScenarioOutcome DropOutcome(const drop::PadDrop& d) {
  ScenarioOutcome o;
  o.final_penetration_m = d.result.final_penetration_m;
  o.peak_force_N = d.result.peak_force_N;
  o.time_to_rest_s = d.result.time_to_rest_s;
  return o;
}

ScenarioOutcome LanderOutcome(const scenario::LanderRun& run) {
  ScenarioOutcome o;
  o.final_roll_deg = run.result.final_attitude.roll_rad / kDeg;
  o.final_pitch_deg = run.result.final_attitude.pitch_rad / kDeg;
  o.max_tilt_deg = run.result.max_tilt_rad / kDeg;
  for (int i = 0; i < lander::kNumLegs; ++i) o.pad_depth_m[i] = run.result.final_penetration_m[i];
  return o;
}
}  // namespace

double MeasureValue(const Measure& m, const std::vector<ScenarioOutcome>& outcomes) {
  const ScenarioOutcome& o = outcomes[m.scenario];
  switch (m.quantity) {
    case Quantity::kFinalPenetration: return o.final_penetration_m;
    case Quantity::kPeakForce: return o.peak_force_N;
    case Quantity::kTimeToRest: return o.time_to_rest_s;
    case Quantity::kFinalRoll: return o.final_roll_deg;
    case Quantity::kFinalPitch: return o.final_pitch_deg;
    case Quantity::kMaxTilt: return o.max_tilt_deg;
    case Quantity::kPadDepth: return o.pad_depth_m[m.pad - 1];
    case Quantity::kPadDepthSpread: {
      const auto [lo, hi] = std::minmax_element(o.pad_depth_m.begin(), o.pad_depth_m.end());
      return *hi / *lo;
    }
  }
  return 0.0;
}

double Simulated(const Target& t, const std::vector<ScenarioOutcome>& outcomes) {
  const double v = MeasureValue(t.measure, outcomes);
  return t.denominator ? v / MeasureValue(*t.denominator, outcomes) : v;
}

double Residual(const Target& t, double simulated) {
  if (t.value) return (simulated - *t.value) / t.uncertainty;
  if (t.at_most && simulated > *t.at_most) return (simulated - *t.at_most) / t.uncertainty;
  if (t.at_least && simulated < *t.at_least) return (simulated - *t.at_least) / t.uncertainty;
  return 0.0;
}

TargetEvaluator::TargetEvaluator(const TargetsFile& file, int threads)
    : file_(file), threads_(threads), editor_(file.parameters), depends_on_(file.scenarios.size()),
      needed_for_fit_(file.scenarios.size(), false), cache_(file.scenarios.size()) {
  for (size_t s = 0; s < file.scenarios.size(); ++s)
    for (size_t p = 0; p < file.parameters.size(); ++p)
      if (Changes(file.parameters[p], file.scenarios[s])) depends_on_[s].push_back(p);
  for (const Target& t : file.targets)
    if (t.fit) {
      needed_for_fit_[t.measure.scenario] = true;
      if (t.denominator) needed_for_fit_[t.denominator->scenario] = true;
    }
}

std::string TargetEvaluator::ParameterValuesText(const std::vector<double>& values) const {
  std::ostringstream out;
  out.precision(17);  // enough to rerun the failing case exactly
  for (size_t p = 0; p < values.size(); ++p) out << (p ? ", " : "") << file_.parameters[p].name << " = " << values[p];
  return out.str();
}

std::vector<double> TargetEvaluator::OwnValues(size_t scenario, const std::vector<double>& values) const {
  std::vector<double> own;
  for (size_t p : depends_on_[scenario]) own.push_back(values[p]);
  return own;
}

ScenarioOutcome TargetEvaluator::RunScenario(size_t index, const std::vector<double>& values) const {
  const ScenarioRun& run = file_.scenarios[index];
  if (run.kind == ScenarioRun::Kind::kLander) {
    scenario::LanderScenario s = *run.lander;
    s.lander = editor_.EditedLander(s.lander, values, s.pad_angular_segments, s.pad_rim);
    s.model = SoilModel(file_.parameters, values);
    return LanderOutcome(scenario::RunLanderScenario(s));
  }
  // The drop's soil under the same model as a lander's (its lambda and Bekker fields); zeta goes in as the drop's
  // own override, stated at the soil's reference gravity like a catalogue zeta.
  const rft::SoilParameters soil = model::ApplyModel(SoilModel(file_.parameters, values), run.soil);
  drop::DropConditions conditions = run.conditions;
  for (size_t p : depends_on_[index])
    if (file_.parameters[p].kind == ParameterKind::kSoilZeta) conditions.zeta_N_m3 = units::ZetaFromN_cm3(values[p]);
  const std::optional<io::PadSpec> pad = editor_.EditedPad(run.pad->source, values);
  return DropOutcome(drop::RunDrop(drop::ResolveDrop(pad ? *pad : *run.pad, soil, conditions)));
}

std::vector<ScenarioOutcome> TargetEvaluator::Run(const std::vector<double>& values, bool fit_only) {
  const size_t n = file_.scenarios.size();
  std::vector<ScenarioOutcome> outcomes(n);
  std::vector<size_t> to_run;
  for (size_t s = 0; s < n; ++s) {
    if (fit_only && !needed_for_fit_[s]) continue;
    const auto it = cache_[s].find(OwnValues(s, values));
    if (it != cache_[s].end())
      outcomes[s] = it->second;
    else
      to_run.push_back(s);
  }
  io::ParallelFor(to_run.size(), threads_, [&](size_t k) {
    try {
      outcomes[to_run[k]] = RunScenario(to_run[k], values);
    } catch (const integ::IntegrationFailure& e) {  // name the run and the parameters it failed at
      throw integ::IntegrationFailure(file_.scenarios[to_run[k]].label + " at " + ParameterValuesText(values) +
                                      ": " + e.what());
    }
  });
  for (size_t s : to_run) cache_[s].emplace(OwnValues(s, values), outcomes[s]);
  scenario_runs_ += int(to_run.size());
  return outcomes;
}

}  // namespace touchdown::targets
