#include <gtest/gtest.h>

#include <cmath>

#include "base/text.hpp"
#include "mission/hazard_manager.hpp"

namespace mission {
namespace {

constexpr double kPd = 0.9;
const double kPfa = std::pow(0.9, 4);  // Jake's archie: width 25, exp 4
constexpr double kPclass = 0.85;

ManagerConfig archie_config() {
  ManagerConfig c;
  c.vname = "archie";
  return c;
}

hazard::ConfigAck archie_ack(double pclass = kPclass) { return {"archie", 25, kPd, kPfa, pclass}; }

hazard::DetectionReport detection(const char* label, double x, double y) {
  hazard::DetectionReport d;
  d.label = label;
  d.x_m = x;
  d.y_m = y;
  return d;
}

hazard::HazardReport answer(const char* label, bool hazard_type) {
  hazard::HazardReport h;
  h.label = label;
  h.type = hazard_type ? hazard::ObjectType::kHazard : hazard::ObjectType::kBenign;
  return h;
}

// Drives the vehicle north along x = x_m from y0 to y1 at 1.5 m/s, 4 Hz, ticking as it goes.
// Returns the time after the last pose.
double drive_north(HazardManager& m, double x_m, double y0, double y1, double t0,
                   Outputs* all = nullptr) {
  double t = t0;
  for (double y = y0; y <= y1; y += 1.5 * 0.25, t += 0.25) {
    m.on_pose({x_m, y}, 0.0, 1.5, t);
    Outputs b = m.tick(t);
    if (all) all->append(std::move(b));
  }
  return t;
}

double prior_plus(double log_lr) { return logistic(logit(0.5) + log_lr); }

TEST(ManagerConfigTable, ParametersAreValidatedAndNamed_Spec13) {
  ManagerConfig c = archie_config();
  EXPECT_EQ(apply_manager_param(c, "Swath_Width", "10").error, "");
  EXPECT_EQ(c.swath_width_m, 10);
  EXPECT_EQ(apply_manager_param(c, "pd", "0.75").error, "");  // uFldHazardMgr's alias of sensor_pd
  EXPECT_EQ(c.pd, 0.75);
  EXPECT_EQ(apply_manager_param(c, "sensor_pd", "1.5").error,
            "parameter sensor_pd=1.5 must be in [0, 1]");
  EXPECT_EQ(apply_manager_param(c, "swath_width", "wide").error,
            "parameter swath_width='wide' is not a number");
  EXPECT_EQ(apply_manager_param(c, "prior_hazard", "0").error,
            "parameter prior_hazard=0 must be in (0, 1)");
  EXPECT_EQ(apply_manager_param(c, "report_name", "\"final report\"").error, "");
  EXPECT_EQ(c.report_name, "final report");
  EXPECT_EQ(apply_manager_param(c, "region", "0,0:10,0:10,10").error, "");
  EXPECT_TRUE(c.region.has_value());
  EXPECT_NE(apply_manager_param(c, "region", "0,0:10,0").error.find("parameter region: polygon"),
            std::string::npos);
  EXPECT_EQ(apply_manager_param(c, "classify_lookahead", "0").error,
            "parameter classify_lookahead='0' is not a whole number in [1, 20]");
  EXPECT_EQ(apply_manager_param(c, "report_xpath", "yes").error, "");
  EXPECT_TRUE(c.report_xpath);
  EXPECT_EQ(apply_manager_param(c, "colour", "red").error, "unknown parameter 'colour'");
  EXPECT_EQ(validate(c).error, "");
  c.detection_latency_s = -1;
  EXPECT_EQ(validate(c).error, "parameter detection_latency=-1 must be >= 0");
  ManagerConfig unnamed;
  EXPECT_EQ(validate(unnamed).error, "the vehicle name is empty");
  EXPECT_GE(manager_parameters().size(), 15u);
}

TEST(Manager, RequestsItsSettingUntilAckedThenKeepsTheSensorOn_Spec13) {
  HazardManager m(archie_config());
  Outputs out = m.tick(0.0);
  ASSERT_EQ(out.postings.size(), 1u);
  EXPECT_EQ(out.postings[0].variable, "UHZ_CONFIG_REQUEST");
  EXPECT_EQ(out.postings[0].text, "vname=archie,width=25,pd=0.9");
  EXPECT_TRUE(m.tick(29.0).postings.empty());
  EXPECT_EQ(m.tick(30.0).postings.size(), 1u);  // retried: the sensor may not have been up
  Outputs wrong = m.on_config_ack({"betty", 10, 0.9, 0.53, 0.93}, 31.0);
  ASSERT_EQ(wrong.run_warnings.size(), 1u);
  EXPECT_FALSE(m.acked());
  m.on_config_ack(archie_ack(), 31.0);
  EXPECT_TRUE(m.acked());
  out = m.tick(32.0);
  ASSERT_EQ(out.postings.size(), 1u);
  EXPECT_EQ(out.postings[0].variable, "UHZ_SENSOR_REQUEST");
  EXPECT_EQ(out.postings[0].text, "vname=archie");
  EXPECT_TRUE(m.tick(36.9).postings.empty());
  EXPECT_EQ(m.tick(37.0).postings.size(), 1u);
  EXPECT_TRUE(m.tick(200.0).postings.size() == 1u);  // no more config requests
}

TEST(Manager, TickIntoAKeptOutputsAppendsWhatTickReturns) {
  HazardManager kept_ticks(archie_config());
  HazardManager fresh_ticks(archie_config());
  Outputs kept;
  kept.events.push_back("earlier");
  kept_ticks.tick(0.0, kept);
  const Outputs fresh = fresh_ticks.tick(0.0);
  ASSERT_EQ(fresh.postings.size(), 1u);
  ASSERT_EQ(kept.postings.size(), 1u);
  EXPECT_EQ(kept.postings[0].variable, fresh.postings[0].variable);
  EXPECT_EQ(kept.postings[0].text, fresh.postings[0].text);
  EXPECT_EQ(kept.events, std::vector<std::string>{"earlier"});  // appended: nothing cleared
  kept.clear();
  EXPECT_TRUE(kept.empty());
  kept_ticks.tick(29.0, kept);
  EXPECT_TRUE(kept.empty());  // a quiet tick adds nothing
  kept.run_warnings.push_back("w");
  EXPECT_FALSE(kept.empty());
}

TEST(Manager, DetectionUpdatesTheBeliefAndRequestsAClassification) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  m.on_pose({0, 0}, 0, 1.5, 1.0);
  const Outputs out = m.on_detection(detection("75", 10, 0), 1.2);
  const auto b = m.belief("75");
  ASSERT_TRUE(b.has_value());
  EXPECT_NEAR(b->p_hazard, 0.9 / (0.9 + 0.6561), 1e-12);
  ASSERT_EQ(out.postings.size(), 1u);
  EXPECT_EQ(out.postings[0].variable, "UHZ_CLASSIFY_REQUEST");
  const double priority =
      std::round(classification_priority(b->p_hazard, kPclass, {}, 2) * 100) / 100;
  EXPECT_EQ(out.postings[0].text, "vname=archie,label=75,priority=" + base::fmt(priority));
  EXPECT_GT(priority, 0.0);
  EXPECT_EQ(m.counters().classify_requests, 1);
}

TEST(Manager, ClassificationUsesThePclassInForceAtTheRequest) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  m.on_detection(detection("75", 500, 500), 1.0);  // far away: no pass bookkeeping involved
  m.on_config_ack({"archie", 10, kPd, std::pow(0.9, 6), 0.93}, 2.0);  // setting changes
  m.on_classification(answer("75", false), 40.0);
  const double expected = llr_detection(kPd, kPfa) + llr_classification(false, kPclass);
  EXPECT_NEAR(m.belief("75")->p_hazard, prior_plus(expected), 1e-12);
  EXPECT_EQ(m.counters().classify_answers, 1);
  // An answer nobody asked for is still evidence (with the current pclass), with a warning.
  const Outputs extra = m.on_classification(answer("75", true), 41.0);
  EXPECT_EQ(extra.run_warnings.size(), 1u);
  EXPECT_NEAR(m.belief("75")->p_hazard, prior_plus(expected + llr_classification(true, 0.93)),
              1e-12);
}

