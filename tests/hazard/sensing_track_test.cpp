// Sweeping and sub-stepping (sensing_track.hpp's rule): objects the swath passed over
// between two node reports, passes across reports, per-report gates, iteration-rate
// independence, the heading used for credits, and the error bound of turning segments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "hazard/driver.hpp"
#include "scenario/reference_scenario.hpp"
#include "hazard/sensing_track.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::credits_of;
using testing::Driver;
using testing::quiet_block;

// ---- the pieces and the walk (pure) --------------------------------------------------------------

std::vector<std::uint32_t> events_of(const std::vector<TrackPiece>& pieces, glm::dvec2 p,
                                     bool inside, bool* end_inside = nullptr) {
  std::vector<std::uint32_t> events;
  const bool end = walk_pieces(pieces, p, inside, events);
  if (end_inside) *end_inside = end;
  return events;
}

TEST(SensingTrack, AStraightSegmentIsSweptExactlyEdgesIncluded) {
  // W 5, L 2: from (0,0) to (0,20) heading north; the swept area is |x| <= 5, -1 <= y <= 21.
  const std::vector<TrackPose> track = {{{0, 0}, 0, true}, {{0, 20}, 0, true}};
  const auto pieces = track_pieces(track, false, TrackMode::kSweep, 0, 5, 2);
  ASSERT_EQ(pieces.size(), 1u);
  bool end = false;
  EXPECT_EQ(events_of(pieces, {0, 10}, false, &end).size(), 1u);  // passed over, left behind
  EXPECT_FALSE(end);
  EXPECT_EQ(events_of(pieces, {5, 10}, false).size(), 1u);  // on the side edge
  EXPECT_TRUE(events_of(pieces, {5.000001, 10}, false).empty());
  EXPECT_EQ(events_of(pieces, {-5, 21}, false, &end).size(), 1u);  // the end's corner
  EXPECT_TRUE(end);
  EXPECT_TRUE(events_of(pieces, {0, 21.000001}, false).empty());
  EXPECT_TRUE(events_of(pieces, {0, -1.000001}, false).empty());
}

TEST(SensingTrack, CrabbingTranslatesTheSwathSideways) {
  // Heading north, moving east 30 m: the swept area is -5 <= x <= 35, |y| <= 1.
  const std::vector<TrackPose> track = {{{0, 0}, 0, true}, {{30, 0}, 0, true}};
  const auto pieces = track_pieces(track, false, TrackMode::kSweep, 0, 5, 2);
  EXPECT_EQ(events_of(pieces, {17, 0.5}, false).size(), 1u);
  EXPECT_TRUE(events_of(pieces, {17, 1.5}, false).empty());
}

TEST(SensingTrack, AnObjectStayingInsideIsOnePassAcrossReports) {
  const std::vector<TrackPose> track = {
      {{0, 0}, 0, true}, {{0, 1}, 0, true}, {{0, 2}, 0, true}, {{0, 3}, 0, true}};
  for (TrackMode mode : {TrackMode::kSweep, TrackMode::kSubsteps}) {
    const auto pieces = track_pieces(track, false, mode, 4, 5, 10);
    bool end = false;
    EXPECT_TRUE(events_of(pieces, {1, 2}, true, &end).empty());  // inside before and all along
    EXPECT_TRUE(end);
  }
}

TEST(SensingTrack, LeavingAndComingBackAreTwoPasses) {
  // Out and back along y: the object at y = 0 is left behind, then passed over again.
  const std::vector<TrackPose> track = {{{0, -10}, 0, true}, {{0, 10}, 0, true},
                                        {{0, 30}, 0, true}, {{0, -10}, 0, true}};
  const auto pieces = track_pieces(track, false, TrackMode::kSweep, 0, 5, 2);
  EXPECT_EQ(events_of(pieces, {0, 0}, false), (std::vector<std::uint32_t>{0, 2}));
}

TEST(SensingTrack, SubstepsSampleNTimesPerSegmentEndingAtTheReport) {
  const std::vector<TrackPose> track = {{{0, 0}, 0, true}, {{0, 20}, 0, true}};
  const auto pieces = track_pieces(track, false, TrackMode::kSubsteps, 4, 5, 2);
  ASSERT_EQ(pieces.size(), 4u);
  EXPECT_EQ(pieces[0].start.center(), glm::dvec2(0, 5));
  EXPECT_EQ(pieces[3].start.center(), glm::dvec2(0, 20));
  EXPECT_EQ(events_of(pieces, {0, 10.9}, false).size(), 1u);  // near the sample at y = 10
  EXPECT_TRUE(events_of(pieces, {0, 12.5}, false).empty());   // between samples: missed
}

