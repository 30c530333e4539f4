#include "apps/sweep_run_flags.h"
#include "apps/option_checks.h"

#include <chrono>
#include <cmath>
#include <thread>

#include "rft/input_error.h"
#include "rft/physical_limits.h"

namespace touchdown::app {

void AddSweepRunFlags(CLI::App* cmd, SweepRunFlags* flags, const std::string& runs) {
  cmd->add_option("--threads", flags->threads, "worker threads per process (default: every core)")
      ->check(NumberIn(0, limits::kMaxThreads));
  cmd->add_option("--shard", flags->shard,
                  "I/N: run only " + runs + " with index mod N == I (job arrays; combine the shards with merge)");
  cmd->add_option("--model", flags->model, "model file (MODEL.yaml) with per-soil zeta overrides");
  cmd->add_option("--progress", flags->progress, "auto (bar on a terminal, else lines), bar, lines or none")
      ->check(CLI::IsMember({"auto", "bar", "lines", "none"}));
  cmd->add_option("--batch", flags->batch, runs + " per database transaction (default 512)")
      ->check(NumberIn(1, 1000000));  // a bounded range: CLI::PositiveNumber prints DBL_MAX as its range
  flags->max_evaluations = cmd->add_option(
      "--max-drop-evaluations", flags->max_drop_evaluations,
      "work limit per run: right-hand-side evaluations of its integrator, 0 = none (default: the file's "
      "max_drop_evaluations, else " + std::to_string(sweep::kDefaultMaxDropEvaluations) +
          "); deterministic; a run over it is recorded as failed, and retried by a rerun with a higher limit");
  flags->max_wall = cmd->add_option("--max-drop-wall-time", flags->max_drop_wall_time_s,
                                    "opt-in wall-clock limit per run in seconds, 0 = none (default: the file's "
                                    "max_drop_wall_time_s, else none); which runs fail on it depends on machine load");
}

void ApplyDropLimits(const SweepRunFlags& flags, sweep::SweepPlan* plan) {
  if (flags.max_wall->count() > 0) {
    if (!(std::isfinite(flags.max_drop_wall_time_s) && flags.max_drop_wall_time_s >= 0.0))
      throw InputError("--max-drop-wall-time: must be a finite number of seconds >= 0 (0: no limit), got " +
                       flags.max_wall->as<std::string>());
    plan->rig.integrator.max_wall_time_s = flags.max_drop_wall_time_s;
  }
  if (flags.max_evaluations->count() > 0) {
    const double n = flags.max_drop_evaluations;
    if (!(n >= 0.0 && n <= 1e15 && n == std::floor(n)))
      throw InputError("--max-drop-evaluations: must be a whole number between 0 (no limit) and 1e15, got " +
                       flags.max_evaluations->as<std::string>());
    plan->rig.integrator.max_rhs_evaluations = static_cast<long>(n);
  }
}

sweep::SweepRunOptions RunOptionsFrom(const SweepRunFlags& flags) {
  sweep::SweepRunOptions options;
  options.threads = flags.threads;
  if (!flags.shard.empty()) options.shard = sweep::ParseShard(flags.shard);
  options.batch_size = static_cast<size_t>(flags.batch);
  options.progress = flags.progress == "bar"     ? sweep::ProgressMode::kBar
                     : flags.progress == "lines" ? sweep::ProgressMode::kLines
                     : flags.progress == "none"  ? sweep::ProgressMode::kNone
                                                 : sweep::ProgressMode::kAuto;
  return options;
}

void OpenSweepOutput(const io::OutputTarget& target, bool together) {
  if (!together) {
    io::OpenOutputDirectory(target, io::OutputKind::kSweep);
    return;
  }
  try {
    io::OpenOutputDirectory(target, io::OutputKind::kSweep);
  } catch (const InputError&) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    io::OpenOutputDirectory(target, io::OutputKind::kSweep);
  }
}

}  // namespace touchdown::app
