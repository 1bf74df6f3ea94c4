#include <gtest/gtest.h>

#include "mission/messages/hazard_handover.hpp"
#include "mission/messages/hazard_search.hpp"
#include "mission/messages/hazardset_eval.hpp"
#include "mission/messages/hazardset_report.hpp"
#include "mission/messages/mission_params.hpp"

namespace mission {
namespace {

// ---- HAZARDSET_REPORT ----------------------------------------------------------------------

TEST(HazardsetReport, ParsesTheSpecExample_Spec14_2) {
  const auto r = parse_hazardset_report(
      "source=archie#name=archie#x=-52,y=-290,label=75#x=41,y=-108,label=53");
  EXPECT_EQ(r.source, "archie");
  EXPECT_EQ(r.name, "archie");
  ASSERT_EQ(r.objects.size(), 2u);
  EXPECT_EQ(*r.objects[0].label, "75");
  EXPECT_EQ(*r.objects[0].x_m, -52);
  EXPECT_EQ(*r.objects[1].y_m, -108);
  EXPECT_TRUE(r.has_label("53"));
  EXPECT_FALSE(r.has_label("5"));
}

TEST(HazardsetReport, XpathPartCountsAsALabellessObjectLikeTheOriginal_Spec14_2) {
  const auto r = parse_hazardset_report("source=archie#xpath=123.5#x=1,y=2,label=7");
  ASSERT_EQ(r.objects.size(), 2u);  // the quirk: total_objects will say 2
  EXPECT_FALSE(r.objects[0].label.has_value());
  EXPECT_FALSE(r.objects[0].x_m.has_value());
  EXPECT_FALSE(r.xpath_m.has_value());
}

TEST(HazardsetReport, MetadataIsRecognisedByPrefixAndEmptyPartsAreSkipped) {
  const auto r = parse_hazardset_report(
      " source = betty # name=final #transit_path_width=20#search_region=pts={0,0:10,0:10,10}##"
      "x=5,y=5,label=a,type=hazard,hr=0.3#");
  EXPECT_EQ(r.source, "betty");
  EXPECT_EQ(r.name, "final");
  EXPECT_EQ(*r.search_region, "pts={0,0:10,0:10,10}");
  ASSERT_EQ(r.objects.size(), 1u);
  EXPECT_EQ(*r.objects[0].label, "a");
  EXPECT_EQ(parse_hazardset_report("").objects.size(), 0u);
  EXPECT_EQ(parse_hazardset_report("x=1,y=2,label=3").source, "");  // no source part
}

TEST(HazardsetReport, AspectFieldsFollowTheLabelAndRoundTrip_Spec4_4) {
  HazardsetReport r;
  r.source = "archie";
  ReportedObject o{std::string("99"), 37.0, -207.0, 57.0, 20.0, 45.0};
  r.objects = {o};
  const std::string text = format_hazardset_report(r);
  EXPECT_EQ(text, "source=archie#x=37,y=-207,label=99,aspect=57,aspect_min=20,aspect_max=45");
  const auto back = parse_hazardset_report(text);
  EXPECT_EQ(*back.objects.at(0).aspect_max_deg, 45);
}

TEST(HazardsetReport, BadNumbersLeaveThePositionUnsetButKeepTheObject) {
  const auto r = parse_hazardset_report("source=a#x=abc,y=2,label=9");
  ASSERT_EQ(r.objects.size(), 1u);
  EXPECT_FALSE(r.objects[0].x_m.has_value());
  EXPECT_EQ(*r.objects[0].y_m, 2);
  EXPECT_TRUE(r.has_label("9"));
}

TEST(HazardsetReport, FormatsInTheSpecOrderAndRoundTrips) {
  HazardsetReport r;
  r.source = "archie";
  r.name = "archie";
  r.objects = {reported_object("75", -52.0, -290.004), reported_object("53", 41.0, -108.0)};
  const std::string text = format_hazardset_report(r);
  EXPECT_EQ(text, "source=archie#name=archie#x=-52,y=-290,label=75#x=41,y=-108,label=53");
  const auto back = parse_hazardset_report(text);
  EXPECT_EQ(back.source, r.source);
  ASSERT_EQ(back.objects.size(), 2u);
  EXPECT_EQ(*back.objects[1].label, "53");
  r.xpath_m = 17.25;
  r.search_region = "pts={0,0:1,0:1,1}";
  EXPECT_EQ(format_hazardset_report(r).substr(0, 64),
            "source=archie#name=archie#xpath=17.2#search_region=pts={0,0:1,0:");
}

// ---- UHZ_MISSION_PARAMS --------------------------------------------------------------------

TEST(MissionParams, FormatsTheOriginalsKeysAndPrecision_Spec14_2) {
  MissionParams p;
  p.search_region = "pts={-150,-75:-150,-400:400,-400:400,-75}";
  EXPECT_EQ(format_mission_params(p),
            "penalty_missed_hazard=100,penalty_nonopt_hazard=50,penalty_false_alarm=10,"
            "penalty_max_time_over=0,max_time=0,penalty_max_time_rate=0,transit_path_width=20,"
            "search_region=pts={-150,-75:-150,-400:400,-400:400,-75}");
  p.max_time_s = 1234.5678;
  p.penalty_false_alarm = 2.123456;
  p.transit_path_width_m = 0;
  p.search_region.reset();
  EXPECT_EQ(format_mission_params(p),
            "penalty_missed_hazard=100,penalty_nonopt_hazard=50,penalty_false_alarm=2.12346,"
            "penalty_max_time_over=0,max_time=1234.57,penalty_max_time_rate=0");
}

TEST(MissionParams, ParsesWithBracesMissingKeysAndCaseInsensitiveKeys) {
  const auto parsed = parse_mission_params(
      "PENALTY_MISSED_HAZARD=150,penalty_false_alarm=25,search_region=pts={0,0:10,0:10,10},"
      "future=1");
  ASSERT_TRUE(parsed) << parsed.error;
  EXPECT_EQ(parsed.value->penalty_missed_hazard, 150);
  EXPECT_EQ(parsed.value->penalty_false_alarm, 25);
  EXPECT_EQ(parsed.value->penalty_nonopt_hazard, 50);  // default kept
  EXPECT_EQ(*parsed.value->search_region, "pts={0,0:10,0:10,10}");
  const auto bad = parse_mission_params("penalty_false_alarm=ten");
  EXPECT_FALSE(bad);
  EXPECT_EQ(bad.error,
            "UHZ_MISSION_PARAMS field 'penalty_false_alarm' value 'ten' is not a number");
}

TEST(MissionParams, RoundTrips) {
  MissionParams p;
  p.penalty_missed_hazard = 75.5;
  p.max_time_s = 3600;
  p.penalty_max_time_rate = 0.25;
  p.search_region = "pts={0,0:10,0:10,10}";
  const auto back = parse_mission_params(format_mission_params(p));
  ASSERT_TRUE(back);
  EXPECT_EQ(back.value->penalty_missed_hazard, 75.5);
  EXPECT_EQ(back.value->max_time_s, 3600);
  EXPECT_EQ(back.value->penalty_max_time_rate, 0.25);
  EXPECT_EQ(back.value->search_region, p.search_region);
}

// ---- HAZARDSET_EVAL ------------------------------------------------------------------------

HazardsetEval sample_eval() {
  HazardsetEval e;
  e.vname = "archie";
  e.report_name = "final";
  e.total_score = 120.0;
  e.norm_score = 100.0 * (600 - 120) / 600.0;  // 80
  e.score_missed_hazards = 100;
  e.score_false_alarms = 20;
  e.total_objects = 6;
  e.total_time_s = 812.123456;
  e.received_time_s = 900.5;
  e.start_time_s = 88.25;
  e.missed_hazards = 1;
  e.correct_hazards = 4;
  e.false_alarms = 2;
  e.penalty_false_alarm = 10;
  e.penalty_missed_hazard = 100;
  e.object_report = {{"75", "hazard", true, std::nullopt},
                     {"82", "benign", true, 10.0},
                     {"53", "hazard", false, 100.0},
                     {"14", "benign", false, std::nullopt}};
  return e;
}

TEST(HazardsetEval, ShortFormHasTheOriginalsKeysOrderAndPrecision_Spec14_2) {
  EXPECT_EQ(format_hazardset_eval(sample_eval()),
            "vname=archie,report_name=final,total_score=120,norm_score=80,score_missed_hazards=100,"
            "score_false_alarms=20,score_time_overage=0,total_objects=6,total_time=812.12346,"
            "received_time=900.5,start_time=88.25,missed_hazards=1,correct_hazards=4,"
            "false_alarms=2,"
            "penalty_false_alarm=10,penalty_missed_hazard=100,penalty_max_time_over=0,"
            "penalty_max_time_rate=0,max_time=0");
  HazardsetEval no_name = sample_eval();
  no_name.report_name.clear();
  EXPECT_EQ(format_hazardset_eval(no_name).substr(0, 30), "vname=archie,total_score=120,n");
}

TEST(HazardsetEval, FullFormAppendsTheObjectReport) {
  const std::string full = format_hazardset_eval_full(sample_eval());
  const std::string tail =
      ",object_report={label=75,truth=hazard,report=hazard#label=82,truth=benign,report=hazard,"
      "penalty=10#label=53,truth=hazard,report=nothing,penalty=100#label=14,truth=benign,"
      "report=nothing}";
  ASSERT_GT(full.size(), tail.size());
  EXPECT_EQ(full.substr(full.size() - tail.size()), tail);
  EXPECT_EQ(full.substr(0, full.size() - tail.size()), format_hazardset_eval(sample_eval()));
}

TEST(HazardsetEval, BothFormsParseBack) {
  const auto back = parse_hazardset_eval(format_hazardset_eval_full(sample_eval()));
  ASSERT_TRUE(back) << back.error;
  const HazardsetEval& e = *back.value;
  EXPECT_EQ(e.vname, "archie");
  EXPECT_EQ(e.report_name, "final");
  EXPECT_EQ(e.norm_score, 80);
  EXPECT_EQ(e.total_objects, 6);
  EXPECT_EQ(e.false_alarms, 2);
  EXPECT_NEAR(e.total_time_s, 812.12346, 1e-9);
  ASSERT_EQ(e.object_report.size(), 4u);
  EXPECT_EQ(e.object_report[2].label, "53");
  EXPECT_FALSE(e.object_report[2].reported);
  EXPECT_EQ(*e.object_report[2].penalty, 100);
  EXPECT_FALSE(e.object_report[3].penalty.has_value());
  const auto brief = parse_hazardset_eval(format_hazardset_eval(sample_eval()));
  ASSERT_TRUE(brief);
  EXPECT_TRUE(brief.value->object_report.empty());
}

TEST(HazardsetEval, BadFieldsAreNamed) {
  EXPECT_EQ(parse_hazardset_eval("vname=a,total_objects=-3").error,
            "HAZARDSET_EVAL field 'total_objects' value '-3' is not a count");
  EXPECT_EQ(parse_hazardset_eval("vname=a,norm_score=high").error,
            "HAZARDSET_EVAL field 'norm_score' value 'high' is not a number");
  EXPECT_EQ(parse_hazardset_eval("total_score=1").error, "HAZARDSET_EVAL has no 'vname' field");
  EXPECT_FALSE(parse_hazardset_eval("vname=a,object_report=label=1"));
}

// ---- HAZARD_SEARCH_START / HAZARD_SEARCH_SCORE ---------------------------------------------

TEST(HazardSearch, StartAcceptsAnythingAndScoreIsANumberInRange) {
  EXPECT_TRUE(parse_hazard_search_start("whatever"));
  EXPECT_EQ(format_hazard_search_start({}), "true");
  EXPECT_EQ(*parse_hazard_search_score("86.666667").value, 86.666667);
  EXPECT_EQ(parse_hazard_search_score("nan").error,
            "HAZARD_SEARCH_SCORE value 'nan' is not a number in [0, 100]");
  EXPECT_FALSE(parse_hazard_search_score("101"));
}

// ---- HAZARD_HANDOVER -----------------------------------------------------------------------

Handover sample_handover() {
  Handover h;
  h.source = "archie";
  h.dest = "betty";
  h.prior_hazard = 0.5;
  HandoverObject a{"75", -52, -290, {}};
  a.evidence.log_lr = 2.8414;
  a.evidence.detections = 1;
  a.evidence.said_hazard = 1;
  HandoverObject b{"82", -41, -246.5, {}};
  b.evidence.log_lr = -1.5347;
  b.evidence.detections = 1;
  b.evidence.missed_passes = 2;
  b.evidence.said_benign = 1;
  h.objects = {a, b};
  return h;
}

TEST(Handover, FormatsTheDocumentedLine) {
  EXPECT_EQ(format_handover(sample_handover()),
            "source=archie#dest=betty#prior=0.5#label=75,x=-52,y=-290,evidence=2.8414,det=1,miss=0,"
            "said_hazard=1,said_benign=0#label=82,x=-41,y=-246.5,evidence=-1.5347,det=1,miss=2,"
            "said_hazard=0,said_benign=1");
  EXPECT_EQ(handover_variable_for("betty"), "HAZARD_HANDOVER_BETTY");
}

TEST(Handover, RoundTrips) {
  const auto back = parse_handover(format_handover(sample_handover()));
  ASSERT_TRUE(back) << back.error;
  EXPECT_EQ(back.value->source, "archie");
  EXPECT_EQ(back.value->dest, "betty");
  EXPECT_EQ(back.value->prior_hazard, 0.5);
  ASSERT_EQ(back.value->objects.size(), 2u);
  EXPECT_EQ(back.value->objects[1].label, "82");
  EXPECT_EQ(back.value->objects[1].y_m, -246.5);
  EXPECT_EQ(back.value->objects[1].evidence.log_lr, -1.5347);
  EXPECT_EQ(back.value->objects[1].evidence.missed_passes, 2);
  EXPECT_TRUE(back.value->warnings.empty());
}

TEST(Handover, BadHeaderIsAnErrorAndBadObjectsAreSkippedWithAWarning) {
  EXPECT_FALSE(parse_handover("source=archie#dest=betty"));
  EXPECT_EQ(parse_handover("dest=betty#source=archie#prior=0.5").error,
            "HAZARD_HANDOVER first part 'dest=betty' is not source=<vehicle>");
  EXPECT_EQ(parse_handover("source=a#dest=b#prior=1").error,
            "HAZARD_HANDOVER part 'prior=1' is not prior=<p> with p in (0, 1)");
  const auto h = parse_handover(
      "source=a#dest=b#prior=0.4#label=1,x=0,y=0,evidence=0.5#label=2,x=zz,y=0,evidence=1#"
      "label=3,x=1,y=1#label=4,x=1,y=1,evidence=1,det=-1#label=5,x=2,y=2,evidence=-1");
  ASSERT_TRUE(h) << h.error;
  ASSERT_EQ(h.value->objects.size(), 2u);
  EXPECT_EQ(h.value->objects[1].label, "5");
  ASSERT_EQ(h.value->warnings.size(), 3u);
  EXPECT_EQ(h.value->warnings[0],
            "HAZARD_HANDOVER object 'label=2,x=zz,y=0,evidence=1': field 'x' value 'zz' is not "
            "valid");
  EXPECT_EQ(h.value->warnings[1],
            "HAZARD_HANDOVER object 'label=3,x=1,y=1': missing field 'evidence'");
}

// Hostile input (found by fuzz/mission_mail): an empty header part has no key=value pair at all; it
// used to throw std::out_of_range out of the parser (and terminate pHazardMgr).
TEST(Handover, EmptyHeaderPartsAreErrorsNotExceptions) {
  EXPECT_EQ(parse_handover("##").error, "HAZARD_HANDOVER first part '' is not source=<vehicle>");
  EXPECT_EQ(parse_handover("#dest=b#prior=0.5").error,
            "HAZARD_HANDOVER first part '' is not source=<vehicle>");
  EXPECT_EQ(parse_handover("source=a##prior=0.5").error,
            "HAZARD_HANDOVER second part '' is not dest=<vehicle>");
  EXPECT_EQ(parse_handover("source=a#dest=b# #label=1").error,
            "HAZARD_HANDOVER part '' is not prior=<p> with p in (0, 1)");
}

}  // namespace
}  // namespace mission
