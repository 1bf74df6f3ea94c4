// The text layer: FMT/FIX, strict numbers (differences.md "Numbers"), words, lists, angles (N3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "base/key_value_reader.hpp"
#include "base/text.hpp"

namespace base {
namespace {

TEST(Text, FixIsPrintfFixed) {
  EXPECT_EQ(base::fix(0.9, 2), "0.90");
  EXPECT_EQ(base::fix(0.6561, 2), "0.66");
  EXPECT_EQ(base::fix(25, 1), "25.0");
  EXPECT_EQ(base::fix(-0.001, 2), "-0.00");
  EXPECT_EQ(base::fix(1e300, 0).size(), 301u);  // long values do not truncate
}

TEST(Text, JoinedPutsThePiecesInOneString) {
  EXPECT_EQ(joined({}), "");
  EXPECT_EQ(joined({"Detection report sent to vehicle: ", "v1", " (label ", "", ")"}),
            "Detection report sent to vehicle: v1 (label )");
  const std::string long_piece(40, 'a');
  EXPECT_EQ(joined({long_piece, "b"}), long_piece + "b");
}

TEST(Text, FmtMatchesSpecExamples_Spec0) {
  EXPECT_EQ(base::fmt(25, 1), "25");
  EXPECT_EQ(base::fmt(0.6561, 3), "0.656");
  EXPECT_EQ(base::fmt(0.7396, 3), "0.74");
  EXPECT_EQ(base::fmt(-293.60001, 2), "-293.6");
  EXPECT_EQ(base::fmt(-0.001, 2), "0");
  EXPECT_EQ(base::fmt(0.73), "0.73");  // default 5 decimals
  EXPECT_EQ(base::fmt(100), "100");    // zeros before the point stay
  EXPECT_EQ(base::fmt(-0.4, 0), "0");  // "-0" without a point also maps to "0"
}

TEST(Text, NumbersAcceptSignFractionExponent_Rulings) {
  EXPECT_EQ(base::parse_number("42"), 42.0);
  EXPECT_EQ(base::parse_number(" -3.5 "), -3.5);
  EXPECT_EQ(base::parse_number("+.5"), 0.5);
  EXPECT_EQ(base::parse_number("5."), 5.0);
  EXPECT_EQ(base::parse_number("1e3"), 1000.0);
  EXPECT_EQ(base::parse_number("2.5E-1"), 0.25);
  EXPECT_EQ(base::parse_number("1e-400"), 0.0);  // underflow is finite
}

TEST(Text, NumbersRejectNonFiniteAndJunk_Rulings) {
  for (const char* bad : {"", " ", "nan", "NaN", "inf", "-inf", "1e999", "-1e999", "0x10", "1e",
                          "e5", ".", "-", "--5", "1.2.3", "5 m", "1,5", "infinity", "1e+"}) {
    EXPECT_FALSE(base::parse_number(bad)) << bad;
  }
}

TEST(Text, UnsignedWholeNumbers) {
  EXPECT_EQ(base::parse_unsigned("18446744073709551615"), 18446744073709551615ull);
  EXPECT_EQ(base::parse_unsigned("+7"), 7u);
  EXPECT_FALSE(base::parse_unsigned("18446744073709551616"));
  EXPECT_FALSE(base::parse_unsigned("-1"));
  EXPECT_FALSE(base::parse_unsigned("1.5"));
  EXPECT_FALSE(base::parse_unsigned("1e3"));
}

TEST(Text, BooleanWordsAnyCase_Spec0) {
  for (const char* t : {"true", "TRUE", "yes", "On"}) EXPECT_EQ(base::parse_bool(t), true) << t;
  for (const char* f : {"false", "No", "OFF"}) EXPECT_EQ(base::parse_bool(f), false) << f;
  for (const char* x : {"1", "0", "toggle", "", "truee"}) EXPECT_FALSE(base::parse_bool(x)) << x;
}

TEST(Text, KeyValueListsTrimAndSplitAtFirstEquals) {
  const auto kv = base::split_key_values(" a = 1 , b=x=y,, c ,d=");
  ASSERT_EQ(kv.size(), 4u);
  EXPECT_EQ(kv[0].key, "a");
  EXPECT_EQ(kv[0].value, "1");
  EXPECT_EQ(kv[1].key, "b");
  EXPECT_EQ(kv[1].value, "x=y");
  EXPECT_EQ(kv[2].key, "c");
  EXPECT_FALSE(kv[2].has_equals);
  EXPECT_EQ(kv[3].key, "d");
  EXPECT_EQ(kv[3].value, "");
}

TEST(Text, BracesProtectCommasWhenAsked) {
  const auto kv = base::split_key_values("pts={1,2:3,4},label=x", ',', true);
  ASSERT_EQ(kv.size(), 2u);
  EXPECT_EQ(kv[0].value, "{1,2:3,4}");
  EXPECT_EQ(base::split_key_values("pts={1,2:3,4},label=x").size(), 4u);
}

// The edges of the brace rule (the speed work rewrote the scan): nesting, an unmatched '}' (an
// ordinary byte), an unclosed '{' (the rest is one piece), '=' only inside braces.
TEST(Text, BraceEdgesSplitAsBefore) {
  const auto kv = base::split_key_values(" a={x,{y,z}},b}=1,c , {d=2,e} ,f={g", ',', true);
  ASSERT_EQ(kv.size(), 5u);
  EXPECT_EQ(kv[0].key, "a");
  EXPECT_EQ(kv[0].value, "{x,{y,z}}");
  EXPECT_EQ(kv[1].key, "b}");
  EXPECT_EQ(kv[1].value, "1");
  EXPECT_FALSE(kv[2].has_equals);
  EXPECT_EQ(kv[2].key, "c");
  EXPECT_EQ(kv[3].key, "{d");
  EXPECT_EQ(kv[3].value, "2,e}");
  EXPECT_EQ(kv[4].key, "f");
  EXPECT_EQ(kv[4].value, "{g");
  const auto tail = base::split_key_values("x={1,2}y,z={", ',', true);
  ASSERT_EQ(tail.size(), 2u);
  EXPECT_EQ(tail[0].value, "{1,2}y");
  EXPECT_EQ(tail[1].value, "{");
}

TEST(Text, KeyValueReaderGivesTheSplitPieces) {
  const std::string_view text = "NAME=v1, X=3,,{a,b}, Y = 4 ,junk";
  const auto all = base::split_key_values(text, ',', true);
  base::KeyValueReader reader(text, ',', true);
  std::size_t i = 0;
  for (base::KeyValue kv; reader.next(kv); ++i) {
    ASSERT_LT(i, all.size());
    EXPECT_EQ(kv.key, all[i].key);
    EXPECT_EQ(kv.value, all[i].value);
    EXPECT_EQ(kv.has_equals, all[i].has_equals);
  }
  EXPECT_EQ(i, 5u);
}

// The pieces by the contract's words, one byte at a time: a piece ends at a separator outside
// {...}; its key is before its first '=', wherever that is; both sides trimmed; blank pieces
// without '=' skipped. The reader (a table-driven scan) must agree on every text.
std::vector<KeyValue> pieces_by_contract(std::string_view text, char separator, bool braces) {
  std::vector<KeyValue> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t i = start;
    int depth = 0;
    for (; i < text.size(); ++i) {
      if (braces && text[i] == '{') ++depth;
      if (braces && text[i] == '}' && depth > 0) --depth;
      if (text[i] == separator && depth == 0) break;
    }
    const std::string_view piece = text.substr(start, i - start);
    start = i + 1;
    const std::size_t equals = piece.find('=');
    if (equals == std::string_view::npos) {
      if (!trim(piece).empty()) out.push_back({trim(piece), {}, false});
    } else {
      out.push_back({trim(piece.substr(0, equals)), trim(piece.substr(equals + 1)), true});
    }
  }
  return out;
}

TEST(Text, KeyValueReaderAgreesWithTheContractOnGeneratedTexts) {
  constexpr std::string_view kBytes = "ab=,{} \t;";
  std::uint64_t state = 12345;
  for (int n = 0; n < 20000; ++n) {
    std::string text;
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const std::size_t length = (state >> 33) % 24;
    for (std::size_t k = 0; k < length; ++k) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      text.push_back(kBytes[(state >> 33) % kBytes.size()]);
    }
    for (const char separator : {',', ';'}) {
      for (const bool braces : {false, true}) {
        const auto want = pieces_by_contract(text, separator, braces);
        const auto got = split_key_values(text, separator, braces);
        ASSERT_EQ(got.size(), want.size()) << "'" << text << "' " << separator << braces;
        for (std::size_t i = 0; i < got.size(); ++i) {
          EXPECT_EQ(got[i].key, want[i].key) << "'" << text << "'";
          EXPECT_EQ(got[i].value, want[i].value) << "'" << text << "'";
          EXPECT_EQ(got[i].has_equals, want[i].has_equals) << "'" << text << "'";
        }
      }
    }
  }
}

