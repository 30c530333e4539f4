// The README's examples run as written: every line of every ```sh block under "## Examples" is run
// with bash, in order, from a directory laid out like the repository root after the build
// (data/, build/apps/touchdown, build/python), and must exit 0. The quick-start block above them
// is not run here: its test command is CI's first stage, and its main command builds into build/
// (which this test is running from); each step of the main job is one of the examples.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include "tests/scratch_dir_test.h"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> ReadmeExampleLines() {
  std::ifstream in(std::string(TOUCHDOWN_SOURCE_DIR) + "/README.md");
  std::vector<std::string> lines;
  bool in_examples = false, in_block = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) in_examples = line == "## Examples";
    if (!in_examples) continue;
    if (line.rfind("```", 0) == 0) {
      in_block = !in_block && line == "```sh";
      continue;
    }
    if (in_block && !line.empty()) lines.push_back(line);
  }
  return lines;
}

std::string Quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

class Readme : public touchdown::testing_scratch::ScratchDirTest {};

TEST_F(Readme, EveryExampleRunsAsWritten) {
  const std::vector<std::string> lines = ReadmeExampleLines();
  ASSERT_GE(lines.size(), 15u) << "the README's Examples section lost its blocks";
  const fs::path root = Path("root");
  fs::create_directories(root / "build" / "apps");
  fs::create_directory_symlink(std::string(TOUCHDOWN_SOURCE_DIR) + "/data", root / "data");
  fs::create_symlink(TOUCHDOWN_BINARY, root / "build" / "apps" / "touchdown");
#ifdef TOUCHDOWN_PYTHON_PACKAGE_DIR
  fs::create_directory_symlink(TOUCHDOWN_PYTHON_PACKAGE_DIR, root / "build" / "python");
#endif
  int k = 0;
  for (const std::string& line : lines) {
    const bool python = line.find("python3") != std::string::npos;
#ifndef TOUCHDOWN_PYTHON_PACKAGE_DIR
    if (python) continue;  // this build has no Python module (the sanitizer build)
#endif
    const std::string script = Write("line" + std::to_string(k) + ".sh", line + "\n");
    const std::string out = Path("out" + std::to_string(k)), err = Path("err" + std::to_string(k));
    ++k;
    const std::string command = "cd " + Quoted(root.string()) + " && bash " + Quoted(script) + " > " + Quoted(out) +
                                " 2> " + Quoted(err);
    const int raw = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << line << "\n" << Slurp(err);
    if (python) {
      // Regression pin: the README's Python line (a flat pad on fjs1_lp at 1 m/s, touchdown.drop)
      // prints a final penetration of 0.00785 m.
      EXPECT_NEAR(std::stod(Slurp(out)), 0.00785, 1e-5) << line;
    }
  }
  EXPECT_TRUE(fs::is_regular_file(root / "runs" / "hex_vtk" / "drop.pvd"));
  EXPECT_TRUE(fs::is_regular_file(root / "runs" / "pad_dataset" / "drops.csv"));
  EXPECT_TRUE(fs::is_regular_file(root / "runs" / "lunar_quick" / "summary.json"));
}

}  // namespace
