#pragma once
// Progress of a long job on standard error: a bar on a terminal ([####....] done/total, rate,
// ETA), else a plain line every `interval_s`, and lines of notes (a failed drop) above the bar.
// A job that ends within `quiet_s` prints nothing at all, so quick commands keep a clean stderr.
// Add and Note may be called from worker threads. A caller that shows progress its own way (the
// Python module's bar) passes ProgressCounts and polls them from its thread.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <mutex>
#include <string>

namespace touchdown::io {

enum class ProgressMode { kAuto, kBar, kLines, kNone };

// The counts a Progress shows, kept up to date whatever its mode, for another thread to read while
// the job runs. A job of several stages (a study's landings, then its re-checks) starts each
// anew: total and done then both change.
struct ProgressCounts {
  std::atomic<int64_t> done{0};
  std::atomic<int64_t> total{0};  // 0: not known
};

struct ProgressOptions {
  ProgressMode mode = ProgressMode::kAuto;  // auto: a bar when `out` is a terminal's stderr, else lines
  double interval_s = 10.0;                 // between lines
  double quiet_s = 1.0;                     // nothing shown before this much time has passed
  std::ostream* out = nullptr;              // default std::cerr
  ProgressCounts* counts = nullptr;         // also kept here when given
};

class Progress {
 public:
  // `label` starts each line ("sweep", "diagnose"); `unit` counts the work ("drops", "fits").
  // `done_before`: units finished by an earlier run (a resumed sweep), counted as done but not in the rate.
  Progress(std::string label, std::string unit, int64_t total, ProgressOptions options = {}, int64_t done_before = 0);
  ~Progress();  // Finish() if not called
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // `n` more units done; `detail` is appended to the status (e.g. ", 2 failed").
  void Add(int64_t n, const std::string& detail = "");
  void SetTotal(int64_t total);  // work found on the way (diagnose's pairs)
  // A line of its own (printed whatever the quiet time: it says something went wrong).
  void Note(const std::string& line);
  void Finish(const std::string& detail = "");

 private:
  double Elapsed() const;
  void Show(bool final);
  std::ostream& out_;
  std::string label_, unit_, detail_;
  ProgressOptions options_;
  bool bar_ = false, silent_ = false, shown_ = false, finished_ = false;
  int64_t total_, before_, done_ = 0;
  std::chrono::steady_clock::time_point start_;
  double last_shown_s_ = -1e9;
  std::mutex mutex_;
};

// h:mm:ss, or "?" for a time not known yet.
std::string FormatDuration(double seconds);

}  // namespace touchdown::io
