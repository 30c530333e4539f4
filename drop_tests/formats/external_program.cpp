#include "drop_tests/formats/external_program.h"

// posix_spawnp rather than Boost.Process (Debian 12 ships 1.74): glibc 2.36 has everything
// needed (posix_spawn_file_actions_addchdir_np for the working directory, adddup2 for the
// log), it starts the child with CLONE_VFORK instead of fork(), so a process holding gigabytes
// of traces does not copy its page tables, and it reports a failed exec (program missing) as
// its return value. Boost.Process 1.74 forks, needs Boost.Filesystem linked, and its v1 error
// reporting and start_dir would be more code around the same four system calls.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

extern char** environ;

namespace touchdown::io {

namespace fs = std::filesystem;

namespace {

// A file descriptor closed on every path out of RunProgram; O_CLOEXEC so it never leaks into
// another child.
class Fd {
 public:
  Fd(const fs::path& path, int flags) : fd_(::open(path.c_str(), flags | O_CLOEXEC, 0644)) {
    if (fd_ < 0) throw fs::filesystem_error("cannot open", path, std::error_code(errno, std::generic_category()));
  }
  ~Fd() { ::close(fd_); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

class FileActions {
 public:
  FileActions() { ::posix_spawn_file_actions_init(&actions_); }
  ~FileActions() { ::posix_spawn_file_actions_destroy(&actions_); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
  posix_spawn_file_actions_t* get() { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

// The last non-empty line of a text file, at most `max_chars` long ("" when unreadable).
std::string LastLogLine(const fs::path& log, size_t max_chars = 300) {
  std::ifstream in(log, std::ios::binary);
  std::string line, last;
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.pop_back();
    if (!line.empty()) last = line;
  }
  if (last.size() > max_chars) last = last.substr(0, max_chars) + "...";
  return last;
}

std::string Tail(const fs::path& log) {
  const std::string line = LastLogLine(log);
  return line.empty() ? std::string() : ": " + line;
}

}  // namespace

void RunProgram(const ProgramRun& run) {
  if (run.argv.empty() || run.argv.front().empty()) throw std::invalid_argument("RunProgram: no program named");
  const std::string& program = run.argv.front();
  if (run.stderr_log.empty()) throw std::invalid_argument("RunProgram: no stderr log for " + program);
  // Opened here, not by the child, so a log that cannot be written is reported as that (with
  // its path and errno) rather than as the program failing to start.
  const Fd in("/dev/null", O_RDONLY);
  const Fd err(run.stderr_log, O_WRONLY | O_CREAT | O_TRUNC);
  const Fd out(run.stdout_file.empty() ? fs::path("/dev/null") : run.stdout_file, O_WRONLY | O_CREAT | O_TRUNC);

  FileActions actions;
  ::posix_spawn_file_actions_adddup2(actions.get(), in.get(), STDIN_FILENO);
  ::posix_spawn_file_actions_adddup2(actions.get(), out.get(), STDOUT_FILENO);
  ::posix_spawn_file_actions_adddup2(actions.get(), err.get(), STDERR_FILENO);
  if (!run.working_directory.empty()) {
    std::error_code ec;
    if (!fs::is_directory(run.working_directory, ec))
      throw fs::filesystem_error("cannot run " + program + " in", run.working_directory,
                                 ec ? ec : std::make_error_code(std::errc::not_a_directory));
    ::posix_spawn_file_actions_addchdir_np(actions.get(), run.working_directory.c_str());
  }

  std::vector<char*> argv;
  for (const std::string& a : run.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawn_error = ::posix_spawnp(&pid, program.c_str(), actions.get(), nullptr, argv.data(), environ);
  if (spawn_error != 0)
    throw ExternalProgramError("cannot run " + program + ": " + std::strerror(spawn_error), program, spawn_error, -1,
                               0, run.stderr_log);

  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR)
      throw ExternalProgramError("waiting for " + program + ": " + std::strerror(errno), program, 0, -1, 0,
                                 run.stderr_log);
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return;
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    throw ExternalProgramError(program + " was killed by signal " + std::to_string(sig) + " (" + ::strsignal(sig) +
                                   ")" + Tail(run.stderr_log) + " (log: " + run.stderr_log.string() + ")",
                               program, 0, -1, sig, run.stderr_log);
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  throw ExternalProgramError(program + " exited with status " + std::to_string(code) + Tail(run.stderr_log) +
                                 " (log: " + run.stderr_log.string() + ")",
                             program, 0, code, 0, run.stderr_log);
}

}  // namespace touchdown::io
