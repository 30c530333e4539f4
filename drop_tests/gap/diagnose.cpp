#include "drop_tests/gap/diagnose.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <iomanip>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <set>
#include <sstream>

#include "drop_tests/dataset/sensor_sampling.h"
#include "drop_tests/gap/diagnose_selection.h"
#include "drop_tests/gap/fixed_text.h"
#include "drop_tests/util/nearest_name.h"
#include "drop_tests/util/work_pool.h"
#include "rft/input_error.h"

namespace touchdown::gap {

const char* FindingKindName(FindingKind kind) { return NameIn(kFindingKindNames, kind); }

namespace {

const char* const kPhases[4] = {"impact_onset", "mid_stroke", "stopping", "rest"};

std::vector<bool> HeldOutSplit(const dataset::Dataset& ds) {
  std::map<std::string, std::vector<size_t>> cells;
  for (size_t i = 0; i < ds.drops.size(); ++i) {
    const dataset::DatasetDrop& d = ds.drops[i];
    cells[d.pad + "|" + d.soil + "|" + rft::AtmosphereName(d.atmosphere)].push_back(i);
  }
  std::vector<bool> held(ds.drops.size(), false);
  for (auto& [cell, idx] : cells) {
    std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) {
      const dataset::DatasetDrop &x = ds.drops[a], &y = ds.drops[b];
      if (x.impact_speed_m_s != y.impact_speed_m_s) return x.impact_speed_m_s < y.impact_speed_m_s;
      return x.drop_id < y.drop_id;
    });
    for (size_t r = 0; r < idx.size(); ++r) held[idx[r]] = r % 3 == 1;
  }
  return held;
}

// --fit-on: the designated drops train, every other one is held out.
std::vector<bool> DesignatedSplit(const dataset::Dataset& ds, const std::vector<std::string>& fit_on) {
  std::vector<std::string> ids;
  for (const dataset::DatasetDrop& d : ds.drops) ids.push_back(d.drop_id);
  std::vector<bool> held(ds.drops.size(), true);
  for (const std::string& id : fit_on) {
    const auto it = std::find(ids.begin(), ids.end(), id);
    if (it == ids.end()) {
      const std::optional<std::string> near = io::NearestName(id, ids);
      throw MakeInputError(ds.directory + "/drops.csv", "--fit-on",
                           "no drop '" + id + "'" + (near ? " (did you mean '" + *near + "'?)" : ""));
    }
    held[static_cast<size_t>(it - ids.begin())] = false;
  }
  std::set<std::string> soils, fitted_soils;
  for (size_t i = 0; i < ds.drops.size(); ++i) {
    soils.insert(ds.drops[i].soil);
    if (!held[i]) fitted_soils.insert(ds.drops[i].soil);
  }
  for (const std::string& soil : soils)
    if (!fitted_soils.count(soil))
      throw MakeInputError(ds.directory + "/drops.csv", "--fit-on",
                           "no designated drop on soil '" + soil + "': its zeta cannot be calibrated");
  if (std::find(held.begin(), held.end(), true) == held.end())
    throw MakeInputError(ds.directory + "/drops.csv", "--fit-on", "designates every drop: none is left to predict");
  return held;
}

