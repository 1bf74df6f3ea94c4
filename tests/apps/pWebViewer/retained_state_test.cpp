// The retained state's rules (retained_state.hpp): what a page that connects late receives.
#include <gtest/gtest.h>

#include "retained_state.hpp"

namespace web_viewer {
namespace {

Mail text(const std::string& var, const std::string& value, double time_s = 0.0, const std::string& src = "app") {
  Mail m;
  m.var = var;
  m.sval = value;
  m.time_s = time_s;
  m.src = src;
  return m;
}

Mail number(const std::string& var, double value, double time_s = 0.0) {
  Mail m;
  m.var = var;
  m.is_double = true;
  m.dval = value;
  m.time_s = time_s;
  return m;
}

std::vector<std::string> values(const RetainedState& state) {
  std::vector<std::string> out;
  for (const Mail& m : state.snapshot()) out.push_back(m.is_double ? std::to_string(m.dval) : m.sval);
  return out;
}

using Values = std::vector<std::string>;

TEST(RetainedState, SameLabelReplacesAndKeepsOtherLabels) {
  RetainedState state;
  state.apply(text("VIEW_MARKER", "x=1,y=1,label=a"));
  state.apply(text("VIEW_MARKER", "x=2,y=2,label=b"));
  state.apply(text("VIEW_MARKER", "x=3,y=3,label=a"));
  EXPECT_EQ(values(state), (Values{"x=2,y=2,label=b", "x=3,y=3,label=a"}));
}

TEST(RetainedState, LabelsArePerVariable) {
  RetainedState state;
  state.apply(text("VIEW_MARKER", "x=1,label=a"));
  state.apply(text("VIEW_CIRCLE", "x=1,radius=3,label=a"));
  EXPECT_EQ(state.size(), 2u);
}

TEST(RetainedState, ActiveFalseRemovesTheLabel) {
  RetainedState state;
  state.apply(text("VIEW_MARKER", "x=1,y=1,label=a"));
  state.apply(text("VIEW_MARKER", "x=2,y=1,label=b"));
  state.apply(text("VIEW_MARKER", "x=1,y=1,label=a,active=false"));
  EXPECT_EQ(values(state), (Values{"x=2,y=1,label=b"}));
  state.apply(text("VIEW_MARKER", "label=b,active=off"));  // only "false" removes, as on the page
  EXPECT_EQ(values(state), (Values{"label=b,active=off"}));
  state.apply(text("VIEW_MARKER", "label=b,active=FALSE"));
  EXPECT_TRUE(values(state).empty());
}

TEST(RetainedState, LabelInsideBracesIsNotTheLabel) {
  RetainedState state;
  state.apply(text("VIEW_SEGLIST", "pts={1,2:3,4},label=s"));
  state.apply(text("VIEW_SEGLIST", "pts={5,6:7,8},label=s"));
  EXPECT_EQ(values(state), (Values{"pts={5,6:7,8},label=s"}));
}

TEST(RetainedState, UnlabelledPostingsKeepABoundedRingOfTheNewest) {
  RetentionLimits limits;
  limits.unlabelled_ring = 3;
  RetainedState state(limits);
  for (int i = 0; i < 5; ++i) state.apply(text("VIEW_SEGLIST", "pts={0,0:1," + std::to_string(i) + "}"));
  state.apply(text("VIEW_SEGLIST", "pts={0,0:9,9},active=false"));  // nothing to remove: not kept
  EXPECT_EQ(values(state), (Values{"pts={0,0:1,2}", "pts={0,0:1,3}", "pts={0,0:1,4}"}));
}

TEST(RetainedState, ANewLabelBeyondTheBoundEvictsTheOldest) {
  RetentionLimits limits;
  limits.max_labels = 2;
  RetainedState state(limits);
  state.apply(text("VIEW_CIRCLE", "label=1"));
  state.apply(text("VIEW_CIRCLE", "label=2"));
  state.apply(text("VIEW_CIRCLE", "label=1,x=5"));  // 1 is now the newest
  state.apply(text("VIEW_CIRCLE", "label=3"));
  EXPECT_EQ(values(state), (Values{"label=1,x=5", "label=3"}));
}

TEST(RetainedState, TrailKeepsTheLastReportsPerVehicle) {
  RetentionLimits limits;
  limits.trail_length = 2;
  RetainedState state(limits);
  for (int i = 0; i < 4; ++i) {
    state.apply(text("NODE_REPORT", "NAME=archie,X=" + std::to_string(i)));
    state.apply(text("NODE_REPORT", "NAME=betty,X=" + std::to_string(i)));
  }
  EXPECT_EQ(values(state), (Values{"NAME=archie,X=2", "NAME=betty,X=2", "NAME=archie,X=3", "NAME=betty,X=3"}));
}

TEST(RetainedState, VehiclesBeyondTheBoundAreRefused) {
  RetentionLimits limits;
  limits.max_vehicles = 1;
  RetainedState state(limits);
  state.apply(text("NODE_REPORT", "NAME=archie,X=1"));
  state.apply(text("NODE_REPORT", "NAME=betty,X=1"));
  state.apply(text("NODE_REPORT", "NAME=archie,X=2"));
  EXPECT_EQ(values(state), (Values{"NAME=archie,X=1", "NAME=archie,X=2"}));
  EXPECT_EQ(state.refused(), 1u);
}

TEST(RetainedState, AppCastIsKeptPerNodeAndApp) {
  RetainedState state;
  state.apply(text("APPCAST", "proc=uA!@#iter=1!@#node=shoreside!@#messages=one"));
  state.apply(text("APPCAST", "proc=uB!@#iter=1!@#node=shoreside!@#messages=two"));
  state.apply(text("APPCAST", "proc=uA!@#iter=1!@#node=archie!@#messages=three"));
  state.apply(text("APPCAST", "proc=uA!@#iter=2!@#node=shoreside!@#messages=four"));
  EXPECT_EQ(values(state), (Values{"proc=uB!@#iter=1!@#node=shoreside!@#messages=two",
                                   "proc=uA!@#iter=1!@#node=archie!@#messages=three",
                                   "proc=uA!@#iter=2!@#node=shoreside!@#messages=four"}));
}

TEST(RetainedState, OtherVariablesKeepTheirNewestValue) {
  RetainedState state;
  state.apply(number("HAZARD_SEARCH_SCORE", 10));
  state.apply(text("HAZARDSET_EVAL", "vname=betty,score=10"));
  state.apply(number("HAZARD_SEARCH_SCORE", 86.5));
  const auto kept = state.snapshot();
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0].var, "HAZARDSET_EVAL");
  EXPECT_TRUE(kept[1].is_double);
  EXPECT_EQ(kept[1].dval, 86.5);
}

