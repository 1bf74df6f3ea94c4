// The wake-up of a thread that waits for mail ("A missed wake-up"): mail recorded
// between a fetch and the wait ends the wait at once.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "moos/mail_signal.hpp"

namespace moos {
namespace {

using Clock = MailSignal::Clock;
constexpr auto kLongWait = std::chrono::seconds(30);

TEST(MailSignal, MailRecordedBeforeTheWaitEndsItAtOnce_Hardening) {
  MailSignal signal;
  signal.take();    // the watcher's turn: forget, then fetch ...
  signal.notify();  // ... mail arrives after the fetch, before the wait
  const auto start = Clock::now();
  EXPECT_TRUE(signal.wait_until(start + kLongWait));
  EXPECT_LT(Clock::now() - start, kLongWait / 2);  // returned without waiting for the deadline
}

TEST(MailSignal, WithoutMailTheWaitEndsAtTheDeadline) {
  MailSignal signal;
  signal.notify();
  signal.take();  // what was recorded before the fetch is forgotten
  EXPECT_FALSE(signal.wait_until(Clock::now() + std::chrono::milliseconds(20)));
}

TEST(MailSignal, MailFromAnotherThreadWakesTheWaiter) {
  MailSignal signal;
  signal.take();
  std::thread poster([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    signal.notify();
  });
  EXPECT_TRUE(signal.wait_until(Clock::now() + kLongWait));
  poster.join();
}

}  // namespace
}  // namespace moos
