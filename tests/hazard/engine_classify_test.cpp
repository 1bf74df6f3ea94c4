// Classification: credits, the decision, the queue, release timing, clear, refusals
// (manual 3.2, 6.2, 7.2; differences.md D7, D8, D9, D10, D19, D25, D37, "Credits", "Clear",
// "Release timing", T7, T6).
#include <gtest/gtest.h>

#include "hazard/dice.hpp"
#include "hazard/engine.hpp"
#include "hazard/sensor_model.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::credits_of;
using testing::Driver;
using testing::first_label;
using testing::label_of;
using testing::quiet_block;
using testing::values_of;

// Objects near the origin; `v` is configured with pd 1 (every object with pfa 1 is detected)
// and made to pass over them once at t = 0, heading 90.
std::string field_block(std::string_view interval_s, std::string_view extra = {}) {
  return quiet_block("min_classify_interval = " + std::string(interval_s) + "\n" +
                     "hazard = x=0,y=0,label=A,type=hazard\n"
                     "hazard = x=1,y=0,label=B,type=hazard\n"
                     "hazard = x=2,y=0,label=C,type=benign\n"
                     "hazard = x=3,y=0,label=D,type=benign\n"
                     "hazard = x=300,y=0,label=far,type=hazard\n" +
                     std::string(extra));
}

void pass_over(Driver& d, const std::string& v = "v") {
  d.sensor_on(v);
  d.mail("UHZ_CONFIG_REQUEST", "vname=" + v + ",width=25,pd=1");
  d.pose(v, 0, 0, 90);
  d.tick();
}

// (time, label) of every released answer of vehicle `v` while ticking once a second.
std::vector<std::pair<double, std::string>> releases(
    Driver& d, double from, double to, const std::string& var = "UHZ_HAZARD_REPORT_V") {
  std::vector<std::pair<double, std::string>> out;
  for (double t = from; t <= to; t += 1) {
    for (const auto& r : values_of(d.tick_at(t), var)) out.emplace_back(t, label_of(r));
  }
  return out;
}

// T7's three requests at t = 1: A (default 50), B (95), C (50).
void ask_a_b_c(Driver& d) {
  d.now = 1;
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A");
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=B,priority=95");
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=C,priority=50");
}

TEST(EngineClassify, QueueOrderAndFirstReleaseAtNextIteration_T7_D8_D9) {
  Driver d(field_block("10"));
  pass_over(d);
  ask_a_b_c(d);
  const auto got = releases(d, 1, 40);
  EXPECT_EQ(got, (std::vector<std::pair<double, std::string>>{{1, "B"}, {11, "A"}, {21, "C"}}));
}

TEST(EngineClassify, TopRequestGoesFirstOneIntervalAfterItArrived_T7_D8) {
  Driver d(field_block("10"));
  pass_over(d);
  ask_a_b_c(d);
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=D,priority=10,action=top");
  const auto got = releases(d, 1, 50);
  EXPECT_EQ(got, (std::vector<std::pair<double, std::string>>{
                     {11, "D"}, {21, "B"}, {31, "A"}, {41, "C"}}));
}

TEST(EngineClassify, RateLimitAndIdleVehicleAnsweredAtOnce_D9) {
  Driver d(field_block("10"));
  pass_over(d);
  d.now = 1;
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A");
  releases(d, 1, 5);
  d.now = 100;  // long idle: the next answer comes at the next iteration
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=B");
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=C");
  const auto got = releases(d, 100, 115);
  EXPECT_EQ(got, (std::vector<std::pair<double, std::string>>{{100, "B"}, {110, "C"}}));
}

TEST(EngineClassify, ZeroIntervalReleasesOnePerVehiclePerIteration_D9) {
  Driver d(field_block("0"));
  pass_over(d, "v");
  pass_over(d, "w");
  for (const char* v : {"v", "w"}) {
    for (const char* l : {"A", "B"}) {
      d.mail("UHZ_CLASSIFY_REQUEST", std::string("vname=") + v + ",label=" + l);
    }
  }
  const Outputs first = d.tick();
  EXPECT_EQ(values_of(first, "UHZ_HAZARD_REPORT").size(), 2u);  // one each
  EXPECT_EQ(values_of(first, "UHZ_HAZARD_REPORT_V").size(), 1u);
  EXPECT_EQ(values_of(d.tick(), "UHZ_HAZARD_REPORT").size(), 2u);
  EXPECT_TRUE(values_of(d.tick(), "UHZ_HAZARD_REPORT").empty());
}

