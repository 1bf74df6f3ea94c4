// Contract in include/moos/light_mutex.hpp: the contended case, a semaphore of turns.

#include "moos/light_mutex.hpp"

namespace moos {

void LightMutex::wait_for_turn() {
  std::unique_lock<std::mutex> lock(turn_mutex_);
  turn_given_.wait(lock, [this] { return turns_ > 0; });
  --turns_;
}

void LightMutex::hand_over_turn() {
  {
    // Released here, taken by the waiter: the holder's writes happen before the waiter's turn.
    std::lock_guard<std::mutex> lock(turn_mutex_);
    ++turns_;
  }
  turn_given_.notify_one();
}

}  // namespace moos
