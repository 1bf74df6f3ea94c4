// Wildcard registration strings (wire spec 5.5, 9.2): the lenient reading the reference DB
// does, plus the description of what was skipped, which moosdb-lite uses to refuse with a reason.

#include <gtest/gtest.h>

#include <string>

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

}  // namespace
}  // namespace moos