DropGap ComputeGap(const FitProblem& p, const FitDrop& d, const FitResult& model, const dataset::Dataset& ds) {
  DropGap g;
  g.drop_id = d.drop_id;
  g.held_out = !d.train;
  g.noise_nrmse = d.noise_force_N / d.force_scale_N;
  g.phase_ms.assign(4, 0.0);
  const std::optional<dataset::DatasetTrace> sim = SimulateRecorded(p, d, model);
  const dataset::DatasetDrop& m = ds.drops[d.dataset_index];
  if (!sim) {
    g.failed = true;
    g.force_nrmse = g.force_nrmse_penetration = 1.0;
    g.final_penetration_rel_error = g.peak_force_rel_error = 1.0;
    g.overall_ms = 1.0;
    return g;
  }
  // The force NRMSE over the counted samples (FitDrop::ForceCounted); sim is recorded at the
  // measured times, sample by sample.
  double sum = 0.0, used = 0.0;
  for (size_t i = 0; i < sim->size(); ++i)
    if (d.ForceCounted(i)) sum += std::pow(sim->force_N[i] - m.trace.force_N[i], 2), used += 1;
  g.force_nrmse = used > 0 ? std::sqrt(sum / used) / d.force_scale_N : std::nan("");
  g.force_nrmse_penetration = dataset::ForceNrmsePenetration(m.trace, *sim).value;
  const double d_meas = m.FinalPenetration(), f_meas = m.PeakForce();
  g.final_penetration_rel_error = (sim->penetration_m.back() - d_meas) / d_meas;
  g.peak_force_rel_error = (*std::max_element(sim->force_N.begin(), sim->force_N.end()) - f_meas) / f_meas;
  // Stroke phases on the simulated record: the stop is where it first reaches its final depth.
  const double d_final = sim->penetration_m.back();
  double t_stop = sim->t_s.back();
  for (size_t i = 0; i < sim->size(); ++i)
    if (sim->penetration_m[i] >= d_final - 1e-9 * std::abs(d_final)) {
      t_stop = sim->t_s[i];
      break;
    }
  std::vector<double> count(4, 0.0);
  double total = 0.0, bias = 0.0, stroke = 0.0;
  for (size_t i = 0; i < sim->size(); ++i) {
    const double t = sim->t_s[i];
    if (t < 0) continue;
    const int phase = t < 0.2 * t_stop ? 0 : t < 0.7 * t_stop ? 1 : t <= t_stop ? 2 : 3;
    // A skipped sample stays in force_residual as 0, so replicates still align sample by sample.
    const double e = d.ForceCounted(i) ? (sim->force_N[i] - m.trace.force_N[i]) / d.force_scale_N : 0.0;
    g.force_residual.push_back(e);
    if (!d.ForceCounted(i)) continue;
    g.phase_ms[phase] += e * e;
    if (phase < 3) bias += e, stroke += 1;
    count[phase] += 1;
    total += e * e;
  }
  double n = 0;
  for (int k = 0; k < 4; ++k) {
    n += count[k];
    g.phase_ms[k] = count[k] > 0 ? g.phase_ms[k] / count[k] : std::nan("");
  }
  g.overall_ms = n > 0 ? total / n : 0.0;
  g.force_bias = stroke > 0 ? bias / stroke : 0.0;
  return g;
}

GapSummary HeldOutSummary(const std::vector<DropGap>& gaps) {
  GapSummary s;
  double n = 0, n_pen = 0;
  for (const DropGap& g : gaps) {
    if (!g.held_out) continue;
    n += 1;
    s.force_nrmse += g.force_nrmse;
    s.final_penetration_rel_error += std::abs(g.final_penetration_rel_error);
    s.peak_force_rel_error += std::abs(g.peak_force_rel_error);
    s.noise_nrmse += g.noise_nrmse;
    s.mean_square += g.force_nrmse * g.force_nrmse;
    s.noise_mean_square += g.noise_nrmse * g.noise_nrmse;
    if (std::isfinite(g.force_nrmse_penetration)) s.force_nrmse_penetration += g.force_nrmse_penetration, n_pen += 1;
  }
  if (n > 0) {
    s.force_nrmse /= n, s.final_penetration_rel_error /= n, s.peak_force_rel_error /= n;
    s.noise_nrmse /= n, s.mean_square /= n, s.noise_mean_square /= n;
  }
  s.force_nrmse_penetration = n_pen > 0 ? s.force_nrmse_penetration / n_pen : std::nan("");
  return s;
}

std::vector<DropGap> AllGaps(const Diagnosis& d, const FitResult& model, const dataset::Dataset& ds, int threads) {
  std::vector<DropGap> gaps(d.problem.drops.size());
  io::ParallelFor(gaps.size(), threads,
                  [&](size_t i) { gaps[i] = ComputeGap(d.problem, d.problem.drops[i], model, ds); });
  return gaps;
}