TEST(Manager, ReportsForAnotherVehicleAreIgnored) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  hazard::DetectionReport d = detection("75", 1, 1);
  d.vname = "betty";
  EXPECT_EQ(m.on_detection(d, 1.0).run_warnings.size(), 1u);
  EXPECT_FALSE(m.belief("75").has_value());
}

TEST(Manager, APassWithoutADetectionCountsAsAMissAfterTheLatency) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  // First pass: the object at (10, 50) is detected as the vehicle goes by.
  double t = drive_north(m, 0, 0, 48, 1.0);
  m.on_detection(detection("a", 10, 50), t);
  t = drive_north(m, 0, 48.375, 120, t);
  t += 20;  // long after: the pass is resolved, detected
  m.tick(t);
  EXPECT_EQ(m.counters().missed_passes, 0);
  // Second pass on a parallel line 15 m away (inside W - margin = 24.9), nothing reported.
  t = drive_north(m, 25, 0, 120, t);
  m.tick(t + 20);
  EXPECT_EQ(m.counters().missed_passes, 1);
  const double expected = llr_detection(kPd, kPfa) + llr_missed_pass(kPd, kPfa);
  EXPECT_NEAR(m.belief("a")->p_hazard, prior_plus(expected), 1e-12);
  EXPECT_EQ(m.belief("a")->own.missed_passes, 1);
}

