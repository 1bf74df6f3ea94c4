#pragma once
// Ranges that libMOOS accepts for the settings every MOOS process shares, in one place so that
// the command line, the mission reader, the client and the tools agree on them.
//
// Contract:
// - A time warp is valid in (0, kMaxTimeWarp] (wire spec 0.3).
// - parse_time_warp accepts what base::parse_number accepts and a valid warp; nullopt otherwise.
// - kMaxPort is the highest TCP port number; clients connect to ports 1..kMaxPort.
// - CommsTick is a whole number of Hz in 1..kMaxCommsTickHz (wire spec 4.2).

#include <optional>
#include <string_view>

#include "base/text.hpp"

namespace moos {

/// The largest time warp libMOOS accepts (wire spec 0.3).
inline constexpr double kMaxTimeWarp = 400.0;
/// The highest TCP port number.
inline constexpr int kMaxPort = 65535;
/// The highest CommsTick libMOOS accepts, in Hz (wire spec 4.2): CommsTick is in 1..200.
inline constexpr int kMaxCommsTickHz = 200;

/// AppTick range, in MOOS-time Hz (issue 12): below one iteration per 1,000 MOOS seconds an app
/// looks stalled; above 1 kHz (x warp in real time) it only busy-loops. libMOOS accepts any
/// positive number; we refuse the rest with a warning and keep the default.
inline constexpr double kMinAppTickHz = 1e-3;
inline constexpr double kMaxAppTickHz = 1000.0;
constexpr bool is_valid_app_tick(double hz) { return hz >= kMinAppTickHz && hz <= kMaxAppTickHz; }

/// True for 0 < warp <= kMaxTimeWarp (false for NaN).
constexpr bool is_valid_time_warp(double warp) { return warp > 0 && warp <= kMaxTimeWarp; }

/// A number (base::parse_number) that is a valid time warp; nullopt otherwise.
inline std::optional<double> parse_time_warp(std::string_view text) {
  const std::optional<double> warp = base::parse_number(text);
  if (!warp || !is_valid_time_warp(*warp)) return std::nullopt;
  return warp;
}

}  // namespace moos