std::vector<double> Ranks(const std::vector<double>& v) {
  std::vector<size_t> idx(v.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (size_t i = 0; i < idx.size();) {
    size_t j = i;
    while (j + 1 < idx.size() && v[idx[j + 1]] == v[idx[i]]) ++j;
    for (size_t k = i; k <= j; ++k) r[idx[k]] = 0.5 * (i + j);
    i = j + 1;
  }
  return r;
}

double Pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = a.size();
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n, mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0, saa = 0, sbb = 0;
  for (size_t i = 0; i < a.size(); ++i) sab += (a[i] - ma) * (b[i] - mb), saa += (a[i] - ma) * (a[i] - ma), sbb += (b[i] - mb) * (b[i] - mb);
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

// Share of the variance of y explained by the grouping (eta squared).
double EtaSquared(const std::vector<double>& y, const std::vector<int>& group, int groups) {
  const double mean = std::accumulate(y.begin(), y.end(), 0.0) / y.size();
  std::vector<double> sum(groups, 0.0), n(groups, 0.0);
  double total = 0;
  for (size_t i = 0; i < y.size(); ++i) sum[group[i]] += y[i], n[group[i]] += 1, total += (y[i] - mean) * (y[i] - mean);
  double between = 0;
  for (int g = 0; g < groups; ++g)
    if (n[g] > 0) between += n[g] * (sum[g] / n[g] - mean) * (sum[g] / n[g] - mean);
  return total > 0 ? between / total : 0.0;
}

std::vector<Finding> WhereAnalysis(const dataset::Dataset& ds, const FitProblem& p, const std::vector<DropGap>& gaps,
                                   const DiagnoseOptions& o) {
  std::vector<Finding> out;
  std::mt19937 rng(o.seed);
  std::vector<double> nrmse, bias;
  for (const DropGap& g : gaps) nrmse.push_back(g.force_nrmse), bias.push_back(g.final_penetration_rel_error);
  const size_t n = nrmse.size();
  // Levels are compared on the size of the gap (force NRMSE) and on its sign (the signed final
  // penetration error): a model calibrated on all drops splits a one-sided gap into opposite
  // biases (too shallow in air, too deep in vacuum), which the NRMSE alone hides.
  auto categorical = [&](const std::string& factor, const std::function<std::string(const dataset::DatasetDrop&)>& level,
                         bool on_bias) {
    const std::vector<double>& y = on_bias ? bias : nrmse;
    std::map<std::string, int> ids;
    std::vector<int> group;
    for (const FitDrop& d : p.drops) {
      const std::string l = level(ds.drops[d.dataset_index]);
      if (!ids.count(l)) ids.emplace(l, static_cast<int>(ids.size()));
      group.push_back(ids[l]);
    }
    if (ids.size() < 2) return;
    const int G = static_cast<int>(ids.size());
    const double stat = EtaSquared(y, group, G);
    std::vector<int> perm = group;
    int hits = 0;
    for (int k = 0; k < o.permutations; ++k) {
      std::shuffle(perm.begin(), perm.end(), rng);
      hits += EtaSquared(y, perm, G) >= stat - 1e-15;
    }
    Finding f{FindingKind::kCondition, factor + (on_bias ? " (penetration bias)" : ""), "", stat, (hits + 1.0) / (o.permutations + 1.0), false};
    std::ostringstream s;
    s << (on_bias ? "signed final penetration error (sim - measured) / measured by " : "force NRMSE by ") << factor << ":";
    for (const auto& [name, gi] : ids) {
      double sum = 0, c = 0;
      for (size_t i = 0; i < n; ++i)
        if (group[i] == gi) sum += y[i], c += 1;
      s << " " << name << " " << (on_bias && sum > 0 ? "+" : "") << Fixed(sum / c, 3) << " (n=" << c << ")";
    }
    s << "; eta^2 = " << Fixed(stat, 2);
    f.summary = s.str();
    out.push_back(f);
  };
  for (bool on_bias : {false, true}) {
    categorical("atmosphere", [](const dataset::DatasetDrop& d) { return std::string(rft::AtmosphereName(d.atmosphere)); }, on_bias);
    categorical("pad", [](const dataset::DatasetDrop& d) { return d.pad; }, on_bias);
    categorical("soil", [](const dataset::DatasetDrop& d) { return d.soil; }, on_bias);
  }
  auto numeric = [&](const std::string& factor, const std::function<std::optional<double>(const dataset::DatasetDrop&)>& value) {
    std::vector<double> x;
    for (const FitDrop& d : p.drops) {
      const std::optional<double> v = value(ds.drops[d.dataset_index]);
      if (!v) return;
      x.push_back(*v);
    }
    if (std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); })) return;
    const std::vector<double> rx = Ranks(x), ry = Ranks(nrmse);
    const double rho = Pearson(rx, ry);
    std::vector<double> perm = ry;
    int hits = 0;
    for (int k = 0; k < o.permutations; ++k) {
      std::shuffle(perm.begin(), perm.end(), rng);
      hits += std::abs(Pearson(rx, perm)) >= std::abs(rho) - 1e-15;
    }
    Finding f{FindingKind::kCondition, factor, "", rho, (hits + 1.0) / (o.permutations + 1.0), false};
    f.summary = "force NRMSE " + std::string(rho > 0 ? "grows" : "falls") + " with " + factor +
                " (Spearman rho = " + Fixed(rho, 2) + ")";
    out.push_back(f);
  };
  numeric("impact_speed", [](const dataset::DatasetDrop& d) { return std::optional<double>(d.impact_speed_m_s); });
  numeric("tilt", [&](const dataset::DatasetDrop& d) { return ds.ExtraNumber(d, "tilt_deg"); });
  // Phases: log of each drop's phase mean square over its overall mean square; sign-flip test.
  for (int ph = 0; ph < 4; ++ph) {
    std::vector<double> l;
    for (const DropGap& g : gaps)
      if (std::isfinite(g.phase_ms[ph]) && g.overall_ms > 0 && g.phase_ms[ph] > 0)
        l.push_back(std::log(g.phase_ms[ph] / g.overall_ms));
    if (l.size() < 2) continue;
    const double mean = std::accumulate(l.begin(), l.end(), 0.0) / l.size();
    int hits = 0;
    std::uniform_int_distribution<int> coin(0, 1);
    for (int k = 0; k < o.permutations; ++k) {
      double s = 0;
      for (double v : l) s += coin(rng) ? v : -v;
      hits += s / l.size() >= mean - 1e-15;
    }
    Finding f{FindingKind::kPhase, kPhases[ph], "", std::exp(mean), (hits + 1.0) / (o.permutations + 1.0), false};
    f.summary = std::string(kPhases[ph]) + ": mean squared force residual " + Fixed(std::exp(mean), 2) +
                "x the drop's average (geometric mean over " + std::to_string(l.size()) + " drops)";
    out.push_back(f);
  }
  const double alpha = 0.05 / std::max<size_t>(out.size(), 1);  // Bonferroni over the tests made
  for (Finding& f : out) f.significant = f.p_value < alpha && (f.kind != FindingKind::kPhase || f.statistic > 1.0);
  return out;
}

