#pragma once
// A mutex whose uncontended lock() and unlock() are one atomic operation each (a "benaphore":
// a count of the threads that hold or want it, and a semaphore that only a contended lock waits
// on). The in-process bus takes its lock for every posting and for every fetch that finds mail;
// in a lockstep mission nobody ever waits, and std::mutex's library calls were a third of a
// fetch.
//
// Contract: BasicLockable (std::lock_guard, std::unique_lock); mutual exclusion, and what a
// holder wrote before unlock() happens before what the next holder does after lock(). Not
// recursive. A contended lock() sleeps (no spinning) until an unlock() hands it over; waiters
// are served in the order the semaphore's condition variable wakes them.

#include <atomic>
#include <condition_variable>
#include <mutex>

namespace moos {

class LightMutex {
 public:
  LightMutex() = default;
  LightMutex(const LightMutex&) = delete;
  LightMutex& operator=(const LightMutex&) = delete;

  void lock() {
    // Acquire: pairs with the release of the unlock() that the count says came before.
    if (wanted_.fetch_add(1, std::memory_order_acquire) > 0) wait_for_turn();
  }
  void unlock() {
    // More than this holder counted: someone waits (or is about to), and gets the turn.
    if (wanted_.fetch_sub(1, std::memory_order_release) > 1) hand_over_turn();
  }

 private:
  void wait_for_turn();
  void hand_over_turn();

  std::atomic<int> wanted_{0};  ///< threads holding the mutex or waiting for it
  // The semaphore of the contended case: turns handed over and not yet taken.
  std::mutex turn_mutex_;
  std::condition_variable turn_given_;
  int turns_ = 0;
};

}  // namespace moos
