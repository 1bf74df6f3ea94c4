#pragma once
// Interval rules on the MOOS clock (docs/differences.md D9, D11, D12).
//
// Contract: every interval rule of the engine asks one question, "has `interval_s` passed
// between `since_s` and `now_s`?", through elapsed_at_least(), so the rule is written once:
//   sensor window      active while !elapsed_at_least(now, last request, 600 s)
//   turn window        a heading sample counts while !elapsed_at_least(newest, sample, 2 s)
//   reset window       a width change is denied while !elapsed_at_least(now, last change, interval)
//   classify interval  an answer is released when elapsed_at_least(now, last release or top, ...)
//   options summary    posted when elapsed_at_least(now, last summary, interval)
// Why a tolerance: MOOS times are epoch seconds (about 1.8e9 s), where consecutive doubles are
// 2.4e-7 s apart, and iteration times that are not binary fractions (AppTick 3, a time warp
// multiplying wall-clock differences) carry rounding of that size: t0 + 90 x (1/3 s) can come
// out 29.99999976 s after t0. An exact comparison would then miss the iteration at which a 30 s
// interval is reached, and every later deadline would slip by a tick (drift). An elapsed time
// short of the interval by at most kClockRounding of |now| therefore counts as reached. The
// allowance is 2^-45 of the clock (128 units in the last place): 51 us at 1.8e9 s, 2.8e-12 s at
// 100 s; far below any tick, and it covers a warp of 100 applied to wall-clock rounding.
// Rejected alternative: scheduling by counting ticks (the engine does not own the clock).

#include <cmath>

namespace hazard {

/// Relative allowance for clock rounding (see the file comment): 2^-45.
inline constexpr double kClockRounding = 1.0 / 35184372088832.0;

/// The rounding allowance at clock reading `now_s`, seconds (>= 0).
inline double clock_tolerance_s(double now_s) { return std::fabs(now_s) * kClockRounding; }

/// True when at least `interval_s` has passed from `since_s` to `now_s`, allowing for clock
/// rounding. `interval_s` >= 0; times finite.
inline bool elapsed_at_least(double now_s, double since_s, double interval_s) {
  return now_s - since_s >= interval_s - clock_tolerance_s(now_s);
}

}  // namespace hazard
