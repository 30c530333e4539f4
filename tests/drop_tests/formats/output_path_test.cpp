// Where touchdown may write (drop_tests/formats/output_path.h): never over anything it did not write, and
// an output appears whole or not at all.
#include "drop_tests/formats/output_path.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "rft/input_error.h"

namespace touchdown::io {
namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void Write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// An output of one file, `summary.txt` holding `text`.
auto Fill(const std::string& text) {
  return [text](const std::string& staging) { Write(fs::path(staging) / "summary.txt", text); };
}

// The message of the InputError `f` throws ("" when it throws none).
template <typename F>
std::string Refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// A pid that no process has: a child that has exited and been reaped.
long DeadPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

class OutputPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("td_output_path_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    previous_ = fs::current_path();
    fs::current_path(dir_);
  }
  void TearDown() override {
    fs::current_path(previous_);
    fs::remove_all(dir_);
  }
  // Every entry of the scratch directory, so a test can see that nothing was left behind.
  static int Entries(const fs::path& p) { return static_cast<int>(std::distance(fs::directory_iterator(p), {})); }
  fs::path dir_, previous_;
};

TEST_F(OutputPathTest, NewDirectoryAppearsWholeWithItsMarker) {
  WriteOutputDirectory("out", OutputKind::kCampaign, Fill("one"));
  EXPECT_EQ(Read("out/summary.txt"), "one");
  const std::string marker = Read(fs::path("out") / kOutputMarker);
  EXPECT_NE(marker.find("kind: campaign"), std::string::npos);
  EXPECT_NE(marker.find("\nsummary.txt\n"), std::string::npos);
  EXPECT_EQ(Entries("."), 1);  // no staging directory left beside it
}

TEST_F(OutputPathTest, EmptyDirectoryAndEarlierOutputOfTheSameKindAreReplaced) {
  fs::create_directory("empty");
  WriteOutputDirectory("empty", OutputKind::kLander, Fill("a"));
  EXPECT_EQ(Read("empty/summary.txt"), "a");
  WriteOutputDirectory("empty", OutputKind::kLander, [](const std::string& staging) {
    Write(fs::path(staging) / "other.txt", "b");
  });
  EXPECT_FALSE(fs::exists("empty/summary.txt"));  // the old output went, whole
  EXPECT_EQ(Read("empty/other.txt"), "b");
  EXPECT_EQ(Entries("."), 1);
}

TEST_F(OutputPathTest, DirectoryOfTheUsersIsRefusedAndKept) {
  fs::create_directory("k");
  Write("k/notes.txt", "mine");
  const std::string why = Refusal([] { WriteOutputDirectory("k", OutputKind::kCampaign, Fill("x")); });
  EXPECT_EQ(why.rfind("k: ", 0), 0u) << why;
  EXPECT_NE(why.find("not written by touchdown"), std::string::npos) << why;
  EXPECT_EQ(Read("k/notes.txt"), "mine");
  EXPECT_EQ(Entries("."), 1);
}

TEST_F(OutputPathTest, FileTheUserAddedToAnOutputIsNeverDeleted) {
  WriteOutputDirectory("run", OutputKind::kCampaign, Fill("x"));
  Write("run/notes.txt", "mine");
  const std::string why = Refusal([] { WriteOutputDirectory("run", OutputKind::kCampaign, Fill("y")); });
  EXPECT_NE(why.find("'notes.txt', which touchdown did not write"), std::string::npos) << why;
  EXPECT_EQ(Read("run/notes.txt"), "mine");
  EXPECT_EQ(Read("run/summary.txt"), "x");
}

// A symbolic link the user put under the name of one of touchdown's files is the user's: a whole
// replacement is refused rather than deleting it, and what it points to is kept.
TEST_F(OutputPathTest, ALinkTheUserPutInPlaceOfAnOutputFileIsNeverDeleted) {
  WriteOutputDirectory("run", OutputKind::kCampaign, Fill("x"));
  Write("mine.txt", "mine");
  fs::remove("run/summary.txt");
  fs::create_symlink(fs::absolute("mine.txt"), "run/summary.txt");
  const std::string why = Refusal([] { WriteOutputDirectory("run", OutputKind::kCampaign, Fill("y")); });
  EXPECT_NE(why.find("'summary.txt', a symbolic link touchdown did not make"), std::string::npos) << why;
  EXPECT_TRUE(fs::is_symlink("run/summary.txt"));
  EXPECT_EQ(Read("mine.txt"), "mine");
}

