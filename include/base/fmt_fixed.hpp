#pragma once
// FMT(v, D) with D known at compile time, written inline at a pointer: the number writer of the
// texts posted most often (a node report is five to seven numbers, ten times a second per
// vehicle).
//
// Why not write_fmt_fast (text.hpp) alone: with D a run-time value, each number was a call of
// about 150 instructions (the trailing zeros found by divisions, the length counted first to
// write from the right). Here the power of ten is a constant, the whole part is written from
// the left, the decimals are trimmed as bytes, and the call disappears: 50 to 60 instructions.
// write_fmt_fast dispatches to this writer, so both give one text.
//
// Exactness: |v| * 10^D is rounded to the nearest integer as printf rounds the exact binary
// value (ties to even). The product is off by at most half an ulp; only when it lies that
// close to a tie (x.5) does the exact error decide, in rounds_up_near_tie (fma).
// tests/base/fmt_fixed_test.cpp holds the text to snprintf("%.*f") over millions of values.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace base {

namespace detail {

inline constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

inline constexpr double kFixedScale[10] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
inline constexpr std::uint64_t kFixedUnit[10] = {1,      10,      100,      1000,      10000,
                                                 100000, 1000000, 10000000, 100000000, 1000000000};

/// Whether magnitude * scale, whose rounded product `scaled` has `fraction` above its floor
/// (odd or not), lies above the tie or on it with an odd floor: the exact error of the product
/// (fma) settles it. Out of line: reached only near a tie.
bool rounds_up_near_tie(double magnitude, double scale, double scaled, double fraction, bool odd);

/// Decimal digits of `v` (at least 10000, below 2^53) at `p`, left to right; the end.
char* write_long_whole(char* p, std::uint64_t v);

inline void put_pair(char* p, std::uint64_t two_digits) {
  std::memcpy(p, kDigitPairs + 2 * two_digits, 2);
}

/// Decimal digits of `v` (below 10000) at `p`; the end. Positions, speeds and headings have at
/// most four digits before the point: those without a loop or a call.
[[gnu::always_inline]] inline char* write_short_whole(char* p, std::uint64_t v) {
  if (v < 10) {
    *p = static_cast<char>('0' + v);
    return p + 1;
  }
  if (v < 100) {
    put_pair(p, v);
    return p + 2;
  }
  const std::uint64_t high = v / 100;
  const std::uint64_t low = v - high * 100;
  if (high < 10) {
    *p = static_cast<char>('0' + high);
    put_pair(p + 1, low);
    return p + 3;
  }
  put_pair(p, high);
  put_pair(p + 2, low);
  return p + 4;
}

/// Decimal digits of `v` (below 2^53) at `p`; the end.
[[gnu::always_inline]] inline char* write_whole(char* p, std::uint64_t v) {
  return v < 10000 ? write_short_whole(p, v) : write_long_whole(p, v);
}

/// '.' and the D decimals of `units` (1 .. 10^D - 1, leading zeros kept) at `p`, trailing
/// zeros dropped as FMT drops them (a non-zero digit always remains); the end.
template <int D>
[[gnu::always_inline]] inline char* write_decimals(char* p, std::uint64_t units) {
  *p = '.';
  char* const end = p + 1 + D;
  char* q = end;
  for (int left = D; left >= 2; left -= 2) {
    q -= 2;
    put_pair(q, units % 100);
    units /= 100;
  }
  if constexpr (D % 2 == 1) q[-1] = static_cast<char>('0' + units);
  char* last = end;
  while (last[-1] == '0') --last;
  return last;
}

}  // namespace detail

/// The longest text write_fmt_fixed writes (16 digits, a point and a sign), and the room it
/// needs at `dest`.
inline constexpr std::size_t kFmtFixedMaxChars = 24;

/// The digits of the last whole part of at least 10000 written through it: a writer of time
/// stamps (ten digits, the same for a second of reports) copies them instead of writing them.
struct LongWholeCache {
  std::uint64_t whole = 0;  ///< 0: none yet (a long whole part is at least 10000)
  std::size_t size = 0;
  char digits[24];  ///< 16 digits at most (below 2^53), copied 16 at a time
};

