#include <cmath>
#include <csignal>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "apps/command_help.h"
#include "apps/commands.h"
#include "apps/option_checks.h"
#include "apps/sweep_run_flags.h"
#include "drop_tests/formats/dataset_csv.h"
#include "drop_tests/formats/output_path.h"
#include "drop_tests/stability/rare_event_shards.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_followups.h"
#include "drop_tests/stability/study_outputs.h"
#include "drop_tests/stability/study_rare_event.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_mpi.h"
#include "drop_tests/sweep/sweep_stop.h"
#include "lander/integ/cvode_integrator.h"
#include "rft/input_error.h"
#include "rft/physical_limits.h"

namespace touchdown::app {

namespace {
struct StabilityArgs {
  std::string study, out, samples, method = "monte_carlo";
  SweepRunFlags run;
};

// --samples: a whole number within the bound a study file's random.samples has
// (limits::kSamples); text that is not a number is told so, not quoted a range.
int64_t ParseSamples(const std::string& text) {
  const auto not_whole = [&] {
    return MakeInputError("", "--samples", "must be a whole number of samples, got '" + text + "'");
  };
  double v = 0.0;
  size_t used = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    throw not_whole();
  }
  if (used != text.size()) throw not_whole();
  limits::Require(limits::kSamples, v, "", "--samples");
  if (v != std::floor(v)) throw not_whole();
  return static_cast<int64_t>(v);
}

// One line for the re-checks and one per joint-range variant (or why it did not run).
void PrintFollowUps(const stability::StudySummary& s) {
  if (s.recheck && s.recheck->enabled)
    std::cout << "  re-checked " << s.recheck->rechecked << " landing(s) near the boundary with the reference model "
              << "(rtol " << s.recheck->rtol << ", tip-over angle " << s.recheck->tip_angle_deg << " deg, margin "
              << s.recheck->margin_deg << " deg): " << s.recheck->outcome_changed << " changed outcome"
              << (s.recheck->reference_failed > 0
                      ? ", " + std::to_string(s.recheck->reference_failed) + " failed (fast result kept)"
                      : std::string())
              << "\n";
  if (!s.joint_range) return;
  const stability::JointRangeReport& j = *s.joint_range;
  if (!j.ran) {
    std::cout << "  joint-range sensitivity not run: " << j.reason << "\n";
    return;
  }
  for (const stability::JointRangeVariant& v : j.variants) {
    std::cout << "  joint range x" << v.factor << " (half angle " << v.half_angle_deg << " deg), " << v.landings
              << " landings: ";
    if (v.landings == 0)
      std::cout << "none completed\n";
    else
      std::cout << "P(tip-over) = " << v.probability << ", 95 % interval [" << v.interval.low << ", "
                << v.interval.high << "], " << v.differs_from_study << " differ from x1\n";
  }
  if (j.screen_margin_deg && j.screened_in < j.samples)
    std::cout << "  joint-range screen: " << j.screened_in << " of the " << j.samples
              << " landings ran at x0.5 and x1.5; the other " << j.samples - j.screened_in
              << " stood, settled, more than " << *j.screen_margin_deg << " deg below the tip-over angle ("
              << j.tip_angle_deg << " deg) and kept the study's outcome\n";
}

// The soil's share of the outcome's variance, and P(tip) across the soil's 95 % range.
void PrintSoilShares(const stability::Study& study, const stability::SoilSplit& split) {
  std::ostringstream shares;
  shares << std::setprecision(3);
  for (const stability::ShareEstimate& e : split.shares)
    if (e.outcome == "tipped_over" || e.outcome == "max_tilt_deg" || e.outcome == "max_pad_penetration_m")
      shares << (shares.tellp() > 0 ? ", " : "") << e.outcome << " " << e.soil_share << " [" << e.soil_share_low << ", "
             << e.soil_share_high << "]";
  std::cout << "  soil uncertainty (" << study.soil_uncertainty->parameters.size()
            << " parameter(s) drawn), the soil's share of the variance: " << shares.str() << std::setprecision(4)
            << "; P(tip-over) across the soil's 95 % range " << split.p_tip_at_soil_ends.first << " to "
            << split.p_tip_at_soil_ends.second << "\n";
}

void PrintSoilPairing(const stability::StudySummary& s) {
  if (!s.soil_pairing) return;
  const stability::SoilPairingReport& p = *s.soil_pairing;
  if (!p.ran) {
    std::cout << "  soil pairing: " << p.reason << "\n";
    return;
  }
  std::cout << "  paired with the soils at their best values (" << p.landings << " landings): P(tip-over) "
            << (p.landings > 0 ? double(p.tipped_best) / double(p.landings) : 0.0) << " ["
            << p.interval_best.low << ", " << p.interval_best.high << "] against "
            << (p.landings > 0 ? double(p.tipped_drawn) / double(p.landings) : 0.0) << " drawn; "
            << p.tipped_only_drawn.size() + p.tipped_only_best.size() << " outcome(s) changed by the soil ("
            << p.tipped_only_drawn.size() << " tipped only with the drawn soil, " << p.tipped_only_best.size()
            << " only at the best values)";
  for (const stability::PairedOutcome& o : p.outcomes)
    if (o.outcome == "tipped_over" || o.outcome == "max_tilt_deg")
      std::cout << "; " << o.outcome << " paired share " << std::setprecision(3) << o.share << std::setprecision(4);
  std::cout << "\n";
}

// The soil's uncertainty: the linear split, and the pairing with the best values.
void PrintSoilSplit(const stability::Study& study, const stability::StudySummary& s) {
  if (!study.soil_uncertainty) return;
  if (!s.soil_split) std::cout << "  soil uncertainty: too few landings to split the variance\n";
  else PrintSoilShares(study, *s.soil_split);
  PrintSoilPairing(s);
}

void PrintStudyResult(const stability::Study& study, const stability::StudySummary& s, const std::string& out) {
  std::cout << "stability " << study.plan.name << ": " << s.landings << " landings"
            << (s.failed > 0 ? " (" + std::to_string(s.failed) + " failed, not counted)" : std::string()) << ", "
            << s.tipped << " tipped over: ";
  if (s.landings == 0)
    std::cout << "no tip-over probability without a finished landing\n";
  else
    std::cout << "P(tip-over) = " << std::setprecision(4) << s.tip_over_probability << ", 95 % interval ["
              << s.interval.low << ", " << s.interval.high << "]\n";
  for (const stability::MetricPercentiles& m : s.metrics)
    if (m.count > 0 && (std::string(m.metric->name) == "max_tilt_deg" ||
                        std::string(m.metric->name) == "max_pad_penetration_m"))
      std::cout << "  " << m.metric->name << ": p50 " << m.p50 << ", p95 " << m.p95 << ", p99 " << m.p99 << ", max "
                << m.max << " " << m.metric->unit << "\n";
  if (s.swung_past_edge_on > 0)
    std::cout << "  " << s.swung_past_edge_on << " of the landings (" << s.tipped_swung_past_edge_on
              << " of the tip-overs) swung a pad past edge-on on its ball joint: these answers depend on the joints' "
                 "range (legs.cone_limit; docs/stability_studies.md, \"The pads' ball joints\")\n";
  if (s.margin_checked > 0)
    std::cout << "  tip-over margin (least distance of the centre of mass inside the support polygon): its sign "
              << (s.margin_disagreements == 0 ? "agrees with the outcome on all " + std::to_string(s.margin_checked)
                                              : "DISAGREES with the outcome on " +
                                                    std::to_string(s.margin_disagreements) + " of " +
                                                    std::to_string(s.margin_checked))
              << " landings\n";
  PrintFollowUps(s);
  PrintSoilSplit(study, s);
  std::cout << "wrote " << out << "/ (summary.json, percentiles.csv" << (study.map ? ", tip_over_map.csv" : "")
            << (study.soil_uncertainty ? ", soil_parameters.csv" : "") << ", plots/)\n";
}

// A study whose every landing failed has no answer (no probability, no percentiles): the solver
// failed, exit 3, naming the first failure. Its outputs are written all the same (summary.json
// says why each number is absent), and a rerun with other limits runs the failed landings again.
void RequireACompletedLanding(const stability::Study& study, const stability::StudySummary& s, const std::string& out) {
  if (s.landings > 0 || s.failed == 0) return;
  throw integ::IntegrationFailure("stability " + study.plan.name + ": all " + std::to_string(s.failed) +
                                  " landings failed, so there is no tip-over probability (first: " + s.first_failure +
                                  "); " + out + "/summary.json records them, and a rerun runs them again");
}
// The estimate of a rare-event method, its design points, then the analysis of its first level.
void PrintRareEventResult(const stability::Study& study, const stability::RareEventStudyResult& r) {
  const stability::RareEventEstimate& e = r.estimate;
  std::cout << "stability " << study.plan.name << " (" << stability::StudyMethodName(r.method) << "): " << r.landings
            << " landings spent"
            << (r.failed > 0 ? " (" + std::to_string(r.failed) + " failed, counted as not tipped over)" : std::string())
            << ": P(tip-over) = " << std::setprecision(4) << e.probability << ", 95 % interval [" << e.interval.low
            << ", " << e.interval.high << "], coefficient of variation " << e.cov << "\n";
  if (r.subset && !r.subset->reached_failure)
    std::cout << "  the subset levels did not reach the tip-over boundary within " << r.subset->levels.size()
              << " levels: the estimate is a bound, not a value\n";
  for (const stability::RareEventDesignPoint& p : r.design_points) {
    std::cout << "  design point " << p.drop_id << " (beta " << p.beta << "):";
    const nlohmann::json conditions = stability::StudyVariablesJson(study, p.u);
    for (const auto& [key, value] : conditions.items())
      std::cout << " " << key << " " << (value.is_number() ? io::FormatNumber(value.get<double>()) : value.dump());
    std::cout << "\n";
  }
  if (r.margin_disagreements > 0)
    std::cout << "  " << r.margin_disagreements << " landing(s) whose tip-over margin disagrees with the outcome\n";
  std::cout << "  the first level, " << r.samples << " plain Monte Carlo landings of the study's distribution:\n";
}

// A rare-event run's OUT, and a shard's own OUT/shard_I_of_N (rare_event_shards.h): every shard of
// the run is given the same OUT.
void OpenRareEventOutput(const StabilityArgs& args, const sweep::Shard& shard) {
  OpenSweepOutput({args.out, {args.study, args.run.model}}, shard.count > 1 || sweep::LaunchedByMpirun());
  if (shard.count == 1) return;
  stability::RequireOneShardSplit(args.out, shard);
  io::OpenOutputDirectory(stability::RareEventShardDir(args.out, shard), io::OutputKind::kSweep);
}

// `--method subset|importance`: the estimator's landings into OUT/<method>/, then the analysis
// of its first level with the estimate in summary.json.
void RunRareEventCommand(const StabilityArgs& args, const stability::Study& study, stability::StudyMethod method,
                         int64_t samples, const sweep::SweepRunOptions& options) {
  // Under mpirun every rank runs the estimator (the landings are shared out); rank 0 reports and writes.
  const int rank = sweep::RankFromMpirun();
  const bool quiet = options.progress == sweep::ProgressMode::kNone || rank != 0;
  const stability::RareEventStudyResult r =
      stability::RunRareEventStudy(study, method, samples, args.out, options, quiet ? nullptr : &std::cerr);
  if (rank != 0) {
    if (r.stop_signal != 0) std::exit(128 + r.stop_signal);
    return;
  }
  if (r.stop_signal != 0) {
    std::cout << "stability " << study.plan.name << ": stopped by signal " << r.stop_signal
              << " after committing the landings in flight; run the same command again to resume\n";
    std::exit(128 + r.stop_signal);
  }
  if (options.shard.count > 1 && options.shard.index != 0) {
    std::cout << "stability " << study.plan.name << " (" << stability::StudyMethodName(r.method) << "): shard "
              << options.shard.Text() << " done, " << r.computed << " landings run now, " << r.already_done
              << " already done, P(tip-over) = " << std::setprecision(4) << r.estimate.probability << "; shard 0/"
              << options.shard.count << " writes " << args.out << "/summary.json\n";
    return;
  }
  const stability::StudySummary summary = stability::WriteRareEventAnalysis(study, r, args.out);
  stability::Study first = study;
  first.plan = r.first_level_plan;
  std::cout << "stability " << study.plan.name << ": " << r.computed << " landings run now, " << r.already_done
            << " already done\n";
  PrintRareEventResult(study, r);
  PrintStudyResult(first, summary, args.out);
}
}  // namespace

