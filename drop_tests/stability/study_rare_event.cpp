#include "drop_tests/stability/study_rare_event.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>

#include <boost/math/distributions/normal.hpp>

#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/json_number.h"
#include "drop_tests/stability/rare_event_shards.h"
#include "drop_tests/stability/study_followups.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/stability/study_summary.h"
#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep_mpi.h"
#include "rft/input_error.h"

namespace touchdown::stability {

namespace {
using sweep::DropRecord;

constexpr int kListedDesignPoints = 5;

// The run stopped by a signal between two batches: unwinds the estimator.
struct StoppedBySignal {
  int signal = 0;
};

// The landings a pass may ask for at most: the plan's size (part of its digest). The importance
// method's own pass (DIR/importance/) is the design point's refinement and the weighted sample; its
// subset pass is the subset method's run (DIR/subset/), shared with `--method subset`.
int64_t Budget(StudyMethod method, int64_t samples) {
  if (method == StudyMethod::kSubset) return static_cast<int64_t>(kSubsetMaxLevels) * samples;
  return 1 + 7 * static_cast<int64_t>(kDesignPointRounds) + samples;
}

// Phi(u) in [0, 1): a uniform the plan's random parameters take (1 itself is no draw of theirs).
double UniformOf(double u) {
  const double p = boost::math::cdf(boost::math::normal(), u);
  return std::min(p, std::nextafter(1.0, 0.0));
}

std::vector<double> UniformsOf(const Eigen::VectorXd& u) {
  std::vector<double> out(static_cast<size_t>(u.size()));
  for (Eigen::Index k = 0; k < u.size(); ++k) out[static_cast<size_t>(k)] = UniformOf(u[k]);
  return out;
}

std::string MethodDir(const std::string& out_dir, StudyMethod method) {
  return (std::filesystem::path(out_dir) / StudyMethodName(method)).string();
}

// The estimator's limit state: each batch of points runs as landings `next` onward of the
// rare-event plan, through the sweep engine into the pass's directory, and comes back as their
// margins. A shard (options.shard, N > 1) runs its share of each batch into its own directory and
// meets the other shards after it (rare_event_shards.h).
class LandingLimitState {
 public:
  LandingLimitState(const Study& study, StudyMethod method, StudyMethod run_method, int64_t samples,
                    const std::string& out_dir, const sweep::SweepRunOptions& options, RareEventStudyResult& result,
                    std::ostream* say)
      : study_(study), method_(method), samples_(samples), options_(options), result_(result) {
    if (sharded()) {
      barrier_.emplace(out_dir, StudyMethodName(method), StudyMethodName(run_method), options.shard, options.stop, say);
      dir_ = barrier_->OwnDir();
    } else {
      dir_ = MethodDir(out_dir, method);
    }
  }

  void operator()(const std::vector<Eigen::VectorXd>& u, std::vector<double>& g) {
    const int64_t first = static_cast<int64_t>(records_.size()), n = static_cast<int64_t>(u.size());
    const sweep::SweepPlan plan = RareEventPlan(study_, method_, samples_, first, u);
    sweep::SweepRunOptions o = options_;
    o.indices = std::vector<int64_t>();
    for (int64_t i = first; i < first + n; ++i) o.indices->push_back(i);
    // Under mpirun every rank runs the estimator in step: the batch's landings are shared out
    // over the ranks, rank 0 stores them and hands every rank the batch's records (and whether
    // the run was stopped), so each rank chooses the same next points.
    const bool mpi = sweep::LaunchedByMpirun();
    int rank = 0;
    const sweep::SweepRunSummary run = mpi ? sweep::RunSweepMpi(plan, dir_, o, &rank) : sweep::RunSweep(plan, dir_, o);
    result_.computed += run.computed;
    result_.already_done += run.already_done;
    std::vector<DropRecord> batch;
    int stop_signal = run.stop_signal;
    if (rank == 0 && stop_signal == 0) {
      batch = StoredBatch(first, n);
      if (barrier_) {
        std::optional<std::vector<DropRecord>> whole = barrier_->Gather(plan, first, n, batch);
        if (whole) batch = std::move(*whole);
        else stop_signal = options_.stop->load();
      }
    }
    if (mpi) {
      const std::string shared = sweep::BroadcastFromRankZero(
          rank != 0 ? std::string() : stop_signal != 0 ? "S" + std::to_string(stop_signal) : "R" + sweep::SerializeRecords(batch));
      if (shared.front() == 'S') stop_signal = std::stoi(shared.substr(1));
      else if (rank != 0) batch = sweep::DeserializeRecords(shared.substr(1));
    }
    if (stop_signal != 0) throw StoppedBySignal{stop_signal};
    g.resize(u.size());
    for (int64_t k = 0; k < n; ++k) {
      const DropRecord& r = batch[static_cast<size_t>(k)];
      g[k] = LimitStateOfLanding(r);
      result_.failed += !r.ok;
      result_.margin_disagreements += r.ok && !std::isnan(r.min_stability_margin_m) &&
                                      (r.min_stability_margin_m <= 0.0) != Tipped(r);
      records_.push_back(r);
      points_.push_back(u[k]);
      values_.push_back(g[k]);
    }
  }