CandidateScore Score(Diagnosis& d, const dataset::Dataset& ds, const std::vector<std::string>& ids,
                     const FitResult* start, const DiagnoseOptions& o) {
  CandidateScore c;
  c.effect_ids = ids;
  for (const std::string& id : ids) c.name += (c.name.empty() ? "" : "+") + id;
  if (c.name.empty()) c.name = "base";
  if (!CandidateApplies(d.problem, ids, &c.why_not)) {
    c.applies = false;
    return c;
  }
  c.fit = FitCandidate(d.problem, ids, start);
  d.simulations += c.fit.simulations;
  c.gaps = AllGaps(d, c.fit, ds, o.threads);
  c.held_out = HeldOutSummary(c.gaps);
  return c;
}

std::string DescribeResidual(const Diagnosis& d) {
  std::ostringstream s;
  std::vector<const Finding*> sig;
  for (const Finding& f : d.where)
    if (f.significant) sig.push_back(&f);
  if (sig.empty()) s << "The base model's residual shows no significant concentration by condition or phase";
  else {
    s << "The base model's residual concentrates: ";
    for (size_t i = 0; i < sig.size(); ++i) s << (i ? "; " : "") << sig[i]->summary << " (p = " << Fixed(sig[i]->p_value, 4) << ")";
  }
  s << ". Held-out force NRMSE " << Fixed(d.base.held_out.force_nrmse, 4) << " against an estimated sensor-noise floor of "
    << Fixed(d.base.held_out.noise_nrmse, 4) << ".";
  return s.str();
}

}  // namespace

std::vector<std::string> DiagnoseBaseNames() {
  return NameList(kDiagnoseBaseNames);
}

std::vector<std::string> SensorSamplingOptionNames() {
  std::vector<std::string> names{"auto"};
  for (const std::string& n : dataset::SensorSamplingNames()) names.push_back(n);
  return names;
}

DiagnoseBase ParseDiagnoseBase(const std::string& name, const std::string& where, const std::string& field) {
  return ParseName(kDiagnoseBaseNames, name, where, field);
}

std::vector<std::string> RigOffsetsNames() {
  return NameList(kRigOffsetsNames);
}

RigOffsets ParseRigOffsets(const std::string& name, const std::string& where, const std::string& field) {
  return ParseName(kRigOffsetsNames, name, where, field);
}

