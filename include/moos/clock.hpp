#pragma once
// Where a MOOS process gets its time (docs/protocol.md 1.10): real seconds since the Unix epoch,
// which the caller multiplies by the time warp (local time) and offsets by the skew (MOOS time).
//
// Contract:
// - unix_now_s() is real, unwarped, epoch-based seconds with microsecond resolution or better.
// - sleep_real_s() waits real seconds; ManualClock instead advances itself by that amount, so a
//   loop that sleeps between iterations runs instantly and deterministically in tests.
// - Both clocks are safe to read from several threads.

#include <atomic>
#include <mutex>

#include "moos/mail_signal.hpp"

namespace moos {

class Clock {
 public:
  virtual ~Clock() = default;
  /// Real seconds since the Unix epoch.
  virtual double unix_now_s() const = 0;
  /// Waits `real_s` real seconds (nothing for real_s <= 0).
  virtual void sleep_real_s(double real_s) = 0;
  /// As sleep_real_s, but ends as soon as `wake` records mail (at once if it already has).
  /// A clock that no other thread can outrun (ManualClock) just advances.
  virtual void sleep_real_s_unless_woken(double real_s, MailSignal& wake) {
    (void)wake;
    sleep_real_s(real_s);
  }
};

/// The operating system's clock.
class SystemClock final : public Clock {
 public:
  double unix_now_s() const override;
  void sleep_real_s(double real_s) override;
  void sleep_real_s_unless_woken(double real_s, MailSignal& wake) override;
};

/// One process-wide SystemClock.
SystemClock& system_clock();

/// A clock that moves only when told to (tests, simulations).
class ManualClock final : public Clock {
 public:
  /// 2023-11-14T22:13:20Z: a realistic epoch value, so code that mixes epoch times and
  /// durations is exercised as in a real run (the examples of docs/protocol.md section 8 use it
  /// too).
  static constexpr double kDefaultStartUnix_s = 1700000000.0;

  explicit ManualClock(double start_unix_s = kDefaultStartUnix_s) : now_s_(start_unix_s) {}

  double unix_now_s() const override;
  /// Advances the clock by `real_s` (a negative value is ignored: time never runs backwards).
  void sleep_real_s(double real_s) override;
  void advance_real_s(double real_s) { sleep_real_s(real_s); }
  /// Sets the time; a value earlier than now is ignored.
  void set_unix_s(double unix_s);

 private:
  std::mutex mutex_;  ///< orders the writers; readers only load (every app reads it per cycle)
  std::atomic<double> now_s_;
};

}  // namespace moos
