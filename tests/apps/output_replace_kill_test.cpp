// Replacing an earlier output is atomic: `campaign`, `export` and `lander` are
// killed (SIGKILL) at random moments while they replace an earlier output of theirs, and what is left
// at the target must be one complete output, the old or the new, never a mixture or a part. The next
// run removes what the killed runs left beside the target.
#include <gtest/gtest.h>
#include <signal.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/touchdown_process.h"

namespace {

namespace fs = std::filesystem;
namespace testing_process = touchdown::testing_process;
using Clock = std::chrono::steady_clock;

pid_t Start(const fs::path& dir, const std::vector<std::string>& args) {
  const pid_t pid = testing_process::StartTouchdown(args, dir.string());
  EXPECT_GT(pid, 0) << "cannot start " << TOUCHDOWN_BINARY;
  return pid;
}

int Wait(pid_t pid) { return testing_process::WaitForStatus(pid); }

// Runs to the end; returns the wall time in seconds.
double RunToEnd(const fs::path& dir, const std::vector<std::string>& args) {
  const auto start = Clock::now();
  const int status = Wait(Start(dir, args));
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "touchdown " << args.front() << " failed";
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Every file below `dir` with its bytes (PNG images by name only: a renderer's bytes are not ours to pin).
std::map<std::string, std::string> Fingerprint(const fs::path& dir) {
  std::map<std::string, std::string> files;
  if (!fs::exists(dir)) return files;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = e.path().lexically_relative(dir).generic_string();
    std::string bytes = "png, not empty";
    if (e.path().extension() != ".png" || e.file_size() == 0) {
      std::ifstream in(e.path(), std::ios::binary);
      std::stringstream s;
      s << in.rdbuf();
      bytes = s.str();
    }
    files[rel] = bytes;
  }
  return files;
}

// What is left beside `target` (hidden `.TARGET.*` entries), with what each holds.
// (Text appended piece by piece: GCC 12 warns, -Wrestrict, on "literal" + string here.)
std::string Leftovers(const fs::path& dir, const std::string& target) {
  std::string left, prefix = ".";
  prefix += target;
  prefix += '.';
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    if (e.path().filename().string().rfind(prefix, 0) != 0) continue;
    left += e.path().filename().string();
    left += " [";
    if (e.is_directory())
      for (const fs::directory_entry& f : fs::directory_iterator(e.path())) {
        left += ' ';
        left += f.path().filename().string();
      }
    left += " ] ";
  }
  return left;
}

class OutputReplaceKill : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("td_kill_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void Write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }

  // Replaces the old output at `out` by the new one `kills` times, each killed after a random delay
  // within the new run's own duration (and a little past it), and checks what is left each time.
  void KillWhileReplacing(const std::vector<std::string>& old_args, const std::vector<std::string>& new_args,
                          int kills, unsigned seed) {
    const std::string out = "out";
    const double seconds = RunToEnd(dir_, new_args);
    const auto new_output = Fingerprint(dir_ / out);
    RunToEnd(dir_, old_args);
    const auto old_output = Fingerprint(dir_ / out);
    ASSERT_NE(old_output, new_output) << "the test needs two different outputs";
    ASSERT_TRUE(old_output.count(".touchdown-output"));
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> delay(0.0, 1.2 * seconds);
    int old_left = 0, new_left = 0;
    for (int k = 0; k < kills; ++k) {
      const pid_t pid = Start(dir_, new_args);
      std::this_thread::sleep_for(std::chrono::duration<double>(delay(random)));
      ::kill(pid, SIGKILL);
      Wait(pid);
      const auto left = Fingerprint(dir_ / out);
      if (left == old_output) {
        ++old_left;
      } else if (left == new_output) {
        ++new_left;
        RunToEnd(dir_, old_args);  // back to the old output for the next kill
      } else {
        ADD_FAILURE() << "kill " << k << ": the output is neither the old nor the new one (" << left.size()
                      << " files; old " << old_output.size() << ", new " << new_output.size() << ")";
      }
    }
    std::cout << "[ kills    ] " << new_args.front() << ": " << kills << " kills, old output left " << old_left
              << " times, new " << new_left << " times (a run takes " << seconds << " s)\n";
    RunToEnd(dir_, new_args);
    EXPECT_EQ(Fingerprint(dir_ / out), new_output);
    EXPECT_EQ(Leftovers(dir_, out), "") << "staging directories of killed runs were left behind";
  }

  fs::path dir_;
};

TEST_F(OutputReplaceKill, Campaign) {
  const std::string head = "schema_version: 1\ntype: campaign\nname: kill_test\ngravity_m_s2: 9.81\n"
                           "reference_speed_m_s: 1.0\ndrops:\n";
  Write("old.yaml", head + "  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [0.7, 1.0]}\n");
  Write("new.yaml", head + "  - {pad: flat, soil: fjs1_lp, impact_speeds_m_s: [0.5, 0.7, 1.0, 1.5]}\n"
                           "  - {pad: c4, soil: fjs1_cp, impact_speeds_m_s: [0.5, 0.7, 1.0, 1.5]}\n"
                           "  - {pad: curved, soil: fjs1_lp, impact_speeds_m_s: [0.5, 0.7, 1.0, 1.5]}\n");
  KillWhileReplacing({"campaign", "old.yaml", "--out", "out"}, {"campaign", "new.yaml", "--out", "out"}, 10, 1);
}

TEST_F(OutputReplaceKill, Lander) {
  const std::string scenario = std::string(TOUCHDOWN_SOURCE_DIR) + "/data/scenarios/lander_case_A.yaml";
  std::ifstream in(scenario);
  std::stringstream text;
  text << in.rdbuf();
  std::string higher = text.str();
  const std::string from = "drop_height_m: 0.10";
  ASSERT_NE(higher.find(from), std::string::npos);
  higher.replace(higher.find(from), from.size(), "drop_height_m: 0.20");
  Write("higher.yaml", higher);
  KillWhileReplacing({"lander", scenario, "--out", "out"}, {"lander", "higher.yaml", "--out", "out"}, 10, 2);
}

TEST_F(OutputReplaceKill, Export) {
  const std::string head = "schema_version: 1\ntype: sweep\nname: kill_test\ntraces: full\n";
  Write("a.yaml", head + "grid: {pad: [flat], soil: [fjs1_lp], impact_speed_m_s: [0.7, 1.0]}\n");
  Write("b.yaml", head + "grid: {pad: [flat, c4], soil: [fjs1_lp, fjs1_cp], impact_speed_m_s: {from: 0.5, to: 1.5, "
                         "count: 12}}\n");
  RunToEnd(dir_, {"sweep", "a.yaml", "--out", "a", "--threads", "1", "--progress", "none"});
  RunToEnd(dir_, {"sweep", "b.yaml", "--out", "b", "--threads", "1", "--progress", "none"});
  KillWhileReplacing({"export", "a", "--to", "out"}, {"export", "b", "--to", "out"}, 10, 3);
}

}  // namespace
