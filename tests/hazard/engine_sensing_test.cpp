// Sensing: activity window, entry events, passes, gates, swath visuals, detection outcomes
// (manual 3.1, 7, 8, 9; differences.md D1, D5, D12, D13, "Pass", "Visuals").
#include <gtest/gtest.h>

#include <set>

#include "hazard/sensor_model.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::credits_of;
using testing::objects_with_credits;
using testing::Driver;
using testing::first_label;
using testing::quiet_block;
using testing::values_of;

// Two options (20 and 25 m, exp 4); with a request for pd 1 every object is detected.
std::string sensing_block(std::string_view extra = {}) {
  return quiet_block("sensor_config = width=20, exp=4, pclass=0.8\n" + std::string(extra));
}

struct Recorder {
  std::vector<Decision> decisions;
  std::vector<std::string> labels;  // vehicle:label:pass
  void attach(hazard::Driver& e) {
    e.set_decision_observer([this](const Decision& d) {
      decisions.push_back(d);
      labels.push_back(std::string(d.vehicle) + ":" + std::string(d.label) + ":" +
                       std::to_string(d.pass));
    });
  }
};

TEST(EngineSensing, NoSensingWithoutASensorRequest_D12) {
  Driver d(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.pose("v", 0, 0);
  d.tick();
  EXPECT_TRUE(r.decisions.empty());
  d.sensor_on("v");
  d.tick();
  EXPECT_EQ(r.labels, std::vector<std::string>{"v:a:1"});  // already inside: event at once
}

TEST(EngineSensing, OneRequestKeepsTheSensorOnForSixHundredSeconds_D12) {
  Driver d(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.sensor_on("v");
  d.pose("v", 100, 100);
  d.tick_at(1);
  d.pose("v", 0, 0);
  d.tick_at(599.9);  // still active
  EXPECT_EQ(r.decisions.size(), 1u);
  d.pose("v", 100, 100);
  d.tick_at(599.95);  // leaves
  d.pose("v", 0, 0);
  d.tick_at(600.0);   // inactive: no event, and the inside/outside state is frozen
  EXPECT_EQ(r.decisions.size(), 1u);
  d.sensor_on("v");   // active again: the object is inside and was outside -> pass 2
  d.tick();
  EXPECT_EQ(r.labels.back(), "v:a:2");
}

TEST(EngineSensing, EventsOnEntryOnlyAndPassesCount_Spec8_5) {
  Driver d(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.sensor_on("v");
  d.pose("v", 0, -100);
  d.tick_at(1);
  for (double y : {-3.0, 0.0, 3.0, 4.9}) {  // swath_length 10: inside while |dy| <= 5
    d.pose("v", 0, y);
    d.tick_at(d.now + 1);
  }
  EXPECT_EQ(r.labels, std::vector<std::string>{"v:a:1"});
  d.pose("v", 0, 5.1);  // out
  d.tick_at(d.now + 1);
  d.pose("v", 0, 2);    // in again: pass 2
  d.tick_at(d.now + 1);
  EXPECT_EQ(r.labels, (std::vector<std::string>{"v:a:1", "v:a:2"}));
}

TEST(EngineSensing, SwathIsTotalLengthAlongAndWidthEachSide_D1_D2) {
  Driver d(quiet_block(
      "hazard = x=24.9,y=0,label=in_side,type=hazard\n"
      "hazard = x=-25.1,y=0,label=out_side,type=hazard\n"
      "hazard = x=0,y=4.9,label=in_front,type=hazard\n"
      "hazard = x=0,y=5.1,label=out_front,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.sensor_on("v");
  d.pose("v", 0, 0, 0);
  d.tick();
  std::set<std::string> seen(r.labels.begin(), r.labels.end());
  EXPECT_EQ(seen, (std::set<std::string>{"v:in_side:1", "v:in_front:1"}));
}

TEST(EngineSensing, EventsOrderedByObjectLoadOrder) {
  Driver d(quiet_block("hazard = x=3,y=0,label=z,type=hazard\n"
                       "hazard = x=-3,y=0,label=b,type=hazard\n"
                       "hazard = x=0,y=0,label=m,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.sensor_on("v");
  d.pose("v", 0, 0);
  d.tick();
  EXPECT_EQ(r.labels, (std::vector<std::string>{"v:z:1", "v:b:1", "v:m:1"}));
}

TEST(EngineSensing, SpeedGateFreezesStateAndTurnsSwathRed_Manual9_Rulings) {
  Driver d(sensing_block("max_vehicle_speed = 2\nshow_swath = true\n"
                         "hazard = x=0,y=0,label=a,type=hazard\n"
                         "hazard = x=0,y=40,label=b,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.sensor_on("v");
  d.pose("v", 0, 0, 0, 1.0);  // a inside, sensor on
  d.tick_at(1);
  d.pose("v", 0, 40, 0, 2.5);  // too fast: b enters unseen, a leaves unseen
  const Outputs fast = d.tick_at(2);
  EXPECT_NE(values_of(fast, "VIEW_POLYGON").at(0).find("fill_color=red"), std::string::npos);
  d.pose("v", 0, 40, 0, 2.0);  // 2.0 is not above 2.0: on; b still inside -> event now
  const Outputs slow = d.tick_at(3);
  EXPECT_NE(values_of(slow, "VIEW_POLYGON").at(0).find("fill_color=white"), std::string::npos);
  d.pose("v", 0, 0, 0, 1.0);  // back over a: a was marked outside at t=3 -> pass 2
  d.tick_at(4);
  EXPECT_EQ(r.labels, (std::vector<std::string>{"v:a:1", "v:b:1", "v:a:2"}));
}

TEST(EngineSensing, ObjectInsideAcrossABlackoutStaysInTheSamePass_Rulings) {
  Driver d(sensing_block("max_vehicle_speed = 2\nhazard = x=0,y=0,label=a,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.sensor_on("v");
  d.pose("v", 0, 0, 0, 1);
  d.tick_at(1);
  d.pose("v", 0, 100, 0, 5);  // off, and away
  d.tick_at(2);
  d.pose("v", 0, 0, 0, 5);    // off, back over it
  d.tick_at(3);
  d.pose("v", 0, 0, 0, 1);    // on: it never was seen outside
  d.tick_at(4);
  EXPECT_EQ(r.labels, std::vector<std::string>{"v:a:1"});
}

TEST(EngineSensing, TurnRateBlackout_Manual8_D13) {
  Driver d(sensing_block("max_turn_rate = 1.5\nhazard = x=0,y=0,label=a,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.sensor_on("v");
  d.pose("v", 0, -100, 0);
  d.tick_at(0.0);
  d.now = 0.5;
  d.pose("v", 0, -100, 10);  // 10 deg in 0.5 s = 20 deg/s
  d.now = 1.0;
  d.pose("v", 0, 0, 20);     // over the object while turning
  d.tick();
  EXPECT_TRUE(r.decisions.empty());
  d.now = 3.5;
  d.pose("v", 0, 0, 20);     // steady for 2.5 s: the turning samples left the window
  d.tick();
  EXPECT_EQ(r.labels, std::vector<std::string>{"v:a:1"});
}

TEST(EngineSensing, SlowTurnKeepsSensorOn_D13) {
  Driver d(sensing_block("max_turn_rate = 1.5\nhazard = x=0,y=0,label=a,type=hazard\n"));
  Recorder r;
  r.attach(d.driver);
  d.sensor_on("v");
  for (int i = 0; i <= 8; ++i) {
    d.now = i * 0.5;
    d.pose("v", 0, i == 8 ? 0.0 : -100.0, i * 0.5);  // 1 deg/s
    d.tick();
  }
  EXPECT_EQ(r.labels, std::vector<std::string>{"v:a:1"});
}

TEST(EngineSensing, NoNodeReportWarnsOnceAndIsRetracted_Spec6) {
  Driver d(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"));
  d.sensor_on("v");
  const Outputs first = d.tick();
  EXPECT_EQ(first.run_warnings, std::vector<std::string>{"No NODE_REPORT received for v"});
  EXPECT_TRUE(d.tick().run_warnings.empty());
  const Outputs report = d.pose("v", 50, 50);
  EXPECT_EQ(report.retracted_run_warnings,
            std::vector<std::string>{"No NODE_REPORT received for v"});
}

// Every detection outcome is the model applied to the counter-based die (D5, T4).
TEST(EngineSensing, DetectionOutcomesFollowTheDiceExactly_T4_D5) {
  std::string block = quiet_block("sensor_config = width=20, exp=4, pclass=0.8\n");
  for (int i = 0; i < 60; ++i) {
    const std::string type = i % 3 == 0 ? "hazard" : "benign";
    std::string extra = i % 3 == 1 ? ",hr=0.73" : "";
    if (i % 3 == 2) extra = ",aspect=0,aspect_min=10,aspect_max=50";  // heading 90: g = 1
    block += "hazard = x=" + std::to_string(i % 10 - 5) + ",y=" + std::to_string(i / 10 - 3) +
             ",label=o" + std::to_string(i) + ",type=" + type + extra + "\n";
  }
  Driver d(block, {}, /*seed=*/77);
  d.sensor_on("archie");
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=20,pd=0.9");
  d.pose("archie", 0, 0, 90);  // along x: |dx| <= 5, |dy| <= 20
  const Outputs out = d.tick();
  const Dice dice(77);
  std::set<std::string> expected;
  for (int i = 0; i < 60; ++i) {
    const std::string label = "o" + std::to_string(i);
    const double u = dice.detection_u(hash_name("archie"), hash_name(label), 1);
    double p = 0.9;                                                       // hazard: pd
    if (i % 3 == 1) p = resemblance_false_alarm_probability(0.6561, 0.73);  // 0.69305
    if (i % 3 == 2) p = 0.9;  // benign, g = 1: pfa' = pd^1 (D5)
    if (u < p) expected.insert(label);
  }
  std::set<std::string> reported;
  for (const std::string& v : values_of(out, "UHZ_DETECTION_REPORT_ARCHIE")) {
    const auto at = v.find("label=") + 6;
    reported.insert(v.substr(at, v.find(',', at) - at));
  }
  EXPECT_EQ(reported, expected);
  EXPECT_GT(expected.size(), 30u);
}

TEST(EngineSensing, DetectionReportsAndCircle_D24_Spec8_7) {
  Driver d(sensing_block("show_detections = 60\n"
                         "hazard = x=-2,y=1,label=75,type=hazard,aspect=57,aspect_min=20,"
                         "aspect_max=45\n"));
  d.sensor_on("archie");
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=20,pd=1");
  d.now = 12.5;
  d.pose("archie", 0, 0);
  const Outputs out = d.tick();
  ASSERT_GE(out.postings.size(), 3u);
  const auto n = out.postings.size();
  EXPECT_EQ(out.postings[n - 3].variable, "UHZ_DETECTION_REPORT");
  EXPECT_EQ(out.postings[n - 3].value,
            "vname=archie,x=-2,y=1,label=75,aspect=57,aspect_min=20,aspect_max=45");
  EXPECT_EQ(out.postings[n - 2].variable, "UHZ_DETECTION_REPORT_ARCHIE");
  EXPECT_EQ(out.postings[n - 2].value, "x=-2,y=1,label=75,aspect=57,aspect_min=20,aspect_max=45");
  EXPECT_EQ(out.postings[n - 1].variable, "VIEW_CIRCLE");
  EXPECT_EQ(out.postings[n - 1].value,
            "x=-2,y=1,radius=10,vertices=12,duration=60,edge_color=white,fill_color=white,"
            "time=12.5,vertex_size=0,edge_size=1,fill_transparency=0.3");
  EXPECT_TRUE(contains(out.events, "Detection report sent to vehicle: archie"));
  EXPECT_EQ(d.vehicle("archie").counters.detections, 1);
}

TEST(EngineSensing, PinkCircleWhenOnlyTheDegradedRocDetects_D5_Manual7_3) {
  // Benign, heading 90, aspect 0 with window 10..50: g = 1, so pfa' = pd = 0.9 while the
  // undegraded pfa = 0.9^4. Pick labels whose die falls in between, and one below both.
  const std::string pink_label =
      first_label(5, "v", "b", [](double u, double) { return u >= 0.6561 && u < 0.9; });
  const std::string white_label =
      first_label(5, "v", "w", [](double u, double) { return u < 0.6561; });
  Driver d(quiet_block("sensor_config = width=20, exp=4, pclass=0.8\nshow_detections = nolimit\n"
                       "hazard = x=0,y=0,label=" + pink_label +
                       ",type=benign,aspect=0,aspect_min=10,aspect_max=50\n"
                       "hazard = x=1,y=0,label=" + white_label +
                       ",type=benign,aspect=0,aspect_min=10,aspect_max=50\n"),
           {}, 5);
  d.sensor_on("v");
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=20,pd=0.9");
  d.pose("v", 0, 0, 90);
  const auto circles = values_of(d.tick(), "VIEW_CIRCLE");
  ASSERT_EQ(circles.size(), 2u);  // both reported (D5), the first pink, the second white
  EXPECT_NE(circles[0].find("edge_color=pink,fill_color=pink"), std::string::npos);
  EXPECT_EQ(circles[0].find("duration"), std::string::npos);
  EXPECT_NE(circles[1].find("edge_color=white,fill_color=white"), std::string::npos);
  EXPECT_EQ(objects_with_credits(d.vehicle("v")), 2u);  // both granted a credit
}

TEST(EngineSensing, HazardsDetectWithPdWhateverTheAspect_D5) {
  // A hazard whose die lies between pfa (0.9^4) and pd (0.9) is detected, even fully degraded.
  const std::string label =
      first_label(5, "v", "h", [](double u, double) { return u >= 0.6561 && u < 0.9; });
  Driver d(quiet_block("hazard = x=0,y=0,label=" + label +
                       ",type=hazard,aspect=0,aspect_min=0,aspect_max=0\n"),
           {}, 5);
  d.sensor_on("v");
  d.pose("v", 0, 0, 90);
  const Outputs out = d.tick();
  ASSERT_EQ(values_of(out, "UHZ_DETECTION_REPORT").size(), 1u);
  EXPECT_EQ(credits_of(d.vehicle("v"), 0).size(), 1u);
}

TEST(EngineSensing, NoCirclesWhenShowDetectionsIsZero_D38) {
  Driver d(sensing_block("hazard = x=0,y=0,label=a,type=hazard\n"));  // show_detections = 0
  d.sensor_on("v");
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=20,pd=1");
  d.pose("v", 0, 0);
  const Outputs out = d.tick();
  EXPECT_EQ(values_of(out, "UHZ_DETECTION_REPORT").size(), 1u);
  EXPECT_TRUE(values_of(out, "VIEW_CIRCLE").empty());
}

TEST(EngineSensing, SwathPolygonAndLabel_Spec5_3_Manual7_8) {
  struct Case {
    const char* switches;
    const char* msg;
  };
  for (const Case& c : {Case{"show_pd = true\nshow_pfa = true\n", "msg=0.90/0.66"},
                        Case{"show_pd = true\nshow_pfa = false\n", "msg=0.90,"},
                        Case{"show_pd = false\nshow_pfa = true\n", "msg=pfa=0.66"},
                        Case{"show_pd = false\nshow_pfa = false\n", "msg=_null_"}}) {
    Driver d(std::string("sensor_config = width=25, exp=4, pclass=0.8\nswath_length = 5\n"
                         "hazard = x=100,y=100,label=a,type=hazard\n") +
             c.switches);
    d.sensor_on("archie");
    d.pose("archie", 0, 0, 0, 1);
    const auto polys = values_of(d.tick(), "VIEW_POLYGON");
    ASSERT_EQ(polys.size(), 1u);
    EXPECT_EQ(polys[0].substr(0, polys[0].find(",msg")),
              "pts={25,2.5:25,-2.5:-25,-2.5:-25,2.5},label=sensor_swath_archie");
    EXPECT_NE(polys[0].find(c.msg), std::string::npos) << polys[0];
    EXPECT_NE(polys[0].find("edge_color=green,fill_color=white,vertex_size=0,edge_size=0,"
                            "fill_transparency=0.2"),
              std::string::npos);
  }
}

TEST(EngineSensing, NoSwathPostingsWhenShowSwathIsFalse_Effects) {
  Driver d(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"));
  d.sensor_on("v");
  d.pose("v", 0, 0);
  EXPECT_TRUE(values_of(d.tick(), "VIEW_POLYGON").empty());
}

// While nothing is inside, an iteration whose swath lies in a box around an earlier pose known to
// hold no object builds no swath (QuietBox). The entries are those of an engine that builds the
// swath every iteration (to post it): objects on the edges, a diagonal leg, jumps beyond the box.
TEST(EngineSensing, QuietIterationsMissNoEntry) {
  const std::string objects =
      "hazard = x=0,y=40,label=a,type=hazard\n"
      "hazard = x=25,y=85,label=edge,type=benign\n"
      "hazard = x=-25.001,y=90,label=out,type=hazard\n"
      "hazard = x=0,y=125,label=front,type=hazard\n"
      "hazard = x=60,y=190,label=diag,type=benign\n";
  Driver plain(quiet_block(objects));
  Driver shown(quiet_block(objects + "show_swath = true\n"));
  Recorder without_swath, with_swath;
  without_swath.attach(plain.driver);
  with_swath.attach(shown.driver);
  for (Driver* d : {&plain, &shown}) {
    d->sensor_on("v");
    for (int i = 0; i <= 360; ++i) {  // north at 0.37 m per iteration
      d->pose("v", 0, i * 0.37, 0);
      d->tick_at(d->now + 0.1);
    }
    for (int i = 0; i <= 200; ++i) {  // north-east from (0, 133)
      d->pose("v", i * 0.3, 133 + i * 0.3, 45);
      d->tick_at(d->now + 0.1);
    }
    for (const double y : {500.0, 40.0, 300.0, 125.0}) {  // jumps
      d->pose("v", 0, y, 0);
      d->tick_at(d->now + 0.1);
    }
  }
  EXPECT_EQ(without_swath.labels, with_swath.labels);
  EXPECT_EQ(without_swath.labels,
            (std::vector<std::string>{"v:a:1", "v:edge:1", "v:front:1", "v:diag:1", "v:a:2",
                                      "v:front:2"}));
}

TEST(EngineSensing, CountersOfChancesAndReports) {
  Driver d(sensing_block("hazard = x=0,y=0,label=a,type=hazard\n"
                         "hazard = x=1,y=0,label=b,type=benign\n"));
  d.sensor_on("v");
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=20,pd=1");
  d.pose("v", 0, 0);
  d.tick();
  const VehicleCounters& c = d.vehicle("v").counters;
  EXPECT_EQ(c.hazard_chances, 1);
  EXPECT_EQ(c.hazard_reports, 1);
  EXPECT_EQ(c.benign_chances, 1);
  EXPECT_EQ(c.benign_reports, 1);  // pd 1 -> pfa 1
  EXPECT_EQ(c.sensor_requests, 1);
}

}  // namespace
}  // namespace hazard