  const std::vector<DropRecord>& records() const { return records_; }
  bool sharded() const { return options_.shard.count > 1; }

  // This run's landings (its shard's) among first..first+n-1 as stored in dir_, in index order. A
  // shard's come with their traces, if the plan stores any: shard 0 stores the whole run's at the end.
  std::vector<DropRecord> StoredBatch(int64_t first, int64_t n) const {
    const sweep::Shard& shard = options_.shard;
    int64_t share = 0;
    for (int64_t i = first; i < first + n; ++i) share += i % shard.count == shard.index;
    const sweep::ResultsDb db(sweep::ResultsDbPath(dir_), sweep::ResultsDb::Access::kReadOnly);
    // The database holds the shard's landings only, so its next `share` from `first` are these.
    const std::vector<DropRecord> batch = db.ReadPage(first, static_cast<size_t>(share), /*with_traces=*/sharded());
    for (int64_t i = first, k = 0; i < first + n; ++i) {
      if (i % shard.count != shard.index) continue;
      // the engine ran every listed landing of the shard: a missing one is a bug
      if (k >= static_cast<int64_t>(batch.size()) || batch[static_cast<size_t>(k)].index != i)
        throw std::logic_error("rare-event landing " + std::to_string(i) + " missing from " + dir_);
      ++k;
    }
    return batch;
  }
  const std::vector<Eigen::VectorXd>& points() const { return points_; }
  const std::vector<double>& values() const { return values_; }

 private:
  const Study& study_;
  StudyMethod method_;
  int64_t samples_;
  std::string dir_;
  sweep::SweepRunOptions options_;
  RareEventStudyResult& result_;
  std::optional<RareEventShardBarrier> barrier_;  // a shard's: where it meets the others
  std::vector<DropRecord> records_;  // in evaluation order: records_[k] is landing k
  std::vector<Eigen::VectorXd> points_;
  std::vector<double> values_;
};

// The failing landings of smallest |u| over the passes (ties in pass, then landing order), at most
// kListedDesignPoints.
std::vector<RareEventDesignPoint> DesignPoints(const std::vector<std::pair<StudyMethod, const LandingLimitState*>>& passes) {
  std::vector<RareEventDesignPoint> failing;
  for (const auto& [method, g] : passes)
    for (size_t k = 0; k < g->values().size(); ++k)
      if (g->values()[k] <= 0.0)
        failing.push_back({g->points()[k], g->points()[k].norm(), g->records()[k].drop_id, StudyMethodName(method)});
  std::stable_sort(failing.begin(), failing.end(),
                   [](const RareEventDesignPoint& a, const RareEventDesignPoint& b) { return a.beta < b.beta; });
  if (failing.size() > static_cast<size_t>(kListedDesignPoints)) failing.resize(kListedDesignPoints);
  return failing;
}

// Where shard 0 of a sharded run stores the whole run's landings of each pass once it is done
// (every shard then holds them all): DIR/<pass>/, as a single process stores them, so that the same
// command without --shard finds every landing done. Opened before any landing runs: a DIR holding
// another run there is refused at once, and no single process writes there meanwhile.
class WholeRunStores {
 public:
  WholeRunStores(const Study& study, StudyMethod method, int64_t samples, const std::string& out_dir,
                 const sweep::SweepRunOptions& options) {
    if (options.shard.count == 1 || options.shard.index != 0 || sweep::RankFromMpirun() != 0) return;
    for (StudyMethod pass : {StudyMethod::kSubset, StudyMethod::kImportance})
      if (pass == StudyMethod::kSubset || method == StudyMethod::kImportance)
        stores_.emplace(pass, sweep::OpenSweepStore(RareEventPlan(study, pass, samples, 0, {}), MethodDir(out_dir, pass),
                                                    sweep::Shard{}));
  }
  void Store(StudyMethod pass, const std::vector<DropRecord>& records) {
    const auto it = stores_.find(pass);
    if (it != stores_.end() && !records.empty()) it->second.db->Insert(records);  // one transaction
  }

