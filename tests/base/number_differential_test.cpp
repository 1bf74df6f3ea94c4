// The text grammar's numbers against their references, on many generated inputs:
// parse_number (std::from_chars, strtod for what it reports out of range) against the grammar
// of differences.md "Numbers", checked by a regular expression and converted by strtod; fix and
// fmt (integer arithmetic, std::to_chars when a tie is too close to call) against C printf.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <regex>
#include <string>

#include "base/text.hpp"
#include "number_reference.hpp"

namespace base {
namespace {

using test_support::reference_number;

// Same double, bit for bit (the sign of zero included), or both refused.
void expect_same_number(const std::string& text) {
  const auto got = parse_number(text);
  const auto want = reference_number(text);
  ASSERT_EQ(got.has_value(), want.has_value()) << "'" << text << "'";
  if (!got) return;
  std::uint64_t a = 0, b = 0;
  std::memcpy(&a, &*got, sizeof a);
  std::memcpy(&b, &*want, sizeof b);
  ASSERT_EQ(a, b) << "'" << text << "'";
}

std::string digits(std::mt19937_64& rng, int max_count) {
  std::string out;
  const int n = static_cast<int>(rng() % static_cast<std::uint64_t>(max_count + 1));
  for (int i = 0; i < n; ++i) out.push_back(static_cast<char>('0' + rng() % 10));
  return out;
}

// Texts near and off the grammar: signs, long mantissas, exponents past both ends of double.
std::string number_like(std::mt19937_64& rng) {
  std::string out;
  if (rng() % 4 == 0) out += rng() % 2 ? " " : "\t";
  if (rng() % 3 == 0) out.push_back(rng() % 2 ? '-' : '+');
  out += digits(rng, rng() % 8 == 0 ? 40 : 12);
  if (rng() % 2) out += "." + digits(rng, rng() % 8 == 0 ? 40 : 12);
  if (rng() % 2) {
    out.push_back(rng() % 2 ? 'e' : 'E');
    if (rng() % 2) out.push_back(rng() % 2 ? '-' : '+');
    out += std::to_string(rng() % 420);
  }
  if (rng() % 16 == 0) out.insert(rng() % (out.size() + 1), 1, "+-.eEx n"[rng() % 8]);
  if (rng() % 4 == 0) out += rng() % 2 ? " " : "\r\n";
  return out;
}

TEST(NumberDifferential, GeneratedTextsReadAsTheStrtodReferenceReadsThem) {
  std::mt19937_64 rng(14);
  for (int i = 0; i < 200000; ++i) expect_same_number(number_like(rng));
}

TEST(NumberDifferential, EdgesOfDoubleReadAsTheStrtodReferenceReadsThem) {
  for (const char* text :
       {"0", "-0", "+0", "-0.0", "0e0", "-0e-5", "1.7976931348623157e308",
        "1.7976931348623158e308", "1.7976931348623159e308", "-1.7976931348623159e308", "1e308",
        "1e309", "4.9406564584124654e-324", "2.4703282292062327e-324",
        "2.4703282292062328e-324", "-2.4703282292062328e-324", "1e-320", "1e-400", "-1e-400",
        "2.2250738585072011e-308", "2.2250738585072014e-308", "9007199254740993",
        "0.1000000000000000055511151231257827", "123456789012345678901234567890", "+.5", "5.",
        ".5e1", "+5.e-1", "00000000000000000000000001", "1e0000000000000000000000002", ".",
        "+", "e1", "1e", "1e+", "--1", "+-1", "1..2", "0x1p3", "inf", "nan", "1 2", ""}) {
    expect_same_number(text);
  }
  expect_same_number("0." + std::string(800, '0') + "1e790");  // far past 19 digits
  expect_same_number(std::string(400, '9'));
}

// The reference of fix: C printf.
std::string printf_fixed(double value, int decimals) {
  char text[512];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// The reference of fmt: printf, trailing zeros and point dropped, "-0" read as "0".
std::string printf_fmt(double value, int decimals) {
  std::string s = printf_fixed(value, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

// Values of every kind a log carries: coordinates, probabilities, exact ties (x.5, x.25 ...),
// decimal fractions near ties (0.125, 2.675), huge and tiny magnitudes, raw bit patterns.
double value_like(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double sign = rng() % 2 ? -1.0 : 1.0;
  switch (rng() % 6) {
    case 0: return sign * unit(rng) * 20000.0;
    case 1: return sign * static_cast<double>(rng() % 2000000) / 1000.0;
    case 2: return sign * (static_cast<double>(rng() % 100000) + 0.5) / std::pow(10.0, rng() % 6);
    case 3: return sign * static_cast<double>(rng() % 100000) / 8.0 / std::pow(10.0, rng() % 4);
    case 4: return sign * unit(rng) * std::pow(10.0, static_cast<double>(rng() % 40) - 20.0);
    default: {
      double v = 0.0;
      do {
        const std::uint64_t bits = rng();
        std::memcpy(&v, &bits, sizeof v);
      } while (!std::isfinite(v));
      return v;
    }
  }
}

// parse_number divides the digits by a power of ten itself when both are exact (at most 2^53
// and 22 decimals): the texts on either side of those limits, and mail's usual decimals.
TEST(NumberDifferential, PlainDecimalsOnBothSidesOfTheExactLimitsReadAsStrtodReadsThem) {
  for (const char* text :
       {"9007199254740992", "9007199254740993", "900719925474099.3", "-9007199254740.993",
        "0.9007199254740993", "1.0000000000000000000001", "0.0000000000000000000001",
        "0.00000000000000000000001", "1234567890123456789", "12345678901234567890",
        "0.1", "0.2", "0.3", "-470.50", "-0.00", "1700000000.05", "99999999999999999.9", "1.",
        "-.25", "000000000000000000000.5", "3.14159265358979323"}) {
    expect_same_number(text);
  }
  std::mt19937_64 rng(53);
  for (int i = 0; i < 200000; ++i) {
    std::string text = (rng() % 2 ? "-" : "") + digits(rng, 10);
    if (rng() % 4 != 0) text += "." + digits(rng, 12);
    expect_same_number(text);
  }
}

// read_plain_decimal (scanners read a number where it stands): a prefix it takes is read as
// parse_number reads that prefix alone, bit for bit; what it leaves is not a plain decimal's
// byte (so the prefix is the whole run of one).
TEST(NumberDifferential, PlainDecimalPrefixReadsAsParseNumberReadsIt) {
  std::mt19937_64 rng(54);
  for (int i = 0; i < 300000; ++i) {
    std::string text = number_like(rng);
    if (rng() % 2) text += ",X=1";
    double got = 0.0;
    const std::size_t length = read_plain_decimal(text, got);
    if (length == 0) continue;
    const auto want = parse_number(text.substr(0, length));
    ASSERT_TRUE(want) << "'" << text << "'";
    std::uint64_t a = 0, b = 0;
    std::memcpy(&a, &got, sizeof a);
    std::memcpy(&b, &*want, sizeof b);
    ASSERT_EQ(a, b) << "'" << text << "'";
    if (length < text.size()) {
      const char next = text[length];
      ASSERT_FALSE(next >= '0' && next <= '9') << "'" << text << "'";
      ASSERT_FALSE(next == '.' && text.substr(0, length).find('.') == std::string::npos)
          << "'" << text << "'";
    }
  }
  double v = 0.0;
  EXPECT_EQ(read_plain_decimal("-12.5,X=1", v), 5U);
  EXPECT_EQ(v, -12.5);
  EXPECT_EQ(read_plain_decimal("+.5e3", v), 3U);
  for (const char* refused : {"", "-", "+", ".", "-.", " 1", "e5", "12345678901234567890",
                              "9007199254740993", "0.00000000000000000000001"})
    EXPECT_EQ(read_plain_decimal(refused, v), 0U) << "'" << refused << "'";
}

TEST(NumberDifferential, FixAndFmtWriteWhatPrintfWrites) {
  std::mt19937_64 rng(2026);
  for (int i = 0; i < 300000; ++i) {
    const double v = value_like(rng);
    const int decimals = static_cast<int>(rng() % 13);
    ASSERT_EQ(fix(v, decimals), printf_fixed(v, decimals)) << v << " " << decimals;
    ASSERT_EQ(fmt(v, decimals), printf_fmt(v, decimals)) << v << " " << decimals;
  }
  for (const double v : {0.0, -0.0, 0.5, 1.5, 2.5, -2.5, 0.125, 0.375, 2.675, 1.005, 1e15, 9e15,
                         9007199254740991.0, 9007199254740993.0, 1e22, 5e-324, -1e-10}) {
    for (int decimals = 0; decimals <= 12; ++decimals) {
      EXPECT_EQ(fix(v, decimals), printf_fixed(v, decimals)) << v << " " << decimals;
      EXPECT_EQ(fmt(v, decimals), printf_fmt(v, decimals)) << v << " " << decimals;
    }
  }
}

TEST(NumberDifferential, FormatGWritesWhatPrintfWrites) {
  const auto printf_g = [](double v, int significant) {
    char buf[512];
    std::snprintf(buf, sizeof buf, "%.*g", significant, v);
    return std::string(buf);
  };
  std::mt19937_64 rng(2028);
  for (int i = 0; i < 200000; ++i) {
    const double v = value_like(rng);
    const int significant = static_cast<int>(rng() % 18);
    ASSERT_EQ(format_g(v, significant), printf_g(v, significant)) << v << " " << significant;
  }
  for (const double v : {0.0, -0.0, 0.5, 1e-5, 1e-4, 123456.0, 1234567.0, 1e300, -1e-300, 5e-324,
                         std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::quiet_NaN(),
                         -std::numeric_limits<double>::quiet_NaN()}) {
    for (int significant = 0; significant <= 17; ++significant) {
      EXPECT_EQ(format_g(v, significant), printf_g(v, significant)) << v << " " << significant;
    }
  }
  for (const int significant : {-1, 40, 60}) {  // none given (6), and past 64 characters
    EXPECT_EQ(format_g(0.1, significant), printf_g(0.1, significant)) << significant;
    EXPECT_EQ(format_g(-1e300, significant), printf_g(-1e300, significant)) << significant;
  }
}

// write_fmt_fast writes fmt()'s text within its stated room, or nothing at all; and it takes
// every value a swath or a marker has (below 2^53 / 10^d, at most 9 decimals).
TEST(NumberDifferential, WriteFmtFastWritesFmtsTextOrNothing) {
  std::mt19937_64 rng(2027);
  int written = 0;
  for (int i = 0; i < 300000; ++i) {
    const double v = value_like(rng);
    const int decimals = static_cast<int>(rng() % 13);
    char room[kFastFmtMaxChars + 8];
    std::memset(room, '#', sizeof room);
    const char* const end = write_fmt_fast(room, v, decimals);
    const bool common = decimals <= 9 && std::fabs(v) * std::pow(10.0, decimals) < 0x1p52;
    if (common) {
      ASSERT_NE(end, nullptr) << v << " " << decimals;
    }
    if (!end) {
      ASSERT_EQ(room[0], '#') << v << " " << decimals;
      continue;
    }
    ++written;
    ASSERT_LE(end - room, static_cast<std::ptrdiff_t>(kFastFmtMaxChars)) << v;
    ASSERT_EQ(std::string(static_cast<const char*>(room), end), fmt(v, decimals))
        << v << " " << decimals;
    // (the room past the text may hold scratch digits; nothing is written beyond the room)
    for (const char* rest = room + kFastFmtMaxChars; rest < room + sizeof room; ++rest)
      ASSERT_EQ(*rest, '#') << v;
  }
  EXPECT_GT(written, 150000);  // the generator reaches the fast path, not only its refusals
  char room[kFastFmtMaxChars];
  const double longest = -9007199254740991.0 / 10.0;  // 16 digits, a point and a sign
  const char* const end = write_fmt_fast(room, longest, 1);
  ASSERT_NE(end, nullptr);
  EXPECT_EQ(std::string(static_cast<const char*>(room), end), "-900719925474099.1");
  for (const double refused : {1e300, std::nan(""), HUGE_VAL, -HUGE_VAL})
    EXPECT_EQ(write_fmt_fast(room, refused, 2), nullptr) << refused;
  EXPECT_EQ(write_fmt_fast(room, 1.5, 10), nullptr);
}

// The read-back form writes the same text and reports what that text reads as: all of it taken
// by read_plain_decimal, the number parse_number gives, bit for bit (a writer that keeps its
// reader's parse relies on it: NodeReportMemo::format).
TEST(NumberDifferential, WriteFmtFastReadBackIsWhatTheTextReadsAs) {
  std::mt19937_64 rng(2029);
  for (int i = 0; i < 300000; ++i) {
    const double v = value_like(rng);
    const int decimals = static_cast<int>(rng() % 11);
    char plain[kFastFmtMaxChars];
    char room[kFastFmtMaxChars];
    double read_back = 0.0;
    const char* const plain_end = write_fmt_fast(plain, v, decimals);
    const char* const end = write_fmt_fast(room, v, decimals, read_back);
    ASSERT_EQ(end == nullptr, plain_end == nullptr) << v << " " << decimals;
    if (!end) continue;
    const std::string text(static_cast<const char*>(room), end);
    ASSERT_EQ(text, std::string(static_cast<const char*>(plain), plain_end));
    double read = 0.0;
    ASSERT_EQ(read_plain_decimal(text, read), text.size()) << text;
    const auto parsed = parse_number(text);
    ASSERT_TRUE(parsed) << text;
    std::uint64_t a = 0, b = 0, c = 0;
    std::memcpy(&a, &read_back, sizeof a);
    std::memcpy(&b, &read, sizeof b);
    std::memcpy(&c, &*parsed, sizeof c);
    ASSERT_EQ(a, b) << text;
    ASSERT_EQ(a, c) << text;
  }
}

TEST(NumberDifferential, AppendedFormsEqualTheReturnedOnes) {
  std::string out = "x=";
  append_fix(out, 2.675, 2);
  out += ",y=";
  append_fmt(out, -0.001, 2);
  out += ",z=";
  append_fmt(out, 25.0, 1);
  EXPECT_EQ(out, "x=" + fix(2.675, 2) + ",y=" + fmt(-0.001, 2) + ",z=" + fmt(25.0, 1));
  EXPECT_EQ(out, "x=2.67,y=0,z=25");
}

}  // namespace
}  // namespace base
