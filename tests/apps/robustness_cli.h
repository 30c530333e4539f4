#pragma once
// Running the touchdown executable as a user does, for the robustness table and the
// determinism checks (the same way tests/apps/cli_test.cpp does: TOUCHDOWN_BINARY from CMake,
// the data directory from TOUCHDOWN_DATA_DIR, a private temporary directory per test).
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace touchdown::testing_cli {

namespace fs = std::filesystem;

struct CliRun {
  int status = -1;  // exit status; -1 if killed by a signal (a crash)
  int signal = 0;
  std::string out, err;
};

inline std::string Slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string ShellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// A scratch directory (removed at the end) and the touchdown binary.
class Sandbox {
 public:
  explicit Sandbox(const std::string& name)
      : dir_(fs::temp_directory_path() / ("touchdown_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  ~Sandbox() { fs::remove_all(dir_); }
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  const fs::path& dir() const { return dir_; }

  std::string Write(const std::string& name, const std::string& bytes) const {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }

  // `args` is a shell word list (already quoted where needed); stdout and stderr are captured.
  CliRun Touchdown(const std::string& args, const std::string& env = "") const {
    const std::string out = (dir_ / ".stdout").string(), err = (dir_ / ".stderr").string();
    const std::string command =
        "cd " + ShellQuote(dir_.string()) + " && " + env + (env.empty() ? "" : " ") + TOUCHDOWN_BINARY + " " + args +
        " >" + ShellQuote(out) + " 2>" + ShellQuote(err);
    const int raw = std::system(command.c_str());
    CliRun r;
    if (WIFEXITED(raw)) {
      r.status = WEXITSTATUS(raw);
      // The shell reports a child killed by a signal as 128 + signal.
      if (r.status > 128) r.signal = r.status - 128;
    } else if (WIFSIGNALED(raw)) {
      r.signal = WTERMSIG(raw);
    }
    r.out = Slurp(out);
    r.err = Slurp(err);
    return r;
  }

 private:
  fs::path dir_;
};

// The directory the binary reads pads and soils from in these tests.
inline std::string DataDir() {
  if (const char* env = std::getenv("TOUCHDOWN_DATA_DIR"); env && *env) return env;
  return std::string(TOUCHDOWN_SOURCE_DIR) + "/data";
}

}  // namespace touchdown::testing_cli
