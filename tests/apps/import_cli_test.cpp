// `touchdown import` as a user meets it: the shipped raw example imported (exit 0, its summary
// printed, a dataset diagnose can read); every bad input one line on stderr naming the file and
// the row and column or field, exit 2, and nothing written; a link or a folder of the user's at
// --out refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include "tests/drop_tests/dataset/daq_test_files.h"
#include "tests/scratch_dir_test.h"

namespace {

namespace fs = std::filesystem;
using touchdown::dataset::testing_drop::DropLine;
using touchdown::dataset::testing_drop::DropShape;
using touchdown::dataset::testing_drop::MakeDrop;
using touchdown::dataset::testing_drop::MappingText;
using touchdown::dataset::testing_drop::RawDropText;

struct ImportRun {
  int status = -1;
  std::string out, err;
};

class ImportCli : public touchdown::testing_scratch::ScratchDirTest {
 protected:
  ImportRun Touchdown(const std::string& args) {
    const std::string out = Path("stdout"), err = Path("stderr");
    const int raw = std::system((std::string(TOUCHDOWN_BINARY) + " " + args + " >" + out + " 2>" + err).c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, Slurp(out), Slurp(err)};
  }
  // A mapping of two drops made in code, its raw files beside it.
  std::string WriteMadeSet() {
    fs::create_directories(dir_ / "set" / "raw");
    DropShape s;
    s.force_noise_N = 0.3;
    Write("set/raw/d1.csv", RawDropText(MakeDrop(s), false, true));
    s.seed = 2, s.phase = 0.6;
    Write("set/raw/d2.csv", RawDropText(MakeDrop(s), false, true));
    return Write("set/import.yaml",
                 MappingText(false, "{column: Time, unit: ms}", DropLine("d1", "flat", 1.0) + DropLine("d2", "flat", 1.0)));
  }
  static std::string Example() { return std::string(TOUCHDOWN_SOURCE_DIR) + "/data/datasets/rig_daq_synthetic_raw/import.yaml"; }
  void ExpectOneLineRefusal(const ImportRun& r, const std::string& start) {
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err.rfind("touchdown: " + start, 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
};

TEST_F(ImportCli, TheShippedExampleImports) {
  const ImportRun r = Touchdown("import " + Example() + " --out " + Path("rig"));
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["name"], "rig_daq_synthetic");
  EXPECT_EQ(j["drops"], 12);
  EXPECT_EQ(j["penetration_from"], "displacement");
  for (const auto& d : j["per_drop"]) {
    EXPECT_GT(d["touchdown_uncertainty_s"].get<double>(), 0.0);
    EXPECT_LT(d["touchdown_uncertainty_s"].get<double>(), 0.002);
    EXPECT_GT(d["final_penetration_m"].get<double>(), 0.003);
  }
  for (const char* file : {"drops.csv", "README.md", "import.yaml", "traces/c4_lp_vac_v0.60_r1.csv"})
    EXPECT_TRUE(fs::is_regular_file(dir_ / "rig" / file)) << file;
  EXPECT_NE(Slurp(dir_ / "rig" / "README.md").find("SYNTHETIC"), std::string::npos);
  // Its own output is replaced whole on a rerun.
  EXPECT_EQ(Touchdown("import " + Example() + " --out " + Path("rig")).status, 0);
}

TEST_F(ImportCli, ABadCellIsOneLineAndNothingIsWritten) {
  const std::string mapping = WriteMadeSet();
  std::string raw = Slurp(dir_ / "set" / "raw" / "d2.csv");
  const size_t line7 = [&] {
    size_t at = 0;
    for (int k = 0; k < 6; ++k) at = raw.find('\n', at) + 1;
    return at;
  }();
  const size_t cell = raw.find(';', line7) + 1;  // the force's cell on line 7
  Write("set/raw/d2.csv", raw.substr(0, cell) + "#" + raw.substr(cell));
  const ImportRun r = Touchdown("import " + mapping + " --out " + Path("out"));
  ExpectOneLineRefusal(r, Path("set/raw/d2.csv") + ": line 7, column 2 (Fz): not a finite number: '#");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(ImportCli, AMappingMistakeNamesItsField) {
  const std::string mapping = WriteMadeSet();
  std::string text = Slurp(mapping);
  text.replace(text.find("gain: 0.05"), 10, "gain: fast");
  Write("set/import.yaml", text);
  ExpectOneLineRefusal(Touchdown("import " + mapping + " --out " + Path("out")),
                       mapping + ": channels.force.gain: must be a number, got 'fast'");
  ExpectOneLineRefusal(Touchdown("import " + Path("none.yaml") + " --out " + Path("out")), Path("none.yaml") + ": ");
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(ImportCli, ALinkOrAUsersFolderIsRefused) {
  const std::string mapping = WriteMadeSet();
  fs::create_directories(dir_ / "mine");
  Write("mine/notes.txt", "mine\n");
  const ImportRun folder = Touchdown("import " + mapping + " --out " + Path("mine"));
  EXPECT_EQ(folder.status, 2) << folder.err;
  EXPECT_EQ(Slurp(dir_ / "mine" / "notes.txt"), "mine\n");
  EXPECT_EQ(std::count(folder.err.begin(), folder.err.end(), '\n'), 1) << folder.err;
  fs::create_directory_symlink(dir_ / "elsewhere", dir_ / "link");
  const ImportRun link = Touchdown("import " + mapping + " --out " + Path("link"));
  EXPECT_EQ(link.status, 2) << link.err;
  EXPECT_FALSE(fs::exists(dir_ / "elsewhere"));
  const ImportRun inside = Touchdown("import " + mapping + " --out " + Path("set/raw"));
  EXPECT_EQ(inside.status, 2) << inside.err;
  const ImportRun made = Touchdown("import " + mapping + " --out " + Path("out"));
  EXPECT_EQ(made.status, 0) << made.err;
}

}  // namespace