namespace detail {

/// write_long_whole, through `cache` when there is one. `p` has room for 16 bytes.
inline char* write_cached_whole(char* p, std::uint64_t whole, LongWholeCache* cache) {
  if (!cache) return write_long_whole(p, whole);
  if (whole != cache->whole) {
    cache->size = static_cast<std::size_t>(write_long_whole(cache->digits, whole) - cache->digits);
    cache->whole = whole;
  }
  std::memcpy(p, cache->digits, 16);
  return p + cache->size;
}

/// The text of units / 10^D at `dest` ('-' first when `negative`), its read-back in
/// `read_back` (parse_number's: one correctly rounded division, as the reader's; trailing zeros
/// dropped or not, the quotient is the same real number); the end. `LongWhole`: the whole part
/// is at least 10000 (write_long_whole, a call, or `cache`'s copy).
template <int D, bool LongWhole>
[[gnu::always_inline]] inline char* write_units(char* dest, bool negative, std::uint64_t units,
                                                double& read_back, LongWholeCache* cache) {
  constexpr double kScale = kFixedScale[D];
  constexpr std::uint64_t kUnit = kFixedUnit[D];
  *dest = '-';
  char* p = dest + (negative ? 1 : 0);
  const std::uint64_t whole = units / kUnit;
  const std::uint64_t decimals = units - whole * kUnit;  // (before the whole: one division)
  p = LongWhole ? write_cached_whole(p, whole, cache) : write_short_whole(p, whole);
  if constexpr (D > 0) {
    if (decimals != 0) p = write_decimals<D>(p, decimals);
  }
  const double v = static_cast<double>(static_cast<std::int64_t>(units)) / kScale;
  read_back = negative ? -v : v;
  return p;
}

/// write_units for a whole part of at least 10000 (time stamps), out of line: the usual numbers'
/// inlined writer then makes no call but this tail call, and keeps nothing across one.
template <int D>
[[gnu::noinline]] char* write_long_units(char* dest, bool negative, std::uint64_t units,
                                         double& read_back, LongWholeCache* cache) {
  return write_units<D, true>(dest, negative, units, read_back, cache);
}

/// units (the rounded |value| * 10^D) and the sign write_fmt_fixed writes, given `round_up`.
template <int D>
[[gnu::always_inline]] inline char* write_rounded(char* dest, double value, std::int64_t truncated,
                                                  bool round_up, double& read_back,
                                                  LongWholeCache* cache) {
  const auto units = static_cast<std::uint64_t>(truncated) + (round_up ? 1U : 0U);
  const bool negative = std::signbit(value) && units != 0;  // "-0" as "0"
  if (units >= 10000 * kFixedUnit[D])
    return write_long_units<D>(dest, negative, units, read_back, cache);
  return write_units<D, false>(dest, negative, units, read_back, nullptr);
}

/// write_fmt_fixed for a product that lies within its error of a tie: the exact error decides
/// (rounds_up_near_tie). Out of line and rare.
template <int D>
[[gnu::noinline]] char* write_fixed_near_tie(char* dest, double value, double& read_back,
                                             LongWholeCache* cache) {
  constexpr double kScale = kFixedScale[D];
  const double magnitude = std::fabs(value);
  const double scaled = magnitude * kScale;
  const auto truncated = static_cast<std::int64_t>(scaled);
  const double fraction = scaled - static_cast<double>(truncated);
  const bool round_up =
      rounds_up_near_tie(magnitude, kScale, scaled, fraction, (truncated & 1) != 0);
  return write_rounded<D>(dest, value, truncated, round_up, read_back, cache);
}

}  // namespace detail

/// FMT(value, D) (text.hpp: FIX, trailing zeros and point dropped, "-0" as "0") at `dest`,
/// which has room for kFmtFixedMaxChars bytes, when |value| * 10^D is below 2^53: the end of
/// the text (the room past it may hold scratch digits), with `read_back` the number the text
/// reads as (parse_number's, bit for bit).
/// Otherwise nullptr and nothing written (NaN and infinities too).
/// The usual number (no tie near, a whole part below 10000) makes no call: the rare cases are
/// tail calls, so the inlined writer saves no register. `cache` (may be nullptr) keeps the
/// digits of a whole part of at least 10000 from one call to the next (LongWholeCache).
template <int D>
[[gnu::always_inline]] inline char* write_fmt_fixed(char* dest, double value, double& read_back,
                                                    LongWholeCache* cache = nullptr) {
  static_assert(D >= 0 && D <= 9, "at most 9 decimals: 10^D * 2^53 stays exact in the units");
  constexpr double kScale = detail::kFixedScale[D];
  const double magnitude = std::fabs(value);
  const double scaled = magnitude * kScale;
  if (!(scaled < 0x1p53)) return nullptr;
  // Truncation is floor here; through int64, one instruction each way.
  const auto truncated = static_cast<std::int64_t>(scaled);
  const double fraction = scaled - static_cast<double>(truncated);  // exact below 2^53
  if (__builtin_expect(std::fabs(fraction - 0.5) <= scaled * 0x1p-50, 0))
    return detail::write_fixed_near_tie<D>(dest, value, read_back, cache);
  return detail::write_rounded<D>(dest, value, truncated, fraction > 0.5, read_back, cache);
}

}  // namespace base
