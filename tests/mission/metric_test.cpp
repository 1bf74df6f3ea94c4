#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "mission/metric.hpp"

namespace mission {
namespace {

// The Jake hazard file (manual 2.3) with gen_hazards' header and region line.
constexpr const char* kJakeHazards =
    "// gen_hazards --polygon=-150,-75:-150,-400:400,-400:400,-75 --objects=5,hazard "
    "--objects=10,benign\n"
    "region = pts={-150,-75:-150,-400:400,-400:400,-75}\n"
    "hazard = x=-52,y=-290,label=75,type=hazard\n"
    "hazard = x=41,y=-108,label=53,type=hazard\n"
    "hazard = x=-64,y=-124,label=98,type=hazard\n"
    "hazard = x=232,y=-80,label=91,type=hazard\n"
    "hazard = x=239,y=-315,label=19,type=hazard\n"
    "hazard = x=-41,y=-246,label=82,type=benign\n"
    "hazard = x=185,y=-93,label=64,type=benign\n"
    "hazard = x=-150,y=-201,label=11,type=benign\n"
    "hazard = x=-76,y=-82,label=14,type=benign\n"
    "hazard = x=-73,y=-309,label=28,type=benign\n"
    "hazard = x=346,y=-371,label=73,type=benign\n"
    "hazard = x=-83,y=-390,label=77,type=benign\n"
    "hazard = x=220,y=-201,label=15,type=benign\n"
    "hazard = x=134,y=-204,label=95,type=benign\n"
    "hazard = x=370,y=-107,label=99,type=benign\n";

HazardMetric jake_metric(double start_s = 100.0) {
  HazardMetric m;
  EXPECT_TRUE(m.load_hazard_file("hazards.txt", kJakeHazards).empty());
  m.start(start_s);
  return m;
}

std::string report_of(const std::vector<const char*>& labels, const char* source = "archie") {
  std::string out = std::string("source=") + source;
  for (const char* l : labels) out += std::string("#x=0,y=0,label=") + l;
  return out;
}

TEST(MetricConfig, DefaultsAreTheOriginals_Spec14_1) {
  const HazardMetric m;
  EXPECT_EQ(m.config().penalty_missed_hazard, 100);
  EXPECT_EQ(m.config().penalty_false_alarm, 10);
  EXPECT_EQ(m.config().penalty_nonopt_hazard, 50);
  EXPECT_EQ(m.config().penalty_max_time_over, 0);
  EXPECT_EQ(m.config().penalty_max_time_rate, 0);
  EXPECT_EQ(m.config().max_time_s, 0);
  EXPECT_FALSE(m.config().show_xpath);
  ASSERT_EQ(metric_parameters().size(), 8u);
  EXPECT_STREQ(metric_parameters()[0].name, "penalty_missed_hazard");
  EXPECT_STREQ(metric_parameters()[0].default_text, "100");
}

TEST(MetricConfig, KeysAreCaseInsensitiveAndBadValuesAreNamed) {
  HazardMetric m;
  EXPECT_EQ(m.configure("PENALTY_False_Alarm", " 25 ").warning, "");
  EXPECT_EQ(m.config().penalty_false_alarm, 25);
  EXPECT_EQ(m.configure("max_time", "soon").warning,
            "parameter max_time='soon' is not a number; keeps 0");
  EXPECT_EQ(m.configure("penalty_missed_hazard", "-5").warning,
            "parameter penalty_missed_hazard=-5 must be >= 0; keeps 100");
  EXPECT_EQ(m.configure("penalty_missed_hazard", "nan").warning,
            "parameter penalty_missed_hazard='nan' is not a number; keeps 100");
  EXPECT_EQ(m.config().penalty_missed_hazard, 100);
  EXPECT_EQ(m.configure("show_xpath", "maybe").warning,
            "parameter show_xpath='maybe' is not true or false");
  EXPECT_EQ(m.configure("show_xpath", "TRUE").warning, "");
  EXPECT_TRUE(m.config().show_xpath);
  EXPECT_EQ(m.configure("colour", "red").warning, "unknown parameter 'colour'");
  EXPECT_EQ(m.configure("penalty_false_alarm", "30").warning,
            "parameter penalty_false_alarm is repeated; the last value (30) is used");
  EXPECT_EQ(m.config().penalty_false_alarm, 30);
  const auto file = m.configure("Hazard_File", "hazards.txt");
  EXPECT_EQ(file.warning, "");
  EXPECT_EQ(*file.hazard_file, "hazards.txt");
  EXPECT_EQ(HazardMetric::hazard_file_missing("nope.txt"),
            "Reading nope.txt: Empty or File Not found.");
}

TEST(MetricTruth, UsesTheSensorsLoaderAndReadsRegionAndSource) {
  HazardMetric m;
  const auto warnings = m.load_hazard_file(
      "h.txt",
      "source = field_7  // a comment\n"
      "region = 0,0:10,0:5,2:10,10:0,10\n"
      "hazard = x=1,y=1,label=a,type=hazard // trailing comment\n"
      "hazard = x=2,y=2,label=b,type=inert\n"
      "hazard = x=3,y=3,label=a,type=benign\n"
      "something else\n");
  EXPECT_EQ(m.source(), "field_7");
  EXPECT_FALSE(m.region().has_value());  // not convex
  EXPECT_EQ(m.truth().hazard_count(), 1);
  // "inert" is rejected by the shared loader (differences.md "Validation").
  EXPECT_EQ(m.truth().benign_count(), 0);
  bool bad_region = false, duplicate = false, strange = false;
  for (const auto& w : warnings) {
    bad_region |= w.find("h.txt:2: bad region spec") != std::string::npos;
    duplicate |= w.find("h.txt:5") != std::string::npos && w.find("duplicate") != std::string::npos;
    strange |= w.find("h.txt:6") != std::string::npos;
  }
  EXPECT_TRUE(bad_region);
  EXPECT_TRUE(duplicate);
  EXPECT_TRUE(strange);
}

TEST(MetricTruth, SeveralHazardFilesLoadTogetherAndDuplicatesAcrossFilesAreWarned) {
  HazardMetric m;
  EXPECT_TRUE(m.load_hazard_file("a.txt", "hazard = x=1,y=1,label=1,type=hazard\n").empty());
  const auto warnings = m.load_hazard_file(
      "b.txt", "hazard = x=2,y=2,label=2,type=benign\nhazard = x=3,y=3,label=1,type=benign\n");
  EXPECT_EQ(m.truth().hazard_count(), 1);
  EXPECT_EQ(m.truth().benign_count(), 1);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("b.txt:2"), std::string::npos);
  m.start(0);
  EXPECT_EQ(m.source(), "a.txt");  // no source line: the first file's name
}

TEST(MetricTruth, SourceDefaultsToTheFileName) {
  const HazardMetric m = jake_metric();
  EXPECT_EQ(m.source(), "hazards.txt");
  EXPECT_EQ(m.truth().hazard_count(), 5);
  EXPECT_EQ(m.truth().benign_count(), 10);
  ASSERT_TRUE(m.region().has_value());
  EXPECT_EQ(m.worst_score(), 10 * 10 + 100 * 5);
}

TEST(MetricScore, AllHazardsAndTwoFalseAlarmsByHand_Spec14_2) {
  const HazardMetric m = jake_metric();
  const auto report = parse_hazardset_report(report_of({"75", "53", "98", "91", "19", "82", "64"}));
  const auto e = m.evaluate(report, 400);
  EXPECT_EQ(e.correct_hazards, 5);
  EXPECT_EQ(e.false_alarms, 2);
  EXPECT_EQ(e.missed_hazards, 0);
  EXPECT_EQ(e.total_score, 20);
  EXPECT_NEAR(e.norm_score, 100.0 * (600 - 20) / 600, 1e-12);  // 96.67
  EXPECT_EQ(e.total_objects, 7);
  EXPECT_EQ(e.score_time_overage, 0);
}

TEST(MetricScore, MissedHazardFalseAlarmAndExtraLabelsByHand_Spec14_2) {
  const HazardMetric m = jake_metric();
  // 19 missed (100), 15 false alarm (10), "999" and "x" not in the truth: ignored.
  const auto e = m.evaluate(
      parse_hazardset_report(report_of({"75", "53", "98", "91", "15", "999", "x"})), 400);
  EXPECT_EQ(e.missed_hazards, 1);
  EXPECT_EQ(e.false_alarms, 1);
  EXPECT_EQ(e.correct_hazards, 4);
  EXPECT_EQ(e.score_missed_hazards, 100);
  EXPECT_EQ(e.score_false_alarms, 10);
  EXPECT_EQ(e.total_score, 110);
  EXPECT_NEAR(e.norm_score, 100.0 * 490 / 600, 1e-12);
  EXPECT_EQ(e.total_objects, 7);  // extra labels still count as reported objects
  // Object report in file order, with penalties on the two mistakes only.
  ASSERT_EQ(e.object_report.size(), 15u);
  EXPECT_EQ(e.object_report[0].label, "75");
  EXPECT_FALSE(e.object_report[0].penalty.has_value());
  EXPECT_EQ(e.object_report[4].label, "19");
  EXPECT_FALSE(e.object_report[4].reported);
  EXPECT_EQ(*e.object_report[4].penalty, 100);
  EXPECT_EQ(e.object_report[12].label, "15");
  EXPECT_EQ(e.object_report[12].truth, "benign");
  EXPECT_EQ(*e.object_report[12].penalty, 10);
}

TEST(MetricScore, NothingReportedScoresZeroAndEverythingCorrectScores100) {
  const HazardMetric m = jake_metric();
  auto score = [&](const std::vector<const char*>& labels) {
    return m.evaluate(parse_hazardset_report(report_of(labels)), 400).norm_score;
  };
  EXPECT_EQ(score({"1000"}), 100.0 * 100 / 600);
  EXPECT_EQ(score({"75", "53", "98", "91", "19"}), 100);
  // Every object reported: 10 false alarms, 100 of 600.
  EXPECT_NEAR(score({"75", "53", "98", "91", "19", "82", "64", "11", "14", "28", "73", "77", "15",
                     "95", "99"}),
              100.0 * 500 / 600, 1e-12);
}

TEST(MetricScore, TimeOverageByHand_Spec14_2) {
  HazardMetric m;
  m.load_hazard_file("hazards.txt", kJakeHazards);
  m.configure("max_time", "100");
  m.configure("penalty_max_time_over", "30");
  m.configure("penalty_max_time_rate", "0.5");
  m.start(900);
  m.on_search_start(1000);
  const auto report = parse_hazardset_report(report_of({"75", "53", "98", "91", "19"}));
  EXPECT_EQ(m.evaluate(report, 1100).score_time_overage, 0);  // exactly at the limit
  const auto e = m.evaluate(report, 1150);                     // 50 s over
  EXPECT_EQ(e.score_time_overage, 30 + 0.5 * 50);
  EXPECT_EQ(e.total_score, 55);
  EXPECT_NEAR(e.norm_score, 100.0 * (600 - 55) / 600, 1e-12);
  EXPECT_EQ(e.total_time_s, 150);
  EXPECT_EQ(e.received_time_s, 250);
  EXPECT_EQ(e.start_time_s, 100);
  // Without a search start there is no elapsed time and no overage.
  HazardMetric never;
  never.load_hazard_file("hazards.txt", kJakeHazards);
  never.configure("max_time", "100");
  never.configure("penalty_max_time_over", "30");
  never.start(900);
  const auto e2 = never.evaluate(report, 5000);
  EXPECT_EQ(e2.score_time_overage, 0);
  EXPECT_EQ(e2.start_time_s, 0);
}

TEST(MetricScore, WorstScoreZeroGivesADefinedScore_N17) {
  HazardMetric empty;
  empty.load_hazard_file("empty.txt", "");
  empty.start(0);
  const auto e = empty.evaluate(parse_hazardset_report("source=a#x=1,y=1,label=1"), 10);
  EXPECT_EQ(e.norm_score, 100);  // nothing to find, nothing lost
  EXPECT_FALSE(std::isnan(e.norm_score));
  HazardMetric late;
  late.load_hazard_file("empty.txt", "");
  late.configure("max_time", "5");
  late.configure("penalty_max_time_over", "1");
  late.start(0);
  late.on_search_start(0);
  EXPECT_EQ(late.evaluate(parse_hazardset_report("source=a#x=1,y=1,label=1"), 10).norm_score, 0);
  HazardMetric free_penalties;  // objects but zero penalties
  free_penalties.load_hazard_file("hazards.txt", kJakeHazards);
  free_penalties.configure("penalty_missed_hazard", "0");
  free_penalties.configure("penalty_false_alarm", "0");
  free_penalties.start(0);
  EXPECT_EQ(free_penalties.evaluate(parse_hazardset_report(report_of({"82"})), 10).norm_score, 100);
}

TEST(MetricReports, PostsScoreAndEvalsInTheOriginalsOrder_Spec14_2) {
  HazardMetric m = jake_metric();
  const Outputs out =
      m.on_hazardset_report(report_of({"75", "53", "98", "91", "19", "82", "64"}), 400);
  ASSERT_EQ(out.postings.size(), 5u);
  EXPECT_EQ(out.postings[0].variable, "HAZARD_SEARCH_SCORE");
  ASSERT_TRUE(out.postings[0].number.has_value());
  EXPECT_NEAR(*out.postings[0].number, 96.666666, 1e-5);
  EXPECT_EQ(out.postings[1].variable, "HAZARDSET_EVAL_FULL");
  EXPECT_EQ(out.postings[2].variable, "HAZARDSET_EVAL_FULL_ARCHIE");
  EXPECT_EQ(out.postings[3].variable, "HAZARDSET_EVAL");
  EXPECT_EQ(out.postings[4].variable, "HAZARDSET_EVAL_ARCHIE");
  EXPECT_EQ(out.postings[1].text, out.postings[2].text);
  EXPECT_EQ(out.postings[3].text.substr(0, 53),
            "vname=archie,total_score=20,norm_score=96.67,score_mi");
  EXPECT_NE(out.postings[1].text.find(",object_report={label=75,truth=hazard,report=hazard#"),
            std::string::npos);
  EXPECT_NE(out.postings[3].text.find("received_time=300,start_time=0,"), std::string::npos);
}

TEST(MetricReports, RejectsMissingOrActualSourceAndIgnoresEmptyReports) {
  HazardMetric m = jake_metric();
  Outputs out = m.on_hazardset_report("x=1,y=2,label=75", 400);
  EXPECT_TRUE(out.postings.empty());
  ASSERT_EQ(out.run_warnings.size(), 1u);
  EXPECT_EQ(out.run_warnings[0], "Rejected HAZARDSET_REPORT: Missing Source info");
  out = m.on_hazardset_report("source=actual#x=1,y=2,label=75", 400);
  EXPECT_EQ(out.run_warnings.at(0), "Rejected HAZARDSET_REPORT: Source claims to be actual");
  out = m.on_hazardset_report("source=archie#name=empty", 400);
  EXPECT_TRUE(out.postings.empty());
  EXPECT_TRUE(out.run_warnings.empty());
  EXPECT_EQ(out.events.size(), 1u);
  EXPECT_EQ(m.reports_received(), 0);
  EXPECT_TRUE(m.sources().empty());
}

TEST(MetricReports, StoresTheLatestReportPerSource) {
  HazardMetric m = jake_metric();
  m.on_hazardset_report(report_of({"75"}, "archie"), 200);
  m.on_hazardset_report(report_of({"75", "53", "98", "91", "19"}, "archie"), 300);
  m.on_hazardset_report(report_of({"82"}, "betty"), 310);
  EXPECT_EQ(m.reports_received(), 3);
  ASSERT_EQ(m.sources().size(), 2u);
  EXPECT_EQ(m.sources().at("archie").reports_received, 2);
  EXPECT_EQ(m.sources().at("archie").eval.norm_score, 100);
  EXPECT_EQ(m.sources().at("betty").eval.missed_hazards, 5);
}

TEST(MetricReports, XpathQuirkInflatesTotalObjectsOnly) {
  HazardMetric m = jake_metric();
  const auto with = m.evaluate(parse_hazardset_report("source=a#xpath=12#x=0,y=0,label=75"), 400);
  const auto without = m.evaluate(parse_hazardset_report("source=a#x=0,y=0,label=75"), 400);
  EXPECT_EQ(with.total_objects, 2);
  EXPECT_EQ(without.total_objects, 1);
  EXPECT_EQ(with.total_score, without.total_score);
}

TEST(MetricStart, PostsRegionLaneAndMissionParams) {
  HazardMetric m;
  m.load_hazard_file("hazards.txt", kJakeHazards);
  m.configure("show_xpath", "true");
  const Outputs out = m.start(0);
  ASSERT_EQ(out.postings.size(), 3u);
  EXPECT_EQ(out.postings[0].variable, "VIEW_POLYGON");
  EXPECT_EQ(out.postings[0].text.substr(0, 80),
            "pts={-150,-75:-150,-400:400,-400:400,-75},label=search_region,edge_color=gray45,");
  EXPECT_EQ(out.postings[1].variable, "VIEW_POLYGON");
  EXPECT_NE(out.postings[1].text.find("label=min_path"), std::string::npos);
  EXPECT_NE(out.postings[1].text.find("fill_color=yellow"), std::string::npos);
  EXPECT_NE(out.postings[1].text.find("fill_transparency=0.12"), std::string::npos);
  EXPECT_EQ(out.postings[2].variable, "UHZ_MISSION_PARAMS");
  EXPECT_EQ(out.postings[2].text,
            "penalty_missed_hazard=100,penalty_nonopt_hazard=50,penalty_false_alarm=10,"
            "penalty_max_time_over=0,max_time=0,penalty_max_time_rate=0,transit_path_width=20,"
            "search_region=pts={-150,-75:-150,-400:400,-400:400,-75}");
  EXPECT_TRUE(m.iterate(49, 1).postings.empty());
  EXPECT_EQ(m.iterate(50, 1).postings.at(0).text, out.postings[2].text);
  EXPECT_EQ(m.iterate(100, 1).postings.size(), 1u);
  // The application asks iterate_posts first: it must agree with iterate.
  for (long i : {1L, 2L, 49L, 50L, 51L, 99L, 100L})
    EXPECT_EQ(HazardMetric::iterate_posts(i), !m.iterate(i, 1).postings.empty()) << i;
}

TEST(TransitLane, FirstXWithTheFewestHazardsByHand_Spec14_2) {
  const auto region = ConvexPolygon::parse("0,0:100,0:100,50:0,50").value.value();
  // Candidates x = 20..79; hazards at x = 25 and 30 leave strips [x-20, x+20] empty from x = 51.
  const auto lane = min_hazard_lane(region, {{25, 10}, {30, 40}, {500, 10}}, 20);
  ASSERT_TRUE(lane.has_value());
  EXPECT_EQ(lane->x_m, 51);
  EXPECT_EQ(lane->hazard_count, 0);
  // With a third hazard at x = 71 every strip holds one or two: x <= 45 holds 25 and 30, x = 46..50
  // only 30 (edges inclusive: x = 50 is [30, 70]), x >= 51 only 71. The first x with one wins.
  const auto lane2 = min_hazard_lane(region, {{25, 10}, {30, 40}, {71, 10}}, 20);
  EXPECT_EQ(lane2->hazard_count, 1);
  EXPECT_EQ(lane2->x_m, 46);
  const auto narrow = ConvexPolygon::parse("0,0:30,0:30,50:0,50").value.value();
  EXPECT_FALSE(min_hazard_lane(narrow, {}, 20).has_value());
  const auto exact = ConvexPolygon::parse("0,0:40,0:40,50:0,50").value.value();
  const auto single = min_hazard_lane(exact, {{10, 10}}, 20);
  ASSERT_TRUE(single.has_value());
  EXPECT_EQ(single->x_m, 20);
  EXPECT_EQ(single->hazard_count, 1);  // counted, unlike the original's 0
}

// The lane's counts come from the sorted x of the points (two binary searches per strip); they
// equal the rule's direct count, points on the strip's and the region's edges included.
TEST(TransitLane, EqualsTheDirectCountOnRandomPoints) {
  const auto region = *ConvexPolygon::parse("0,0:300,0:300,-200:0,-200").value;
  std::vector<glm::dvec2> points;
  std::uint64_t state = 12345;
  auto next = [&] { return (state = state * 6364136223846793005ULL + 1442695040888963407ULL) >> 40; };
  for (int i = 0; i < 400; ++i)  // whole metres, some outside the region's y extent
    points.push_back({static_cast<double>(next() % 320) - 10, -static_cast<double>(next() % 240)});
  const double w = 20.0;
  std::optional<TransitLane> direct;
  for (double x = w; x < 300 - w; x += 1.0) {
    int n = 0;
    for (const auto& p : points)
      n += (p.x >= x - w && p.x <= x + w && p.y >= -200 && p.y <= 0) ? 1 : 0;
    if (!direct || n < direct->hazard_count) direct = TransitLane{x, n};
  }
  const auto lane = min_hazard_lane(region, points, w);
  ASSERT_TRUE(lane && direct);
  EXPECT_EQ(lane->x_m, direct->x_m);
  EXPECT_EQ(lane->hazard_count, direct->hazard_count);
  EXPECT_EQ(min_hazard_lane(region, points, -1.0)->hazard_count, 0);  // an empty strip
}

}  // namespace
}  // namespace mission