TEST(SensingTrack, SegmentsEndingAtAGatedReportAreNotSensed_RulingsPass) {
  // The middle segment ends at a report whose gates failed: nothing changes over it.
  const std::vector<TrackPose> track = {{{0, 0}, 0, true}, {{0, 20}, 0, false}, {{0, 40}, 0, true}};
  const auto pieces = track_pieces(track, false, TrackMode::kSweep, 0, 5, 2);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_TRUE(events_of(pieces, {0, 10}, false).empty());    // only under the gated segment
  EXPECT_EQ(events_of(pieces, {0, 30}, false).size(), 1u);  // under the sensed one
  bool end = true;
  EXPECT_TRUE(events_of(pieces, {0, 10}, true, &end).empty());
  EXPECT_FALSE(end);  // left behind while sensed again: outside now, no event
}

TEST(SensingTrack, TheStartPoseIsSensedOnlyWhenAsked) {
  const std::vector<TrackPose> track = {{{0, 0}, 0, true}};
  EXPECT_TRUE(track_pieces(track, false, TrackMode::kSweep, 0, 5, 2).empty());
  const auto pieces = track_pieces(track, true, TrackMode::kSweep, 0, 5, 2);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(events_of(pieces, {1, 0}, false).size(), 1u);
}

TEST(SensingTrack, TurnsAreSplitSoThatEachPieceErrsAtMostFiveCentimetres) {
  // r (1 - cos(d / 2)) <= 0.05 m per piece of turn d, with the fewest pieces; capped at 64.
  EXPECT_EQ(sweep_pieces_for_turn(0.0, 25), 1);
  const double r = std::hypot(25.0, 2.5);
  for (double turn : {0.5, -3.0, 7.0, 40.0, -90.0}) {
    const int n = sweep_pieces_for_turn(turn, r);
    EXPECT_LE(sweep_turn_error_m(turn / n, r), 0.05) << turn;
    if (n > 1) {
      EXPECT_GT(sweep_turn_error_m(turn / (n - 1), r), 0.05) << turn;
    }
  }
  EXPECT_EQ(sweep_pieces_for_turn(7.0, r), 1);  // 7.2 deg fit in one piece at r = 25.1 m
  EXPECT_EQ(sweep_pieces_for_turn(90.0, r), 13);
  EXPECT_EQ(sweep_pieces_for_turn(1e4, r), kMaxSweepPieces);
  EXPECT_NEAR(sweep_turn_error_m(180.0 / kMaxSweepPieces, r), 0.0076, 1e-4);
}

TEST(SensingTrack, ConsecutivePiecesShareTheirJunctionSoTurnsMakeNoPhantomPasses) {
  // A 1 deg/s left arc (radius 114.6 m) at 2 m/s with a report every 0.1 s: an object well
  // inside the swath's sides is passed exactly once, however many junctions its pass spans.
  const double radius = 2.0 / (3.14159265358979323846 / 180.0), w = 25, l = 5;
  std::vector<TrackPose> track;
  for (int k = 0; k <= 900; ++k) {  // 90 deg
    const double th = k * 0.1 * 2.0 / radius;
    track.push_back({{radius * std::sin(th), radius - radius * std::cos(th)},
                     base::norm360(90.0 - th * 180 / 3.14159265358979323846), true});
  }
  const auto pieces = track_pieces(track, false, TrackMode::kSweep, 0, w, l);
  ASSERT_EQ(pieces.size(), 900u);
  for (std::size_t i = 1; i < pieces.size(); ++i) {
    ASSERT_EQ(pieces[i].start.center(), pieces[i - 1].end.center());
  }
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> angle(0.1, 1.4), offset(-w + 1, w - 1);
  int not_once = 0;
  for (int i = 0; i < 2000; ++i) {
    const double th = angle(rng), rho = radius - offset(rng);  // offset to starboard
    const glm::dvec2 p{rho * std::sin(th), radius - rho * std::cos(th)};
    not_once += events_of(pieces, p, false).size() != 1u;
  }
  EXPECT_EQ(not_once, 0);
}

