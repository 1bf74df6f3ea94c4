#pragma once
// Ranges that libMOOS accepts for the settings every MOOS process shares, in one place so that
// the command line, the mission reader, the client and the tools agree on them.
//
// Contract:
// - A time warp is valid in (0, kMaxTimeWarp] (docs/protocol.md 1.10).
// - parse_time_warp accepts what base::parse_number accepts and a valid warp; nullopt otherwise.
// - kMaxPort is the highest TCP port number. Clients connect to ports kMinConnectPort..kMaxPort;
//   a server may listen on kAnyListenPort..kMaxPort, where kAnyListenPort (0) lets the operating
//   system pick a free port (kConnectPortRange, kListenPortRange).
// - A Range is a closed or open interval of numbers; contains() is false for NaN.
// - CommsTick is a whole number of Hz in 1..kMaxCommsTickHz (docs/protocol.md 4.2).

#include <limits>
#include <optional>
#include <string_view>

#include "base/text.hpp"

namespace moos {

/// An interval of numbers, each end closed (included) or open.
struct Range {
  double low;
  double high;
  bool low_open = false;
  bool high_open = false;
  /// True when `value` lies in the interval (false for NaN).
  constexpr bool contains(double value) const {
    return (low_open ? value > low : value >= low) && (high_open ? value < high : value <= high);
  }
};

/// Every finite number; numbers more than 0 (a duration to wait, a rate); 0 or more.
inline constexpr Range kAnyNumber{-std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
inline constexpr Range kPositive{0.0, std::numeric_limits<double>::max(), true, false};
inline constexpr Range kNonNegative{0.0, std::numeric_limits<double>::max()};

/// A real-time wait a user asks for (moos-cli --timeout, --connect-timeout), s: (0, 1e8], about
/// three years. A longer one overflows std::chrono's steady clock (64-bit nanoseconds, 292
/// years) when it becomes a deadline: 1e300 once made moos-cli give up at once.
inline constexpr double kMaxRealWait_s = 1.0e8;
inline constexpr Range kRealWaitRange{0.0, kMaxRealWait_s, true, false};

/// The largest time warp libMOOS accepts (docs/protocol.md 1.10).
inline constexpr double kMaxTimeWarp = 400.0;
/// A time warp: (0, kMaxTimeWarp].
inline constexpr Range kTimeWarpRange{0.0, kMaxTimeWarp, true, false};
/// The highest TCP port number.
inline constexpr int kMaxPort = 65535;
/// The lowest port a client connects to (there is no port 0 to connect to).
inline constexpr int kMinConnectPort = 1;
/// The port a server listens on to let the operating system pick a free one.
inline constexpr int kAnyListenPort = 0;
/// Ports a client connects to, and ports a server listens on.
inline constexpr Range kConnectPortRange{kMinConnectPort, kMaxPort};
inline constexpr Range kListenPortRange{kAnyListenPort, kMaxPort};
/// The highest CommsTick libMOOS accepts, in Hz (docs/protocol.md 4.2): CommsTick is in 1..200.
inline constexpr int kMaxCommsTickHz = 200;
/// CommsTick in Hz: 1..kMaxCommsTickHz.
inline constexpr Range kCommsTickRangeHz{1, kMaxCommsTickHz};

/// AppTick range, in MOOS-time Hz: below one iteration per 1,000 MOOS seconds an app
/// looks stalled; above 1 kHz (x warp in real time) it only busy-loops. libMOOS accepts any
/// positive number; we refuse the rest with a warning and keep the default.
inline constexpr double kMinAppTickHz = 1e-3;
inline constexpr double kMaxAppTickHz = 1000.0;
constexpr bool is_valid_app_tick(double hz) { return hz >= kMinAppTickHz && hz <= kMaxAppTickHz; }

/// True for 0 < warp <= kMaxTimeWarp (false for NaN).
constexpr bool is_valid_time_warp(double warp) { return kTimeWarpRange.contains(warp); }

/// A number (base::parse_number) that is a valid time warp; nullopt otherwise.
inline std::optional<double> parse_time_warp(std::string_view text) {
  const std::optional<double> warp = base::parse_number(text);
  if (!warp || !is_valid_time_warp(*warp)) return std::nullopt;
  return warp;
}

}  // namespace moos