TEST(Manager, AGrazingPassIsDoubtfulAndNotCounted) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  m.on_detection(detection("a", 10, 50), 0.5);  // known from afar
  // Track 24.95 m from the object: beyond W - margin = 24.9 but within W = 25, so the sensor may
  // or may not have rolled.
  const double t = drive_north(m, 34.95, 0, 120, 1.0);
  m.tick(t + 20);
  EXPECT_EQ(m.counters().missed_passes, 0);
  EXPECT_EQ(m.counters().doubtful_passes, 1);
}

TEST(Manager, NoPassesWhileTurningOrTooFast_Manual8and9) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  m.on_detection(detection("a", 10, 50), 0.5);
  // Turning 3 deg/s all the way: the sensor is off, its state frozen.
  double t = 1.0, heading = 0.0;
  for (double y = 0; y <= 120; y += 0.375, t += 0.25, heading += 0.75) {
    m.on_pose({0, y}, heading, 1.5, t);
    m.tick(t);
  }
  // Too fast.
  for (double y = 0; y <= 120; y += 0.75, t += 0.25) {
    m.on_pose({0, y}, 0.0, 3.0, t);
    m.tick(t);
  }
  m.tick(t + 20);
  EXPECT_EQ(m.counters().missed_passes, 0);
  EXPECT_EQ(m.counters().doubtful_passes, 0);
}

TEST(Manager, LateDetectionClaimsTheEndedPassAndEarlyDetectionClaimsTheNextEntry) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  m.on_detection(detection("a", 10, 50), 0.5);  // known from afar (unmatched for 10 s only)
  double t = drive_north(m, 0, 0, 55, 20.0);     // leaves the swath at y = 52.875, 5.6 s before t
  m.on_detection(detection("a", 10, 50), t + 2);  // arrives 7.6 s after the pass ended
  m.tick(t + 30);
  EXPECT_EQ(m.counters().missed_passes, 0);
  EXPECT_EQ(m.belief("a")->own.detections, 2);
  // A report that arrives a moment before the manager sees the object enter is that pass's.
  m.on_detection(detection("a", 10, 50), t + 40);
  t = drive_north(m, 0, 45, 120, t + 40.5);  // enters 1.75 s later
  m.tick(t + 30);
  EXPECT_EQ(m.belief("a")->own.detections, 3);
  EXPECT_EQ(m.counters().missed_passes, 0);
}

