#pragma once
// Running another program (gnuplot) the way touchdown runs everything: an argument vector,
// never a shell, so no character of a user's path or name is ever interpreted. The program's
// stderr goes to a log file, its exit status is checked, and every failure is an exception
// naming the program, what went wrong and the log.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace touchdown::io {

struct ProgramRun {
  std::vector<std::string> argv;             // argv[0] is looked up on PATH; passed verbatim
  std::filesystem::path working_directory;   // empty: the caller's
  std::filesystem::path stderr_log;          // required: created or truncated
  std::filesystem::path stdout_file;         // empty: discarded (/dev/null)
};

class ExternalProgramError : public std::runtime_error {
 public:
  ExternalProgramError(const std::string& message, std::string program, int spawn_errno, int exit_status,
                       int signal, std::filesystem::path log)
      : std::runtime_error(message),
        program_(std::move(program)),
        spawn_errno_(spawn_errno),
        exit_status_(exit_status),
        signal_(signal),
        log_(std::move(log)) {}
  const std::string& program() const { return program_; }
  int spawn_errno() const { return spawn_errno_; }  // non-zero: the program did not start
  int exit_status() const { return exit_status_; }  // -1 unless it exited
  int signal() const { return signal_; }            // non-zero: killed by this signal
  const std::filesystem::path& log() const { return log_; }

 private:
  std::string program_;
  int spawn_errno_;
  int exit_status_;
  int signal_;
  std::filesystem::path log_;
};

// Runs the program to completion. Returns normally only when it exited with status 0; otherwise
// throws ExternalProgramError whose message (one line) carries the last line of the log.
void RunProgram(const ProgramRun& run);

}  // namespace touchdown::io
