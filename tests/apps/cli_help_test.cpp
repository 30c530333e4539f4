// What a user sees when asking for help or mistyping: every command's --help shows examples,
// and each example runs as written (exit 0) from a directory laid out like the repository root;
// a mistyped command, pad or soil is named with the nearest real one (exit 2, one line).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include "tests/scratch_dir_test.h"
#include "tests/touchdown_process.h"

namespace {

struct HelpRun {
  int status = -1;
  std::string out, err;
};

const std::vector<std::string> kHelpCommands = {"drop",    "campaign", "force", "sweep", "export",
                                                "merge",   "compare",  "calibrate", "trade", "lander",
                                                "synth",   "diagnose", "stability", "validate",
                                                "import", "schema"};

class CliHelp : public touchdown::testing_scratch::ScratchDirTest {
 protected:
  HelpRun RunIn(const std::vector<std::string>& args, const std::string& dir) {
    const std::string out = Path("stdout"), err = Path("stderr");
    const pid_t pid = touchdown::testing_process::StartTouchdown(args, dir, out, err);
    const int raw = touchdown::testing_process::WaitForStatus(pid);
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, Slurp(out), Slurp(err)};
  }
  // The example command lines of a help text, as argument vectors (comments after '#' dropped).
  static std::vector<std::vector<std::string>> ExampleLines(const std::string& help) {
    std::vector<std::vector<std::string>> examples;
    std::istringstream lines(help.substr(help.find("Examples")));
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("  touchdown ", 0) != 0) continue;
      std::istringstream words(line.substr(0, line.find('#')));
      std::vector<std::string> args;
      for (std::string w; words >> w;) args.push_back(w);
      examples.push_back({args.begin() + 1, args.end()});
    }
    return examples;
  }
};

TEST_F(CliHelp, EveryCommandsExamplesRunAsWritten) {
  const std::string root = Path("root");
  std::filesystem::create_directories(root);
  std::filesystem::create_directory_symlink(std::string(TOUCHDOWN_SOURCE_DIR) + "/data", root + "/data");
  int examples = 0;
  for (const std::string& command : kHelpCommands) {
    SCOPED_TRACE(command);
    const HelpRun help = RunIn({command, "--help"}, root);
    ASSERT_EQ(help.status, 0) << help.err;
    ASSERT_NE(help.out.find("Examples"), std::string::npos) << help.out;
    const auto lines = ExampleLines(help.out);
    EXPECT_FALSE(lines.empty());
    for (const std::vector<std::string>& args : lines) {
      std::vector<std::string> quiet = args;
      if (command == "sweep" || command == "stability") quiet.insert(quiet.end(), {"--progress", "none"});
      const HelpRun r = RunIn(quiet, root);
      EXPECT_EQ(r.status, 0) << args.back() << ": " << r.err;
      ++examples;
    }
  }
  EXPECT_GE(examples, 15);
}

