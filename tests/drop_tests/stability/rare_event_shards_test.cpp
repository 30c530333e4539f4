// A rare-event run split into shards (`--shard I/N` with `--method subset`): two shards running
// side by side in one DIR meet after every batch and end with the single process's estimate, bit
// for bit, and its whole database in DIR/subset/; a shard stopped while it waits for the other
// resumes; a DIR holding a shard of another split, or another plan's batch, is refused.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "drop_tests/stability/rare_event_shards.h"
#include "drop_tests/stability/study.h"
#include "drop_tests/stability/study_rare_event.h"
#include "drop_tests/sweep/sweep.h"
#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::stability {
namespace {

// The tiny subset study of study_rare_event_test.cpp: 10 landings a level on the coarse lander,
// slopes up to 20 deg with up to 1.5 m/s downhill (two levels, about 30 landings).
const std::string kShardedStudy =
    "schema_version: 1\ntype: stability\nname: rare\nlander: {scenario: " + std::string(TOUCHDOWN_SOURCE_DIR) +
    "/data/studies/lab_coarse_lander_scenario.yaml}\nfixed: {downhill_azimuth_deg: -90, yaw_relative_to_slope_deg: "
    "90, horizontal_azimuth_deg: -90}\nrandom: {samples: 10, seed: 5, slope_deg: {uniform: [0, 20]},\n"
    "         horizontal_speed_m_s: {uniform: [0, 1.5]}}\n";

sweep::SweepRunOptions ShardOptions(int index, int count, const std::atomic<int>* stop = nullptr) {
  sweep::SweepRunOptions options;
  options.progress = sweep::ProgressMode::kNone;
  options.threads = 1;
  options.shard = {index, count};
  options.stop = stop;
  return options;
}

struct RareEventShards : testing_scratch::ScratchDirTest {
  // Both shards of two at once, each on its own thread, into `dir`.
  std::pair<RareEventStudyResult, RareEventStudyResult> RunTwoShards(const Study& study, const std::string& dir) {
    RareEventStudyResult r0, r1;
    std::thread other([&] { r1 = RunRareEventStudy(study, StudyMethod::kSubset, 10, dir, ShardOptions(1, 2)); });
    r0 = RunRareEventStudy(study, StudyMethod::kSubset, 10, dir, ShardOptions(0, 2));
    other.join();
    return {r0, r1};
  }
  static std::vector<sweep::DropRecord> Stored(const std::string& dir) {
    return sweep::ResultsDb(sweep::ResultsDbPath(dir), sweep::ResultsDb::Access::kReadOnly).ReadAll(false);
  }
};

void ExpectSameRun(const Study& study, const RareEventStudyResult& a, const RareEventStudyResult& b) {
  EXPECT_EQ(a.stop_signal, 0);
  EXPECT_EQ(a.landings, b.landings);
  EXPECT_EQ(a.failed, b.failed);
  EXPECT_EQ(std::memcmp(&a.estimate.probability, &b.estimate.probability, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(&a.estimate.cov, &b.estimate.cov, sizeof(double)), 0);
  EXPECT_EQ(RareEventJson(study, a).dump(), RareEventJson(study, b).dump());
  ASSERT_EQ(a.first_level.size(), b.first_level.size());
  for (size_t k = 0; k < a.first_level.size(); ++k)
    EXPECT_TRUE(sweep::SameRecord(a.first_level[k], b.first_level[k], false)) << k;
}

TEST_F(RareEventShards, TwoShardsSideBySideEqualTheSingleProcessAndStoreItsWholeRun) {
  const Study study = LoadStudy(Write("study.yaml", kShardedStudy));
  sweep::SweepRunOptions single = ShardOptions(0, 1);
  single.threads = 2;
  const RareEventStudyResult one = RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("one"), single);
  ASSERT_GT(one.landings, 10);  // the chains ran: batches after the first level
  const auto [r0, r1] = RunTwoShards(study, Path("sharded"));
  ExpectSameRun(study, r0, one);
  ExpectSameRun(study, r1, one);
  EXPECT_EQ(r0.computed + r1.computed, one.landings);  // each landing ran once, on its shard
  EXPECT_EQ(r0.computed, (one.landings + 1) / 2);  // shard 0's are landings 0, 2, 4, ...
  // Shard 0 stored the whole run as one process does; each shard's database holds its share.
  const std::vector<sweep::DropRecord> whole = Stored(Path("sharded") + "/subset"), single_db = Stored(Path("one") + "/subset");
  ASSERT_EQ(whole.size(), single_db.size());
  for (size_t k = 0; k < whole.size(); ++k) EXPECT_TRUE(sweep::SameRecord(whole[k], single_db[k])) << k;
  for (const sweep::DropRecord& r : Stored(Path("sharded") + "/shard_1_of_2/subset")) EXPECT_EQ(r.index % 2, 1);
  // A rerun of a shard finds its landings and the other's batches, and runs nothing.
  const RareEventStudyResult again =
      RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("sharded"), ShardOptions(1, 2));
  ExpectSameRun(study, again, one);
  EXPECT_EQ(again.computed, 0);
  // So does the single process in the shards' DIR: the whole run is in DIR/subset/.
  const RareEventStudyResult resumed = RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("sharded"), single);
  ExpectSameRun(study, resumed, one);
  EXPECT_EQ(resumed.computed, 0);
}