TEST(EngineClassify, CreditsArePerVehicleAndObject_D7) {
  Driver d(field_block("0"));
  pass_over(d);
  const Outputs unknown_obj = d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=far");
  EXPECT_TRUE(contains(unknown_obj.run_warnings, "No detection credit for v and label far"));
  EXPECT_TRUE(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A").run_warnings.empty());
  const Outputs again = d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A");
  EXPECT_TRUE(contains(again.run_warnings, "No detection credit for v and label A"));
  // Another vehicle's detection of `far` gives v nothing.
  d.sensor_on("w");
  d.mail("UHZ_CONFIG_REQUEST", "vname=w,width=25,pd=1");
  d.pose("w", 300, 0, 90);
  d.tick();
  ASSERT_FALSE(credits_of(d.vehicle("w"), 4).empty());
  EXPECT_TRUE(contains(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=far").run_warnings,
                       "No detection credit for v and label far"));
  EXPECT_TRUE(d.mail("UHZ_CLASSIFY_REQUEST", "vname=w,label=far").run_warnings.empty());
  EXPECT_EQ(d.vehicle("v").counters.classify_requests, 4);
  EXPECT_FALSE(credits_of(d.vehicle("v"), 2).empty());  // C unused
}

// A label whose slot in the engine's recent-object cache is the slot of `label` (the first one
// after "x<from>").
std::string label_in_slot_of(std::string_view label, int from = 0) {
  const auto slot = [](std::string_view l) { return mix64(hash_name(l)) % kRecentObjectSlots; };
  for (int i = from;; ++i) {
    std::string candidate = "x" + std::to_string(i);
    if (slot(candidate) == slot(label)) return candidate;
  }
}

// The cache in front of the label lookup holds A after its detection; a request for another
// label in A's slot is that label's, never A's.
TEST(EngineClassify, RecentObjectCacheNeverAnswersForAnotherLabel) {
  const std::string twin = label_in_slot_of("A");
  Driver d(quiet_block("min_classify_interval = 0\n"
                       "hazard = x=0,y=0,label=A,type=hazard\n"
                       "hazard = x=300,y=0,label=" + twin + ",type=hazard\n"));
  pass_over(d);
  EXPECT_TRUE(contains(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + twin).run_warnings,
                       "No detection credit for v and label " + twin));
  const std::string unknown = label_in_slot_of("A", std::stoi(twin.substr(1)) + 1);
  EXPECT_TRUE(contains(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + unknown).run_warnings,
                       "v classify request for unknown label: " + unknown));
  EXPECT_TRUE(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A").run_warnings.empty());
}

