// write_fmt_fixed<D> (and write_fmt_fast, which dispatches to it) against C printf: the text of
// snprintf("%.*f") with FMT's trimming, on millions of values across magnitudes, on exact and
// near rounding ties, and at the edges of the fast path; and the read-back against
// parse_number of the text, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include "base/fmt_fixed.hpp"
#include "base/text.hpp"

namespace base {
namespace {

// FMT by its definition (text.hpp): printf's FIX, then trailing zeros and a trailing point
// dropped (only after a point), then "-0" as "0".
std::string reference_fmt(double value, int decimals) {
  char buf[512];
  const int n = std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  std::string out(buf, static_cast<std::size_t>(n));
  if (out.find('.') != std::string::npos) {
    while (out.back() == '0') out.pop_back();
    if (out.back() == '.') out.pop_back();
  }
  if (out == "-0") out = "0";
  return out;
}

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

template <int D>
char* write_fixed(char* dest, double value, double& read_back) {
  return write_fmt_fixed<D>(dest, value, read_back);
}

// The writer for a run-time D, by the template itself (not through write_fmt_fast).
char* write_fixed_at(int decimals, char* dest, double value, double& read_back) {
  using Writer = char* (*)(char*, double, double&);
  static constexpr Writer kWriters[10] = {write_fixed<0>, write_fixed<1>, write_fixed<2>,
                                          write_fixed<3>, write_fixed<4>, write_fixed<5>,
                                          write_fixed<6>, write_fixed<7>, write_fixed<8>,
                                          write_fixed<9>};
  return kWriters[decimals](dest, value, read_back);
}

// One value through both writers: printf's text or, outside the fast path, nothing written;
// the read-back is parse_number's of the text.
void check(double value, int decimals) {
  char room[kFmtFixedMaxChars + 8];
  std::memset(room, '#', sizeof room);
  double read_back = -1.0;
  const char* const end = write_fixed_at(decimals, room, value, read_back);
  const bool fast = std::fabs(value) * std::pow(10.0, decimals) < 0x1p53;
  const bool certainly_fast = std::fabs(value) * std::pow(10.0, decimals) < 0x1p52;
  if (certainly_fast) {
    ASSERT_NE(end, nullptr) << value << " " << decimals;
  }
  if (!fast && std::fabs(value) * std::pow(10.0, decimals) > 0x1p54) {
    ASSERT_EQ(end, nullptr) << value << " " << decimals;
  }
  char via_fast[kFastFmtMaxChars];
  double fast_read_back = -2.0;
  const char* const fast_end = write_fmt_fast(via_fast, value, decimals, fast_read_back);
  ASSERT_EQ(fast_end == nullptr, end == nullptr) << value << " " << decimals;
  if (!end) {
    ASSERT_EQ(room[0], '#') << value << " " << decimals;  // nothing written
    return;
  }
  const std::string text(static_cast<const char*>(room), end);
  ASSERT_LE(text.size(), kFmtFixedMaxChars) << text;
  // (the room past the text may hold scratch digits; nothing is written beyond the room)
  for (const char* rest = room + kFmtFixedMaxChars; rest < room + sizeof room; ++rest)
    ASSERT_EQ(*rest, '#') << text;
  ASSERT_EQ(text, reference_fmt(value, decimals)) << value << " " << decimals;
  ASSERT_EQ(std::string(static_cast<const char*>(via_fast), fast_end), text);
  const auto parsed = parse_number(text);
  ASSERT_TRUE(parsed) << text;
  ASSERT_EQ(bits(read_back), bits(*parsed)) << text;
  ASSERT_EQ(bits(fast_read_back), bits(*parsed)) << text;
}

// Values whose |v| * 10^D spreads over 2^-4 .. 2^54 (past the fast path's end), either sign.
double across_magnitudes(std::mt19937_64& rng, int decimals) {
  const int exponent = static_cast<int>(rng() % 59) - 4;
  const double mantissa = 1.0 + static_cast<double>(rng() >> 12) * 0x1p-52;
  const double v = std::ldexp(mantissa, exponent) / std::pow(10.0, decimals);
  return rng() % 2 ? -v : v;
}

TEST(FmtFixed, RandomValuesOfEveryMagnitudeAndPrecisionAreWrittenAsPrintfWrites) {
  std::mt19937_64 rng(20261128);
  for (int i = 0; i < 1000000; ++i) {
    const int decimals = static_cast<int>(rng() % 10);
    check(across_magnitudes(rng, decimals), decimals);
    if (HasFailure()) return;
  }
}

// Dyadic values k / 2^s: many lie exactly on a tie at D decimals (0.125 at 2, 1.0625 at 3),
// which printf rounds to the even neighbour; their neighbours one ulp away do not.
TEST(FmtFixed, ExactTiesGoToTheEvenNeighbourAndTheirNeighboursAwayFromIt) {
  std::mt19937_64 rng(2029);
  for (int i = 0; i < 400000; ++i) {
    const int decimals = static_cast<int>(rng() % 10);
    const int shift = 1 + static_cast<int>(rng() % 34);
    const double k = static_cast<double>(rng() % (std::uint64_t{1} << 40));
    double v = std::ldexp(k, -shift);
    if (rng() % 2) v = -v;
    check(v, decimals);
    check(std::nextafter(v, HUGE_VAL), decimals);
    check(std::nextafter(v, -HUGE_VAL), decimals);
    if (HasFailure()) return;
  }
}

// Decimal-looking values (a position to the centimetre, a time to the millisecond) and their
// halves, where the product's rounding lies nearest the tie.
TEST(FmtFixed, DecimalValuesAndTheirHalfStepsAreWrittenAsPrintfWrites) {
  std::mt19937_64 rng(2031);
  for (int i = 0; i < 500000; ++i) {
    const int decimals = static_cast<int>(rng() % 10);
    const double steps = static_cast<double>(rng() % 2000000001) - 1000000000.0;
    const double scale = std::pow(10.0, decimals);
    check(steps / scale, decimals);
    check((steps + 0.5) / scale, decimals);
    if (HasFailure()) return;
  }
}

TEST(FmtFixed, EdgeValues) {
  char room[kFmtFixedMaxChars];
  double read_back = 0.0;
  const auto text = [&](const char* end) { return std::string(static_cast<const char*>(room), end); };
  // Negative zero and negatives that round to zero are "0", reading back as +0.
  EXPECT_EQ(text(write_fmt_fixed<2>(room, -0.0, read_back)), "0");
  EXPECT_EQ(bits(read_back), bits(0.0));
  EXPECT_EQ(text(write_fmt_fixed<2>(room, -0.004, read_back)), "0");
  EXPECT_EQ(bits(read_back), bits(0.0));
  EXPECT_EQ(text(write_fmt_fixed<0>(room, -0.5, read_back)), "0");
  // Ties to even, as printf.
  EXPECT_EQ(text(write_fmt_fixed<2>(room, 0.125, read_back)), "0.12");
  EXPECT_EQ(text(write_fmt_fixed<2>(room, 0.375, read_back)), "0.38");
  EXPECT_EQ(text(write_fmt_fixed<0>(room, 2.5, read_back)), "2");
  EXPECT_EQ(text(write_fmt_fixed<0>(room, -3.5, read_back)), "-4");
  EXPECT_EQ(text(write_fmt_fixed<3>(room, 1.0625, read_back)), "1.062");
  // Not a tie in binary: 2.675 is below 2.675 exactly.
  EXPECT_EQ(text(write_fmt_fixed<2>(room, 2.675, read_back)), "2.67");
  // Trailing zeros and the point go; a carry reaches the whole part.
  EXPECT_EQ(text(write_fmt_fixed<3>(room, 1.5, read_back)), "1.5");
  EXPECT_EQ(text(write_fmt_fixed<2>(room, 9.999, read_back)), "10");
  EXPECT_EQ(text(write_fmt_fixed<9>(room, 0.000000001, read_back)), "0.000000001");
  EXPECT_EQ(text(write_fmt_fixed<3>(room, 1700000024.75, read_back)), "1700000024.75");
  // 1e15 and up: within the fast path up to 2^53 units, refused beyond.
  EXPECT_EQ(text(write_fmt_fixed<0>(room, 1e15, read_back)), "1000000000000000");
  EXPECT_EQ(text(write_fmt_fixed<0>(room, 9007199254740991.0, read_back)), "9007199254740991");
  EXPECT_EQ(text(write_fmt_fixed<1>(room, -900719925474099.1, read_back)), "-900719925474099.1");
  EXPECT_EQ(write_fmt_fixed<0>(room, 9007199254740992.0, read_back), nullptr);
  EXPECT_EQ(write_fmt_fixed<1>(room, 1e15, read_back), nullptr);
  EXPECT_EQ(write_fmt_fixed<2>(room, 1e300, read_back), nullptr);
  // NaN and infinities are outside the fast path, as before; fmt() still writes them.
  for (const double refused : {std::numeric_limits<double>::quiet_NaN(), HUGE_VAL, -HUGE_VAL}) {
    room[0] = '#';
    EXPECT_EQ(write_fmt_fixed<2>(room, refused, read_back), nullptr) << refused;
    EXPECT_EQ(room[0], '#');
    EXPECT_EQ(write_fmt_fast(room, refused, 2), nullptr) << refused;
  }
  EXPECT_EQ(fmt(HUGE_VAL, 2), "inf");
  EXPECT_EQ(fmt(-HUGE_VAL, 2), "-inf");
  EXPECT_EQ(fmt(std::numeric_limits<double>::quiet_NaN(), 2), "nan");
  EXPECT_EQ(write_fmt_fast(room, 1.5, 10), nullptr);  // beyond 9 decimals: fmt's way
  EXPECT_EQ(text(write_fmt_fast(room, 1.5, -3)), "2");  // a negative count is 0
}

}  // namespace
}  // namespace base