Diagnosis RunDiagnosis(const dataset::Dataset& ds, const DiagnoseOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (ds.drops.size() < 3) throw MakeInputError(ds.directory, "drops.csv", "diagnose needs at least 3 drops");
  Diagnosis d;
  d.dataset_dir = ds.directory;
  d.fit_on = o.fit_on;
  d.held_out = o.fit_on.empty() ? HeldOutSplit(ds) : DesignatedSplit(ds, o.fit_on);
  d.problem = MakeFitProblem(ds, d.held_out, o.threads, o.skip_stop_samples);
  if (o.base == DiagnoseBase::kBekker) {
    if (o.start_model)
      throw MakeInputError(o.start_model->name, "soils", "--model starts RFT's zeta; the Bekker base fits its own soils");
    d.bekker_base = UseBekkerBase(ds, d.problem);
  } else {
    if (o.start_model)
      for (rft::SoilParameters& s : d.problem.soils) {
        const auto it = o.start_model->soils.find(s.name);
        if (it != o.start_model->soils.end())
          s.SetZetaAtGravity(it->second.zeta_N_m3, it->second.reference_gravity_m_s2);
      }
    StartZetaWhereMissing(ds, d.problem);  // a Bekker soil's RFT base (law_candidate.h)
  }
  // The record's common offsets in time and depth are the rig's nuisances in every fit (no longer
  // a candidate of the soil's): a detector's lag behind an anti-alias filter is in every raw file.
  d.problem.sensor_fit.offsets = o.drop_nuisances && o.rig_offsets == RigOffsets::kEveryModel;
  SetCandidateTerms(d.problem);  // from the base's soils (a Bekker base's too)
  io::Progress progress("diagnose", "fits", 1 + static_cast<int64_t>(d.problem.terms.size()), o.progress);
  // 1: the sensor (inferred, or as given) and the drops' nuisances: their spreads from the base's
  // fit under that sensor, within the conditions the drops repeat.
  d.problem.drop_nuisances = o.drop_nuisances;
  d.problem.refit_drop_nuisances = o.refit_drops;
  if (!(o.drop_nuisances && TrainingReplicateDf(d.problem) >= kMinNuisanceDf)) CountStopSamples(d.problem);
  FitResult first;
  if (o.sensor_sampling) {
    d.problem.sensor = dataset::SensorModel{*o.sensor_sampling};
    d.sensor.given = true;
    d.sensor.chosen = d.problem.sensor;
    first = FitCandidate(d.problem, {});
  } else {
    d.sensor = InferSensor(d.problem, o.min_delta_bic);
    first = d.sensor.base;
  }
  d.simulations += first.simulations;
  if (d.problem.drop_nuisances && EstimateNuisanceSpreads(d.problem, first) < kMinNuisanceDf) {
    d.problem.drop_nuisances = false;
    d.nuisances_without_replicates = true;
  }
  // 2: the base model, its gap, where it concentrates.
  d.base = Score(d, ds, {}, &first, o);
  progress.Add(1, ", last: base");
  d.where = WhereAnalysis(ds, d.problem, d.base.gaps, o);
  d.floor = ComputeFloor(d.problem, d.base.gaps, d.base.held_out.noise_mean_square);
  d.lack_of_fit_before = LackOfFit(d.problem, d.base.gaps);
  if (o.law_candidate) d.law_candidate = ScoreBekkerLaw(ds, d.problem, d.base.held_out.force_nrmse);
  // 3: forward selection of the candidate terms.
  const auto score = [&](const std::vector<std::string>& ids, const FitResult& start) {
    return Score(d, ds, ids, &start, o);
  };
  ScreenModel screen = [&](const std::vector<std::string>& ids, const FitResult& start) -> std::optional<FitResult> {
    std::string why;
    if (!CandidateApplies(d.problem, ids, &why)) return std::nullopt;
    FitResult f = FitCandidate(d.problem, ids, &start, kScreenIterations);
    d.simulations += f.simulations;
    return f;
  };
  const long training = std::count_if(d.problem.drops.begin(), d.problem.drops.end(), [](const FitDrop& x) { return x.train; });
  if (training < kMinTrainingDropsScreened) screen = nullptr;
  SelectForward(d, o, score, screen, progress);
  progress.Finish();
  // The rig's common offsets are named (as nuisances) when the final model's intervals exclude 0.
  const CandidateScore& final_model = d.winner >= 0 ? d.candidates[d.winner] : d.base;
  for (const ParameterEstimate& e : final_model.fit.sensor_estimates)
    if (e.effect == "sensor_offset" && (e.low > 0.0 || e.high < 0.0) &&
        std::find(d.named_nuisances.begin(), d.named_nuisances.end(), "sensor_offset") == d.named_nuisances.end())
      d.named_nuisances.push_back("sensor_offset");
  if (d.winner < 0) d.residual_description = DescribeResidual(d);
  else d.where_after = WhereAnalysis(ds, d.problem, d.candidates[d.winner].gaps, o);
  if (d.winner >= 0) d.lack_of_fit_after = LackOfFit(d.problem, d.candidates[d.winner].gaps);
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return d;
}

}  // namespace touchdown::gap