TEST(EngineClassify, CreditsSurviveInactivityAndWidthChanges_Rulings) {
  Driver d(field_block("0",
                       "sensor_config = width=50, exp=2, pclass=0.6\nmin_reset_interval = 0\n"));
  pass_over(d);
  d.now = 5000;  // sensor long inactive
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=50,pd=0.9");
  EXPECT_TRUE(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A").run_warnings.empty());
}

TEST(EngineClassify, SeveralCreditsForOneObjectAreUsedOldestFirst_Rulings) {
  Driver d(field_block("0"));
  std::vector<std::uint32_t> passes;
  d.driver.set_decision_observer([&](const Decision& x) {
    if (x.purpose == DiePurpose::kClassification) passes.push_back(x.pass);
  });
  pass_over(d);
  d.pose("v", 500, 500, 90);
  d.tick();
  d.pose("v", 0, 0, 90);
  d.tick();  // pass 2 of every object
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A");
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A");
  EXPECT_EQ(passes, (std::vector<std::uint32_t>{1, 2}));
}

TEST(EngineClassify, AnswersFollowTheDiceAndFormats_D25_D19) {
  std::string block = quiet_block("min_classify_interval = 0\nshow_detections = 30\n");
  for (int i = 0; i < 40; ++i) {
    block += "hazard = x=" + std::to_string(i % 8 - 4) + ",y=0,label=o" + std::to_string(i) +
             ",type=" + (i % 2 ? "hazard" : "benign") + "\n";
  }
  Driver d(block, {}, 99);
  pass_over(d);  // pd 1, pfa 1: every object detected, pass 1
  const Dice dice(99);
  for (int i = 0; i < 40; ++i) {
    const std::string label = "o" + std::to_string(i);
    d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + label);
    const Outputs out = d.tick();
    const auto per_vehicle = values_of(out, "UHZ_HAZARD_REPORT_V");
    const auto general = values_of(out, "UHZ_HAZARD_REPORT");
    const auto circles = values_of(out, "VIEW_CIRCLE");
    ASSERT_EQ(per_vehicle.size(), 1u);
    ASSERT_EQ(circles.size(), 1u);
    const bool correct = dice.classification_v(hash_name("v"), hash_name(label), 1) <= 0.8;
    const bool truth_hazard = i % 2 == 1;
    const std::string reported = (truth_hazard == correct) ? "hazard" : "benign";
    const std::string x = std::to_string(i % 8 - 4);
    EXPECT_EQ(per_vehicle[0], "x=" + x + ",y=0,label=" + label + ",type=" + reported);
    EXPECT_EQ(general, std::vector<std::string>{"vname=v," + per_vehicle[0]});
    const std::string colour = reported == "hazard" ? "yellow" : "green";
    EXPECT_EQ(circles[0], "x=" + x + ",y=0,radius=10,vertices=5,edge_color=" + colour +
                              ",fill_color=" + colour + ",time=0,vertex_size=0,edge_size=1,"
                              "fill_transparency=0.3");  // never a duration
    // Order: the per-vehicle variable first.
    EXPECT_EQ(out.postings[out.postings.size() - 3].variable, "UHZ_HAZARD_REPORT_V");
  }
  EXPECT_EQ(d.vehicle("v").counters.answers, 40);
}

// T6: pc 0.8, benign hr 0.3 -> pc' 0.94; g 0.5 -> pc'' 0.72; a die in (0.72, 0.94] gives a wrong
// answer caused by aspect: reported hazard, pink fill, edge 2, transparency 0.5.
TEST(EngineClassify, AspectAffectedAnswerIsPink_T6_D19) {
  const std::string label = first_label(
      11, "v", "t", [](double u, double v) { return u < 0.65 && v > 0.72 && v <= 0.94; });
  Driver d(quiet_block("min_classify_interval = 0\nshow_detections = nolimit\nhazard = x=0,y=0,"
                       "label=" + label + ",type=benign,hr=0.3,aspect=60,aspect_min=10,"
                       "aspect_max=50\n"),
           {}, 11);
  pass_over(d);  // heading 90 vs aspect 60: 30 deg -> g = 0.5
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + label);
  const Outputs out = d.tick();
  EXPECT_EQ(values_of(out, "UHZ_HAZARD_REPORT_V").at(0).find("type=hazard") != std::string::npos,
            true);
  EXPECT_NE(values_of(out, "VIEW_CIRCLE").at(0).find(
                "edge_color=yellow,fill_color=pink,time=0,vertex_size=0,edge_size=2,"
                "fill_transparency=0.5"),
            std::string::npos);
}

TEST(EngineClassify, IgnoreResemblancesUsesPlainPc_Manual6_4) {
  // A die between pc (0.8) and pc' (0.94): right with hr, wrong without.
  const std::string label = first_label(
      11, "v", "r", [](double u, double v) { return u < 0.5 && v > 0.8 && v <= 0.94; });
  for (const bool ignore : {false, true}) {
    Driver d(quiet_block("min_classify_interval = 0\nignore_resemblances = " +
                         std::string(ignore ? "true" : "false") + "\nhazard = x=0,y=0,label=" +
                         label + ",type=benign,hr=0.3\n"),
             {}, 11);
    pass_over(d);
    d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + label);
    const std::string answer = values_of(d.tick(), "UHZ_HAZARD_REPORT_V").at(0);
    EXPECT_NE(answer.find(ignore ? "type=hazard" : "type=benign"), std::string::npos) << ignore;
  }
}

