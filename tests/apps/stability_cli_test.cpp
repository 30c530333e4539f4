// `touchdown stability` as a user runs it: a quick look with --samples (recorded), a second run
// that resumes and writes the same summary.json, `touchdown sweep` on the study file running the
// same landings bit for bit, and bad study files refused with exit status 2 and one line naming
// the file and the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sqlite3.h>
#include <sstream>
#include <sys/wait.h>

#include "tests/scratch_dir_test.h"
#include "tests/touchdown_process.h"

namespace {

struct StabilityRun {
  int status = -1;
  std::string out, err;
};

// Level ground, symmetric touchdowns at random speeds and gravities: cheap landings that never tip.
std::string LevelStudy(int samples) {
  return "schema_version: 1\ntype: stability\nname: level_quick\nlander: {scenario: lander_case_A}\n"
         "random: {samples: " + std::to_string(samples) + ", seed: 3, impact_speed_m_s: {uniform: [0.6, 1.0]},\n"
         "         gravity_m_s2: {uniform: [1.62, 9.81]}}\n"
         "study: {map: {x: impact_speed_m_s, y: gravity_m_s2, bins: [2, 2]}}\n";
}

class StabilityCli : public touchdown::testing_scratch::ScratchDirTest {
 protected:
  StabilityRun Run(const std::vector<std::string>& args) {
    const std::string out = Path("stdout"), err = Path("stderr");
    const pid_t pid = touchdown::testing_process::StartTouchdown(args, "", out, err);
    const int raw = touchdown::testing_process::WaitForStatus(pid);
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, Slurp(out), Slurp(err)};
  }
  // Every drops row as text, in index order.
  static std::string Rows(const std::string& db_path) {
    sqlite3* db = nullptr;
    sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
    std::string text;
    sqlite3_exec(
        db, "SELECT * FROM drops ORDER BY drop_index",
        [](void* out, int n, char** values, char**) {
          for (int i = 0; i < n; ++i) *static_cast<std::string*>(out) += std::string(values[i] ? values[i] : "NULL") + "|";
          *static_cast<std::string*>(out) += "\n";
          return 0;
        },
        &text, nullptr);
    sqlite3_close(db);
    return text;
  }
  // study.yaml: ten random landings of the coarse lander across a slope (the rare-event tests' study).
  std::string WriteRareStudy();
};

TEST_F(StabilityCli, SamplesOverrideIsRecordedAndARerunResumesToTheSameSummary) {
  const std::string study = Write("level.yaml", LevelStudy(50));
  const std::string out = Path("out");
  const StabilityRun first = Run({"stability", study, "--out", out, "--samples", "3", "--threads", "2",
                                  "--progress", "none"});
  ASSERT_EQ(first.status, 0) << first.err;
  const std::filesystem::path dir = out;
  const nlohmann::json j = nlohmann::json::parse(Slurp(dir / "summary.json"));
  EXPECT_EQ(j["landings"], 3);
  EXPECT_EQ(j["samples"], 3);
  EXPECT_EQ(j["samples_in_study_file"], 50);
  EXPECT_EQ(j["samples_overridden"], true);
  EXPECT_EQ(j["tip_over_probability"].get<double>(), 0.0);
  EXPECT_NEAR(j["tip_over_probability_interval_95"][1].get<double>(), 1.0 - std::pow(0.025, 1.0 / 3.0), 1e-12);
  for (const char* file : {"results.sqlite", "percentiles.csv", "tip_over_map.csv", "plots/tip_over_map.png",
                           "plots/tip_over_map.svg", "plots/exceedance.png", "plots/exceedance.svg",
                           "plots/histograms.png", "plots/histograms.svg"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / file)) << file;
  // The rerun finds every landing done and writes the same summary, byte for byte.
  const std::string summary = Slurp(dir / "summary.json");
  const StabilityRun second = Run({"stability", study, "--out", out, "--samples", "3", "--progress", "none"});
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_NE(second.out.find("0 landings run now, 3 already done"), std::string::npos) << second.out;
  EXPECT_EQ(Slurp(dir / "summary.json"), summary);
  // Without --samples it is another study: refused in that directory, naming the database.
  const StabilityRun other = Run({"stability", study, "--out", out, "--progress", "none"});
  EXPECT_EQ(other.status, 2);
  EXPECT_NE(other.err.find("plan_digest"), std::string::npos) << other.err;
}

