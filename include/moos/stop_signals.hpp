#pragma once
// StopSignals: SIGINT and SIGTERM turned into a call on an ordinary thread, so that a stop can
// wake a sleeping main loop (a signal handler may not notify a condition variable).
//
// Contract: construct it before any other thread starts: it blocks both signals in the calling
// thread (threads started afterwards inherit the mask, so no thread but its watcher takes them)
// and starts the watcher. A signal that comes before set_handler() acts as it would without this
// class (the default action ends the process); after it, the handler is called once, from the
// watcher's thread. The destructor ends the watcher if no signal came and restores the mask.

#include <atomic>
#include <functional>
#include <mutex>
#include <thread>

#include <signal.h>

namespace moos {

class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  void set_handler(std::function<void()> on_stop);

 private:
  void wait_for_signal();

  sigset_t stop_set_;
  sigset_t previous_mask_;
  std::mutex mutex_;
  std::function<void()> on_stop_;
  std::atomic<bool> signalled_{false};
  std::atomic<bool> closing_{false};
  std::thread watcher_;  ///< last: started once everything above exists
};

}  // namespace moos
