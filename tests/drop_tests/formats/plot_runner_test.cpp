// The program runner (no shell, exit status, stderr log), the plot runner (gnuplot in the
// output directory, every PNG checked complete) and plot decimation.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "drop_tests/formats/external_program.h"
#include "drop_tests/formats/plot_decimation.h"
#include "drop_tests/formats/plot_runner.h"
#include "rft/input_error.h"
#include "tests/scratch_dir_test.h"

namespace touchdown::io {
namespace {

namespace fs = std::filesystem;

using testing_scratch::Slurp;

// A scratch directory whose name holds what broke the shell command lines: a quote, spaces, a
// semicolon and non-ASCII characters.
class PlotRunnerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("touchdown_plot_runner_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    dir_ = root_ / "it's a; touch PWNED; é ✓";
    fs::create_directories(dir_ / "plots");
  }
  void TearDown() override { fs::remove_all(root_); }
  bool Pwned() const { return fs::exists(root_ / "PWNED") || fs::exists(dir_ / "PWNED") || fs::exists("PWNED"); }

  fs::path root_, dir_;
};

const std::vector<std::string> kHostileArgs = {"it's", "a b", "x'; touch PWNED; echo '", "é ✓ 測", "$(touch PWNED)",
                                               "`touch PWNED`", "\"quoted\"", ""};

TEST_F(PlotRunnerTest, ArgumentsReachTheProgramVerbatim) {
  std::vector<std::string> argv = {"printf", "[%s]\\n"};
  argv.insert(argv.end(), kHostileArgs.begin(), kHostileArgs.end());
  RunProgram({argv, dir_, dir_ / "err.log", dir_ / "out.txt"});
  std::string expected;
  for (const std::string& a : kHostileArgs) expected += "[" + a + "]\n";
  EXPECT_EQ(Slurp(dir_ / "out.txt"), expected);
  EXPECT_FALSE(Pwned());
}

TEST_F(PlotRunnerTest, ProgramRunsInTheWorkingDirectory) {
  RunProgram({{"pwd", "-P"}, dir_, root_ / "err.log", root_ / "out.txt"});
  EXPECT_EQ(Slurp(root_ / "out.txt"), fs::canonical(dir_).string() + "\n");
}

TEST_F(PlotRunnerTest, NonZeroExitThrowsNamingProgramStatusAndLog) {
  const fs::path log = dir_ / "ls.log";
  try {
    RunProgram({{"ls", "no such file here"}, dir_, log, {}});
    FAIL() << "a failing program passed";
  } catch (const ExternalProgramError& e) {
    EXPECT_EQ(e.program(), "ls");
    EXPECT_EQ(e.spawn_errno(), 0);
    EXPECT_EQ(e.exit_status(), 2);  // ls: "serious trouble" (a missing operand)
    EXPECT_EQ(e.log(), log);
    const std::string what = e.what();
    EXPECT_NE(what.find("ls exited with status 2"), std::string::npos) << what;
    EXPECT_NE(what.find("no such file here"), std::string::npos) << what;  // ls's own message, from the log
    EXPECT_NE(what.find(log.string()), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;  // one line
  }
  EXPECT_NE(Slurp(log).find("no such file here"), std::string::npos);
}

TEST_F(PlotRunnerTest, ProgramKilledBySignalThrows) {
  try {
    RunProgram({{"perl", "-e", "kill 'TERM', $$"}, dir_, dir_ / "perl.log", {}});  // perl-base is Essential
    FAIL() << "a killed program passed";
  } catch (const ExternalProgramError& e) {
    EXPECT_EQ(e.signal(), SIGTERM);
    EXPECT_NE(std::string(e.what()).find("perl was killed by signal 15"), std::string::npos) << e.what();
  }
}

TEST_F(PlotRunnerTest, MissingProgramThrowsWithENOENT) {
  try {
    RunProgram({{"touchdown-no-such-program"}, dir_, dir_ / "x.log", {}});
    FAIL() << "a missing program passed";
  } catch (const ExternalProgramError& e) {
    EXPECT_EQ(e.spawn_errno(), ENOENT);
    EXPECT_NE(std::string(e.what()).find("cannot run touchdown-no-such-program"), std::string::npos) << e.what();
  }
}

TEST_F(PlotRunnerTest, UnwritableLogIsReportedAsSuch) {
  EXPECT_THROW(RunProgram({{"true"}, dir_, dir_ / "no_dir" / "x.log", {}}), fs::filesystem_error);
}

// PNG completeness ------------------------------------------------------------------------

std::string MinimalPngBytes() {
  const std::string signature = "\x89PNG\r\n\x1a\n";
  const std::string body(40, 'x');  // the chunks in between are not read
  const std::string iend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  return signature + body + iend;
}

TEST_F(PlotRunnerTest, PngProblemFindsTruncatedMissingAndForeignFiles) {
  const std::string png = MinimalPngBytes();
  std::ofstream(dir_ / "ok.png", std::ios::binary) << png;
  std::ofstream(dir_ / "cut.png", std::ios::binary) << png.substr(0, png.size() - 5);
  std::ofstream(dir_ / "tiny.png", std::ios::binary) << png.substr(0, 10);
  std::ofstream(dir_ / "text.png", std::ios::binary) << "not a png at all, but long enough to have a tail";
  EXPECT_EQ(PngProblem(dir_ / "ok.png"), "");
  EXPECT_NE(PngProblem(dir_ / "cut.png").find("truncated"), std::string::npos);
  EXPECT_NE(PngProblem(dir_ / "tiny.png").find("truncated"), std::string::npos);
  EXPECT_EQ(PngProblem(dir_ / "text.png"), "not a PNG");
  EXPECT_EQ(PngProblem(dir_ / "absent.png"), "missing");
}

// RenderPlots -----------------------------------------------------------------------------

const std::string kFigure =
    "set terminal pngcairo size 1000,800 font 'sans,10'\nset output 'plots/a.png'\n"
    "set samples 2000\nplot sin(x)*x with lines lw 2, cos(7*x)*x with points pt 7 title " +
    GnuplotQuote("it's é") + "\n";

TEST_F(PlotRunnerTest, RendersInADirectoryNamedWithQuotesSpacesAndNonAscii) {
  RenderPlots(dir_, {"plots/a.gp", kFigure, {"plots/a.png"}});
  EXPECT_EQ(Slurp(dir_ / "plots" / "a.gp"), kFigure);
  EXPECT_EQ(PngProblem(dir_ / "plots" / "a.png"), "");
  EXPECT_FALSE(fs::exists(dir_ / "plots" / "gnuplot.log"));  // removed when all is well
  EXPECT_FALSE(Pwned());
}

TEST_F(PlotRunnerTest, RelativeDirectoryWorks) {
  const fs::path cwd = fs::current_path();
  fs::current_path(root_);
  try {
    RenderPlots(dir_.filename(), {"plots/a.gp", kFigure, {"plots/a.png"}});
  } catch (...) {
    fs::current_path(cwd);
    throw;
  }
  fs::current_path(cwd);
  EXPECT_EQ(PngProblem(dir_ / "plots" / "a.png"), "");
}

// gnuplot failing is, on a user's machine, gnuplot's installation failing (every script is
// rendered by the test suite): exit 2 with gnuplot's own first error line, on one line.
TEST_F(PlotRunnerTest, GnuplotErrorIsAnInputErrorWithItsFirstErrorLine) {
  try {
    RenderPlots(dir_, {"plots/bad.gp", "set terminal nosuchterminal\nset output 'plots/b.png'\nplot x\n", {"plots/b.png"}});
    FAIL() << "a failing gnuplot passed";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("plots/bad.gp: gnuplot exited with status 1"), std::string::npos) << what;
    EXPECT_NE(what.find("line 1: unknown or ambiguous terminal type"), std::string::npos) << what;
    EXPECT_NE(what.find("log: plots/gnuplot.log"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_TRUE(fs::exists(dir_ / "plots" / "gnuplot.log"));  // kept for the user
}

// A gnuplot that starts but fails on this machine (here a stand-in on the PATH that prints two
// lines and exits 1; the same for one killed by a signal): the first line is the one shown.
TEST_F(PlotRunnerTest, BrokenGnuplotInstallationIsAnInputErrorNamingItsFirstLine) {
  const fs::path bin = root_ / "broken_bin";
  fs::create_directories(bin);
  std::ofstream(bin / "gnuplot") << "#!/bin/sh\necho 'Could not find/open font when opening font \"sans\"' >&2\n"
                                    "echo 'second line' >&2\nexit 1\n";
  fs::permissions(bin / "gnuplot", fs::perms::owner_all);
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", (bin.string() + ":" + path).c_str(), 1);
  std::string message;
  try {
    RenderPlots(dir_, {"plots/a.gp", kFigure, {"plots/a.png"}});
  } catch (const InputError& e) {
    message = e.what();
  } catch (const std::exception& e) {
    message = std::string("not an InputError: ") + e.what();
  }
  // Killed: a stand-in that kills itself.
  std::ofstream(bin / "gnuplot", std::ios::trunc) << "#!/bin/sh\nkill -9 $$\n";
  std::string killed;
  try {
    RenderPlots(dir_, {"plots/a.gp", kFigure, {"plots/a.png"}});
  } catch (const InputError& e) {
    killed = e.what();
  } catch (const std::exception& e) {
    killed = std::string("not an InputError: ") + e.what();
  }
  ::setenv("PATH", path.c_str(), 1);
  EXPECT_EQ(message.find("not an InputError"), std::string::npos) << message;
  EXPECT_NE(message.find("gnuplot exited with status 1: Could not find/open font"), std::string::npos) << message;
  EXPECT_EQ(message.find("second line"), std::string::npos) << message;
  EXPECT_NE(killed.find("plots/a.gp: gnuplot was killed by signal 9"), std::string::npos) << killed;
}

TEST_F(PlotRunnerTest, OutputNotWrittenIsAnInputErrorNamingTheFile) {
  try {
    RenderPlots(dir_, {"plots/a.gp", kFigure, {"plots/a.png", "plots/never.png"}});
    FAIL() << "a missing PNG passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("plots/never.png"), std::string::npos) << e.what();
  }
}

TEST_F(PlotRunnerTest, StalePngOfAnEarlierRunDoesNotPass) {
  std::ofstream(dir_ / "plots" / "stale.png", std::ios::binary) << MinimalPngBytes();
  EXPECT_THROW(RenderPlots(dir_, {"plots/a.gp", kFigure, {"plots/a.png", "plots/stale.png"}}), InputError);
}

TEST_F(PlotRunnerTest, GnuplotMissingIsAClearInputError) {
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  fs::create_directories(root_ / "empty_bin");
  ::setenv("PATH", (root_ / "empty_bin").c_str(), 1);
  try {
    RenderPlots(dir_, {"plots/a.gp", kFigure, {"plots/a.png"}});
    ::setenv("PATH", path.c_str(), 1);
    FAIL() << "rendered without gnuplot";
  } catch (const InputError& e) {
    ::setenv("PATH", path.c_str(), 1);
    EXPECT_NE(std::string(e.what()).find("gnuplot: not found on the PATH"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::exists(dir_ / "plots" / "a.gp"));  // the script is written before gnuplot runs
}

// A full disk, simulated by a file size limit (RLIMIT_FSIZE, inherited by gnuplot): with
// SIGXFSZ ignored, writes fail with EFBIG and gnuplot exits 0 after writing a truncated PNG, as
// on a full disk; with SIGXFSZ at its default gnuplot is killed. Both are write failures.
class FileSizeLimit {
 public:
  FileSizeLimit(rlim_t bytes, bool ignore_sigxfsz) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limited);
    saved_handler_ = std::signal(SIGXFSZ, ignore_sigxfsz ? SIG_IGN : SIG_DFL);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, saved_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*saved_handler_)(int) = SIG_DFL;
};

TEST_F(PlotRunnerTest, TruncatedPngFromAFullDiskIsCaught) {
  std::string message;
  {
    const FileSizeLimit limit(8192, /*ignore_sigxfsz=*/true);
    try {
      RenderPlots(dir_, {"plots/a.gp", kFigure, {"plots/a.png"}});
    } catch (const InputError& e) {
      message = e.what();
    }
  }
  ASSERT_FALSE(message.empty()) << "a truncated PNG passed";
  EXPECT_NE(message.find("plots/a.png"), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_EQ(fs::file_size(dir_ / "plots" / "a.png"), 8192u);  // what gnuplot left
}

TEST_F(PlotRunnerTest, GnuplotKilledAtTheFileSizeLimitIsAWriteFailure) {
  std::string message;
  {
    const FileSizeLimit limit(8192, /*ignore_sigxfsz=*/false);
    try {
      RenderPlots(dir_, {"plots/a.gp", kFigure, {"plots/a.png"}});
    } catch (const InputError& e) {
      message = e.what();
    }
  }
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
}

TEST_F(PlotRunnerTest, PlaceholderRendersWhereThereIsNothingToPlot) {
  const std::string script = "set terminal pngcairo size 400,300\nset output 'plots/empty.png'\n"
                             "set multiplot layout 1,2\n" + PlaceholderPlot("no drop: it's empty") +
                             PlaceholderPlot("nothing") + "unset multiplot\n";
  RenderPlots(dir_, {"plots/empty.gp", script, {"plots/empty.png"}});
  EXPECT_EQ(PngProblem(dir_ / "plots" / "empty.png"), "");
}

TEST(GnuplotQuote, DoublesQuotesAndFlattensLineBreaks) {
  EXPECT_EQ(GnuplotQuote("it's"), "'it''s'");
  EXPECT_EQ(GnuplotQuote("a\nb\r"), "'a b '");
  EXPECT_EQ(GnuplotQuote("é \"x\" $y `z`"), "'é \"x\" $y `z`'");
}

// Decimation ------------------------------------------------------------------------------

TEST(PlotDecimation, ShortTracesAreKeptWhole) {
  std::vector<double> t(kPlotRowsKeptWhole), y(kPlotRowsKeptWhole, 1.0);
  for (size_t i = 0; i < t.size(); ++i) t[i] = static_cast<double>(i);
  const std::vector<size_t> keep = PlotRowsToKeep(t.size(), {t, y});
  ASSERT_EQ(keep.size(), t.size());
  for (size_t i = 0; i < keep.size(); ++i) EXPECT_EQ(keep[i], i);
}

TEST(PlotDecimation, TenMillionRowsKeepEveryBucketsExtremesWithinTheBound) {
  const size_t n = 10'000'000;
  std::vector<double> t(n), force(n), depth(n);
  for (size_t i = 0; i < n; ++i) {
    t[i] = 1e-6 * static_cast<double>(i);
    force[i] = 100.0 * std::sin(1e-4 * static_cast<double>(i)) + 3.0 * std::sin(0.37 * static_cast<double>(i));
    depth[i] = 1e-3 * std::cos(3e-5 * static_cast<double>(i));
  }
  force[7'654'321] = 1e4;  // a one-sample spike
  depth[1'234'567] = -1.0;
  force[42] = std::nan("");
  const std::vector<size_t> keep = PlotRowsToKeep(n, {force, depth});
  EXPECT_LE(keep.size(), kPlotBuckets * (2 + 2 * 2));
  EXPECT_GE(keep.size(), kPlotBuckets * 2);
  EXPECT_EQ(keep.front(), 0u);
  EXPECT_EQ(keep.back(), n - 1);
  for (size_t i = 1; i < keep.size(); ++i) ASSERT_LT(keep[i - 1], keep[i]);
  auto kept = [&](size_t row) { return std::binary_search(keep.begin(), keep.end(), row); };
  EXPECT_TRUE(kept(7'654'321));
  EXPECT_TRUE(kept(1'234'567));
  EXPECT_FALSE(kept(42));
  // Every bucket keeps its own extremes: the envelope of the figure is the full trace's.
  for (size_t b = 0; b < kPlotBuckets; b += 97) {
    const size_t begin = b * n / kPlotBuckets, end = (b + 1) * n / kPlotBuckets;
    double hi = -INFINITY, hi_kept = -INFINITY;
    for (size_t i = begin; i < end; ++i)
      if (!std::isnan(force[i])) {
        hi = std::max(hi, force[i]);
        if (kept(i)) hi_kept = std::max(hi_kept, force[i]);
      }
    EXPECT_EQ(hi_kept, hi) << "bucket " << b;
  }
}

TEST(PlotDecimation, ColumnOfTheWrongLengthIsRefused) {
  const std::vector<double> a(10), b(9);
  EXPECT_THROW(PlotRowsToKeep(10, {a, b}), std::invalid_argument);
}

}  // namespace
}  // namespace touchdown::io