TEST(Text, CaseHelpers) {
  EXPECT_TRUE(base::iequals("Sensor_Config", "sensor_config"));
  EXPECT_FALSE(base::iequals("a", "ab"));
  EXPECT_EQ(base::to_upper("archie-2"), "ARCHIE-2");
  EXPECT_EQ(base::to_lower("AbC"), "abc");
  EXPECT_EQ(base::trim(" \t x y \r\n"), "x y");
}

TEST(Text, AnglesNormaliseWithoutLoops_N3) {
  EXPECT_EQ(base::norm360(-90), 270);
  EXPECT_EQ(base::norm360(720), 0);
  EXPECT_EQ(base::norm360(359.5), 359.5);
  EXPECT_EQ(base::norm360(-1e-17), 0);  // would round to 360
  EXPECT_EQ(base::norm180(180), 180);
  EXPECT_EQ(base::norm180(-180), 180);  // (-180, 180]
  EXPECT_EQ(base::norm180(190), -170);
  // A 20-digit heading passes the number grammar; the original looped ~1e17 times on it.
  const double huge = *base::parse_number("12345678901234567890");
  const double r = base::norm360(huge);
  EXPECT_GE(r, 0.0);
  EXPECT_LT(r, 360.0);
  EXPECT_TRUE(std::isfinite(base::norm360(1e308)));
}

