#pragma once
// One writer per sweep output directory: `sweep` (its rank 0 under MPI; the other ranks never
// touch the directory, so ranks of one run cannot refuse each other) and `merge` hold an
// exclusive flock(2) on DIR/sweep.lock while they write, with their pid in the file. A second
// process is refused at once (InputError, exit 2) naming the holder's pid, rather than waiting:
// two runs on one directory would otherwise both compute every drop. The kernel releases the
// lock when its holder exits, however it exits (SIGKILL included), so a stale file never blocks.
#include <string>

namespace touchdown::sweep {

class SweepDirLock {
 public:
  // Takes the lock of `dir` (which must exist). Throws InputError naming DIR/sweep.lock and the
  // holder's pid when another process holds it, or the OS reason when the file cannot be opened.
  explicit SweepDirLock(const std::string& dir);
  ~SweepDirLock();  // releases the lock (the file stays)
  SweepDirLock(const SweepDirLock&) = delete;
  SweepDirLock& operator=(const SweepDirLock&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace touchdown::sweep