TEST(EngineClassify, ClearEmptiesQueueReturnsCreditsKeepsClock_D10) {
  for (const std::string how : {"UHZ_SENSOR_CLEAR", "UHZ_CLASSIFY_REQUEST"}) {
    Driver d(field_block("10"));
    std::vector<std::string> decided;
    d.driver.set_decision_observer([&](const Decision& x) {
      if (x.purpose == DiePurpose::kClassification) {
        decided.push_back(std::string(x.label) + ":" + std::to_string(x.pass) + ":" +
                          (x.outcome ? "right" : "wrong"));
      }
    });
    pass_over(d);
    d.now = 1;
    d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=A");
    d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=B");
    d.tick();  // A released at 1
    d.now = 2;
    const Outputs cleared = how == "UHZ_SENSOR_CLEAR"
                                ? d.mail(how, "vname=v")
                                : d.mail(how, "vname=v,action=clear");
    EXPECT_TRUE(contains(cleared.events, "Classify queue cleared for v (1 entries)"));
    EXPECT_TRUE(d.vehicle("v").queue.empty());
    EXPECT_FALSE(credits_of(d.vehicle("v"), 1).empty());  // B's credit is back
    d.now = 3;
    EXPECT_TRUE(d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=B").run_warnings.empty());
    ASSERT_EQ(decided.size(), 3u);
    EXPECT_EQ(decided[1], decided[2]) << "a returned credit rolls the same die";
    const auto got = releases(d, 3, 12);
    EXPECT_EQ(got, (std::vector<std::pair<double, std::string>>{{11, "B"}}));  // clock kept
  }
}

TEST(EngineClassify, ClearingNothingSucceedsQuietly_D10) {
  Driver d(field_block("10"));
  EXPECT_TRUE(d.mail("UHZ_SENSOR_CLEAR", "vname=nobody").run_warnings.empty());
  pass_over(d);
  const Outputs out = d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,action=clear");
  EXPECT_TRUE(out.run_warnings.empty());
  EXPECT_TRUE(contains(out.events, "(0 entries)"));
}

TEST(EngineClassify, RefusalsWarnAndTellTheVehicleNothing_D37) {
  Driver d(field_block("0"));
  d.pose("known", 0, 0);
  const Outputs unknown_vehicle = d.mail("UHZ_CLASSIFY_REQUEST", "vname=ghost,label=A");
  EXPECT_TRUE(contains(unknown_vehicle.run_warnings, "unknown vehicle ghost"));
  const Outputs no_setting = d.mail("UHZ_CLASSIFY_REQUEST", "vname=known,label=A");
  EXPECT_TRUE(contains(no_setting.run_warnings, "No sensor setting (no classifier) for known"));
  pass_over(d);
  const Outputs unknown_label = d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=ZZ");
  EXPECT_TRUE(contains(unknown_label.run_warnings, "v classify request for unknown label: ZZ"));
  for (const Outputs* o : {&unknown_vehicle, &no_setting, &unknown_label}) {
    EXPECT_TRUE(o->postings.empty());
  }
  EXPECT_TRUE(values_of(d.tick(), "UHZ_HAZARD_REPORT").empty());
  EXPECT_EQ(d.vehicle("v").counters.classify_requests, 1);  // refused ones count too
}

TEST(EngineClassify, AnswerIsDecidedWithTheSettingsAtRequestTime_Rulings) {
  // A die between 0.6 and 0.9: right with pclass 0.9, wrong with 0.6.
  const std::string label =
      first_label(3, "v", "s", [](double, double v) { return v > 0.6 && v <= 0.9; });
  Driver d(quiet_block("min_classify_interval = 0\nmin_reset_interval = 0\n"
                       "sensor_config = width=10, exp=2, pclass=0.9\n"
                       "sensor_config = width=40, exp=2, pclass=0.6\n"
                       "hazard = x=0,y=0,label=" + label + ",type=hazard\n"),
           {}, 3);
  pass_over(d);  // width 25 (pclass 0.8), pd 1
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=10,pd=1");
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=v,label=" + label);
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=40,pd=1");  // changed before the release
  EXPECT_NE(values_of(d.tick(), "UHZ_HAZARD_REPORT_V").at(0).find("type=hazard"),
            std::string::npos);
}

}  // namespace
}  // namespace hazard
