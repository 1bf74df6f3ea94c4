// AppCast string (docs/protocol.md 7.2, its two examples byte for byte), terminal frame
// (docs/uFldHazardSensor.md, manual section 12) and APPCAST_REQ parsing (7.2).
#include <gtest/gtest.h>

#include "moos/appcast.hpp"

namespace moos {
namespace {

AppCast pfoo() {
  AppCast ac;
  ac.set_proc("pFoo");
  ac.set_node("alpha");
  ac.set_iteration(12);
  return ac;
}

TEST(AppCastString, EmptyAppCastMatchesTheFirstExample_7_2) {
  EXPECT_EQ(pfoo().appcast_string(),
            "proc=pFoo!@#iter=12!@#node=alpha!@#iter=12!@#messages=!@#!@#events_total=0!@#!@#"
            "run_warning_total=0!@#");
}

TEST(AppCastString, FullAppCastMatchesTheSecondExample_7_2) {
  AppCast ac = pfoo();
  ac.set_messages("line one\nline two");
  ac.add_config_warning("bad param");
  ac.add_event("started", 1.5);
  ac.add_run_warning("oops");
  ac.add_run_warning("oops");
  EXPECT_EQ(ac.appcast_string(),
            "proc=pFoo!@#iter=12!@#node=alpha!@#iter=12!@#messages=line one!@line two!@!@#"
            "config_warnings=bad param!@#events_total=1!@#events=[1.50]: started!@#"
            "run_warning_total=2!@#run_warnings=2:oops");
}

TEST(AppCastString, NodeItemIsOmittedWhenEmptyAndListsUseInnerSeparators_7_2) {
  AppCast ac;
  ac.set_proc("p");
  ac.set_iteration(1);
  ac.set_messages("a\n\nb\n");  // an empty middle line is kept, a final newline adds nothing
  ac.add_config_warning("w1");
  ac.add_config_warning("w2");
  ac.add_event("e1", 0);
  ac.add_event("e2", 12.345);
  ac.add_run_warning("zeta");
  ac.add_run_warning("alpha");
  EXPECT_EQ(ac.appcast_string(),
            "proc=p!@#iter=1!@#iter=1!@#messages=a!@!@b!@!@#config_warnings=w1!@w2!@#"
            "events_total=2!@#events=[0.00]: e1!@[12.35]: e2!@#run_warning_total=2!@#"
            "run_warnings=1:alpha!@1:zeta");
}

TEST(AppCastEvents, OldestEventsAreDroppedBeyondTheLimit_7_2) {
  AppCast ac;
  ac.set_max_events(3);
  for (int i = 0; i < 5; ++i) ac.add_event("e" + std::to_string(i), i);
  ASSERT_EQ(ac.events().size(), 3u);
  EXPECT_EQ(ac.events().front(), "[2.00]: e2");
  EXPECT_EQ(ac.events().back(), "[4.00]: e4");
  ac.set_max_events(1000);  // clipped to 50
  EXPECT_EQ(ac.max_events(), AppCast::kMaxEventsLimit);
  ac.set_max_events(0);
  EXPECT_TRUE(ac.events().empty());
}

// A full list's new line takes the buffer of the line it pushes out (an event per detection):
// the same texts, no allocation.
TEST(AppCastEvents, ANewEventReusesTheDroppedLinesBuffer) {
  AppCast ac;
  ac.set_max_events(2);
  const std::string long_text(60, 'x');
  ac.add_event(long_text + "1", 1.0);
  ac.add_event(long_text + "2", 2.0);
  const char* const oldest = ac.events().front().data();
  ac.add_event(long_text + "3", 3.0);
  ASSERT_EQ(ac.events().size(), 2u);
  EXPECT_EQ(ac.events().front(), "[2.00]: " + long_text + "2");
  EXPECT_EQ(ac.events().back(), "[3.00]: " + long_text + "3");
  EXPECT_EQ(ac.events().back().data(), oldest);
}

TEST(AppCastRunWarnings, CountsRetractionAndOverflow_7_2) {
  AppCast ac;
  ac.set_max_run_warnings(2);
  ac.add_run_warning("a");
  ac.add_run_warning("a");
  ac.add_run_warning("b");
  ac.add_run_warning("c");  // table full: counted under "Other Run Warnings"
  ac.add_run_warning("a");  // even a listed text, once the table is full (core-moos)
  EXPECT_EQ(ac.run_warning_count(), 5u);
  EXPECT_EQ(ac.run_warnings().at("a"), 2u);
  EXPECT_EQ(ac.run_warnings().at(std::string(AppCast::kOtherRunWarnings)), 2u);
  EXPECT_TRUE(ac.retract_run_warning("a"));
  EXPECT_EQ(ac.run_warning_count(), 3u);
  EXPECT_FALSE(ac.retract_run_warning("a"));
  EXPECT_FALSE(ac.retract_run_warning("never"));
}

TEST(AppCastConfigWarnings, AtMostOneHundredAreKept) {
  AppCast ac;
  for (int i = 0; i < 105; ++i) ac.add_config_warning("w" + std::to_string(i));
  EXPECT_EQ(ac.config_warnings().size(), AppCast::kMaxConfigWarnings);
  EXPECT_EQ(ac.config_warnings_dropped(), 5u);
}

TEST(AppCastTerminal, HeaderIsPaddedTo62ColumnsLikeTheManualListing_11) {
  AppCast ac;
  ac.set_proc("uFldHazardSensor");
  ac.set_node("shoreside");
  ac.set_iteration(457);
  ac.set_messages("Hazard File: (hazards.txt)");
  const std::string rule(62, '=');
  EXPECT_EQ(ac.terminal_report(),
            rule + "\n" + "uFldHazardSensor shoreside                            0/0(457)\n" + rule +
                "\n" + "Hazard File: (hazards.txt)\n");
  const std::string header = ac.terminal_report().substr(63, 62);
  EXPECT_EQ(header.size(), 62u);
  EXPECT_EQ(header.substr(54), "0/0(457)");
}

TEST(AppCastTerminal, WarningsBodyAndEventsNewestFirst_11) {
  AppCast ac;
  ac.set_proc("pA");
  ac.set_node("n");
  ac.set_iteration(3);
  ac.set_messages("body");
  ac.add_config_warning("cfg one");
  ac.add_config_warning("cfg two");
  ac.add_run_warning("run x");
  ac.add_run_warning("run x");
  ac.add_event("first", 1.0);
  ac.add_event("second", 11.86);
  const std::string rule(62, '=');
  const std::string events_rule(67, '=');
  EXPECT_EQ(ac.terminal_report(),
            rule + "\npA n" + std::string(62 - 4 - 3 - 3, ' ') + "2/2(3)\n" + rule + "\n" +
                "Configuration Warnings: 2\n [1 of 2]: cfg one\n [2 of 2]: cfg two\n\n"
                "Runtime Warnings: 2\n [2]: run x\n\n"
                "body\n" +
                events_rule + "\nMost Recent Events (2):\n" + events_rule + "\n" +
                "[11.86]: second\n[1.00]: first\n");
}

TEST(AppCastRequest, ParsesTheUmacForm_7_2) {
  const auto r = parse_appcast_request("node=henry,app=pHostInfo,duration=3.0,key=uMAC_438,thresh=any",
                                       "henry", "pHostInfo");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->key, "uMAC_438");
  EXPECT_EQ(r->duration_s, 3.0);
  EXPECT_EQ(r->thresh, "any");
}

TEST(AppCastRequest, KeysAreCaseInsensitiveValuesExact_7_2) {
  EXPECT_TRUE(parse_appcast_request("NODE=all,App=all,KEY=k", "x", "y").has_value());
  EXPECT_FALSE(parse_appcast_request("node=Henry,app=all,key=k", "henry", "p").has_value());
  EXPECT_FALSE(parse_appcast_request("node=henry,app=phostinfo,key=k", "henry", "pHostInfo").has_value());
  EXPECT_FALSE(parse_appcast_request("node=henry,app=pHostInfo,duration=3", "henry", "pHostInfo").has_value());
  const auto r = parse_appcast_request(" key = k , thresh = run_warning ", "n", "a");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->thresh, "run_warning");
  EXPECT_EQ(r->duration_s, 0.0);  // absent duration: 0
}

TEST(AppCastRequest, DurationIsClippedToThirtySeconds_7_2) {
  EXPECT_EQ(parse_appcast_request("key=k,duration=100", "n", "a")->duration_s, 30.0);
  EXPECT_EQ(parse_appcast_request("key=k,duration=-5", "n", "a")->duration_s, 0.0);
  EXPECT_EQ(parse_appcast_request("key=k,duration=abc", "n", "a")->duration_s, 0.0);
}

}  // namespace
}  // namespace moos