TEST_F(OutputPathTest, OutputOfAnotherCommandIsRefused) {
  OpenOutputDirectory("sweep_out", OutputKind::kSweep);
  Write("sweep_out/results.sqlite", "hours of work");
  const std::string why = Refusal([] { WriteOutputDirectory("sweep_out", OutputKind::kCampaign, Fill("x")); });
  EXPECT_NE(why.find("holds the output of `touchdown sweep`"), std::string::npos) << why;
  EXPECT_EQ(Read("sweep_out/results.sqlite"), "hours of work");
}

TEST_F(OutputPathTest, CurrentDirectoryItsParentsAndTheRootAreRefused) {
  Write("mine.txt", "mine");
  for (const char* path : {".", "./", "..", "../..", "/"}) {
    const std::string why = Refusal([&] { WriteOutputDirectory(path, OutputKind::kLander, Fill("x")); });
    EXPECT_FALSE(why.empty()) << path;
  }
  EXPECT_EQ(Read("mine.txt"), "mine");
  fs::create_directory("sub");
  EXPECT_FALSE(Refusal([&] { CheckOutputDirectory(fs::absolute(".").string(), OutputKind::kLander); }).empty());
}

TEST_F(OutputPathTest, InputsAreNeverWrittenIntoOverOrAround) {
  fs::create_directories("ds/traces");
  Write("ds/drops.csv", "measured");
  for (const char* path : {"ds", "ds/", "ds/compare", "./ds/../ds"}) {
    const std::string why =
        Refusal([&] { WriteOutputDirectory(OutputTarget(path, {"ds"}), OutputKind::kComparison, Fill("x")); });
    EXPECT_NE(why.find("input 'ds'"), std::string::npos) << path << ": " << why;
  }
  // An earlier output that holds an input is not replaced either.
  WriteOutputDirectory("run", OutputKind::kDataset, [](const std::string& s) { Write(fs::path(s) / "drops.csv", "x"); });
  EXPECT_NE(Refusal([] { CheckOutputDirectory(OutputTarget("run", {"run/drops.csv"}), OutputKind::kDataset); })
                .find("contains the command's input"),
            std::string::npos);
  EXPECT_EQ(Read("ds/drops.csv"), "measured");
}

TEST_F(OutputPathTest, TrailingSlashSpacesQuotesAndNonAsciiNamesWork) {
  for (const char* path : {"new/", "with space", "it's", "x'; touch PWNED; echo '", "régolithe_月"}) {
    WriteOutputDirectory(path, OutputKind::kCampaign, Fill(path));
    EXPECT_EQ(Read(fs::path(path) / "summary.txt"), path);
  }
  for (const fs::directory_entry& e : fs::directory_iterator("."))
    EXPECT_EQ(e.path().filename().string().rfind(".new.partial-", 0), std::string::npos) << e.path();
  EXPECT_FALSE(fs::exists("PWNED"));
  EXPECT_EQ(Entries("."), 5);
}

TEST_F(OutputPathTest, FileOrSymbolicLinkAtTheTargetIsRefused) {
  Write("k", "a file of mine");
  EXPECT_NE(Refusal([] { WriteOutputDirectory("k", OutputKind::kLander, Fill("x")); }).find("not a directory"),
            std::string::npos);
  EXPECT_EQ(Read("k"), "a file of mine");
  fs::create_directory("real");
  fs::create_directory_symlink("real", "link");
  EXPECT_NE(Refusal([] { WriteOutputDirectory("link", OutputKind::kLander, Fill("x")); }).find("symbolic link"),
            std::string::npos);
  EXPECT_TRUE(fs::is_symlink("link"));
}

TEST_F(OutputPathTest, FailedFillLeavesTheEarlierOutputAndNoStaging) {
  WriteOutputDirectory("out", OutputKind::kDiagnosis, Fill("old"));
  EXPECT_THROW(WriteOutputDirectory("out", OutputKind::kDiagnosis,
                                    [](const std::string& staging) {
                                      Write(fs::path(staging) / "summary.txt", "half");
                                      throw std::runtime_error("plotting failed");
                                    }),
               std::runtime_error);
  EXPECT_EQ(Read("out/summary.txt"), "old");
  EXPECT_EQ(Entries("."), 1);
}

TEST_F(OutputPathTest, ErrorsNameTheUsersPathNotTheStagingDirectory) {
  const std::string why = Refusal([] {
    WriteOutputDirectory("out", OutputKind::kDataset, [](const std::string& staging) {
      WriteFileAtomically((fs::path(staging) / "no_such_dir" / "drops.csv").string(), [](std::ostream&) {});
    });
  });
  EXPECT_EQ(why.rfind("out/no_such_dir/drops.csv: cannot write", 0), 0u) << why;
  EXPECT_EQ(why.find(".partial-"), std::string::npos) << why;
}

