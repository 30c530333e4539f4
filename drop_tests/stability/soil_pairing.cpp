#include "drop_tests/stability/soil_pairing.h"

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "drop_tests/stability/study_followups.h"
#include "drop_tests/stability/study_summary.h"

namespace touchdown::stability {

namespace {
using sweep::DropRecord;

// The unbiased sample variance (n - 1 in the denominator); 0 below two values.
double SampleVariance(const std::vector<double>& x) {
  if (x.size() < 2) return 0.0;
  const Eigen::Map<const Eigen::ArrayXd> v(x.data(), Eigen::Index(x.size()));
  return (v - v.mean()).square().sum() / double(x.size() - 1);
}

PairedOutcome Compare(const std::string& outcome, const std::string& unit, const std::vector<double>& drawn,
                      const std::vector<double>& best) {
  PairedOutcome o;
  o.outcome = outcome;
  o.unit = unit;
  o.landings = int64_t(drawn.size());
  std::vector<double> difference, magnitude;
  for (size_t i = 0; i < drawn.size(); ++i) {
    difference.push_back(drawn[i] - best[i]);
    magnitude.push_back(std::abs(drawn[i] - best[i]));
  }
  o.variance = SampleVariance(drawn);
  o.difference_variance = SampleVariance(difference);
  o.share = o.variance > 0.0 ? o.difference_variance / o.variance : 0.0;
  if (!magnitude.empty()) {
    o.abs_difference_p50 = Percentile(magnitude, 50.0);
    o.abs_difference_p95 = Percentile(magnitude, 95.0);
    o.abs_difference_max = Percentile(magnitude, 100.0);
  }
  return o;
}
}  // namespace

sweep::SweepPlan SoilAtBestValuesPlan(const Study& study) {
  sweep::SweepPlan plan = study.plan;
  const SoilUncertainty& u = *study.soil_uncertainty;
  std::vector<double> best;
  for (const UncertainParameter& q : u.parameters) best.push_back(q.mean);
  const std::map<std::string, model::SoilOverride> overrides = SoilOverrides(u, best);
  std::vector<std::pair<std::string, double>> named;
  for (size_t k = 0; k < best.size(); ++k) named.emplace_back(u.parameters[k].column, best[k]);
  plan.soil_overrides_at = [overrides](int64_t) { return overrides; };
  plan.soil_parameters_at = [named](int64_t) { return named; };
  // Appended to the draws' text, which names the calibrations the best values come from.
  plan.variant += ";soil at the calibrations' best values";
  return plan;
}

std::string SoilPairingDir(const std::string& out_dir) {
  return (std::filesystem::path(out_dir) / "soil_at_best_values").string();
}

std::vector<int64_t> SoilPairingIndices(const Study& study) {
  const int64_t n = study.plan.size();
  return SpreadIndices(n, std::min(study.soil_pairing.samples.value_or(n), n));
}

SoilPairingReport PairBySoil(const std::vector<int64_t>& indices, const std::vector<DropRecord>& study_records,
                             const std::vector<DropRecord>& at_best_values) {
  std::map<int64_t, const DropRecord*> drawn, best;
  for (const DropRecord& r : study_records) drawn[r.index] = &r;
  for (const DropRecord& r : at_best_values) best[r.index] = &r;
  SoilPairingReport p;
  p.ran = true;
  p.samples = int64_t(indices.size());
  std::vector<double> tip_drawn, tip_best;
  std::vector<std::vector<double>> metric_drawn(StudyMetrics().size()), metric_best(StudyMetrics().size());
  for (int64_t i : indices) {
    const auto d = drawn.find(i);
    const auto b = best.find(i);
    if (d == drawn.end() || b == best.end() || !d->second->ok || !b->second->ok) {
      ++p.failed;
      continue;
    }
    const DropRecord &x = *d->second, &y = *b->second;
    ++p.landings;
    p.tipped_drawn += Tipped(x);
    p.tipped_best += Tipped(y);
    if (Tipped(x) && !Tipped(y)) p.tipped_only_drawn.push_back(x.drop_id);
    if (!Tipped(x) && Tipped(y)) p.tipped_only_best.push_back(x.drop_id);
    tip_drawn.push_back(Tipped(x) ? 1.0 : 0.0);
    tip_best.push_back(Tipped(y) ? 1.0 : 0.0);
    if (!StayedUp(x) || !StayedUp(y)) continue;
    for (size_t m = 0; m < StudyMetrics().size(); ++m) {
      const double vx = StudyMetrics()[m].value(x), vy = StudyMetrics()[m].value(y);
      if (!std::isfinite(vx) || !std::isfinite(vy)) continue;
      metric_drawn[m].push_back(vx);
      metric_best[m].push_back(vy);
    }
  }
  p.interval_drawn = ClopperPearson(p.tipped_drawn, p.landings);
  p.interval_best = ClopperPearson(p.tipped_best, p.landings);
  p.outcomes.push_back(Compare("tipped_over", "-", tip_drawn, tip_best));
  for (size_t m = 0; m < StudyMetrics().size(); ++m)
    if (!metric_drawn[m].empty())
      p.outcomes.push_back(Compare(StudyMetrics()[m].name, StudyMetrics()[m].unit, metric_drawn[m], metric_best[m]));
  return p;
}

nlohmann::json SoilPairingJson(const SoilPairingReport& p) {
  nlohmann::json out = {{"ran", p.ran}};
  if (!p.ran) {
    out["reason"] = p.reason;
    return out;
  }
  const auto probability = [&](int64_t tipped, const BinomialInterval& ci) {
    nlohmann::json j = {{"tipped_over", tipped}};
    if (p.landings > 0) {
      j["tip_over_probability"] = double(tipped) / double(p.landings);
      j["tip_over_probability_interval_95"] = {ci.low, ci.high};
    }
    return j;
  };
  nlohmann::json outcomes = nlohmann::json::array();
  for (const PairedOutcome& o : p.outcomes)
    outcomes.push_back({{"outcome", o.outcome},
                        {"unit", o.unit},
                        {"landings", o.landings},
                        {"variance", o.variance},
                        {"difference_variance", o.difference_variance},
                        {"soil_share", o.share},
                        {"abs_difference", {{"p50", o.abs_difference_p50}, {"p95", o.abs_difference_p95}, {"max", o.abs_difference_max}}}});
  out.update({{"meaning",
               "the same landings (same index: same touchdown conditions) run again with every drawn soil at its "
               "calibration's best values, re-checked like the study's; a landing's two outcomes differ by the "
               "soil alone. soil_share = var(drawn - best) / var(drawn): the part of the outcome's spread the "
               "soil's uncertainty makes, its interactions with the conditions included (tipped_over over the "
               "landings completed in both, a metric over those that stayed up in both). The measure to trust "
               "for tip-overs (docs/stability_studies.md, \"The soil's uncertainty\")"},
              {"directory", "soil_at_best_values/"},
              {"samples", p.samples},
              {"landings", p.landings},
              {"landings_failed", p.failed},
              {"drawn", probability(p.tipped_drawn, p.interval_drawn)},
              {"best_values", probability(p.tipped_best, p.interval_best)},
              {"outcome_changed", int64_t(p.tipped_only_drawn.size() + p.tipped_only_best.size())},
              {"tipped_only_with_drawn_soil", p.tipped_only_drawn},
              {"tipped_only_at_best_values", p.tipped_only_best},
              {"best_values_rechecked", p.rechecked},
              {"best_values_recheck_changed", p.recheck_changed},
              {"outcomes", outcomes}});
  return out;
}

}  // namespace touchdown::stability