 private:
  std::map<StudyMethod, sweep::SweepStore> stores_;
};

nlohmann::json IntervalJson(const BinomialInterval& i) { return {i.low, i.high}; }

const char* IntervalConstruction(StudyMethod m) {
  if (m == StudyMethod::kSubset)
    return "lognormal, two-sided 95 %: [P exp(s^2/2 - 1.96 s), P exp(s^2/2 + 1.96 s)], s^2 = ln(1 + c^2), with c the "
           "coefficient of variation of fully correlated levels (Au & Beck's upper bound, the sum of the levels' "
           "delta_i): it covered the exact P of an analytic limit state in 99 % of 2,000 seeds "
           "(tests/drop_tests/stability/rare_event_test.cpp)";
  return "normal, two-sided 95 %: P +- 1.96 SE, SE from the weighted sample's variance, the low end floored at 0";
}
}  // namespace

const char* StudyMethodName(StudyMethod m) { return NameIn(kStudyMethodNames, m); }

StudyMethod ParseStudyMethod(const std::string& text, const std::string& field) {
  return ParseName(kStudyMethodNames, text, "", field);
}

namespace {
// What a rare-event run holds per landing of its first level before that level's landings run,
// and keeps: the estimator's point (and its candidate's), the limit state's point, value and
// record. Refused against the machine's memory up front, so that a billion samples per level is
// one line and exit 2, not gigabytes allocated point by point before the first landing.
// Past kMaxSamplesPerLevel a level is refused on every machine (about 10 GB at a few variables; a
// run of 30 such levels is 3e8 landings, years of CPU); below it, against this machine's memory.
constexpr int64_t kMaxSamplesPerLevel = 10'000'000;

void RequireMemoryFor(int64_t samples, int dimension) {
  const double point = sizeof(Eigen::VectorXd) + 16.0 + 8.0 * dimension;  // the object, malloc's header, the values
  const double per_landing = 3.0 * point + sizeof(DropRecord) + 2.0 * sizeof(double);
  if (samples > kMaxSamplesPerLevel)
    throw MakeInputError("", "--samples",
                         std::to_string(samples) + ": a subset run holds each level's landings in memory (about a "
                             "kilobyte each): at most " + std::to_string(kMaxSamplesPerLevel) + " samples per level");
  const double need = per_landing * static_cast<double>(samples);
  const double have = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
  if (have <= 0.0 || need <= 0.5 * have) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "%lld: a subset run holds each level's landings in memory, %.3g GB for %lld (%.0f bytes a landing); "
                "this machine has %.3g GB, half of which allows at most %.3g samples per level",
                static_cast<long long>(samples), need / 1e9, static_cast<long long>(samples), per_landing, have / 1e9,
                std::floor(0.5 * have / per_landing));
  throw MakeInputError("", "--samples", text);
}
}  // namespace

void RequireRareEventStudy(const Study& study, StudyMethod method, int64_t samples) {
  if (method == StudyMethod::kMonteCarlo) return;
  const std::string name = StudyMethodName(method);
  const auto refuse = [&](const std::string& why) {
    throw MakeInputError(study.plan.source, "--method", name + ": " + why);
  };
  if (!study.plan.grid.empty())
    refuse("the study has a grid; a rare-event method needs every variable random (move the grid's axes to random)");
  if (study.plan.random.empty()) refuse("the study has no random variable to estimate over");
  for (const sweep::SweepRandom& r : study.plan.random)
    if (r.per_pad)
      refuse(std::string("the per-pad choice of ") + sweep::SweepParamKey(r.param) +
             " is four variables in one; a rare-event method takes one variable per parameter");
  if (samples < 10 || samples % 10 != 0)
    throw MakeInputError("", "--samples",
                         name + " runs its levels in chains of 1 / p0 = 10 landings: samples must be a multiple of 10, "
                                "at least 10, got " + std::to_string(samples));
  RequireMemoryFor(samples, static_cast<int>(study.plan.random.size()));
}

