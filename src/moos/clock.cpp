#include "moos/clock.hpp"

#include <chrono>
#include <thread>

namespace moos {

double SystemClock::unix_now_s() const {
  using namespace std::chrono;
  const auto since_epoch = system_clock::now().time_since_epoch();
  return duration_cast<duration<double>>(since_epoch).count();
}

void SystemClock::sleep_real_s(double real_s) {
  if (real_s <= 0) return;
  std::this_thread::sleep_for(std::chrono::duration<double>(real_s));
}

void SystemClock::sleep_real_s_unless_woken(double real_s, MailSignal& wake) {
  if (real_s <= 0) return;
  const auto span = std::chrono::duration_cast<MailSignal::Clock::duration>(
      std::chrono::duration<double>(real_s));
  wake.wait_until(MailSignal::Clock::now() + span);
}

SystemClock& system_clock() {
  static SystemClock clock;
  return clock;
}

double ManualClock::unix_now_s() const { return now_s_.load(); }

void ManualClock::sleep_real_s(double real_s) {
  if (!(real_s > 0)) return;
  std::lock_guard<std::mutex> lock(mutex_);
  now_s_ = now_s_.load() + real_s;
}

void ManualClock::set_unix_s(double unix_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (unix_s > now_s_.load()) now_s_ = unix_s;
}

}  // namespace moos
