#include "drop_tests/sweep/sweep_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "rft/input_error.h"

namespace touchdown::sweep {

SweepDirLock::SweepDirLock(const std::string& dir)
    : path_((std::filesystem::path(dir) / "sweep.lock").string()) {
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd_ < 0) throw MakeInputError(path_, "", std::string("cannot open the sweep lock: ") + std::strerror(errno));
  int rc;
  while ((rc = ::flock(fd_, LOCK_EX | LOCK_NB)) != 0 && errno == EINTR) {
  }
  if (rc != 0) {
    const int error = errno;
    char buffer[32] = {};
    const ssize_t n = ::pread(fd_, buffer, sizeof buffer - 1, 0);
    ::close(fd_);
    fd_ = -1;
    std::string holder(buffer, n > 0 ? static_cast<size_t>(n) : 0);
    while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
    if (error == EWOULDBLOCK)
      throw MakeInputError(path_, "",
                           "another touchdown (pid " + (holder.empty() ? std::string("unknown") : holder) +
                               ") is writing to this sweep directory; wait for it to finish, or stop it (a stopped "
                               "sweep resumes when run again)");
    throw MakeInputError(path_, "", std::string("cannot lock: ") + std::strerror(error));
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  // The pid is only informative (for the refusal message): a failed write leaves the lock held.
  if (::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
  }
}

SweepDirLock::~SweepDirLock() {
  if (fd_ >= 0) ::close(fd_);  // closing the only descriptor releases the flock
}

}  // namespace touchdown::sweep
