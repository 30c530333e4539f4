#pragma once
// A sweep file's keys, block by block, in the order WriteSweepPlan writes them (private to
// sweep_plan_file.cpp, whose loader accepts exactly these, and sweep_file_keys.cpp, which writes them;
// drop_tests/formats/key_table.h). A key with no writer is one only a person writes, or a block
// the sweep itself does not read (a study's `study`, `touchdown trade`'s `trade`). The parameters
// under fixed, grid and random are keyed by SweepParamKey, not listed here.
#include "drop_tests/formats/key_table.h"
#include "drop_tests/sweep/sweep_plan.h"

namespace touchdown::sweep::file_keys {

// One random parameter's draw: exactly one of uniform, choice and per_pad_choice.
struct RandomToWrite {
  const SweepPlan& plan;
  const SweepRandom& r;
};

// The plan's numbers read on their own (each with its further check in the loader).
inline constexpr io::NumberKey kRestDurationKey{"rest_duration_s", io::Sign::kNonNegative, nullptr, nullptr, 0.0};
inline constexpr io::NumberKey kMaxDropWallTimeKey{"max_drop_wall_time_s", io::Sign::kNonNegative, nullptr,
                                                   "0 (no limit)"};
inline constexpr io::NumberKey kPadPatchHalfWidthKey{"pad_patch_half_width_m", io::Sign::kPositive, nullptr,
                                                     "the scenario's `under_pad` patches', else 0.08"};

const io::KeyTable<SweepPlan>& SweepKeys();                // the top level
const io::KeyTable<SweepPlan>& LanderBlockKeys();          // `lander`
const io::KeyTable<SweepPlan>& SimulationBlockKeys();      // `simulation`
const io::KeyTable<RandomToWrite>& RandomSpecKeys();       // one parameter's draw under `random`

}  // namespace touchdown::sweep::file_keys