TEST(Manager, FirstDetectionAddsTheMissesSeenInHindsight) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  double t = drive_north(m, 0, 0, 120, 1.0);  // passes (10, 50): nothing reported, unknown yet
  t = drive_north(m, 40, 0, 120, t + 10);     // passes 30 m away: beyond W, no pass
  t = drive_north(m, 5, 0, 48, t + 10);       // third time: detected
  m.on_detection(detection("a", 10, 50), t);
  EXPECT_EQ(m.counters().hindsight_passes, 1);
  const double expected = llr_missed_pass(kPd, kPfa) + llr_detection(kPd, kPfa);
  EXPECT_NEAR(m.belief("a")->p_hazard, prior_plus(expected), 1e-12);
}

TEST(Manager, ReportHoldsTheObjectsWorthReporting_Spec14_2) {
  ManagerConfig c = archie_config();
  c.report_name = "archie_final";
  HazardManager m(c);
  m.on_config_ack(archie_ack(), 0.0);
  for (const char* label : {"a", "b", "c"}) m.on_detection(detection(label, 1000, 1000), 1.0);
  m.on_classification(answer("b", false), 40);
  m.on_classification(answer("b", false), 70);  // p(b) = 0.041 < 1/11
  Outputs out = m.on_hazardset_request(100);
  ASSERT_EQ(out.postings.size(), 1u);
  EXPECT_EQ(out.postings[0].variable, "HAZARDSET_REPORT");
  EXPECT_EQ(out.postings[0].text,
            "source=archie#name=archie_final#x=1000,y=1000,label=a#x=1000,y=1000,label=c");
  // With false alarms as costly as misses, only likely hazards are reported.
  MissionParams even;
  even.penalty_missed_hazard = 10;
  even.penalty_false_alarm = 10;
  m.on_mission_params(even);
  EXPECT_EQ(m.make_report().objects.size(), 2u);  // p = 0.578 > 0.5 still
  m.on_classification(answer("a", false), 100);
  EXPECT_EQ(m.make_report().objects.size(), 1u);  // a: 0.195
}

TEST(Manager, ReportKeepsTheAspectFieldsOfTheDetection_Spec4_4) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  hazard::DetectionReport d = detection("99", 37, -207);
  d.aspect_deg = 57;
  d.aspect_min_deg = 20;
  d.aspect_max_deg = 45;
  m.on_detection(d, 1.0);
  EXPECT_EQ(format_hazardset_report(m.make_report()),
            "source=archie#x=37,y=-207,label=99,aspect=57,aspect_min=20,aspect_max=45");
}

TEST(Manager, XpathIsTheMinimumHazardLaneOverTheReportedObjects) {
  ManagerConfig c = archie_config();
  c.report_xpath = true;
  c.region = ConvexPolygon::parse("0,0:100,0:100,50:0,50").value.value();
  HazardManager m(c);
  m.on_config_ack(archie_ack(), 0.0);
  m.on_detection(detection("a", 25, 10), 1.0);
  m.on_detection(detection("b", 30, 40), 1.0);
  EXPECT_EQ(*m.make_report().xpath_m, 51);
  EXPECT_NE(format_hazardset_report(m.make_report()).find("#xpath=51#"), std::string::npos);
}