TEST_F(CliHelp, HelpListsTheCatalogueAndShowsNoDefaultForRequiredOptions) {
  const HelpRun help = RunIn({"drop", "--help"}, "");
  ASSERT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("c4, curved, flat, hex"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("fjs1_cp, fjs1_cp_bekker, fjs1_cp_spot, fjs1_lp, fjs1_lp_bekker, lunar_nominal_bekker"), std::string::npos)
      << help.out;
  EXPECT_NE(help.out.find("--gravity FLOAT=9.81"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("--speed FLOAT REQUIRED"), std::string::npos) << help.out;
}

TEST_F(CliHelp, MistypedNamesAreAnsweredWithTheNearestOne) {
  struct Typo {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Typo> typos = {
      {{"dropp", "--pad", "flat"}, "unknown command 'dropp' (did you mean 'drop'?)"},
      {{"stabilty", "x.yaml"}, "(did you mean 'stability'?)"},
      {{"drop", "--pad", "flatt", "--soil", "fjs1_lp", "--speed", "1"}, "unknown name 'flatt' (did you mean 'flat'?)"},
      {{"drop", "--pad", "flat", "--soil", "fjs1-lp", "--speed", "1"}, "(did you mean 'fjs1_lp'?)"},
  };
  for (const Typo& t : typos) {
    const HelpRun r = RunIn(t.args, "");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(t.says), std::string::npos) << r.err;
  }
  // Nothing near: no suggestion, only the list.
  const HelpRun far = RunIn({"zzzzzz"}, "");
  EXPECT_EQ(far.status, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
  EXPECT_NE(far.err.find("commands: drop, campaign"), std::string::npos) << far.err;
}

TEST_F(CliHelp, BareTouchdownListsTheCommands) {
  const HelpRun r = RunIn({}, "");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_NE(r.out.find("Usage: touchdown [OPTIONS] SUBCOMMAND"), std::string::npos) << r.out;
  for (const std::string& command : kHelpCommands)
    EXPECT_NE(r.out.find("\n  " + command + " "), std::string::npos) << command << "\n" << r.out;
}

TEST_F(CliHelp, EveryHelpLineFitsIn100Columns) {
  std::vector<std::vector<std::string>> asks = {{"--help"}};
  for (const std::string& command : kHelpCommands) asks.push_back({command, "--help"});
  for (const std::vector<std::string>& ask : asks) {
    const HelpRun help = RunIn(ask, "");
    ASSERT_EQ(help.status, 0) << help.err;
    std::istringstream lines(help.out);
    for (std::string line; std::getline(lines, line);)
      EXPECT_LE(line.size(), 100u) << ask.front() << ": " << line;
  }
}

TEST_F(CliHelp, StabilityListsOnlyStudiesAndSamplesShowsNoDefault) {
  const HelpRun help = RunIn({"stability", "--help"}, "");
  ASSERT_EQ(help.status, 0) << help.err;
  EXPECT_NE(help.out.find("lab_paper_lander, lab_rare_event_agreement, lunar_paper_lander"), std::string::npos) << help.out;
  EXPECT_EQ(help.out.find("_scenario"), std::string::npos) << help.out;
  // --samples is optional and 1 to 1e9: no default (CLI11 would show its empty text or a 0).
  const size_t samples = help.out.find("\n  --samples ");
  ASSERT_NE(samples, std::string::npos) << help.out;
  const std::string line = help.out.substr(samples + 1, help.out.find('\n', samples + 1) - samples - 1);
  EXPECT_EQ(line.find('='), std::string::npos) << line;
}

TEST_F(CliHelp, ScenariosListedInHelpRunByName) {
  const HelpRun help = RunIn({"lander", "--help"}, "");
  ASSERT_NE(help.out.find("lander_case_A, lander_case_B"), std::string::npos) << help.out;
  EXPECT_EQ(help.out.find("sutoh2017_single_footpad,"), std::string::npos) << "a campaign is no lander scenario";
  const std::string dir = Path("cwd");
  std::filesystem::create_directories(dir);
  const HelpRun r = RunIn({"lander", "lander_case_B", "--out", "lander_B", "--no-vtk"}, dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir + "/lander_B/summary.json"));
  // A file of that name in the working directory is the one meant.
  std::ofstream(dir + "/lander_case_A") << "not: a scenario\n";
  const HelpRun mine = RunIn({"lander", "lander_case_A", "--out", "lander_A", "--no-vtk"}, dir);
  EXPECT_EQ(mine.status, 2);
  EXPECT_EQ(mine.err.rfind("touchdown: lander_case_A: ", 0), 0u) << mine.err;
}

TEST_F(CliHelp, AnUnknownOptionIsNamedBeforeAMissingRequiredOne) {
  const HelpRun r = RunIn({"drop", "--sped", "1"}, "");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "touchdown: command line: --sped: unknown option of `touchdown drop` (did you mean '--speed'?); "
            "`touchdown drop --help` lists its options\n");
  const HelpRun version = RunIn({"--version"}, "");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out, std::string("touchdown ") + TOUCHDOWN_PROJECT_VERSION + "\n");
}

}  // namespace