TEST_F(StabilityCli, SweepOnTheStudyFileRunsTheSameLandings) {
  const std::string study = Write("level.yaml", LevelStudy(2));
  ASSERT_EQ(Run({"stability", study, "--out", Path("study"), "--threads", "1", "--progress", "none"}).status, 0);
  const StabilityRun sweep = Run({"sweep", study, "--out", Path("sweep"), "--threads", "2", "--progress", "none"});
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const std::string rows = Rows(Path("study") + "/results.sqlite");
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 2);
  EXPECT_EQ(Rows(Path("sweep") + "/results.sqlite"), rows);
  // ... and `stability` on the sweep's directory only analyses them.
  const StabilityRun analyse = Run({"stability", study, "--out", Path("sweep"), "--progress", "none"});
  ASSERT_EQ(analyse.status, 0) << analyse.err;
  EXPECT_NE(analyse.out.find("0 landings run now, 2 already done"), std::string::npos) << analyse.out;
}

// A random patch field drawn per landing (data/studies/lunar_patchy_ground.yaml): the landings get
// different grounds, and the same ones whatever the number of threads.
TEST_F(StabilityCli, PatchFieldsPerLandingAreTheSameOnOneThreadAndOnTwo) {
  // The shipped study without its joint-range sensitivity (its pads reach their stops: the
  // follow-ups would run each landing twice more; FollowUps* below tests them).
  const std::string dir = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/studies/";
  std::string text = Slurp(dir + "lunar_patchy_ground.yaml");
  const std::string scenario = "scenario: lunar_patchy_ground_scenario.yaml", cases = "  max_tip_over_cases: 100\n";
  ASSERT_NE(text.find(scenario), std::string::npos);
  ASSERT_NE(text.find(cases), std::string::npos);
  text.replace(text.find(scenario), scenario.size(), "scenario: " + dir + "lunar_patchy_ground_scenario.yaml");
  text.replace(text.find(cases), cases.size(), cases + "  joint_range_sensitivity: none\n");
  const std::string study = Write("patchy.yaml", text);
  for (const char* threads : {"1", "2"}) {
    const StabilityRun r = Run({"stability", study, "--out", Path(std::string("patchy") + threads), "--samples", "3",
                                "--threads", threads, "--progress", "none"});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const std::string rows = Rows(Path("patchy1") + "/results.sqlite");
  EXPECT_EQ(Rows(Path("patchy2") + "/results.sqlite"), rows);
  EXPECT_NE(rows.find("fjs1_cp"), std::string::npos);  // some pad on the field's closely packed cells
  EXPECT_NE(rows.find("fjs1_lp"), std::string::npos);
}

// Shards run their landings only; merged, the study analyses to the same summary as one run.
TEST_F(StabilityCli, ShardsMergedAnalyseToTheSameSummaryAsOneRun) {
  const std::string study = Write("level.yaml", LevelStudy(3));
  ASSERT_EQ(Run({"stability", study, "--out", Path("whole"), "--threads", "2", "--progress", "none"}).status, 0);
  for (const char* shard : {"0/2", "1/2"}) {
    const StabilityRun r = Run({"stability", study, "--out", Path(std::string("shard") + shard[0]), "--shard", shard,
                                "--threads", "1", "--progress", "none"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("touchdown merge"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(Path(std::string("shard") + shard[0]) + "/summary.json"));
  }
  const StabilityRun merge = Run({"merge", Path("shard0"), Path("shard1"), "--out", Path("merged")});
  ASSERT_EQ(merge.status, 0) << merge.err;
  const StabilityRun analyse = Run({"stability", study, "--out", Path("merged"), "--progress", "none"});
  ASSERT_EQ(analyse.status, 0) << analyse.err;
  EXPECT_NE(analyse.out.find("0 landings run now, 3 already done"), std::string::npos) << analyse.out;
  EXPECT_EQ(Slurp(Path("merged") + "/summary.json"), Slurp(Path("whole") + "/summary.json"));
}

// The per-landing work limit of `sweep` works on a study too: landings over it are recorded as
// failed and left out of the statistics; a rerun with a higher limit runs exactly those again.
TEST_F(StabilityCli, MaxDropEvaluationsFailsLandingsThatARerunWithAHigherLimitRunsAgain) {
  const std::string study = Write("level.yaml", LevelStudy(2));
  const std::string out = Path("limited");
  const StabilityRun limited = Run({"stability", study, "--out", out, "--max-drop-evaluations", "20",
                                    "--threads", "1", "--progress", "none"});
  // Every landing failed: no answer, exit 3 naming the first failure; the outputs are written.
  EXPECT_EQ(limited.status, 3) << limited.err;
  EXPECT_NE(limited.err.find("all 2 landings failed, so there is no tip-over probability (first: "), std::string::npos)
      << limited.err;
  EXPECT_TRUE(limited.out.empty()) << limited.out;
  nlohmann::json j = nlohmann::json::parse(Slurp(std::filesystem::path(out) / "summary.json"));
  EXPECT_EQ(j["landings"], 0);
  EXPECT_EQ(j["landings_failed"], 2);
  // No number is written as null: the probability and the percentiles are absent, with a reason.
  EXPECT_FALSE(j.contains("tip_over_probability"));
  EXPECT_NE(j["tip_over_probability_reason"].get<std::string>().find("all 2 failed (first: "), std::string::npos);
  EXPECT_FALSE(j["percentiles"]["max_tilt_deg"].contains("p50"));
  EXPECT_EQ(j["percentiles"]["max_tilt_deg"]["landings"], 0);
  for (const nlohmann::json& cell : j["map"]["cells"]) {  // no landing in any cell
    EXPECT_FALSE(cell.contains("tip_over_probability")) << cell.dump();
    EXPECT_EQ(cell["tip_over_probability_reason"], "no landing fell in this cell");
  }
  const StabilityRun rerun = Run({"stability", study, "--out", out, "--threads", "1", "--progress", "none"});
  ASSERT_EQ(rerun.status, 0) << rerun.err;
  EXPECT_NE(rerun.out.find("2 landings run now, 0 already done"), std::string::npos) << rerun.out;
  j = nlohmann::json::parse(Slurp(std::filesystem::path(out) / "summary.json"));
  EXPECT_EQ(j["landings"], 2);
  EXPECT_EQ(j["landings_failed"], 0);
  // A limit that is not a whole number is refused before any directory is made.
  const StabilityRun bad = Run({"stability", study, "--out", Path("bad_limit"), "--max-drop-evaluations", "1.5"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--max-drop-evaluations"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(Path("bad_limit")));
}

// Two landings on a coarse pad: level (stays up, far from the boundary) and a 30 deg slope
// (tips over, its pads at their stops); the joint-range sensitivity on both (K = 2).
std::string FollowUpStudy(const std::string& scenario) {
  return "schema_version: 1\ntype: stability\nname: followups\nlander: {scenario: " + scenario +
         "}\n"
         "fixed: {downhill_azimuth_deg: -90, yaw_relative_to_slope_deg: 90}\n"
         "grid: {slope_deg: [0, 30]}\n"
         "study: {joint_range_sensitivity: {samples: 2}}\n";
}
// The paper's lander with 16-segment pads for 1 s (data/studies/lab_coarse_lander_scenario.yaml).
const std::string kCoarseScenario = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/studies/lab_coarse_lander_scenario.yaml";

std::string StabilityCli::WriteRareStudy() {
  return Write("study.yaml", "schema_version: 1\ntype: stability\nname: rare\nlander: {scenario: " + kCoarseScenario +
                                 "}\nfixed: {downhill_azimuth_deg: -90, yaw_relative_to_slope_deg: 90, horizontal_azimuth_deg: -90}\n"
                                 "random: {samples: 10, seed: 5, slope_deg: {uniform: [0, 20]},\n"
                                 "         horizontal_speed_m_s: {uniform: [0, 1.5]}}\n");
}

// The landing that tipped over ran again with the reference model; summary.json's counts match
// the records; a rerun computes nothing and writes the same summary; so does a run on two threads.
TEST_F(StabilityCli, FollowUpsRecheckTheTipOverAndRunTheJointRangeOnce) {
  const std::string study = Write("study.yaml", FollowUpStudy(kCoarseScenario));
  const StabilityRun first = Run({"stability", study, "--out", Path("one"), "--threads", "1", "--progress", "none"});
  ASSERT_EQ(first.status, 0) << first.err;
  const nlohmann::json j = nlohmann::json::parse(Slurp(Path("one") + "/summary.json"));
  const nlohmann::json& recheck = j["recheck"];
  // Drop 1 tipped over; drop 0 stood level, far below tip_angle_deg - margin_deg: only drop 1 re-runs.
  EXPECT_EQ(j["tipped_over"], 1);
  EXPECT_EQ(recheck["rechecked"], 1);
  EXPECT_EQ(recheck["outcome_changed"], 0);
  EXPECT_EQ(recheck["changed_landings"].size(), 0u);
  EXPECT_EQ(j["tip_overs"][0]["drop_index"], 1);
  // The tip-over margin's sign agrees with the outcome on both landings.
  EXPECT_EQ(j["tip_over_margin"]["landings_checked"], 2);
  EXPECT_EQ(j["tip_over_margin"]["disagreements"], 0);
  EXPECT_LE(j["tip_overs"][0]["min_stability_margin_m"].get<double>(), 0.0);
  EXPECT_GT(j["worst_max_tilt"][0]["min_stability_margin_m"].get<double>(), 0.0);
  EXPECT_LT(j["worst_max_tilt"][0]["max_tilt_deg"].get<double>(),
            recheck["tip_angle_deg"].get<double>() - recheck["margin_deg"].get<double>());
  const std::string rechecked = Rows(Path("one") + "/recheck/results.sqlite");
  EXPECT_EQ(std::count(rechecked.begin(), rechecked.end(), '\n'), 1);
  EXPECT_EQ(rechecked.substr(0, 2), "1|") << rechecked;  // drop 1, under its study index
  // The tipping landing swung its pads to the stops (1 of 2 > 5 %): x0.5, x1, x1.5 on both landings.
  // The screen runs only drop 1 again (it tipped); drop 0 stood level, settled, far below the
  // tip-over angle, and keeps its outcome at every range.
  const nlohmann::json& range = j["joint_range_sensitivity"];
  EXPECT_EQ(range["landings_at_stops"], 1);
  ASSERT_EQ(range["ran"], true) << range.dump();
  EXPECT_EQ(range["samples"], 2);
  EXPECT_EQ(range["screen"]["margin_deg"], 20.0);
  EXPECT_EQ(range["screen"]["landings_run"], 1);
  EXPECT_EQ(range["screen"]["landings_kept_from_study"], 1);
  ASSERT_EQ(range["variants"].size(), 3u);
  for (const nlohmann::json& v : range["variants"]) EXPECT_EQ(v["landings"], 2) << v.dump();
  EXPECT_EQ(range["variants"][1]["tipped_over"], 1);
  for (const char* factor : {"0.5", "1.5"}) {
    const std::string rows = Rows(Path("one") + "/joint_range_x" + factor + "/results.sqlite");
    EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 1) << rows;
    EXPECT_EQ(rows.substr(0, 2), "1|") << rows;
  }
  EXPECT_NE(first.out.find("joint range x0.5 (half angle 15 deg), 2 landings: P(tip-over) = "), std::string::npos)
      << first.out;
  EXPECT_NE(first.out.find("joint-range screen: 1 of the 2 landings ran at x0.5 and x1.5; the other 1 stood"),
            std::string::npos) << first.out;
  EXPECT_NE(first.out.find("follow-ups 3 landings run now, 0 already done"), std::string::npos) << first.out;

  const std::string summary = Slurp(Path("one") + "/summary.json");
  const StabilityRun rerun = Run({"stability", study, "--out", Path("one"), "--threads", "2", "--progress", "none"});
  ASSERT_EQ(rerun.status, 0) << rerun.err;
  EXPECT_NE(rerun.out.find("follow-ups 0 landings run now, 3 already done"), std::string::npos) << rerun.out;
  EXPECT_EQ(Slurp(Path("one") + "/summary.json"), summary);
  const StabilityRun two = Run({"stability", study, "--out", Path("two"), "--threads", "2", "--progress", "none"});
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(Slurp(Path("two") + "/summary.json"), summary);
}

// `--method subset` on a few random landings of the coarse lander: the estimate, the landings it
// spent and its design points in summary.json and on stdout, its landings under subset/.
TEST_F(StabilityCli, SubsetMethodWritesItsEstimateAndDesignPoints) {
  const std::string study = WriteRareStudy();
  const StabilityRun r = Run({"stability", study, "--out", Path("subset"), "--method", "subset", "--samples", "10",
                              "--threads", "2", "--progress", "none"});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(Slurp(Path("subset") + "/summary.json"));
  ASSERT_TRUE(j.contains("rare_event")) << j.dump();
  const nlohmann::json& e = j["rare_event"];
  EXPECT_EQ(j["method"], "subset");
  EXPECT_EQ(e["method"], "subset");
  EXPECT_EQ(j["tip_over_probability"], e["tip_over_probability"]);
  EXPECT_GE(e["landings_spent"].get<int>(), 10);
  EXPECT_EQ(e["margin_disagreements"], 0);
  EXPECT_TRUE(e["coefficient_of_variation"].is_number()) << e.dump();
  ASSERT_GE(e["design_points"].size(), 1u) << e.dump();
  EXPECT_TRUE(e["design_points"][0]["conditions"]["slope_deg"].is_number());
  EXPECT_EQ(j["landings"].get<int>() + j["landings_failed"].get<int>(), 10);  // the first level, analysed as a study
  EXPECT_TRUE(std::filesystem::exists(Path("subset") + "/subset/results.sqlite"));
  EXPECT_NE(r.out.find("(subset): " + std::to_string(e["landings_spent"].get<int>()) + " landings spent"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("design point "), std::string::npos) << r.out;
}

// `--method subset --shard I/N` as a job array runs it: two processes side by side with the same
// --out meet after every batch; shard 0 writes the outputs, byte for byte the single process's, and
// the whole run's landings in OUT/subset/. A shard of another split in OUT is refused, exit 2.
TEST_F(StabilityCli, SubsetAsTwoShardProcessesEqualsTheSingleProcess) {
  const std::string study = WriteRareStudy();
  const std::vector<std::string> args = {"stability", study, "--method", "subset", "--samples", "10", "--progress", "none"};
  std::vector<std::string> single = args;
  single.insert(single.end(), {"--out", Path("one"), "--threads", "2"});
  ASSERT_EQ(Run(single).status, 0);
  std::vector<pid_t> shards;
  for (const char* shard : {"0/2", "1/2"}) {
    std::vector<std::string> a = args;
    a.insert(a.end(), {"--out", Path("sharded"), "--threads", "1", "--shard", shard});
    shards.push_back(touchdown::testing_process::StartTouchdown(a, "", Path(std::string("out_") + shard[0]),
                                                                Path(std::string("err_") + shard[0])));
  }
  for (size_t k = 0; k < shards.size(); ++k) {
    const int raw = touchdown::testing_process::WaitForStatus(shards[k]);
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << k << Slurp(Path("err_" + std::to_string(k)));
  }
  for (const char* file : {"summary.json", "percentiles.csv"})
    EXPECT_EQ(Slurp(Path("sharded") + "/" + file), Slurp(Path("one") + "/" + file)) << file;
  EXPECT_EQ(Rows(Path("sharded") + "/subset/results.sqlite"), Rows(Path("one") + "/subset/results.sqlite"));
  EXPECT_FALSE(Rows(Path("one") + "/subset/results.sqlite").empty());
  EXPECT_NE(Slurp(Path("out_0")).find("landings spent"), std::string::npos) << Slurp(Path("out_0"));
  EXPECT_NE(Slurp(Path("out_1")).find("shard 1/2 done"), std::string::npos) << Slurp(Path("out_1"));
  std::vector<std::string> other_split = args;
  other_split.insert(other_split.end(), {"--out", Path("sharded"), "--shard", "0/3"});
  const StabilityRun refused = Run(other_split);
  EXPECT_EQ(refused.status, 2);
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_NE(refused.err.find("--shard I/2"), std::string::npos) << refused.err;
}

// `mpirun -np 2 touchdown stability --method subset`: both ranks run the estimator, the landings
// are shared out, and rank 0 stores the same landings and writes the same estimate as one process.
TEST_F(StabilityCli, SubsetOnMpiEqualsTheSingleProcess) {
#ifndef TOUCHDOWN_TEST_WITH_MPI
  GTEST_SKIP() << "touchdown was built without MPI (TOUCHDOWN_WITH_MPI=OFF)";
#endif
  const std::string study = WriteRareStudy();
  const std::vector<std::string> args = {"stability", study, "--method", "subset", "--samples", "10", "--progress", "none"};
  std::vector<std::string> single = args;
  single.insert(single.end(), {"--out", Path("one"), "--threads", "2"});
  ASSERT_EQ(Run(single).status, 0);
  // CI runs as root in a 2-core container: allow root and more ranks than cores. LeakSanitizer is
  // off for the ranks (OpenMPI keeps allocations of plugins it has unloaded; sweep_test.cpp).
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  ::setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
  const char* asan = std::getenv("ASAN_OPTIONS");
  ::setenv("ASAN_OPTIONS", (std::string(asan ? asan : "") + ":detect_leaks=0").c_str(), 1);
  std::vector<std::string> mpi = {"mpirun", "--allow-run-as-root", "-np", "2", TOUCHDOWN_BINARY};
  mpi.insert(mpi.end(), args.begin(), args.end());
  mpi.insert(mpi.end(), {"--out", Path("mpi"), "--threads", "1"});
  const pid_t pid = touchdown::testing_process::StartProgram(mpi, "", Path("mpi_stdout"), Path("mpi_stderr"));
  if (pid < 0) GTEST_SKIP() << "mpirun is not installed";
  const int raw = touchdown::testing_process::WaitForStatus(pid);
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << Slurp(Path("mpi_stdout")) << Slurp(Path("mpi_stderr"));
  EXPECT_EQ(Rows(Path("mpi") + "/subset/results.sqlite"), Rows(Path("one") + "/subset/results.sqlite"));
  EXPECT_FALSE(Rows(Path("one") + "/subset/results.sqlite").empty());
  const nlohmann::json a = nlohmann::json::parse(Slurp(Path("one") + "/summary.json"));
  const nlohmann::json b = nlohmann::json::parse(Slurp(Path("mpi") + "/summary.json"));
  EXPECT_EQ(a["rare_event"], b["rare_event"]);
  EXPECT_EQ(a["tip_over_probability"], b["tip_over_probability"]);
  // The estimate is printed once, by rank 0.
  const std::string out = Slurp(Path("mpi_stdout"));
  EXPECT_EQ(out.find("landings spent"), out.rfind("landings spent")) << out;
  EXPECT_NE(out.find("landings spent"), std::string::npos) << out;
}

TEST_F(StabilityCli, BadStudiesExitTwoWithOneLineNamingFileAndField) {
  struct Bad {
    std::string text, field;
    std::vector<std::string> extra;
  };
  const std::string head = "schema_version: 1\ntype: stability\nlander: {scenario: lander_case_A}\n";
  const std::vector<Bad> cases = {
      {head + "grid: {slope_deg: [0, 90]}\n", "grid.slope_deg[1]", {}},
      {head + "grid: {slope_deg: [0, 5]}\nstudy: {map: {x: slope_deg, y: yaw_deg}}\n", "study.map.y", {}},
      {head + "grid: {slope_deg: [0, 5]}\nstudy: {map: {x: slope_deg, y: roll_deg}}\n", "study.map.y", {}},
      {head + "grid: {slope_deg: [0, 5]}\n", "--samples", {"--samples", "4"}},
      {"schema_version: 1\ntype: sweep\nlander: {scenario: lander_case_A}\ngrid: {slope_deg: [0, 5]}\n", "type", {}},
      {head + "grid: {slope_deg: [0, 5]}\nstudy: {recheck: {rtol: 1e-6}}\n", "study.recheck.rtol", {}},
      {head + "grid: {slope_deg: [0, 5]}\nstudy: {recheck: {tilt_margin_deg: 100}}\n",
       "study.recheck.tilt_margin_deg", {}},
      {head + "grid: {slope_deg: [0, 5]}\nstudy: {recheck: {rtol: 1e-9, tolerance: 1}}\n", "study.recheck.tolerance",
       {}},
      // The estimator: a name it knows, a study of random variables only, whole chains per level.
      {head + "grid: {slope_deg: [0, 5]}\n", "--method", {"--method", "bisection"}},
      {head + "grid: {slope_deg: [0, 5]}\n", "--method", {"--method", "subset"}},
      {head + "random: {samples: 10, seed: 1, slope_deg: {uniform: [0, 5]}}\n", "--samples",
       {"--method", "subset", "--samples", "15"}},
      // The soil's uncertainty: a soil the landings stand on, a calibration report that exists.
      {head + "grid: {slope_deg: [0, 5]}\nstudy: {soil_uncertainty: {toyoura: {calibration: c.json}}}\n",
       "study.soil_uncertainty.toyoura", {}},
      {head + "grid: {slope_deg: [0, 5]}\nstudy: {soil_uncertainty: {fjs1_lp: {calibration: missing.json}}}\n",
       "study.soil_uncertainty.fjs1_lp.calibration", {}},
      {head + "grid: {slope_deg: [0, 5]}\nstudy: {soil_uncertainty: {fjs1_lp: {file: c.json}}}\n",
       "study.soil_uncertainty.fjs1_lp.file", {}},
  };
  int k = 0;
  for (const Bad& bad : cases) {
    SCOPED_TRACE(bad.text);
    const std::string file = Write("bad" + std::to_string(k) + ".yaml", bad.text);
    std::vector<std::string> args = {"stability", file, "--out", Path("out" + std::to_string(k++))};
    args.insert(args.end(), bad.extra.begin(), bad.extra.end());
    const StabilityRun r = Run(args);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(bad.field), std::string::npos) << r.err;
    for (const std::string& value : {std::string("bisection"), std::string("15")}) {
      if (std::find(bad.extra.begin(), bad.extra.end(), value) != bad.extra.end()) {
        EXPECT_NE(r.err.find(value), std::string::npos) << r.err;
      }
    }
    if (bad.field != "--samples" && bad.extra != std::vector<std::string>{"--method", "bisection"}) {
      EXPECT_NE(r.err.find(file), std::string::npos) << r.err;
    }
  }
}

}  // namespace
