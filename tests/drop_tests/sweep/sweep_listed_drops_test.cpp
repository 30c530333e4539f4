// A sweep run over a list of its drops (SweepRunOptions::indices, what a stability study's
// follow-ups use): only those run, each once, with the records a whole run gives them; a rerun
// resumes; a shard takes its share of the list; and a plan's `variant` changes its digest, so a
// derived plan's database is never mixed up with the original's.
#include <gtest/gtest.h>

#include <filesystem>

#include "drop_tests/sweep/sweep.h"
#include "rft/input_error.h"
#include "tests/drop_tests/sweep/sweep_test_support.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::sweep {
namespace {
using testing_sweep::Quiet;
using testing_sweep::Records;

// 4 speeds x 3 samples = 12 quick rig drops.
const char* kListedSweep = R"(schema_version: 1
type: sweep
name: listed
traces: none
fixed: {soil: fjs1_lp, pad: flat}
grid: {impact_speed_m_s: {from: 0.5, to: 2.0, count: 4}}
random: {samples: 3, seed: 4, pad_mass_kg: {uniform: [1.0, 2.5]}}
)";

std::vector<int64_t> StoredIndices(const std::filesystem::path& dir) {
  std::vector<int64_t> out;
  for (const DropRecord& r : Records(dir)) out.push_back(r.index);
  return out;
}

struct ListedDrops : testing_scratch::ScratchDirTest {};

TEST_F(ListedDrops, OnlyTheListedDropsRunWithTheRecordsOfAWholeRunAndARerunResumes) {
  const SweepPlan plan = LoadSweepPlan(Write("s.yaml", kListedSweep));
  SweepRunOptions options = Quiet(2);
  options.indices = std::vector<int64_t>{9, 2, 7, 2};  // any order, repeats once
  SweepRunSummary run = RunSweep(plan, Path("listed"), options);
  EXPECT_EQ(run.total, 12);
  EXPECT_EQ(run.in_shard, 3);
  EXPECT_EQ(run.already_done, 0);
  EXPECT_EQ(run.computed, 3);
  EXPECT_EQ(StoredIndices(Path("listed")), (std::vector<int64_t>{2, 7, 9}));
  const std::vector<DropRecord> whole = RunSweepInMemory(plan, 2);
  for (const DropRecord& r : Records(Path("listed"))) EXPECT_TRUE(SameRecord(r, whole.at(r.index))) << r.drop_id;

  options.indices = std::vector<int64_t>{2, 7, 9, 10};  // three stored, one new
  run = RunSweep(plan, Path("listed"), options);
  EXPECT_EQ(run.in_shard, 4);
  EXPECT_EQ(run.already_done, 3);
  EXPECT_EQ(run.computed, 1);
  EXPECT_EQ(StoredIndices(Path("listed")), (std::vector<int64_t>{2, 7, 9, 10}));

  options.indices = std::vector<int64_t>{12};  // outside the plan: the caller's bug
  EXPECT_THROW(RunSweep(plan, Path("listed"), options), std::invalid_argument);
}

TEST_F(ListedDrops, AShardTakesItsShareOfTheList) {
  const SweepPlan plan = LoadSweepPlan(Write("s.yaml", kListedSweep));
  SweepRunOptions options = Quiet(1);
  options.indices = std::vector<int64_t>{0, 1, 3, 4, 5, 8, 10, 11};
  options.shard = {1, 3};  // i mod 3 == 1
  const SweepRunSummary run = RunSweep(plan, Path("shard1"), options);
  EXPECT_EQ(run.in_shard, 3);
  EXPECT_EQ(run.computed, 3);
  EXPECT_EQ(StoredIndices(Path("shard1")), (std::vector<int64_t>{1, 4, 10}));
}

TEST_F(ListedDrops, TheVariantIsPartOfTheDigestAndAbsentFromALoadedPlans) {
  const SweepPlan plan = LoadSweepPlan(Write("s.yaml", kListedSweep));
  EXPECT_EQ(plan.DigestText().find("variant"), std::string::npos);  // databases written before stay valid
  SweepPlan derived = plan;
  derived.variant = "recheck: reference model, rtol 1e-08";
  EXPECT_NE(PlanDigest(derived), PlanDigest(plan));
  SweepPlan other = plan;
  other.variant = "joint range: every cone half angle x0.5";
  EXPECT_NE(PlanDigest(other), PlanDigest(derived));
  // The original's database refuses the derived plan.
  SweepRunOptions options = Quiet(1);
  options.indices = std::vector<int64_t>{0};
  RunSweep(plan, Path("original"), options);
  EXPECT_THROW(RunSweep(derived, Path("original"), options), InputError);
}

}  // namespace
}  // namespace touchdown::sweep
