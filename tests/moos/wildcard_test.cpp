// Wildcard registration strings (docs/protocol.md 5.5, 9.2): the lenient reading the reference DB
// does, plus the description of what was skipped, which moosdb-lite uses to refuse with a reason.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "moos/wildcard.hpp"

namespace moos {
namespace {

std::string problem_of(const std::string& text) {
  std::string problem;
  parse_wildcard_spec(text, &problem);
  return problem;
}

TEST(WildcardSpecProblem, CommaFormOfLibMoosHasNoProblem_5_5) {
  EXPECT_EQ(problem_of("AppPattern=*,VarPattern=NAV_*,Interval=0.5"), "");
  EXPECT_EQ(problem_of("AppPattern=*,VarPattern=*,Interval=1e-05"), "");
}

TEST(WildcardSpecProblem, BlankFormOfPymoos2HasNoProblem_9_2) {
  const std::string text = "AppPattern=* VarPattern=X_* Interval=0.0";
  EXPECT_EQ(problem_of(text), "");
  const WildcardSpec spec = parse_wildcard_spec(text);
  EXPECT_EQ(spec.app_pattern, "*");
  EXPECT_EQ(spec.var_pattern, "X_*");
  EXPECT_EQ(spec.interval_s, 0.0);
}

TEST(WildcardSpecProblem, MissingItemsAreNotProblems_5_5) {
  EXPECT_EQ(problem_of("VarPattern=X"), "");
  EXPECT_EQ(problem_of(""), "");
}

TEST(WildcardSpecProblem, MalformedItemsAreNamedAndTheRestIsStillRead) {
  EXPECT_EQ(problem_of("AppPattern=*,Junk"), "item 'Junk' has no '='");
  EXPECT_EQ(problem_of("apppattern=*"),
            "unknown item 'apppattern' (expected AppPattern, VarPattern, Interval)");
  EXPECT_EQ(problem_of("Interval=-1"), "Interval '-1' is not a number >= 0");
  EXPECT_EQ(problem_of("Interval=nan"), "Interval 'nan' is not a number >= 0");
  EXPECT_EQ(problem_of("Interval=0.5s"), "Interval '0.5s' is not a number >= 0");
  std::string problem;
  const WildcardSpec spec = parse_wildcard_spec("Junk,VarPattern=A*,Interval=x", &problem);
  EXPECT_EQ(problem, "item 'Junk' has no '='");  // the first problem is kept
  EXPECT_EQ(spec.var_pattern, "A*");
  EXPECT_EQ(spec.interval_s, 0.0);
}

TEST(WildcardMatch, StarAndQuestionMarkSemantics_4_1) {
  EXPECT_TRUE(wildcard_match("*", ""));
  EXPECT_TRUE(wildcard_match("NAV_*", "NAV_X"));
  EXPECT_TRUE(wildcard_match("NAV_*", "NAV_"));
  EXPECT_FALSE(wildcard_match("NAV_*", "NAV"));
  EXPECT_TRUE(wildcard_match("?AV_?", "NAV_X"));
  EXPECT_FALSE(wildcard_match("?AV_?", "NAV_XY"));
  EXPECT_TRUE(wildcard_match("*_REPORT*", "UHZ_DETECTION_REPORT_ARCHIE"));
  EXPECT_TRUE(wildcard_match("a*b*c", "abc"));
  EXPECT_TRUE(wildcard_match("a*b*c", "aXbYbZc"));
  EXPECT_FALSE(wildcard_match("a*b*c", "acb"));
  EXPECT_FALSE(wildcard_match("ab*ba", "aba"));  // first and last segments may not overlap
  EXPECT_TRUE(wildcard_match("ab*ba", "abba"));
  EXPECT_TRUE(wildcard_match("**x**", "yxy"));
  EXPECT_FALSE(wildcard_match("nav_*", "NAV_X"));  // case-sensitive
  EXPECT_FALSE(wildcard_match("", "X"));
  EXPECT_TRUE(wildcard_match("", ""));
}

TEST(WildcardMatch, LongSegmentsBeyondOneStateWord) {
  const std::string segment(100, 'q');
  EXPECT_TRUE(wildcard_match("*" + segment + "*", "xx" + segment + "yy"));
  EXPECT_FALSE(wildcard_match("*" + segment + "*", "xx" + segment.substr(1) + "yy"));
  EXPECT_TRUE(wildcard_match("*?" + segment.substr(1) + "*", "x" + segment));
}

// Agrees with a slow, obviously right reference on every pattern and text over a small alphabet.
bool reference_match(const std::string& p, const std::string& t, std::size_t i = 0,
                     std::size_t j = 0) {
  if (i == p.size()) return j == t.size();
  if (p[i] == '*') return reference_match(p, t, i + 1, j) ||
                          (j < t.size() && reference_match(p, t, i, j + 1));
  return j < t.size() && (p[i] == '?' || p[i] == t[j]) && reference_match(p, t, i + 1, j + 1);
}

TEST(WildcardMatch, AgreesWithAReferenceOnEveryShortCase) {
  const std::string alphabet = "ab*?";
  std::vector<std::string> patterns{""};
  for (int len = 1; len <= 5; ++len) {
    const std::size_t from = patterns.size();
    for (std::size_t k = 0; k < from; ++k)
      if (patterns[k].size() == static_cast<std::size_t>(len - 1))
        for (char c : alphabet) patterns.push_back(patterns[k] + c);
  }
  std::vector<std::string> texts{""};
  for (int len = 1; len <= 6; ++len) {
    const std::size_t from = texts.size();
    for (std::size_t k = 0; k < from; ++k)
      if (texts[k].size() == static_cast<std::size_t>(len - 1))
        for (char c : std::string("ab")) texts.push_back(texts[k] + c);
  }
  int checked = 0;
  for (const std::string& p : patterns)
    for (const std::string& t : texts) {
      ASSERT_EQ(wildcard_match(p, t), reference_match(p, t)) << "pattern " << p << " text " << t;
      ++checked;
    }
  EXPECT_GT(checked, 100000);
}

TEST(WildcardSpecProblem, OverlongPatternsAreRefusedAndMatchNothing_Hardening) {
  const std::string long_pattern(kMaxWildcardPatternChars + 1, '*');
  std::string problem;
  const WildcardSpec spec = parse_wildcard_spec("AppPattern=*,VarPattern=" + long_pattern, &problem);
  EXPECT_EQ(problem, "VarPattern of 257 characters is longer than 256");
  EXPECT_FALSE(spec.matches("app", "X"));
  EXPECT_EQ(problem_of("VarPattern=" + std::string(kMaxWildcardPatternChars, '*')), "");
}

}  // namespace
}  // namespace moos