std::uint64_t bits_of(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// norm360's inline cases must give the bits of the general path (outputs depend on them).
void expect_same_as_general(double a) {
  const double fast = base::norm360(a);
  const double general = base::detail::norm360_general(a);
  if (std::isnan(general)) {
    EXPECT_TRUE(std::isnan(fast)) << a;
    return;
  }
  EXPECT_EQ(bits_of(fast), bits_of(general)) << a;
  const double half = general > 180.0 ? general - 360.0 : general;
  EXPECT_EQ(bits_of(base::norm180(a)), bits_of(half)) << a;
}

TEST(Text, AnglesInlineCasesMatchTheGeneralPath) {
  const double inf = std::numeric_limits<double>::infinity();
  const double below360 = std::nextafter(360.0, 0.0);
  for (double a : {0.0, -0.0, 360.0, -360.0, below360, -below360, 359.9999999999999,
                   -359.9999999999999, std::nextafter(-360.0, 0.0), std::nextafter(-360.0, -inf),
                   std::nextafter(0.0, -1.0), -1e-300, 1e-300, -1e-17, 180.0, -180.0, 720.0, -720.0,
                   1e15, -1e15, 1e308, -1e308, inf, -inf,
                   std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::min(),
                   -std::numeric_limits<double>::denorm_min()}) {
    expect_same_as_general(a);
  }
  // Pseudo-random values within a few turns, and arbitrary bit patterns.
  std::uint64_t state = 0x9E3779B97F4A7C15ULL;
  for (int i = 0; i < 100000; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double unit = static_cast<double>(state >> 11) / 9007199254740992.0;  // [0, 1)
    expect_same_as_general((unit - 0.5) * 2000.0);
    double any = 0.0;
    std::memcpy(&any, &state, sizeof any);
    expect_same_as_general(any);
  }
}

TEST(Text, ExcerptCutsHugeValues) {
  const std::string big(1 << 20, 'x');
  const std::string e = base::excerpt(big, 10);
  EXPECT_EQ(e, "xxxxxxxxxx ... (1048576 bytes)");
  EXPECT_EQ(base::excerpt("short", 10), "short");
}

TEST(Text, UnderflowIsFiniteAndReadsAsZero_Rulings) {
  ASSERT_TRUE(base::parse_number("1e-400").has_value());
  EXPECT_EQ(*base::parse_number("1e-400"), 0.0);
  EXPECT_FALSE(base::parse_number("1e400").has_value());
  EXPECT_FALSE(base::parse_number("0x10").has_value());
}

TEST(Text, IntegersWithinBoundsOnly) {
  EXPECT_EQ(base::parse_integer(" +42 ", 1, 65535), 42);
  EXPECT_FALSE(base::parse_integer("0", 1, 65535).has_value());
  EXPECT_FALSE(base::parse_integer("65536", 1, 65535).has_value());
  EXPECT_FALSE(base::parse_integer("4.2", 0, 100).has_value());
  EXPECT_FALSE(base::parse_integer("", 0, 100).has_value());
}

TEST(Text, MissionBlanksAndPrefixes_Spec6_2) {
  EXPECT_EQ(base::remove_blanks(" a b\t\rc "), "abc");
  EXPECT_TRUE(base::starts_with("ProcessConfig", "Process"));
  EXPECT_FALSE(base::starts_with("Pro", "Process"));
  EXPECT_TRUE(base::ends_with("file.alog", ".alog"));
  EXPECT_FALSE(base::ends_with("alog", "file.alog"));
  const auto pieces = base::split("a,,b ", ',');
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(pieces[1], "");
  EXPECT_EQ(pieces[2], "b ");
}

TEST(Text, GeneralAndShortestFormats) {
  EXPECT_EQ(base::format_g(0.1 + 0.2), "0.3");
  EXPECT_EQ(base::format_g(123456789.0), "1.23457e+08");
  EXPECT_EQ(base::format_shortest(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(base::format_shortest(2.5), "2.5");
}

TEST(Text, EscapeForLogKeepsOneLineAndUtf8_Hardening) {
  EXPECT_EQ(base::escape_for_log("plain text, 1.5"), "plain text, 1.5");
  EXPECT_EQ(base::escape_for_log("a\nb\rc\td"), "a\\x0Ab\\x0Dc\\x09d");
  EXPECT_EQ(base::escape_for_log(std::string("n\0ul", 4)), "n\\x00ul");
  EXPECT_EQ(base::escape_for_log("back\\slash"), "back\\x5Cslash");
  EXPECT_EQ(base::escape_for_log("\x1b[31mred"), "\\x1B[31mred");
  EXPECT_EQ(base::escape_for_log("caf\xc3\xa9"), "caf\xc3\xa9");
}

TEST(Text, LogExcerptCutsThenEscapes_Hardening) {
  EXPECT_EQ(base::log_excerpt("a\nb"), "a\\x0Ab");
  const std::string long_text = std::string(200, 'x') + "\x1b";
  EXPECT_EQ(base::log_excerpt(long_text), base::escape_for_log(base::excerpt(long_text)));
  EXPECT_EQ(base::log_excerpt(long_text).find('\x1b'), std::string::npos);
  EXPECT_LT(base::log_excerpt(long_text).size(), long_text.size());
}

}  // namespace
}  // namespace base
