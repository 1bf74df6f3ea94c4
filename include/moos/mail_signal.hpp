#pragma once
// A wake-up for a thread that waits for mail ("A missed wake-up"): mail that arrives
// between a fetch and the wait must end the wait at once, not at its deadline.
//
// Contract: notify() records that mail arrived and wakes a waiter. take() forgets what was
// recorded; call it BEFORE fetching, so mail that arrives during or after the fetch is still
// recorded. wait_until() returns true as soon as mail is recorded (at once if it already is) and
// false at the deadline. Thread-safe.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>

namespace moos {

class MailSignal {
 public:
  using Clock = std::chrono::steady_clock;

  void notify() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      pending_ = true;
    }
    arrived_.notify_all();
  }

  /// Whether mail was recorded since the last take().
  bool pending() const { return pending_.load(std::memory_order_acquire); }

  void take() {
    // An app cycles far more often than mail wakes it: without mail there is nothing to clear,
    // and no lock to take. A notify() racing with this check leaves its mail recorded.
    if (!pending()) return;
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = false;
  }

  bool wait_until(Clock::time_point deadline) {
    std::unique_lock<std::mutex> lock(mutex_);
    return arrived_.wait_until(lock, deadline, [this] { return pending_.load(); });
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable arrived_;
  std::atomic<bool> pending_{false};  ///< mail arrived since the last take(); written under mutex_
};

}  // namespace moos