void AddStabilityCommand(CLI::App& app) {
  auto args = std::make_shared<StabilityArgs>();
  CLI::App* cmd = app.add_subcommand(
      "stability", "Landing-stability study: run (or resume) its lander sweep, then tip-over probability, "
                   "percentiles, worst cases, tables and plots");
  cmd->add_option("study", args->study, "study (type: stability): a YAML file, or a bundled one by name (lunar_paper_lander)")
      ->required();
  cmd->add_option("--out", args->out, "output directory (results.sqlite, summary.json, *.csv, plots/); a rerun resumes")
      ->required()
      ->check(NonEmptyPath());
  CLI::Option* samples = cmd->add_option(
      "--samples", args->samples,
      "random samples instead of the study's, 1 to 1e9 (a quick look; recorded in summary.json)");
  cmd->add_option("--method", args->method,
                  "tip-over probability estimator: monte_carlo (the study's landings, default), subset (subset "
                  "simulation on the tip-over margin), importance (sampling around the subset run's design point); "
                  "with subset or importance, --samples is the landings per level / of the importance sample "
                  "(default 1000, a multiple of 10), and the shards of a job array (--shard I/N) all take the "
                  "same --out: each runs its share of every batch into OUT/shard_I_of_N/ and waits for the "
                  "others' after it; shard 0 writes the outputs");
  AddSweepRunFlags(cmd, &args->run, "landings");
  cmd->callback([args, samples] {
    const stability::StudyMethod method = stability::ParseStudyMethod(args->method);
    args->study = ResolveCommandInput("stability", args->study);
    const std::optional<int64_t> given_samples =
        samples->count() > 0 ? std::optional<int64_t>(ParseSamples(args->samples)) : std::nullopt;
    const bool rare_event = method != stability::StudyMethod::kMonteCarlo;
    const std::optional<int64_t> override_samples = rare_event ? std::nullopt : given_samples;
    stability::Study study = stability::LoadStudy(args->study, args->run.model, override_samples);
    ApplyDropLimits(args->run, &study.plan);
    sweep::SweepRunOptions options = RunOptionsFrom(args->run);
    if (rare_event) {
      const int64_t per_level = given_samples.value_or(stability::kDefaultRareEventSamples);
      stability::RequireRareEventStudy(study, method, per_level);
      OpenRareEventOutput(*args, options.shard);
      const sweep::StopOnSignals stop_on_signals;
      options.stop = &sweep::StopOnSignals::flag();
      RunRareEventCommand(*args, study, method, per_level, options);
      return;
    }
    OpenSweepOutput({args->out, {args->study, args->run.model}}, sweep::LaunchedByMpirun());
    const sweep::StopOnSignals stop_on_signals;
    options.stop = &sweep::StopOnSignals::flag();
    int rank = 0;
    const sweep::SweepRunSummary run = sweep::LaunchedByMpirun()
                                           ? sweep::RunSweepMpi(study.plan, args->out, options, &rank)
                                           : sweep::RunSweep(study.plan, args->out, options);
    if (run.stop_signal != 0) {
      if (rank == 0)
        std::cout << "stability " << study.plan.name << ": stopped by signal " << run.stop_signal
                  << " after committing the landings in flight; run the same command again to resume\n";
      std::exit(128 + run.stop_signal);
    }
    if (rank != 0) return;
    const auto print_run = [&] {
      std::cout << "stability " << study.plan.name << ": " << run.computed << " landings run now, "
                << run.already_done << " already done, in " << std::fixed << std::setprecision(2) << run.seconds
                << " s on " << run.ranks << " rank(s) x " << run.threads << " thread(s)\n"
                << std::defaultfloat;
    };
    if (options.shard.count > 1) {
      print_run();
      std::cout << "shard " << options.shard.Text() << " done; `touchdown merge` the shards' directories, then run "
                << "`touchdown stability` on the merged one for the follow-ups and the analysis\nwrote "
                << sweep::ResultsDbPath(args->out) << "\n";
      return;
    }
    // The follow-ups on this process alone (rank 0 under MPI), with its threads: they are few.
    // What each one runs is said beside the progress (stderr).
    const stability::StudyFollowUps follow_ups =
        stability::RunStudyFollowUps(study, stability::ReadStudyRecords(study, args->out), args->out, options,
                                     options.progress == sweep::ProgressMode::kNone ? nullptr : &std::cerr);
    if (follow_ups.stop_signal != 0) {
      std::cout << "stability " << study.plan.name << ": stopped by signal " << follow_ups.stop_signal
                << " during its follow-ups, after committing the landings in flight; run the same command again to "
                   "resume\n";
      std::exit(128 + follow_ups.stop_signal);
    }
    const stability::StudySummary summary = stability::WriteStudyAnalysis(study, args->out, follow_ups);
    RequireACompletedLanding(study, summary, args->out);
    print_run();
    if (follow_ups.computed + follow_ups.already_done > 0)
      std::cout << "stability " << study.plan.name << ": follow-ups " << follow_ups.computed << " landings run now, "
                << follow_ups.already_done << " already done\n";
    PrintStudyResult(study, summary, args->out);
  });
}

}  // namespace touchdown::app