TEST(Manager, MissionParamsSetPenaltiesAndLendTheRegionForTheLane) {
  ManagerConfig c = archie_config();
  c.report_xpath = true;  // no region configured: the grader's is used
  HazardManager m(c);
  m.on_config_ack(archie_ack(), 0.0);
  m.on_detection(detection("a", 25, 10), 1.0);
  m.on_detection(detection("b", 30, 40), 1.0);
  EXPECT_FALSE(m.make_report().xpath_m.has_value());
  MissionParams params;
  params.penalty_missed_hazard = 70;
  params.penalty_false_alarm = 30;
  params.search_region = "pts={0,0:100,0:100,50:0,50}";
  EXPECT_TRUE(m.on_mission_params(params).run_warnings.empty());
  EXPECT_EQ(m.penalties().missed_hazard, 70);
  EXPECT_EQ(m.penalties().false_alarm, 30);
  EXPECT_EQ(*m.make_report().xpath_m, 51);
  params.penalty_false_alarm = -1;
  EXPECT_EQ(m.on_mission_params(params).run_warnings.size(), 1u);
  EXPECT_EQ(m.penalties().false_alarm, 30);  // the bad message changed nothing
}

TEST(Manager, HandoverCarriesEvidenceAndTheReceiverAddsItOnce) {
  HazardManager archie(archie_config());
  archie.on_config_ack(archie_ack(), 0.0);
  archie.on_detection(detection("75", 100, 100), 1.0);
  archie.on_classification(answer("75", false), 40.0);
  archie.on_detection(detection("53", 200, 100), 2.0);
  const Outputs out = archie.handover_to("betty");
  ASSERT_EQ(out.postings.size(), 2u);
  EXPECT_EQ(out.postings[0].variable, "HAZARD_HANDOVER");
  EXPECT_EQ(out.postings[1].variable, "HAZARD_HANDOVER_BETTY");
  const auto parsed = parse_handover(out.postings[1].text);
  ASSERT_TRUE(parsed) << parsed.error;

  ManagerConfig bc;
  bc.vname = "betty";
  bc.swath_width_m = 10;
  HazardManager betty(bc);
  betty.on_handover(*parsed.value, 3000.0);
  EXPECT_NEAR(betty.belief("75")->p_hazard, archie.belief("75")->p_hazard, 1e-6);
  EXPECT_TRUE(betty.belief("75")->handed_over);
  betty.on_handover(*parsed.value, 3001.0);  // again: replaces, does not add
  EXPECT_NEAR(betty.belief("75")->p_hazard, archie.belief("75")->p_hazard, 1e-6);
  // Betty's own evidence adds to archie's.
  betty.on_config_ack({"betty", 10, kPd, std::pow(0.9, 6), 0.93}, 3002.0);
  betty.on_detection(detection("75", 100, 100), 3100.0);
  betty.on_classification(answer("75", false), 3140.0);
  const double expected = llr_detection(kPd, kPfa) + llr_classification(false, kPclass) +
                          llr_detection(kPd, std::pow(0.9, 6)) + llr_classification(false, 0.93);
  EXPECT_NEAR(betty.belief("75")->p_hazard, prior_plus(expected), 1e-6);
  EXPECT_FALSE(betty.belief("75")->reported);  // 0.9 -> two "benign" answers from two vehicles
  // A hand-over meant for someone else is ignored.
  ManagerConfig cc;
  cc.vname = "charlie";
  HazardManager charlie(cc);
  EXPECT_EQ(charlie.on_handover(*parsed.value, 1.0).run_warnings.size(), 1u);
  EXPECT_TRUE(charlie.beliefs().empty());
}

TEST(Manager, AnObjectHandedOverMidPassIsEnteredByTheNextPose) {
  // Archie knows no object while it drives (its poses skip the swath work), then learns one
  // beside the track from betty: the next pose enters it, and the pass without a detection
  // counts as a miss.
  ManagerConfig bc;
  bc.vname = "betty";
  HazardManager betty(bc);
  betty.on_config_ack({"betty", 25, kPd, kPfa, kPclass}, 0.0);
  betty.on_detection(detection("75", 10, 50), 1.0);
  const auto handover = parse_handover(betty.handover_to("archie").postings.back().text);
  ASSERT_TRUE(handover) << handover.error;

  HazardManager archie(archie_config());
  archie.on_config_ack(archie_ack(), 0.0);
  double t = drive_north(archie, 0, 0, 48, 1.0);
  archie.on_handover(*handover.value, t);
  t = drive_north(archie, 0, 48.375, 120, t);
  archie.tick(t + 20);
  EXPECT_EQ(archie.counters().missed_passes, 1);
  EXPECT_EQ(archie.belief("75")->own.missed_passes, 1);
}