TEST_F(OutputPathTest, StagingLeftByAKilledRunIsRemovedByTheNextRun) {
  WriteOutputDirectory("out", OutputKind::kLander, Fill("old"));
  const std::string dead = std::to_string(DeadPid());
  fs::create_directory(".out.partial-" + dead);  // what a killed run left: its marker is in it
  Write(".out.partial-" + dead + "/" + kOutputMarker, "touchdown output\nkind: lander\n");
  fs::create_directory(".out.partial-2" + dead);  // killed before its marker was written
  fs::create_directory(".out.partial-1" + dead);  // something else in it and no marker: not ours, kept
  Write(".out.partial-1" + dead + "/data.csv", "x");
  Write(".trace.csv.partial-" + dead, "t_s\n");   // a killed file write
  WriteOutputDirectory("out", OutputKind::kLander, Fill("new"));
  WriteOutputFile("trace.csv", [](std::ostream& out) { out << "t_s\n"; });
  EXPECT_FALSE(fs::exists(".out.partial-" + dead));
  EXPECT_FALSE(fs::exists(".trace.csv.partial-" + dead));
  EXPECT_FALSE(fs::exists(".out.partial-2" + dead));
  EXPECT_TRUE(fs::exists(".out.partial-1" + dead));
  EXPECT_EQ(Read("out/summary.txt"), "new");
}

// On a disk that a cluster's nodes share, a leftover of a process on another machine is that
// machine's to judge: a pid that is dead here may be alive there (a shard writing now).
TEST_F(OutputPathTest, StagingOfAProcessOnAnotherMachineIsLeftAlone) {
  const std::string tag = OutputOwnerTag();
  ASSERT_NE(tag.find('@'), std::string::npos) << tag;
  EXPECT_EQ(tag.substr(0, tag.find('@')), std::to_string(::getpid()));
  const std::string dead = std::to_string(DeadPid());
  const std::string here = tag.substr(tag.find('@'));  // "@HOST"
  fs::create_directory(".out.partial-" + dead + "@another-node");  // another node's shard, maybe alive
  Write(".out.partial-" + dead + "@another-node/" + kOutputMarker, "touchdown output\nkind: lander\n");
  fs::create_directory(".out.partial-" + dead + here);  // a killed run of this machine's
  Write(".out.partial-" + dead + here + "/" + kOutputMarker, "touchdown output\nkind: lander\n");
  Write(".trace.csv.partial-" + dead + "@another-node", "t_s\n");
  WriteOutputDirectory("out", OutputKind::kLander, Fill("new"));
  WriteOutputFile("trace.csv", [](std::ostream& out) { out << "t_s\n"; });
  EXPECT_TRUE(fs::exists(".out.partial-" + dead + "@another-node"));
  EXPECT_TRUE(fs::exists(".trace.csv.partial-" + dead + "@another-node"));
  EXPECT_FALSE(fs::exists(".out.partial-" + dead + here));
  EXPECT_EQ(Read("out/summary.txt"), "new");
}

TEST_F(OutputPathTest, OldOutputMovedAsideIsRestoredWhenTheNewOneNeverArrived) {
  const std::string dead = std::to_string(DeadPid());
  WriteOutputDirectory("elsewhere", OutputKind::kLander, Fill("old"));
  fs::rename("elsewhere", ".out.old-" + dead);  // a kill between the two renames of the fallback
  CheckOutputDirectory("out", OutputKind::kLander);
  WriteOutputDirectory("out", OutputKind::kLander, Fill("new"));
  EXPECT_EQ(Read("out/summary.txt"), "new");
  EXPECT_FALSE(fs::exists(".out.old-" + dead));
}

TEST_F(OutputPathTest, SingleFilesAreNewOrMarkedAsTouchdowns) {
  WriteOutputFile("t.csv", [](std::ostream& out) { out << "a\n"; });
  EXPECT_EQ(Read("t.csv"), "a\n");
  EXPECT_NE(Refusal([] { WriteOutputFile("t.csv", [](std::ostream& out) { out << "b\n"; }); })
                .find("exists and was not written by touchdown"),
            std::string::npos);
  EXPECT_EQ(Read("t.csv"), "a\n");
  const std::string mark = "# touchdown model";
  WriteOutputFile("m.yaml", [&](std::ostream& out) { out << mark << "\nx: 1\n"; }, mark);
  WriteOutputFile("m.yaml", [&](std::ostream& out) { out << mark << "\nx: 2\n"; }, mark);
  EXPECT_EQ(Read("m.yaml"), mark + "\nx: 2\n");
  Write("mine.yaml", "x: 0\n");
  EXPECT_FALSE(Refusal([&] { WriteOutputFile("mine.yaml", [](std::ostream&) {}, mark); }).empty());
  EXPECT_EQ(Read("mine.yaml"), "x: 0\n");
  EXPECT_EQ(Entries("."), 3);
}