// A point is "covered" by the linearly turning swath when some pose of a dense sampling,
// with the rectangle grown (or shrunk) by `margin`, holds it.
bool dense_covers(const TrackPose& a, const TrackPose& b, double w, double l, glm::dvec2 p,
                  double margin) {
  constexpr int kSamples = 4000;  // consecutive poses 5 mm apart at most (below)
  const double turn = base::norm180(b.heading_deg - a.heading_deg);
  for (int j = 0; j <= kSamples; ++j) {
    const double t = static_cast<double>(j) / kSamples;
    const Swath s(a.position_m + (b.position_m - a.position_m) * t,
                  a.heading_deg + turn * t, w + margin, l + 2 * margin);
    if (s.contains(p)) return true;
  }
  return false;
}

TEST(SensingTrack, TurningSegmentsMissOrAddOnlyObjectsWithinTheStatedBound) {
  // A 40 deg turn while moving 20 m (W 25, L 5): 6 pieces of 6.7 deg, bound r (1 - cos(d/2)).
  const double w = 25, l = 5;
  const TrackPose a{{0, 0}, 350, true}, b{{8, 18}, 30, true};
  const auto pieces = track_pieces({a, b}, false, TrackMode::kSweep, 0, w, l);
  ASSERT_EQ(pieces.size(), 6u);
  const double bound = sweep_turn_error_m(40.0 / 6, std::hypot(w, l / 2));
  EXPECT_NEAR(bound, 0.0425, 1e-4);
  // The dense reference's own sampling error: poses 4.9 mm apart (19.7 m / 4000) and turning
  // r * 0.01 deg = 4.4 mm per step, so 5 mm of slack covers it.
  const double slack = bound + 5e-3;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-40.0, 50.0);
  int differ = 0;
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec2 p{u(rng), u(rng)};
    const bool swept = !events_of(pieces, p, false).empty();
    if (swept) {
      EXPECT_TRUE(dense_covers(a, b, w, l, p, slack)) << p.x << "," << p.y;
    } else {
      EXPECT_FALSE(dense_covers(a, b, w, l, p, -slack)) << p.x << "," << p.y;
    }
    differ += swept != dense_covers(a, b, w, l, p, 0.0);
  }
  EXPECT_LT(differ, 10);  // differences are rare: only within the bound of the boundary
}

// ---- the engine ------------------------------------------------------------------------------------

struct Decisions {
  std::vector<std::string> tuples;  // vehicle label pass outcome
  void attach(hazard::Driver& e) {
    e.set_decision_observer([this](const Decision& d) {
      tuples.push_back(std::string(d.vehicle) + " " + std::string(d.label) + " " +
                       std::to_string(d.pass) + " " + (d.outcome ? "1" : "0"));
    });
  }
};

// Two reports 40 m apart (y = -20, then y = +20, heading north) over an object at the origin;
// W 25, L 10. Returns the hazard chances counted.
int chances_with(const std::string& mode) {
  Driver d(quiet_block(mode + "hazard = x=0,y=0,label=a,type=hazard\n"));
  d.sensor_on("v");
  d.pose("v", 0, -20);
  d.tick_at(1);
  d.pose("v", 0, 20);
  d.tick_at(2);
  return d.vehicle("v").counters.hazard_chances;
}

TEST(SensingTrackEngine, AnObjectPassedOverBetweenTwoReportsIsAnEventOnlyWhenSweptOrSubstepped) {
  EXPECT_EQ(chances_with(""), 0);                       // sampling: never inside at a report
  EXPECT_EQ(chances_with("swath_substeps = 1\n"), 0);   // every report, nothing between
  EXPECT_EQ(chances_with("swath_substeps = 4\n"), 1);   // samples at y = -10, 0, 10, 20
  EXPECT_EQ(chances_with("swath_sweep = true\n"), 1);   // exactly
}

// A lawnmower at 2 m/s with node reports at 10 Hz: three 100 m legs joined by half circles of
// radius 10 m, over 300 objects; swath W 10, L 1 (so a pose every 2 m leaves gaps).
struct Mower {
  std::vector<TimedMail> mail;
  double end_s = 0.0;
};

