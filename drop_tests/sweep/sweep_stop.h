#pragma once
// SIGINT and SIGTERM during a sweep stop it cleanly instead of killing it: the handler only
// records the signal (a store to a lock-free atomic, async-signal-safe); the sweep checks the
// flag between drops, lets each worker finish the drop it is running, commits what is done and
// returns, and `touchdown sweep` exits 128 + the signal (130, 143). A second SIGINT or SIGTERM
// gets the default action (SA_RESETHAND): it kills at once, which loses no committed drop either.
#include <atomic>
#include <csignal>

namespace touchdown::sweep {

class StopOnSignals {
 public:
  StopOnSignals();   // installs the handlers (the flag starts at 0)
  ~StopOnSignals();  // restores the previous ones
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;
  // 0, or the first signal received (SIGINT or SIGTERM).
  static const std::atomic<int>& flag();

 private:
  struct sigaction old_int_{}, old_term_{};
};

}  // namespace touchdown::sweep