TEST_F(OutputPathTest, SingleFilesAcceptAnyOfSeveralMarks) {
  const std::vector<std::string> marks = {"t_s,force_N", "t_s,force_N,x_m"};
  WriteOutputFile("t.csv", [](std::ostream& out) { out << "t_s,force_N,x_m\n1,2,3\n"; }, marks);
  WriteOutputFile("t.csv", [](std::ostream& out) { out << "t_s,force_N\n1,2\n"; }, marks);
  EXPECT_EQ(Read("t.csv"), "t_s,force_N\n1,2\n");
  Write("mine.csv", "t_s,force_N,other\n");
  EXPECT_FALSE(Refusal([&] { WriteOutputFile("mine.csv", [](std::ostream&) {}, marks); }).empty());
  EXPECT_EQ(Read("mine.csv"), "t_s,force_N,other\n");
}

TEST_F(OutputPathTest, SingleFileIntoAMissingDirectoryIsRefusedAndCreatesNothing) {
  EXPECT_NE(Refusal([] { CheckOutputFile("nowhere/deeper/t.csv"); }).find("does not exist; create it first"),
            std::string::npos);
  EXPECT_NE(Refusal([] { WriteOutputFile("nowhere/t.csv", [](std::ostream& out) { out << "x"; }); })
                .find("nowhere/t.csv: directory '"),
            std::string::npos);
  EXPECT_FALSE(fs::exists("nowhere"));
  fs::create_directory("somewhere");
  WriteOutputFile("somewhere/t.csv", [](std::ostream& out) { out << "x"; });
  EXPECT_EQ(Read("somewhere/t.csv"), "x");
}

TEST_F(OutputPathTest, SingleFileOntoADirectoryIsRefusedAndLeavesNothing) {
  fs::create_directory("d");
  for (const char* path : {"d", "d/", "."}) {
    EXPECT_FALSE(Refusal([&] { WriteOutputFile(path, [](std::ostream& out) { out << "x"; }); }).empty()) << path;
  }
  EXPECT_EQ(Entries("."), 1);
  EXPECT_EQ(Entries("d"), 0);
}

TEST_F(OutputPathTest, InPlaceOutputIsCreatedReopenedAndNeverEmptied) {
  OpenOutputDirectory("s", OutputKind::kSweep);
  Write("s/results.sqlite", "db");
  OpenOutputDirectory("s", OutputKind::kSweep);
  EXPECT_EQ(Read("s/results.sqlite"), "db");
  fs::create_directory("mine");
  Write("mine/a.txt", "a");
  EXPECT_NE(Refusal([] { OpenOutputDirectory("mine", OutputKind::kSweep); }).find("not written by touchdown"),
            std::string::npos);
  EXPECT_NE(Refusal([] { WriteOutputDirectory("s", OutputKind::kSweep, Fill("x")); }).find("in place"),
            std::string::npos);
  EXPECT_EQ(Read("s/results.sqlite"), "db");
}

// A link the user put inside an in-place output (`rm -r st/plots; ln -s ~/mine st/plots`) would be
// written through by a rerun: the output is refused, and what the link points to is untouched.
TEST_F(OutputPathTest, InPlaceOutputHoldingASymbolicLinkIsRefused) {
  OpenOutputDirectory("s", OutputKind::kSweep);
  fs::create_directory("mine");
  Write("mine/exceedance.png", "mine");
  fs::create_directory_symlink(dir_ / "mine", "s/plots");
  EXPECT_NE(Refusal([] { OpenOutputDirectory("s", OutputKind::kSweep); }).find("'plots', a symbolic link"),
            std::string::npos);
  EXPECT_NE(Refusal([] { ReplaceDerivedOutputs("s", OutputKind::kSweep, "summary.json", [](const std::string&) {}); })
                .find("'plots', a symbolic link"),
            std::string::npos);
  EXPECT_EQ(Read("mine/exceedance.png"), "mine");
}

// An analysis of `version`: a summary, a table and a plot in plots/.
auto Analysis(const std::string& version) {
  return [version](const std::string& staging) {
    fs::create_directories(fs::path(staging) / "plots");
    Write(fs::path(staging) / "plots" / "map.png", version);
    Write(fs::path(staging) / "table.csv", version);
    Write(fs::path(staging) / "summary.json", version);
  };
}

