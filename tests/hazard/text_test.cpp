// The text layer: FMT/FIX (spec 0), strict numbers (rulings "Numbers"), words, lists, angles (N3).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hazard/text.hpp"

namespace hazard {
namespace {

TEST(Text, FixIsPrintfFixed) {
  EXPECT_EQ(fix(0.9, 2), "0.90");
  EXPECT_EQ(fix(0.6561, 2), "0.66");
  EXPECT_EQ(fix(25, 1), "25.0");
  EXPECT_EQ(fix(-0.001, 2), "-0.00");
  EXPECT_EQ(fix(1e300, 0).size(), 301u);  // long values do not truncate
}

TEST(Text, FmtMatchesSpecExamples_Spec0) {
  EXPECT_EQ(fmt(25, 1), "25");
  EXPECT_EQ(fmt(0.6561, 3), "0.656");
  EXPECT_EQ(fmt(0.7396, 3), "0.74");
  EXPECT_EQ(fmt(-293.60001, 2), "-293.6");
  EXPECT_EQ(fmt(-0.001, 2), "0");
  EXPECT_EQ(fmt(0.73), "0.73");  // default 5 decimals
  EXPECT_EQ(fmt(100), "100");    // zeros before the point stay
  EXPECT_EQ(fmt(-0.4, 0), "0");  // "-0" without a point also maps to "0"
}

TEST(Text, NumbersAcceptSignFractionExponent_Rulings) {
  EXPECT_EQ(parse_number("42"), 42.0);
  EXPECT_EQ(parse_number(" -3.5 "), -3.5);
  EXPECT_EQ(parse_number("+.5"), 0.5);
  EXPECT_EQ(parse_number("5."), 5.0);
  EXPECT_EQ(parse_number("1e3"), 1000.0);
  EXPECT_EQ(parse_number("2.5E-1"), 0.25);
  EXPECT_EQ(parse_number("1e-400"), 0.0);  // underflow is finite
}

TEST(Text, NumbersRejectNonFiniteAndJunk_Rulings) {
  for (const char* bad : {"", " ", "nan", "NaN", "inf", "-inf", "1e999", "-1e999", "0x10", "1e",
                          "e5", ".", "-", "--5", "1.2.3", "5 m", "1,5", "infinity", "1e+"}) {
    EXPECT_FALSE(parse_number(bad)) << bad;
  }
}

TEST(Text, UnsignedWholeNumbers) {
  EXPECT_EQ(parse_unsigned("18446744073709551615"), 18446744073709551615ull);
  EXPECT_EQ(parse_unsigned("+7"), 7u);
  EXPECT_FALSE(parse_unsigned("18446744073709551616"));
  EXPECT_FALSE(parse_unsigned("-1"));
  EXPECT_FALSE(parse_unsigned("1.5"));
  EXPECT_FALSE(parse_unsigned("1e3"));
}

TEST(Text, BooleanWordsAnyCase_Spec0) {
  for (const char* t : {"true", "TRUE", "yes", "On"}) EXPECT_EQ(parse_bool(t), true) << t;
  for (const char* f : {"false", "No", "OFF"}) EXPECT_EQ(parse_bool(f), false) << f;
  for (const char* x : {"1", "0", "toggle", "", "truee"}) EXPECT_FALSE(parse_bool(x)) << x;
}

TEST(Text, KeyValueListsTrimAndSplitAtFirstEquals) {
  const auto kv = split_key_values(" a = 1 , b=x=y,, c ,d=");
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
  const auto kv = split_key_values("pts={1,2:3,4},label=x", ',', true);
  ASSERT_EQ(kv.size(), 2u);
  EXPECT_EQ(kv[0].value, "{1,2:3,4}");
  EXPECT_EQ(split_key_values("pts={1,2:3,4},label=x").size(), 4u);
}

TEST(Text, CaseHelpers) {
  EXPECT_TRUE(iequals("Sensor_Config", "sensor_config"));
  EXPECT_FALSE(iequals("a", "ab"));
  EXPECT_EQ(to_upper("archie-2"), "ARCHIE-2");
  EXPECT_EQ(to_lower("AbC"), "abc");
  EXPECT_EQ(trim(" \t x y \r\n"), "x y");
}

TEST(Text, AnglesNormaliseWithoutLoops_N3) {
  EXPECT_EQ(norm360(-90), 270);
  EXPECT_EQ(norm360(720), 0);
  EXPECT_EQ(norm360(359.5), 359.5);
  EXPECT_EQ(norm360(-1e-17), 0);  // would round to 360
  EXPECT_EQ(norm180(180), 180);
  EXPECT_EQ(norm180(-180), 180);  // (-180, 180]
  EXPECT_EQ(norm180(190), -170);
  // A 20-digit heading passes the number grammar; the original looped ~1e17 times on it.
  const double huge = *parse_number("12345678901234567890");
  const double r = norm360(huge);
  EXPECT_GE(r, 0.0);
  EXPECT_LT(r, 360.0);
  EXPECT_TRUE(std::isfinite(norm360(1e308)));
}

TEST(Text, ExcerptCutsHugeValues) {
  const std::string big(1 << 20, 'x');
  const std::string e = excerpt(big, 10);
  EXPECT_EQ(e, "xxxxxxxxxx ... (1048576 bytes)");
  EXPECT_EQ(excerpt("short", 10), "short");
}

}  // namespace
}  // namespace hazard