sweep::SweepPlan RareEventPlan(const Study& study, StudyMethod method, int64_t samples, int64_t first,
                               const std::vector<Eigen::VectorXd>& u) {
  sweep::SweepPlan plan = study.plan;
  plan.samples = Budget(method, samples);
  plan.variant += std::string(plan.variant.empty() ? "" : ";") + "rare_event=" + StudyMethodName(method) +
                  ";per_level=" + std::to_string(samples) + ";p0=" + io::FormatNumber(kSubsetP0) +
                  ";levels=" + std::to_string(kSubsetMaxLevels) + ";rounds=" + std::to_string(kDesignPointRounds);
  auto given = std::make_shared<std::map<int64_t, std::vector<double>>>();
  for (size_t k = 0; k < u.size(); ++k) (*given)[first + static_cast<int64_t>(k)] = UniformsOf(u[k]);
  plan.given_uniforms = given;
  return plan;
}

nlohmann::json StudyVariablesJson(const Study& study, const Eigen::VectorXd& u) {
  const sweep::SweepPlan plan = RareEventPlan(study, StudyMethod::kSubset, 10, 0, {u});
  const sweep::SweepDropParams d = plan.DropAt(0);
  nlohmann::json out = nlohmann::json::object();
  for (const sweep::SweepRandom& r : plan.random) {
    const double v = sweep::ParamValue(d, r.param);
    const char* key = sweep::SweepParamKey(r.param);
    if (r.param == sweep::SweepParam::kPad)
      out[key] = plan.pads.at(static_cast<size_t>(v)).name;
    else if (r.param == sweep::SweepParam::kSoil)
      out[key] = plan.soils.at(static_cast<size_t>(v)).name;
    else
      out[key] = sweep::SweepParamFromSi(r.param, v);
  }
  return out;
}

double LimitStateOfLanding(const DropRecord& r) {
  if (!r.ok) return std::numeric_limits<double>::infinity();
  const double m = r.min_stability_margin_m;
  if (Tipped(r)) return std::isnan(m) ? 0.0 : std::min(m, 0.0);
  return std::isnan(m) || m <= 0.0 ? std::numeric_limits<double>::denorm_min() : m;
}


RareEventStudyResult RunRareEventStudy(const Study& study, StudyMethod method, int64_t samples,
                                       const std::string& out_dir, const sweep::SweepRunOptions& options,
                                       std::ostream* say) {
  RequireRareEventStudy(study, method, samples);  // the callers' check, again: nothing may run past it
  RareEventStudyResult result;
  result.method = method;
  result.samples = samples;
  const int dimension = static_cast<int>(study.plan.random.size());
  WholeRunStores whole(study, method, samples, out_dir, options);
  LandingLimitState state(study, StudyMethod::kSubset, method, samples, out_dir, options, result, say);
  const LimitStateBatch g = [&state](const std::vector<Eigen::VectorXd>& u, std::vector<double>& v) { state(u, v); };
  LandingLimitState importance(study, StudyMethod::kImportance, method, samples, out_dir, options, result, say);
  const LimitStateBatch gi = [&importance](const std::vector<Eigen::VectorXd>& u, std::vector<double>& v) {
    importance(u, v);
  };
  try {
    SubsetOptions so;
    so.samples_per_level = samples;
    so.p0 = kSubsetP0;
    so.max_levels = kSubsetMaxLevels;
    so.seed = study.plan.seed;
    if (say) *say << "stability " << study.plan.name << ": subset simulation, " << samples << " landings per level\n";
    result.subset = EstimateSubset(g, dimension, so);
    result.estimate = *result.subset;
    if (method == StudyMethod::kImportance && result.subset->design_point.size() > 0) {
      if (say) *say << "stability " << study.plan.name << ": importance sampling, " << samples << " landings\n";
      const DesignPointRefinement refined = RefineDesignPoint(gi, result.subset->design_point, kDesignPointRounds);
      ImportanceOptions io;
      io.samples = samples;
      io.seed = study.plan.seed;
      io.batch = samples;
      result.importance_centre = refined.point;
      result.estimate = EstimateImportance(gi, refined.point, io);
    }
  } catch (const StoppedBySignal& stopped) {
    result.stop_signal = stopped.signal;
    return result;
  }
  whole.Store(StudyMethod::kSubset, state.records());
  whole.Store(StudyMethod::kImportance, importance.records());
  result.landings = static_cast<int64_t>(state.records().size() + importance.records().size());
  result.design_points = DesignPoints({{StudyMethod::kSubset, &state}, {StudyMethod::kImportance, &importance}});
  result.first_level_plan = RareEventPlan(study, StudyMethod::kSubset, samples, 0,
                                          std::vector<Eigen::VectorXd>(state.points().begin(),
                                                                       state.points().begin() + samples));
  result.first_level_plan.samples = samples;
  result.first_level.assign(state.records().begin(), state.records().begin() + samples);
  return result;
}

