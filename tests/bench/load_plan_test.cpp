// Tracks, swath matching and texts of bench/process/load_plan.
#include "load_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(SplitField, CutsSideBySideStripsOfEqualWidth) {
  const auto strips = bench::split_field(1000, 4);
  ASSERT_EQ(strips.size(), 4u);
  EXPECT_DOUBLE_EQ(strips[0].x_min_m, 0);
  EXPECT_DOUBLE_EQ(strips[1].x_min_m, 250);
  EXPECT_DOUBLE_EQ(strips[3].x_max_m, 1000);
  EXPECT_DOUBLE_EQ(strips[2].y_max_m, 1000);
}

TEST(Lawnmower, RunsNorthAcrossAndSouthInsideItsStrip) {
  const bench::Lawnmower track({100, 300, 0, 500}, 50);  // lanes at 125, 175, 225, 275
  EXPECT_EQ(track.waypoint_count(), 8u);
  EXPECT_DOUBLE_EQ(track.length_m(), 4 * 500 + 3 * 50);
  const auto start = track.at(0);
  EXPECT_DOUBLE_EQ(start.x_m, 125);
  EXPECT_DOUBLE_EQ(start.y_m, 0);
  const auto up = track.at(200);
  EXPECT_DOUBLE_EQ(up.y_m, 200);
  EXPECT_DOUBLE_EQ(up.heading_deg, 0);
  const auto across = track.at(520);
  EXPECT_DOUBLE_EQ(across.x_m, 145);
  EXPECT_DOUBLE_EQ(across.y_m, 500);
  EXPECT_DOUBLE_EQ(across.heading_deg, 90);
  const auto down = track.at(650);
  EXPECT_DOUBLE_EQ(down.x_m, 175);
  EXPECT_DOUBLE_EQ(down.y_m, 400);
  EXPECT_DOUBLE_EQ(down.heading_deg, 180);
}

TEST(Lawnmower, RetracesItsPathAfterTheLastLane) {
  const bench::Lawnmower track({0, 100, 0, 100}, 50);  // lanes at 25 and 75
  const double total = track.length_m();
  const auto back = track.at(total + 10);  // 10 m back up the last lane
  EXPECT_DOUBLE_EQ(back.x_m, 75);
  EXPECT_DOUBLE_EQ(back.y_m, 10);
  EXPECT_DOUBLE_EQ(back.heading_deg, 0);
  const auto home = track.at(2 * total);
  EXPECT_NEAR(home.x_m, 25, 1e-9);
  EXPECT_NEAR(home.y_m, 0, 1e-9);
  for (double d = 0; d < 3 * total; d += 7.3) {
    const auto p = track.at(d);
    EXPECT_GE(p.x_m, 0);
    EXPECT_LE(p.x_m, 100);
    EXPECT_GE(p.y_m, 0);
    EXPECT_LE(p.y_m, 100);
  }
}

TEST(Lawnmower, PutsOneLaneInTheMiddleOfANarrowStrip) {
  const bench::Lawnmower track({0, 20, 0, 100}, 50);
  EXPECT_DOUBLE_EQ(track.at(30).x_m, 10);
}

TEST(InSwath, IsTheRectangleAroundTheVehicleTurnedWithItsHeading) {
  const bench::Pose north{0, 0, 0};
  EXPECT_TRUE(bench::in_swath(north, 25, 2.5, 25, 2.5));    // corner, boundary included
  EXPECT_TRUE(bench::in_swath(north, -24, -2, 25, 2.5));
  EXPECT_FALSE(bench::in_swath(north, 0, 3, 25, 2.5));      // ahead of the swath
  EXPECT_FALSE(bench::in_swath(north, 26, 0, 25, 2.5));
  const bench::Pose east{10, 10, 90};
  EXPECT_TRUE(bench::in_swath(east, 12, -14, 25, 2.5));     // 24 m to starboard, 2 m ahead
  EXPECT_FALSE(bench::in_swath(east, 13, 10, 25, 2.5));     // 3 m ahead
}

TEST(DetectionDelay, CountsFromTheFirstReportOfTheLatestRunWithTheObjectInside) {
  std::deque<bench::SentReport> history;
  // A vehicle heading north at 1 m per report, one report per 0.1 s; object at (10, 20).
  for (int i = 0; i <= 40; ++i) history.push_back({0.1 * i, {0, static_cast<double>(i), 0}});
  // Inside for y in [17.5, 22.5]: reports 18..22. Received at 2.05 s (after report 20).
  const auto delay = bench::detection_delay(history, 2.05, 10, 20, 25, 2.5);
  ASSERT_TRUE(delay);
  EXPECT_NEAR(*delay, 2.05 - 1.8, 1e-12);
  // Received later, after the object left the swath: still the same run.
  EXPECT_NEAR(*bench::detection_delay(history, 3.5, 10, 20, 25, 2.5), 3.5 - 1.8, 1e-12);
  // Received before any report put it inside, or for an object never inside: no match.
  EXPECT_FALSE(bench::detection_delay(history, 1.7, 10, 20, 25, 2.5));
  EXPECT_FALSE(bench::detection_delay(history, 3.5, 100, 20, 25, 2.5));
}

TEST(NodeReport, CarriesWhatTheSensorNeeds) {
  const std::string text = bench::node_report("veh1", {12.345, -6.5, 90}, 1.5, 1000.25);
  EXPECT_EQ(text, "NAME=veh1,X=12.35,Y=-6.50,SPD=1.5,HDG=90.00,TYPE=kayak,TIME=1000.25,LENGTH=4");
  EXPECT_EQ(bench::value_of(text, "NAME"), "veh1");
  EXPECT_EQ(bench::value_of(text, "SPD"), "1.5");
  EXPECT_EQ(bench::value_of(text, "spd"), "");
}

TEST(AppcastIteration, ReadsTheFirstIterItem) {
  EXPECT_EQ(bench::appcast_iteration("proc=uFldHazardSensor!@#iter=1234!@#node=shoreside!@#"
                                     "iter=1234!@#messages=x!@"),
            1234);
  EXPECT_EQ(bench::appcast_iteration("iter=7"), 7);
  EXPECT_FALSE(bench::appcast_iteration("proc=p!@#messages=iter=5!@#"));
  EXPECT_FALSE(bench::appcast_iteration("proc=p!@#iter=many!@#"));
}

TEST(MissionText, NamesThePortWarpFieldAndMarkers) {
  bench::MissionSpec spec;
  spec.port = 9123;
  spec.time_warp = 50;
  spec.hazard_file = "/tmp/f/hazards.txt";
  spec.show_hazards = true;
  const std::string text = bench::mission_text(spec);
  EXPECT_NE(text.find("ServerPort = 9123\n"), std::string::npos);
  EXPECT_NE(text.find("MOOSTimeWarp = 50\n"), std::string::npos);
  EXPECT_NE(text.find("Community = shoreside\n"), std::string::npos);
  EXPECT_NE(text.find("ProcessConfig = uFldHazardSensor\n{"), std::string::npos);
  EXPECT_NE(text.find("  hazard_file = /tmp/f/hazards.txt\n"), std::string::npos);
  EXPECT_NE(text.find("  show_hazards = true\n"), std::string::npos);
  EXPECT_NE(text.find("  AppTick = 4\n"), std::string::npos);
}

}  // namespace