// Two threads of one process writing one output (Python's threads, one `out`) each stage their own
// copy, as two processes do: both finish, and what is there is one of them, whole. They used to
// share one staging name and fail ("cannot move the finished file into place").
TEST_F(OutputPathTest, TwoThreadsWritingOneOutputEachStageApart) {
  for (int round = 0; round < 20; ++round) {
    std::string errors[2];
    std::thread writers[2];
    for (int k = 0; k < 2; ++k)
      writers[k] = std::thread([&, k] {
        try {
          WriteOutputDirectory("out", OutputKind::kLander, Fill(std::string(1, char('a' + k))));
          WriteFileAtomically("trace.csv", [&](std::ostream& out) { out << std::string(100000, char('a' + k)); });
        } catch (const std::exception& e) {
          errors[k] = e.what();
        }
      });
    for (std::thread& t : writers) t.join();
    EXPECT_EQ(errors[0], "");
    EXPECT_EQ(errors[1], "");
    const std::string summary = Read("out/summary.txt"), trace = Read("trace.csv");
    EXPECT_TRUE(summary == "a" || summary == "b") << summary;
    EXPECT_TRUE(trace == std::string(100000, 'a') || trace == std::string(100000, 'b'));
  }
  for (const fs::directory_entry& e : fs::directory_iterator("."))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos) << e.path();
}

TEST_F(OutputPathTest, DerivedOutputsAreReplacedAsOneWhole) {
  OpenOutputDirectory("s", OutputKind::kSweep);
  Write("s/results.sqlite", "db");
  ReplaceDerivedOutputs("s", OutputKind::kSweep, "summary.json", Analysis("1"));
  EXPECT_EQ(Read("s/plots/map.png"), "1");
  ReplaceDerivedOutputs("s", OutputKind::kSweep, "summary.json", Analysis("2"));
  EXPECT_EQ(Read("s/plots/map.png"), "2");
  EXPECT_EQ(Read("s/table.csv"), "2");
  EXPECT_EQ(Read("s/summary.json"), "2");
  EXPECT_EQ(Read("s/results.sqlite"), "db");
  // A failure while the new analysis is drawn (gnuplot failing, a kill) leaves the earlier one whole.
  EXPECT_THROW(ReplaceDerivedOutputs("s", OutputKind::kSweep, "summary.json",
                                     [](const std::string& staging) {
                                       Analysis("3")(staging);
                                       throw InputError("gnuplot failed");
                                     }),
               InputError);
  EXPECT_EQ(Read("s/plots/map.png"), "2");
  EXPECT_EQ(Read("s/summary.json"), "2");
  // Nothing is left beside it: the results, the marker, the list of outputs and the outputs.
  EXPECT_EQ(Entries("s"), 6);
  // An output the new analysis no longer makes goes with the old one.
  ReplaceDerivedOutputs("s", OutputKind::kSweep, "summary.json", [](const std::string& staging) {
    Write(fs::path(staging) / "summary.json", "4");
  });
  EXPECT_FALSE(fs::exists("s/plots"));
  EXPECT_FALSE(fs::exists("s/table.csv"));
  EXPECT_EQ(Read("s/summary.json"), "4");
}

TEST_F(OutputPathTest, DerivedOutputsNeverReplaceAFileOfTheUsers) {
  OpenOutputDirectory("s", OutputKind::kSweep);
  ReplaceDerivedOutputs("s", OutputKind::kSweep, "summary.json", Analysis("1"));
  Write("s/plots/notes.txt", "mine");
  EXPECT_NE(Refusal([] { ReplaceDerivedOutputs("s", OutputKind::kSweep, "summary.json", Analysis("2")); })
                .find("holds 'plots/notes.txt', which touchdown did not write"),
            std::string::npos);
  EXPECT_EQ(Read("s/plots/notes.txt"), "mine");
  EXPECT_EQ(Read("s/summary.json"), "1");
}

// A run killed while it staged its analysis leaves a staging directory; the next run removes it.
TEST_F(OutputPathTest, DerivedOutputsStagingOfAKilledRunIsRemoved) {
  OpenOutputDirectory("s", OutputKind::kSweep);
  const fs::path left = "s/.derived.partial-" + std::to_string(DeadPid());
  fs::create_directories(left / "plots");
  Write(left / kOutputMarker, "touchdown output\nkind: sweep\n");
  Write(left / "plots" / "map.png", "half");
  ReplaceDerivedOutputs("s", OutputKind::kSweep, "summary.json", Analysis("1"));
  EXPECT_FALSE(fs::exists(left));
  EXPECT_EQ(Read("s/plots/map.png"), "1");
}

}  // namespace
}  // namespace touchdown::io