nlohmann::json RareEventJson(const Study& study, const RareEventStudyResult& r) {
  const RareEventEstimate& e = r.estimate;
  nlohmann::json j = {{"method", StudyMethodName(r.method)},
                      {"tip_over_probability", e.probability},
                      {"tip_over_probability_interval_95", IntervalJson(e.interval)},
                      {"interval_method", IntervalConstruction(r.method)},
                      {"coefficient_of_variation", io::FiniteOrNull(e.cov)},
                      {"landings_spent", r.landings},
                      {"landings_failed", r.failed},
                      {"landings_failed_meaning", "failed landings count as not tipped over (limit state +inf)"},
                      {"margin_disagreements", r.margin_disagreements},
                      {"samples", r.samples},
                      {"variables", nlohmann::json::array()},
                      {"limit_state",
                       "min_stability_margin_m of the landing (<= 0: tipped over), the study's random variables "
                       "mapped from standard-normal space by their inverse CDFs"}};
  for (const sweep::SweepRandom& v : study.plan.random) j["variables"].push_back(sweep::SweepParamKey(v.param));
  if (r.subset) {
    const SubsetEstimate& s = *r.subset;
    nlohmann::json levels = nlohmann::json::array();
    for (const SubsetLevel& l : s.levels)
      levels.push_back({{"threshold_m", l.threshold},
                        {"conditional_probability", l.conditional_probability},
                        {"gamma", l.gamma},
                        {"cov", io::FiniteOrNull(l.cov)},
                        {"acceptance_rate", l.acceptance_rate},
                        {"landings", l.evaluations}});
    j["subset"] = {{"p0", kSubsetP0},
                   {"landings_per_level", r.samples},
                   {"tip_over_probability", s.probability},
                   {"tip_over_probability_interval_95", IntervalJson(s.interval)},
                   {"coefficient_of_variation", io::FiniteOrNull(s.cov)},
                   {"coefficient_of_variation_upper", io::FiniteOrNull(s.cov_upper)},
                   {"reached_failure", s.reached_failure},
                   {"levels", levels}};
  }
  if (r.importance_centre)
    j["importance_centre"] = {{"beta", r.importance_centre->norm()},
                              {"conditions", StudyVariablesJson(study, *r.importance_centre)}};
  nlohmann::json points = nlohmann::json::array();
  for (const RareEventDesignPoint& p : r.design_points) {
    nlohmann::json u = nlohmann::json::array();
    for (Eigen::Index k = 0; k < p.u.size(); ++k) u.push_back(p.u[k]);
    points.push_back({{"drop_id", p.drop_id},
                      {"run", p.run},
                      {"beta", p.beta},
                      {"u", u},
                      {"conditions", StudyVariablesJson(study, p.u)}});
  }
  j["design_points"] = points;
  j["design_points_meaning"] =
      "the tipped landings nearest the origin of standard-normal space (smallest beta = |u|), nearest first: the most "
      "likely tip-over conditions the run found, in the study's variables";
  return j;
}

StudySummary WriteRareEventAnalysis(const Study& study, const RareEventStudyResult& r, const std::string& out_dir) {
  Study first = study;
  first.plan = r.first_level_plan;
  StudyFollowUps f;
  f.records = r.first_level;
  f.recheck.enabled = false;
  f.joint_range.enabled = false;
  f.joint_range.reason = "not run with a rare-event method";
  const nlohmann::json rare_event = RareEventJson(study, r);
  const nlohmann::json overrides = {
      {"method", StudyMethodName(r.method)},
      {"tip_over_probability", r.estimate.probability},
      {"tip_over_probability_interval_95", {r.estimate.interval.low, r.estimate.interval.high}},
      {"interval_method", rare_event["interval_method"]},
      {"landings_meaning",
       "landings, tipped_over, percentiles, map, worst cases and tip_overs describe the subset run's first "
       "level (plain Monte Carlo draws of the study's distribution); tip_over_probability is the "
       "estimator's (rare_event)"},
      {"rare_event", rare_event}};
  return WriteStudyAnalysis(first, out_dir, f, &overrides);
}

}  // namespace touchdown::stability
