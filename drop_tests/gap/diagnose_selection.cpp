#include "drop_tests/gap/diagnose_selection.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "drop_tests/gap/fixed_text.h"

namespace touchdown::gap {

namespace {

std::string Short(double v) {
  std::ostringstream s;
  s << std::setprecision(3) << v;
  return s.str();
}

// Gap reduction and explained fraction against the base; Delta BIC against the base and against
// the model the candidate extends.
void Relate(CandidateScore& c, const CandidateScore& base, const CandidateScore& current) {
  if (!c.applies) return;
  c.gap_reduction = base.held_out.force_nrmse > 0 ? 1.0 - c.held_out.force_nrmse / base.held_out.force_nrmse : 0.0;
  const double noise = base.held_out.noise_mean_square;
  const double excess = base.held_out.mean_square - noise;
  c.explained = excess > 0 ? (base.held_out.mean_square - c.held_out.mean_square) / excess : 0.0;
  const double step_excess = current.held_out.mean_square - noise;
  c.step_explained = step_excess > 0 ? (current.held_out.mean_square - c.held_out.mean_square) / step_excess : 0.0;
  c.delta_bic = base.fit.bic - c.fit.bic;
  c.delta_bic_step = current.fit.bic - c.fit.bic;
  c.step_gap_reduction =
      current.held_out.force_nrmse > 0 ? 1.0 - c.held_out.force_nrmse / current.held_out.force_nrmse : 0.0;
}

// The first of a candidate's term parameters the training drops do not identify: its 95 % interval
// covers at least 95 % of the range the fit may take (a fit on few drops can reach a bound with an
// interval over everything, e.g. a sensor offset of -50 mm fitted on one drop). Null if none.
const ParameterEstimate* Unidentified(const CandidateScore& c) {
  for (const ParameterEstimate& e : c.fit.estimates)
    if (!e.effect.empty() && std::isfinite(e.bound_high - e.bound_low) && e.bound_high > e.bound_low &&
        e.high - e.low >= 0.95 * (e.bound_high - e.bound_low))
      return &e;
  return nullptr;
}

// The term a candidate adds to the model it extends (its last).
const std::string& Added(const CandidateScore& c) { return c.effect_ids.back(); }

struct StepOutcome {
  int chosen = -1;  // index into d.candidates
  std::string why;
};

// One step's decision among the candidates `tried` (indices into d.candidates) extending `current`.
StepOutcome DecideStep(const Diagnosis& d, const CandidateScore& current, const std::vector<int>& tried,
                       const DiagnoseOptions& o) {
  StepOutcome out;
  std::vector<int> valid;
  for (int i : tried)
    if (d.candidates[i].applies) valid.push_back(i);
  const std::string from = current.effect_ids.empty() ? "the base model" : current.name;
  if (valid.empty()) {
    out.why = "no further candidate term applies to " + from;
    return out;
  }
  int best = valid.front();
  for (int i : valid)
    if (d.candidates[i].fit.bic < d.candidates[best].fit.bic) best = i;
  const double bic_min = d.candidates[best].fit.bic;
  // Parsimony among the candidates the data cannot tell from the best.
  int k_min = 1 << 30;
  for (int i : valid)
    if (d.candidates[i].fit.bic - bic_min < o.min_delta_bic) k_min = std::min(k_min, d.candidates[i].fit.parameters);
  std::vector<int> simplest;
  for (int i : valid)
    if (d.candidates[i].fit.bic - bic_min < o.min_delta_bic && d.candidates[i].fit.parameters == k_min)
      simplest.push_back(i);
  std::sort(simplest.begin(), simplest.end(),
            [&](int a, int b) { return d.candidates[a].fit.bic < d.candidates[b].fit.bic; });
  const CandidateScore& w = d.candidates[simplest.front()];
  std::ostringstream why;
  const bool gap_small = current.held_out.mean_square <= 1.5 * d.base.held_out.noise_mean_square;
  if (w.delta_bic_step < o.min_delta_bic) {
    why << "no candidate beats " << from << " (best " << Added(w) << ": Delta BIC " << Fixed(w.delta_bic_step, 1)
        << " < " << o.min_delta_bic << ")";
    if (gap_small) why << "; " << from << " already fits to the sensor-noise floor";
  } else if (simplest.size() > 1) {
    why << "ambiguous on top of " << from << ": " << Added(w) << " and " << Added(d.candidates[simplest[1]])
        << " explain the data equally well (Delta BIC " << Fixed(d.candidates[simplest[1]].fit.bic - w.fit.bic, 1)
        << " < " << o.min_delta_bic << ", same number of parameters)";
  } else if (w.held_out.force_nrmse >= current.held_out.force_nrmse) {
    why << "the best candidate on top of " << from << ", " << Added(w) << " (Delta BIC " << Fixed(w.delta_bic_step, 1)
        << "), does not cut the held-out force NRMSE (" << Fixed(current.held_out.force_nrmse, 4) << " -> "
        << Fixed(w.held_out.force_nrmse, 4) << ")";
  } else if (w.step_explained < o.min_step_explained) {
    why << "the best candidate on top of " << from << ", " << Added(w) << " (Delta BIC " << Fixed(w.delta_bic_step, 1)
        << "), explains only " << Fixed(100 * w.step_explained, 0) << " % of the held-out excess over the noise floor "
        << "that " << from << " leaves (needs >= " << Fixed(100 * o.min_step_explained, 0)
        << " %): a term that explains a small part of what remains fits a misfit the library does not hold";
  } else if (const ParameterEstimate* u = Unidentified(w)) {
    why << "the best candidate on top of " << from << ", " << Added(w) << " (Delta BIC " << Fixed(w.delta_bic_step, 1)
        << "), is not identified by the training drops: " << u->effect << "." << u->key << " = "
        << Short(u->value / u->file_to_si) << " with a 95 % interval [" << Short(u->low / u->file_to_si) << ", "
        << Short(u->high / u->file_to_si) << "] over its whole range";
  } else {
    out.chosen = simplest.front();
    // The runner-up: the best other candidate that is a real rival, i.e. not a richer model the
    // data cannot tell from the chosen one (those lose on parsimony, e.g. compaction_peak with a
    // long decay against inertial_drag).
    int runner = -1;
    for (int i : valid) {
      if (i == out.chosen) continue;
      const bool richer_twin =
          d.candidates[i].fit.parameters > w.fit.parameters && d.candidates[i].fit.bic - bic_min < o.min_delta_bic;
      if (!richer_twin && (runner < 0 || d.candidates[i].fit.bic < d.candidates[runner].fit.bic)) runner = i;
    }
    why << Added(w) << " beats " << from << " (Delta BIC " << Fixed(w.delta_bic_step, 1) << ", held-out force NRMSE "
        << Fixed(current.held_out.force_nrmse, 4) << " -> " << Fixed(w.held_out.force_nrmse, 4) << ")";
    if (runner >= 0)
      why << " and the runner-up " << Added(d.candidates[runner]) << " (Delta BIC "
          << Fixed(d.candidates[runner].fit.bic - w.fit.bic, 1) << " worse, held-out NRMSE "
          << Fixed(d.candidates[runner].held_out.force_nrmse, 4) << ")";
  }
  out.why = why.str();
  return out;
}

// Whether the selected model explains most of the base's gap; if not, why.
bool ExplainsTheGap(const CandidateScore& m, const DiagnoseOptions& o, std::string* why) {
  if (m.gap_reduction >= o.min_gap_reduction && m.explained >= o.min_explained) return true;
  *why = "the selected model, " + m.name + ", leaves most of the gap: held-out force NRMSE reduced by " +
         Fixed(100 * m.gap_reduction, 0) + " % and " + Fixed(100 * m.explained, 0) +
         " % of the excess over the noise floor explained (needs >= " + Fixed(100 * o.min_gap_reduction, 0) +
         " % and >= " + Fixed(100 * o.min_explained, 0) + " %)";
  return false;
}

}  // namespace

std::string DynamicTermStatement(const FitProblem& p, const CandidateScore& m) {
  for (const ParameterEstimate& e : m.fit.estimates) {
    if (e.effect != kWeakerDynamicTerm) continue;
    const double shipped = p.shipped_lambda;
    const std::string fitted = "lambda fitted " + Short(e.value) + " [" + Short(e.low) + ", " + Short(e.high) +
                               "] against the shipped " + Short(shipped);
    // "Near zero": within a twentieth of the shipped value, or an interval that reaches zero.
    if (e.high < shipped || e.value <= 0.05 * shipped || e.low <= 0.0)
      return "The data do not support the shipped default's dynamic term (" + fitted + ").";
    return "The data hold a weaker dynamic term than the shipped default's, not significantly weaker (" + fitted +
           ").";
  }
  return "";
}

void SelectForward(Diagnosis& d, const DiagnoseOptions& o, const ScoreModel& score, io::Progress& progress) {
  std::vector<std::string> steps;
  int current = -1;  // index into d.candidates, -1: the base
  for (int step = 1;; ++step) {
    const CandidateScore& cur = current < 0 ? d.base : d.candidates[current];
    const std::vector<std::string> cur_ids = cur.effect_ids;
    const FitResult start = cur.fit;
    std::vector<std::vector<std::string>> models;
    for (const CandidateTerm& t : d.problem.terms)
      if (std::find(cur_ids.begin(), cur_ids.end(), t.name) == cur_ids.end()) {
        models.push_back(cur_ids);
        models.back().push_back(t.name);
      }
    progress.SetTotal(1 + static_cast<int64_t>(d.candidates.size() + models.size()));
    std::vector<int> tried;
    for (const std::vector<std::string>& ids : models) {
      CandidateScore c = score(ids, start);
      // Terms that do not apply are listed once, at the first step.
      if (!c.applies && step > 1) {
        progress.Add(1);
        continue;
      }
      c.step = step;
      c.extends = current;
      Relate(c, d.base, current < 0 ? d.base : d.candidates[current]);
      d.candidates.push_back(std::move(c));
      tried.push_back(static_cast<int>(d.candidates.size()) - 1);
      progress.Add(1, ", last: " + d.candidates.back().name);
    }
    const StepOutcome outcome = DecideStep(d, current < 0 ? d.base : d.candidates[current], tried, o);
    steps.push_back("step " + std::to_string(step) + ": " + outcome.why);
    if (outcome.chosen < 0) break;
    current = outcome.chosen;
    d.selection.push_back(current);
    if (!o.try_pairs) {
      steps.push_back("one term at most (--no-pairs)");
      break;
    }
  }
  std::string verdict;
  if (current >= 0 && ExplainsTheGap(d.candidates[current], o, &verdict)) {
    d.winner = current;
    const CandidateScore& w = d.candidates[current];
    for (const std::string& id : w.effect_ids)
      if (id != kWeakerDynamicTerm) d.named_effects.push_back(id);
    verdict = w.name + " explains the gap: held-out force NRMSE " + Fixed(d.base.held_out.force_nrmse, 4) + " -> " +
              Fixed(w.held_out.force_nrmse, 4) + ", " + Fixed(100 * w.explained, 0) +
              " % of the excess over the noise floor explained";
  }
  // The statement on the soils' own term stands on the steps that selected it (each beat the model
  // before it and explained most of what it left), even when the whole model is not named.
  if (current >= 0) d.dynamic_term_statement = DynamicTermStatement(d.problem, d.candidates[current]);
  for (size_t i = 0; i < d.named_effects.size(); ++i)
    d.named_effect = (i ? d.named_effect + "+" : "") + d.named_effects[i];
  std::string steps_text;
  for (size_t i = 0; i < steps.size(); ++i) steps_text += (i ? "; " : "") + steps[i];
  d.decision = verdict.empty() ? steps_text : verdict + " (" + steps_text + ")";
}

}  // namespace touchdown::gap