// Shard 0 alone runs its share of the first batch, then waits for shard 1; stopped there (as
// SIGTERM stops it), it keeps its landings, and the two shards run again end as one process.
TEST_F(RareEventShards, AShardStoppedWhileItWaitsResumes) {
  const Study study = LoadStudy(Write("study.yaml", kShardedStudy));
  std::atomic<int> stop{0};
  RareEventStudyResult stopped;
  std::thread shard0([&] {
    stopped = RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("dir"), ShardOptions(0, 2, &stop));
  });
  const std::filesystem::path published = Path("dir") + "/shard_0_of_2/subset/batches/0.records";
  for (int k = 0; k < 600 && !std::filesystem::exists(published); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_TRUE(std::filesystem::exists(published));
  stop = 15;
  shard0.join();
  EXPECT_EQ(stopped.stop_signal, 15);
  EXPECT_EQ(stopped.computed, 5);  // its share of the first level's 10
  EXPECT_TRUE(Stored(Path("dir") + "/subset").empty());  // no whole run stored
  const auto [r0, r1] = RunTwoShards(study, Path("dir"));
  EXPECT_EQ(r0.already_done, 5);
  sweep::SweepRunOptions single = ShardOptions(0, 1);
  single.threads = 2;
  const RareEventStudyResult one = RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("one"), single);
  ExpectSameRun(study, r0, one);
  ExpectSameRun(study, r1, one);
}

TEST_F(RareEventShards, AShardOfAnotherSplitInDirIsRefusedNamingTheFlag) {
  std::filesystem::create_directories(Path("dir") + "/shard_2_of_3");
  EXPECT_NO_THROW(RequireOneShardSplit(Path("dir"), {2, 3}));
  try {
    RequireOneShardSplit(Path("dir"), {0, 2});
    FAIL() << "accepted a shard of three beside one of two";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("--shard"), std::string::npos) << what;
    EXPECT_NE(what.find("shard_2_of_3"), std::string::npos) << what;
    EXPECT_NE(what.find("--shard I/3"), std::string::npos) << what;
  }
}

// The other shard's file of the first batch holds another plan's landings: refused once this
// shard has run its share, naming the file.
TEST_F(RareEventShards, AnotherPlansBatchIsRefusedNamingTheFile) {
  const Study study = LoadStudy(Write("study.yaml", kShardedStudy));
  const std::string other = Path("dir") + "/shard_1_of_2/subset/batches/0.records";
  std::filesystem::create_directories(std::filesystem::path(other).parent_path());
  std::ofstream(other) << "touchdown rare-event shard batch\nformat_version " << sweep::kResultsDbVersion
                       << "\nplan_digest 0123456789abcdef\n";
  try {
    RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("dir"), ShardOptions(0, 2));
    FAIL() << "accepted another plan's batch";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(other), std::string::npos) << what;
    EXPECT_NE(what.find("another study or variant"), std::string::npos) << what;
  }
}

// DIR/subset/ holds a single run of another study: shard 0, which stores the whole run there at the
// end, refuses it before running any landing.
TEST_F(RareEventShards, Shard0RefusesADirHoldingAnotherRunBeforeRunningALanding) {
  const Study study = LoadStudy(Write("study.yaml", kShardedStudy));
  sweep::SweepPlan other = RareEventPlan(study, StudyMethod::kSubset, 20, 0, {});  // 20 a level: another variant
  sweep::OpenSweepStore(other, Path("dir") + "/subset", sweep::Shard{});
  EXPECT_THROW(RunRareEventStudy(study, StudyMethod::kSubset, 10, Path("dir"), ShardOptions(0, 2)), InputError);
  EXPECT_FALSE(std::filesystem::exists(Path("dir") + "/shard_0_of_2/subset/results.sqlite"));
}

}  // namespace
}  // namespace touchdown::stability
