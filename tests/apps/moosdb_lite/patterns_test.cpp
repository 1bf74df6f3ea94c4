// The server's strict check of wildcard registration strings (spec 5.5, 9.2); matching and
// parsing themselves are libmoos's (moos/wildcard.hpp) and tested there.

#include <gtest/gtest.h>

#include <string>

#include "patterns.hpp"

namespace moosdb_lite {
namespace {

TEST(WildcardSpecProblem, CommaFormOfLibMoosIsAccepted_5_5) {
  EXPECT_FALSE(wildcard_spec_problem("AppPattern=*,VarPattern=NAV_*,Interval=0.5"));
  EXPECT_FALSE(wildcard_spec_problem("AppPattern=*,VarPattern=*,Interval=1e-05"));
}

TEST(WildcardSpecProblem, BlankFormOfPymoos2IsAccepted_9_2) {
  EXPECT_FALSE(wildcard_spec_problem("AppPattern=* VarPattern=X_* Interval=0.0"));
}

TEST(WildcardSpecProblem, MissingItemsAreAccepted_5_5) {
  EXPECT_FALSE(wildcard_spec_problem("VarPattern=X"));
  EXPECT_FALSE(wildcard_spec_problem(""));
}

TEST(WildcardSpecProblem, MalformedItemsAreNamed) {
  EXPECT_EQ(wildcard_spec_problem("AppPattern=*,Junk"), "item 'Junk' has no '='");
  EXPECT_EQ(wildcard_spec_problem("apppattern=*"),
            "unknown item 'apppattern' (expected AppPattern, VarPattern, Interval)");
  EXPECT_EQ(wildcard_spec_problem("Interval=-1"), "Interval '-1' is not a number >= 0");
  EXPECT_EQ(wildcard_spec_problem("Interval=nan"), "Interval 'nan' is not a number >= 0");
  EXPECT_EQ(wildcard_spec_problem("Interval=0.5s"), "Interval '0.5s' is not a number >= 0");
}

TEST(ParseFiniteNumber, WholeTextMustBeAFiniteNumber) {
  EXPECT_EQ(parse_finite_number("12.5"), 12.5);
  EXPECT_EQ(parse_finite_number("-1e3"), -1000.0);
  EXPECT_FALSE(parse_finite_number(""));
  EXPECT_FALSE(parse_finite_number("12 "));
  EXPECT_FALSE(parse_finite_number("inf"));
  EXPECT_FALSE(parse_finite_number("1e999"));
}

}  // namespace
}  // namespace moosdb_lite
