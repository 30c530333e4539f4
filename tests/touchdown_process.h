#pragma once
// Tests that run the touchdown executable as a user does, as a child process: started with an
// argument vector (posix_spawn, no shell), optionally in another working directory, its standard
// output and error sent to files (or discarded). TOUCHDOWN_BINARY is defined by tests/CMakeLists.txt.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

extern char** environ;

namespace touchdown::testing_process {

// The pid of the started program (words[0], looked up on PATH), or -1 when it could not be started.
inline pid_t StartProgram(std::vector<std::string> words, const std::string& working_dir = "",
                          const std::string& stdout_path = "/dev/null", const std::string& stderr_path = "/dev/null") {
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!working_dir.empty()) posix_spawn_file_actions_addchdir_np(&actions, working_dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int error = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return error == 0 ? pid : -1;
}

// The pid of touchdown started with `args`, or -1 when it could not be started.
inline pid_t StartTouchdown(const std::vector<std::string>& args, const std::string& working_dir = "",
                            const std::string& stdout_path = "/dev/null", const std::string& stderr_path = "/dev/null") {
  std::vector<std::string> words = {TOUCHDOWN_BINARY};
  words.insert(words.end(), args.begin(), args.end());
  return StartProgram(words, working_dir, stdout_path, stderr_path);
}

// The raw wait status of a started process (WIFEXITED, WEXITSTATUS, WTERMSIG apply).
inline int WaitForStatus(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

}  // namespace touchdown::testing_process