TEST(RetainedState, EvaluationsAreKeptPerVehicle) {
  RetainedState state;
  state.apply(text("HAZARDSET_EVAL", "vname=archie,total_score=10"));
  state.apply(text("HAZARDSET_EVAL", "vname=betty,total_score=20"));
  state.apply(text("HAZARDSET_EVAL", "vname=archie,total_score=30"));
  EXPECT_EQ(values(state), (Values{"vname=betty,total_score=20", "vname=archie,total_score=30"}));
}

TEST(RetainedState, ExpiredDurationsAreLeftOutOfTheSnapshot) {
  RetainedState state;
  state.apply(text("VIEW_CIRCLE", "x=0,radius=5,duration=10,label=short", 100.0));
  state.apply(text("VIEW_CIRCLE", "x=0,radius=5,duration=100,label=long", 100.0));
  state.apply(number("DB_UPTIME", 1, 105.0));
  state.set_clock(105.0);
  EXPECT_EQ(state.snapshot().size(), 3u);
  state.apply(number("DB_UPTIME", 2, 111.0));
  state.set_clock(111.0);  // short expired at 110
  EXPECT_EQ(values(state), (Values{"x=0,radius=5,duration=100,label=long", std::to_string(2.0)}));
  // The object's own time field counts from when it says, as on the page.
  state.apply(text("VIEW_CIRCLE", "x=0,radius=5,duration=100,time=5,label=old", 111.0));
  EXPECT_EQ(state.snapshot().size(), 2u);
}

// A posting stamped far in the future (a client with a skewed clock) used to move the time
// durations were judged by, so every later posting with a duration vanished for new pages
// until restart. Durations now run out by the viewer's own clock only.
TEST(RetainedState, APostingStampedInTheFutureHidesNoLaterPosting_Hardening) {
  RetainedState state;
  state.set_clock(100.0);
  state.apply(text("VIEW_MARKER", "x=1,y=1,label=skewed", 1e9));
  state.apply(text("VIEW_CIRCLE", "x=0,radius=5,duration=10,label=later", 101.0));
  state.set_clock(105.0);
  EXPECT_EQ(values(state), (Values{"x=1,y=1,label=skewed", "x=0,radius=5,duration=10,label=later"}));
  state.set_clock(112.0);  // now it has run out, by the viewer's clock
  EXPECT_EQ(values(state), (Values{"x=1,y=1,label=skewed"}));
}

TEST(RetainedState, OversizedStringsAreNotKept) {
  RetentionLimits limits;
  limits.max_value_bytes = 64;
  RetainedState state(limits);
  state.apply(text("VIEW_POINT", "x=1,y=2,label=" + std::string(100, 'p')));
  EXPECT_EQ(state.size(), 0u);
  EXPECT_EQ(state.refused(), 1u);
}

TEST(RetainedState, FieldsAreReadCaseInsensitively) {
  EXPECT_EQ(field_of("X=1,Label=abc,pts={1,2:3,4}", "label"), "abc");
  EXPECT_EQ(field_of("x=1", "label"), "");
  EXPECT_EQ(appcast_field("proc=uA!@#node=n1!@#messages=a=b", "messages"), "a=b");
  EXPECT_EQ(appcast_field("proc=uA", "node"), "");
}

}  // namespace
}  // namespace web_viewer
