// SIGINT / SIGTERM through sigwait on a watcher thread (contract in include/moos/stop_signals.hpp).

#include "moos/stop_signals.hpp"

#include <pthread.h>

#include <utility>

namespace moos {

StopSignals::StopSignals() {
  sigemptyset(&stop_set_);
  sigaddset(&stop_set_, SIGINT);
  sigaddset(&stop_set_, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_set_, &previous_mask_);
  watcher_ = std::thread([this] { wait_for_signal(); });
}

void StopSignals::set_handler(std::function<void()> on_stop) {
  std::lock_guard<std::mutex> lock(mutex_);
  on_stop_ = std::move(on_stop);
}

void StopSignals::wait_for_signal() {
  int signal_number = 0;
  while (sigwait(&stop_set_, &signal_number) != 0) {
  }
  if (closing_) return;  // the destructor's own wake-up, not a user's signal
  signalled_ = true;
  std::function<void()> on_stop;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    on_stop = on_stop_;
  }
  if (on_stop) {
    on_stop();
    return;
  }
  // No handler yet (still starting up): the signal's default action, as without this class.
  signal(signal_number, SIG_DFL);
  sigset_t just_this;
  sigemptyset(&just_this);
  sigaddset(&just_this, signal_number);
  pthread_sigmask(SIG_UNBLOCK, &just_this, nullptr);
  raise(signal_number);
}

StopSignals::~StopSignals() {
  if (!signalled_) {
    closing_ = true;
    pthread_kill(watcher_.native_handle(), SIGTERM);  // ends the watcher's sigwait
  }
  watcher_.join();
  pthread_sigmask(SIG_SETMASK, &previous_mask_, nullptr);
}

}  // namespace moos
