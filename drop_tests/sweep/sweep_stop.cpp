#include "drop_tests/sweep/sweep_stop.h"

namespace touchdown::sweep {

namespace {
std::atomic<int> g_stop_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void RecordStopSignal(int signal) {
  int none = 0;
  g_stop_signal.compare_exchange_strong(none, signal);  // the first one wins
}
}  // namespace

StopOnSignals::StopOnSignals() {
  g_stop_signal.store(0);
  struct sigaction action {};
  action.sa_handler = &RecordStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART | SA_RESETHAND;
  sigaction(SIGINT, &action, &old_int_);
  sigaction(SIGTERM, &action, &old_term_);
}

StopOnSignals::~StopOnSignals() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
}

const std::atomic<int>& StopOnSignals::flag() { return g_stop_signal; }

}  // namespace touchdown::sweep
