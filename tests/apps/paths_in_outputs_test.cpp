// Outputs do not carry this machine's absolute paths. Every command is run
// from a temporary directory with relative paths; the files that name other files
// (scenario_resolved.yaml of campaign and lander, model.yaml of calibrate and diagnose, the sweep
// database's meta table) must hold neither that directory's absolute path nor the data
// directory's, and still lead back to the files (export reloads the sweep file from the meta).
#include <gtest/gtest.h>

#include <sqlite3.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "drop_tests/catalog/catalog.h"
#include "drop_tests/catalog/paths_in_outputs.h"

namespace touchdown::drop {
namespace {

namespace fs = std::filesystem;

// Runs touchdown in `dir` (no shell); returns its exit status.
int RunIn(const fs::path& dir, std::vector<std::string> args) {
  args.insert(args.begin(), TOUCHDOWN_BINARY);
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(126);
    const int null = ::open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string Slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::map<std::string, std::string> RawMeta(const fs::path& db_path) {
  sqlite3* db = nullptr;
  std::map<std::string, std::string> meta;
  if (sqlite3_open_v2(db_path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) return meta;
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(db, "SELECT key, value FROM meta", -1, &st, nullptr);
  while (sqlite3_step(st) == SQLITE_ROW)
    meta[reinterpret_cast<const char*>(sqlite3_column_text(st, 0))] =
        reinterpret_cast<const char*>(sqlite3_column_text(st, 1));
  sqlite3_finalize(st);
  sqlite3_close(db);
  return meta;
}

class OutputPaths : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("touchdown_paths_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    dir_ = fs::canonical(dir_);
    data_ = fs::canonical(io::DataDirectory());
  }
  void TearDown() override { fs::remove_all(dir_); }
  // No absolute path of this machine: neither the working directory nor the data directory.
  void ExpectNoAbsolutePath(const std::string& text, const std::string& what) const {
    EXPECT_EQ(text.find(dir_.string()), std::string::npos) << what << ":\n" << text;
    EXPECT_EQ(text.find(data_.string()), std::string::npos) << what << ":\n" << text;
    EXPECT_EQ(text.find(fs::path(TOUCHDOWN_SOURCE_DIR).string()), std::string::npos) << what << ":\n" << text;
  }
  fs::path dir_, data_;
};

TEST_F(OutputPaths, CampaignAndLanderResolvedScenarios) {
  fs::copy_file(data_ / "scenarios" / "sutoh2017_single_footpad.yaml", dir_ / "camp.yaml");
  fs::copy_file(data_ / "scenarios" / "lander_case_A.yaml", dir_ / "lander.yaml");
  ASSERT_EQ(RunIn(dir_, {"campaign", "camp.yaml", "--out", "runs/campaign"}), 0);
  ASSERT_EQ(RunIn(dir_, {"lander", "lander.yaml", "--out", "runs/lander"}), 0);
  const std::string campaign = Slurp(dir_ / "runs" / "campaign" / "scenario_resolved.yaml");
  const std::string lander = Slurp(dir_ / "runs" / "lander" / "scenario_resolved.yaml");
  ExpectNoAbsolutePath(campaign, "campaign");
  ExpectNoAbsolutePath(lander, "lander");
  // Relative to the output directory; catalog files under $TOUCHDOWN_DATA_DIR.
  EXPECT_NE(campaign.find("source: ../../camp.yaml"), std::string::npos) << campaign;
  EXPECT_NE(campaign.find("file: $TOUCHDOWN_DATA_DIR/pads/flat.yaml"), std::string::npos) << campaign;
  EXPECT_NE(lander.find("source: ../../lander.yaml"), std::string::npos) << lander;
  EXPECT_NE(lander.find("file: $TOUCHDOWN_DATA_DIR/landers/sutoh2017_lander.yaml"), std::string::npos) << lander;
}

TEST_F(OutputPaths, CalibrateAndDiagnoseModelFiles) {
  fs::copy(data_ / "datasets" / "air_vs_vacuum_synthetic", dir_ / "measured", fs::copy_options::recursive);
  fs::create_directories(dir_ / "models");
  ASSERT_EQ(RunIn(dir_, {"calibrate", "measured", "--out", "models/zeta.yaml"}), 0);
  ASSERT_EQ(RunIn(dir_, {"diagnose", "measured", "--out", "diagnosis", "--no-pairs", "--threads", "1"}), 0);
  const std::string calibrated = Slurp(dir_ / "models" / "zeta.yaml");
  const std::string diagnosed = Slurp(dir_ / "diagnosis" / "model.yaml");
  ExpectNoAbsolutePath(calibrated, "calibrate");
  ExpectNoAbsolutePath(diagnosed, "diagnose");
  EXPECT_NE(calibrated.find("dataset: ../measured"), std::string::npos) << calibrated;
  EXPECT_NE(diagnosed.find("dataset: ../measured"), std::string::npos) << diagnosed;
}

TEST_F(OutputPaths, SweepDatabaseMetaAndExportFindsTheSweepAgain) {
  fs::copy_file(data_ / "sweeps" / "pad_trade.yaml", dir_ / "trade.yaml");
  ASSERT_EQ(RunIn(dir_, {"sweep", "trade.yaml", "--out", "sweep"}), 0);
  const std::map<std::string, std::string> meta = RawMeta(dir_ / "sweep" / "results.sqlite");
  ASSERT_FALSE(meta.empty());
  for (const auto& [key, value] : meta) ExpectNoAbsolutePath(value, "meta " + key);
  EXPECT_EQ(meta.at("source"), "../trade.yaml");
  // export re-simulates every trace from the sweep file the meta names, from another directory.
  fs::create_directories(dir_ / "elsewhere");
  EXPECT_EQ(RunIn(dir_ / "elsewhere", {"export", "../sweep", "--to", "../exported", "--full-traces"}), 0);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "exported" / "drops.csv"));
}

TEST(OutputPathsFunctions, RoundTrip) {
  const std::string out = "runs/a";
  EXPECT_EQ(io::PathForOutput("scen.yaml", out), "../../scen.yaml");
  EXPECT_EQ(io::PathForOutput("runs/a/x.yaml", "runs/a/"), "x.yaml");
  EXPECT_EQ(io::PathFromOutput("../../scen.yaml", out), "scen.yaml");
  const std::string pad = (fs::path(io::DataDirectory()) / "pads" / "flat.yaml").string();
  EXPECT_EQ(io::PathForOutput(pad, out), "$TOUCHDOWN_DATA_DIR/pads/flat.yaml");
  EXPECT_EQ(fs::path(io::PathFromOutput("$TOUCHDOWN_DATA_DIR/pads/flat.yaml", out)), fs::path(pad));
  EXPECT_EQ(io::PathFromOutput("/abs/old.yaml", out), "/abs/old.yaml");  // written by an older touchdown
  EXPECT_EQ(io::PathForOutput("", out), "");
}

}  // namespace
}  // namespace touchdown::drop