Mower mower() {
  constexpr double kSpeed = 2.0, kLeg = 100.0, kRadius = 10.0, kPi = 3.14159265358979323846;
  const double arc = kPi * kRadius, lap = kLeg + arc;
  Mower m;
  m.end_s = (3 * kLeg + 2 * arc) / kSpeed;
  for (long k = 0; k * 0.1 <= m.end_s; ++k) {
    const double t = k * 0.1, s = std::min(kSpeed * t, 3 * kLeg + 2 * arc);
    const int lane = std::min(static_cast<int>(s / lap), 2);
    const double in = s - lane * lap;
    const bool east = lane % 2 == 0;
    double x, y, heading;
    if (in <= kLeg) {
      x = east ? in : kLeg - in;
      y = 2 * kRadius * lane;
      heading = east ? 90 : 270;
    } else {  // the half circle up to the next lane, turning left on east legs' ends
      const double a = (in - kLeg) / kRadius;  // radians turned
      const double cx = east ? kLeg : 0.0, cy = 2 * kRadius * lane + kRadius;
      x = cx + (east ? kRadius * std::sin(a) : -kRadius * std::sin(a));
      y = cy - kRadius * std::cos(a);
      heading = base::norm360(east ? 90 - a * 180 / kPi : 270 + a * 180 / kPi);
    }
    m.mail.push_back({t, "NODE_REPORT", testing::node_report("v", x, y, heading, kSpeed)});
    if (k % 1000 == 0) m.mail.push_back({t, "UHZ_SENSOR_REQUEST", "vname=v"});
  }
  return m;
}

std::vector<std::string> replay_mower(const Mower& m, const std::string& mode, double hz) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> x(-5.0, 105.0), y(-10.0, 50.0);
  std::string block = quiet_block("sensor_config = width=10, exp=2, pclass=0.9\n"
                                  "swath_length = 1\n" + mode);
  for (int i = 0; i < 300; ++i) {
    block += "hazard = x=" + base::fmt(x(rng), 2) + ",y=" + base::fmt(y(rng), 2) + ",label=o" +
             std::to_string(i) + ",type=hazard\n";
  }
  hazard::Driver driver(testing::setup_from(block), SeedChoice{3, SeedSource::kCommandLine});
  Decisions r;
  r.attach(driver);
  driver.start(0);
  driver.deliver(Mail{"UHZ_CONFIG_REQUEST", "vname=v,width=10,pd=0.8", 0});
  play_mail(driver, m.mail, hz, m.end_s + 1);
  EXPECT_TRUE(driver.engine().invariant_violations().empty());
  std::sort(r.tuples.begin(), r.tuples.end());
  return r.tuples;
}

TEST(SensingTrackEngine, SweepingAndSubstepsIgnoreTheIterationRateWhereSamplingDoesNot) {
  const Mower m = mower();
  // Sampling the latest pose depends on the iteration rate (the premise).
  EXPECT_NE(replay_mower(m, "", 1.0), replay_mower(m, "", 20.0));
  for (const std::string mode : {"swath_sweep = true\n", "swath_substeps = 3\n"}) {
    const std::vector<std::string> first = replay_mower(m, mode, 1.0);
    EXPECT_GT(first.size(), 100u) << mode;
    EXPECT_EQ(replay_mower(m, mode, 4.0), first) << mode << " at 4 Hz";
    EXPECT_EQ(replay_mower(m, mode, 20.0), first) << mode << " at 20 Hz";
  }
}

TEST(SensingTrackEngine, GatesApplyPerReport_RulingsPass) {
  // Speed gate 2 m/s: the segment ending at a fast report is not sensed, the next one is.
  Driver d(quiet_block("max_vehicle_speed = 2\nswath_sweep = true\n"
                       "hazard = x=0,y=0,label=fast,type=hazard\n"
                       "hazard = x=0,y=40,label=slow,type=hazard\n"));
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=1");
  d.sensor_on("v");
  d.pose("v", 0, -20, 0, 1.5);
  d.pose("v", 0, 20, 0, 3.0);   // over `fast` while too fast
  d.pose("v", 0, 60, 0, 1.5);   // over `slow` at a legal speed
  d.tick_at(1);
  EXPECT_EQ(d.vehicle("v").counters.hazard_chances, 1);
  EXPECT_TRUE(contains(d.all.events, "(label slow)"));
  EXPECT_FALSE(contains(d.all.events, "(label fast)"));
}