// Poses with no record near reuse one answer for metres of travel (no footprint is built); a
// record added meanwhile is looked for at once: an object handed over just ahead of the track,
// passed within the next few metres, counts its missed pass.
TEST(Manager, ObjectHandedOverJustAheadIsPassedAtOnce) {
  HazardManager archie(archie_config());
  archie.on_config_ack(archie_ack(), 0.0);
  archie.on_detection(detection("far", 500, 500), 0.5);  // a record: the poses look for others
  double t = drive_north(archie, 0, 0, 4, 1.0);
  Handover h;
  h.source = "betty";
  h.dest = "archie";
  h.objects.push_back({"ahead", 0, 7.5, {}});
  archie.on_handover(h, t);
  t = drive_north(archie, 0, 4.125, 12, t);  // in at y = 5, out past y = 10
  archie.tick(t + 20);
  EXPECT_EQ(archie.counters().missed_passes, 1);
  EXPECT_EQ(archie.belief("ahead")->own.missed_passes, 1);
}

TEST(Manager, ReacquireRouteVisitsTheHandedOverObjects) {
  HazardManager archie(archie_config());
  archie.on_config_ack(archie_ack(), 0.0);
  archie.on_detection(detection("1", 100, 0), 1.0);
  archie.on_detection(detection("2", 0, 100), 1.0);
  ManagerConfig bc;
  bc.vname = "betty";
  HazardManager betty(bc);
  betty.on_handover(archie.make_handover("betty"), 10.0);
  const auto route = betty.reacquire_route({0, 0}, ReacquireOptions{20});
  ASSERT_EQ(route.size(), 4u);
  EXPECT_NEAR(glm::length((route[0] + route[1]) * 0.5 - glm::dvec2{100, 0}), 0, 1e-9);
  EXPECT_NEAR(glm::length((route[2] + route[3]) * 0.5 - glm::dvec2{0, 100}), 0, 1e-9);
}

TEST(Manager, DetectionBeforeAnyAckIsCountedButNotWeighed) {
  HazardManager m(archie_config());
  const Outputs out = m.on_detection(detection("a", 1, 1), 1.0);
  EXPECT_EQ(out.run_warnings.size(), 1u);
  EXPECT_TRUE(out.postings.empty());
  EXPECT_EQ(m.belief("a")->p_hazard, 0.5);
  EXPECT_EQ(m.belief("a")->own.detections, 1);
}

// Hostile input (found under -fsanitize=undefined,float-cast-overflow): detections anywhere, even
// at positions no grid cell index can hold, and at negative coordinates (cell indices below zero,
// whose key was a left shift of a negative number), are indexed without undefined behaviour.
TEST(Manager, DetectionsAtAnyPositionAreIndexedWithoutOverflow) {
  HazardManager m(archie_config());
  m.on_config_ack(archie_ack(), 0.0);
  m.on_pose({-20, -30}, 0, 1.5, 1.0);
  m.on_detection(detection("far", 1e300, -1e300), 1.1);
  m.on_detection(detection("beyond_cells", 3e10, -3e10), 1.1);
  m.on_detection(detection("near", -10, -30), 1.2);
  for (const char* label : {"far", "beyond_cells", "near"}) {
    const auto b = m.belief(label);
    ASSERT_TRUE(b.has_value()) << label;
    EXPECT_NEAR(b->p_hazard, 0.9 / (0.9 + 0.6561), 1e-12) << label;
  }
}

}  // namespace
}  // namespace mission
