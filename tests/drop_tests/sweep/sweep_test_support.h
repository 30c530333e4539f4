#pragma once
// What the sweep tests that run whole sweeps share: a sweep long enough to stop mid-way, quiet
// run options, and the stored drops of an output directory compared record by record.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "drop_tests/sweep/results_db.h"
#include "drop_tests/sweep/sweep.h"

namespace touchdown::sweep::testing_sweep {

// 3 pads x 20 speeds x 20 samples = 1200 quick drops, summaries only: long enough to be stopped
// or killed mid-way.
inline constexpr const char* kQuickSweep = R"(schema_version: 1
type: sweep
name: quick
traces: none
grid:
  pad: [flat, c4, curved]
  impact_speed_m_s: {from: 0.3, to: 2.0, count: 20}
random: {samples: 20, seed: 5, soil: {choice: [fjs1_lp, fjs1_cp]}, pad_mass_kg: {uniform: [1.2, 2.0]}}
)";

inline std::vector<DropRecord> Records(const std::filesystem::path& out_dir) {
  return ResultsDb(ResultsDbPath(out_dir.string())).ReadAll(/*with_traces=*/true);
}

inline void ExpectSameRecords(const std::vector<DropRecord>& a, const std::vector<DropRecord>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(SameRecord(a[i], b[i])) << "drop " << a[i].drop_id;
}

inline SweepRunOptions Quiet(int threads) {
  SweepRunOptions o;
  o.threads = threads;
  o.progress = ProgressMode::kNone;
  return o;
}

}  // namespace touchdown::sweep::testing_sweep