TEST(SensingTrackEngine, TheFirstEvaluationSensesTheStartPoseItself) {
  Driver d(quiet_block("swath_sweep = true\nhazard = x=0,y=0,label=a,type=hazard\n"));
  d.sensor_on("v");
  d.pose("v", 1, 1);  // one report only: the object is inside it
  d.tick_at(1);
  EXPECT_EQ(d.vehicle("v").counters.hazard_chances, 1);
  d.tick_at(2);  // no new report: nothing moves, nothing new
  EXPECT_EQ(d.vehicle("v").counters.hazard_chances, 1);
}

TEST(SensingTrackEngine, WhatWasPassedOverWhileInactiveIsNotSensed_D12) {
  Driver d(quiet_block("swath_sweep = true\nhazard = x=0,y=0,label=a,type=hazard\n"
                       "hazard = x=0,y=40,label=b,type=hazard\n"));
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=1");
  d.pose("v", 0, -20);
  d.pose("v", 0, 20);  // over `a` before any sensor request
  d.tick_at(1);
  d.sensor_on("v");
  d.pose("v", 0, 60);  // over `b`
  d.tick_at(2);
  EXPECT_TRUE(contains(d.all.events, "label b"));
  EXPECT_FALSE(contains(d.all.events, "label a"));
}

TEST(SensingTrackEngine, TheCreditCarriesThePiecesHeading_D7) {
  // `s` crabs straight over a (heading 10): the report's heading. `t` turns from 0 to 30 while
  // passing over b: the middle heading of the piece that covers it.
  Driver d(quiet_block("swath_sweep = true\nhazard = x=0,y=0,label=a,type=hazard\n"
                       "hazard = x=200,y=0,label=b,type=hazard\n"));
  for (const char* v : {"s", "t"}) {
    d.mail("UHZ_CONFIG_REQUEST", std::string("vname=") + v + ",width=25,pd=1");
    d.sensor_on(v);
  }
  d.pose("s", 0, -20, 10);
  d.pose("t", 200, -20, 0);
  d.tick_at(1);
  d.pose("s", 0, 20, 10);
  d.pose("t", 200, 20, 30);
  d.tick_at(2);
  const ObjectId a = *d.engine.field().find("a"), b = *d.engine.field().find("b");
  const std::vector<Credit> s_credits = credits_of(d.vehicle("s"), a);
  ASSERT_EQ(s_credits.size(), 1u);
  EXPECT_EQ(s_credits.front().heading_deg, 10.0);
  const std::vector<Credit> t_credits = credits_of(d.vehicle("t"), b);
  ASSERT_EQ(t_credits.size(), 1u);
  EXPECT_GT(t_credits.front().heading_deg, 0.0);
  EXPECT_LT(t_credits.front().heading_deg, 30.0);
  EXPECT_EQ(credits_of(d.vehicle("s"), b).size() + credits_of(d.vehicle("t"), a).size(), 0u);
}

TEST(SensingTrackEngine, ATrackIsBoundedAndSaysSoOnce) {
  Driver d(quiet_block("swath_substeps = 2\nhazard = x=0,y=0,label=a,type=hazard\n"));
  d.sensor_on("v");
  int warnings = 0;
  for (std::size_t i = 0; i < kMaxTrackPoses + 100; ++i) {
    warnings += static_cast<int>(d.pose("v", 0, -1000.0 + 0.1 * static_cast<double>(i)).run_warnings.size());
  }
  EXPECT_EQ(warnings, 1);
  EXPECT_EQ(d.vehicle("v").track.size(), kMaxTrackPoses);
  d.tick_at(1);
  EXPECT_EQ(d.vehicle("v").track.size(), 1u);
}

TEST(SensingTrackEngine, SweepingTheReferenceSurveyFindsWhatSamplingFinds_Style11) {
  // Its objects lie well inside the swaths, so the exact sweep agrees with sampling.
  const Scenario s = reference_survey(2.0);
  std::vector<std::string> results[2];
  for (int sweep = 0; sweep < 2; ++sweep) {
    std::vector<ConfigEntry> config = s.config;
    if (sweep) config.push_back({"swath_sweep", "true", "scenario.moos", 99});
    hazard::Driver driver(
        load_configuration(config, testing::no_files),
        SeedChoice{2024, SeedSource::kRandomSeed});
    Decisions r;
    r.attach(driver);
    driver.start(0);
    play_mail(driver, s.mail, 4.0, s.end_time_s);
    std::sort(r.tuples.begin(), r.tuples.end());
    results[sweep] = r.tuples;
  }
  EXPECT_EQ(results[0], results[1]);
}

}  // namespace
}  // namespace hazard
