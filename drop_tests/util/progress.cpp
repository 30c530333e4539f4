#include "drop_tests/util/progress.h"

#include <unistd.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace touchdown::io {

std::string FormatDuration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  const long t = std::lround(s);
  std::ostringstream o;
  o << t / 3600 << ':' << std::setw(2) << std::setfill('0') << (t / 60) % 60 << ':' << std::setw(2) << t % 60;
  return o.str();
}

Progress::Progress(std::string label, std::string unit, int64_t total, ProgressOptions options, int64_t done_before)
    : out_(options.out ? *options.out : std::cerr),
      label_(std::move(label)),
      unit_(std::move(unit)),
      options_(options),
      total_(total),
      before_(done_before),
      start_(std::chrono::steady_clock::now()) {
  const bool terminal = &out_ == &std::cerr && ::isatty(STDERR_FILENO);
  bar_ = options.mode == ProgressMode::kBar || (options.mode == ProgressMode::kAuto && terminal);
  silent_ = options.mode == ProgressMode::kNone;
  if (options_.counts) options_.counts->total.store(total), options_.counts->done.store(done_before);
}

Progress::~Progress() { Finish(detail_); }

double Progress::Elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::Add(int64_t n, const std::string& detail) {
  const std::lock_guard<std::mutex> lock(mutex_);
  done_ += n;
  detail_ = detail;
  if (options_.counts) options_.counts->done.store(before_ + done_);
  const double now = Elapsed();
  if (now >= options_.quiet_s && now - last_shown_s_ >= (bar_ ? 0.1 : options_.interval_s)) Show(false);
}

void Progress::SetTotal(int64_t total) {
  const std::lock_guard<std::mutex> lock(mutex_);
  total_ = total;
  if (options_.counts) options_.counts->total.store(total);
}

void Progress::Note(const std::string& line) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (silent_) return;
  if (bar_ && shown_) out_ << "\r\033[K";
  out_ << label_ << ": " << line << "\n";
  if (bar_ && shown_) Show(false);
}

void Progress::Finish(const std::string& detail) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  detail_ = detail;
  // The closing line only where progress was shown, or the job was not quick.
  if (shown_ || Elapsed() >= options_.quiet_s) Show(true);
}

void Progress::Show(bool final) {
  if (silent_) return;
  shown_ = true;
  const double elapsed = Elapsed();
  last_shown_s_ = elapsed;
  const int64_t done = before_ + done_;
  const double rate = elapsed > 0 ? done_ / elapsed : 0.0;
  const double eta = rate > 0 ? (total_ - done) / rate : NAN;
  const double fraction = total_ > 0 ? std::min(1.0, static_cast<double>(done) / total_) : 1.0;
  const bool slow = rate > 0.0 && rate < 1.0;  // units that take seconds each: s per unit
  std::ostringstream s;
  s << done << "/" << total_ << " " << unit_ << " (" << std::fixed << std::setprecision(1) << 100.0 * fraction
    << "%), " << std::setprecision(slow ? 1 : 0) << (slow ? 1.0 / rate : rate)
    << (slow ? " s/" + unit_.substr(0, unit_.size() - 1) : " " + unit_ + "/s") << ", "
    << (final ? "elapsed " + FormatDuration(elapsed) : "ETA " + FormatDuration(eta)) << detail_;
  if (bar_) {
    const int width = 30, filled = static_cast<int>(fraction * width);
    out_ << "\r\033[K[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << s.str();
    if (final) out_ << "\n";
  } else {
    out_ << label_ << ": " << s.str() << "\n";
  }
  out_.flush();
}

}  // namespace touchdown::io
