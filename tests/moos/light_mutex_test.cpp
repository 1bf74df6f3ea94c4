// moos::LightMutex, the in-process bus's lock: mutual exclusion, and the hand-over to a waiter
// (the tsan preset runs this program: what one holder wrote, the next must see).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include "moos/light_mutex.hpp"

namespace moos {
namespace {

TEST(LightMutex, ThreadsTakingItInTurnLoseNoUpdateAndNeverOverlap) {
  constexpr int kThreads = 4;
  constexpr int kTurns = 20000;
  LightMutex mutex;
  long total = 0;  // plain: only the holder touches it
  std::atomic<int> holders{0};
  std::atomic<int> overlaps{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < kTurns; ++i) {
        std::lock_guard<LightMutex> lock(mutex);
        if (holders.fetch_add(1) != 0) ++overlaps;
        ++total;
        holders.fetch_sub(1);
      }
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(total, static_cast<long>(kThreads) * kTurns);
  EXPECT_EQ(overlaps.load(), 0);
}

TEST(LightMutex, AWaiterGetsItWhenTheHolderLetsGoAndSeesWhatItWrote) {
  LightMutex mutex;
  int written = 0;  // plain: only the holder touches it
  std::atomic<bool> taken{false};
  mutex.lock();
  std::thread waiter([&] {
    std::lock_guard<LightMutex> lock(mutex);
    taken = true;
    EXPECT_EQ(written, 42);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_FALSE(taken.load());  // it waits while the mutex is held
  written = 42;
  mutex.unlock();
  waiter.join();
  EXPECT_TRUE(taken.load());
  std::lock_guard<LightMutex> again(mutex);  // free again, uncontended
}

}  // namespace
}  // namespace moos
