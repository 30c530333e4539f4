#pragma once
// The options every command that runs a sweep shares (`sweep`, `stability`): threads, shard,
// model, progress, batch size and the per-drop work limits. One place registers them, checks them
// and turns them into the engine's run options, so the two commands cannot drift apart.
#include <CLI/CLI.hpp>

#include <string>

#include "drop_tests/formats/output_path.h"
#include "drop_tests/sweep/sweep.h"
#include "drop_tests/sweep/sweep_plan.h"

namespace touchdown::app {

struct SweepRunFlags {
  std::string shard, model, progress = "auto";
  int threads = 0;
  int batch = 512;
  double max_drop_wall_time_s = 0.0;  // only when given; else the plan's (default: none)
  double max_drop_evaluations = 0.0;  // only when given; else the plan's
  CLI::Option* max_wall = nullptr;
  CLI::Option* max_evaluations = nullptr;
};

// `runs` names what one index of the sweep is ("drops", "landings") in the help text.
void AddSweepRunFlags(CLI::App* cmd, SweepRunFlags* flags, const std::string& runs);

// The work limits given on the command line, checked (InputError naming the flag) and written
// into the plan; call before opening the output directory.
void ApplyDropLimits(const SweepRunFlags& flags, sweep::SweepPlan* plan);

sweep::SweepRunOptions RunOptionsFrom(const SweepRunFlags& flags);

// Opens a sweep's output directory (io::OpenOutputDirectory) for processes that start together, the
// ranks under mpirun and the shards of a job array (`together`): one may find it just created by
// another, its marker not yet in place (a directory not touchdown's, refused); a moment later it is,
// so such a refusal is tried once more after half a second. Alone, a refusal stands.
void OpenSweepOutput(const io::OutputTarget& target, bool together);

}  // namespace touchdown::app
