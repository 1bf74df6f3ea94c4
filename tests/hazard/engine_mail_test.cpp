// Mail at the edge: malformed mail warns and changes nothing else; start-up and PMV_CONNECT
// visuals; the options summary; the interface lists (docs/messages.md; differences.md "Visuals",
// D21).
#include <gtest/gtest.h>

#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::Driver;
using testing::quiet_block;
using testing::values_of;

const std::string kField = quiet_block(
    "min_classify_interval = 5\n"
    "hazard = x=0,y=0,label=A,type=hazard\nhazard = x=2,y=0,label=B,type=benign,hr=0.4\n"
    "hazard = x=-2,y=3,label=C,type=benign\n");

// A scenario of good mail; `bad` is delivered between each good message.
std::vector<Posting> run(const std::vector<std::pair<std::string, std::string>>& bad,
                         std::vector<std::string>* warnings = nullptr) {
  Driver d(kField, {}, 8);
  const std::vector<std::pair<std::string, std::string>> good = {
      {"UHZ_SENSOR_REQUEST", "vname=v"},
      {"UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=0.95"},
      {"NODE_REPORT", testing::node_report("v", 0, -50, 0)},
      {"NODE_REPORT", testing::node_report("v", 0, 0, 0)},
      {"UHZ_CLASSIFY_REQUEST", "vname=v,label=A"},
      {"UHZ_CLASSIFY_REQUEST", "vname=v,label=B"},
      {"NODE_REPORT", testing::node_report("v", 0, 50, 0)},
  };
  for (const auto& [var, value] : good) {
    for (const auto& [bvar, bvalue] : bad) {
      const Outputs out = d.mail(bvar, bvalue);
      EXPECT_TRUE(out.postings.empty()) << bvar << " " << bvalue.substr(0, 60);
      if (warnings) {
        warnings->insert(warnings->end(), out.run_warnings.begin(), out.run_warnings.end());
      }
    }
    d.mail(var, value);
    d.tick_at(d.now + 1);
  }
  for (int i = 0; i < 20; ++i) d.tick_at(d.now + 1);
  return d.all.postings;
}

TEST(EngineMail, MalformedMailWarnsAndChangesNothingElse) {
  const std::string huge = "NAME=v,X=" + std::string(1 << 20, '1') + ",Y=0,SPD=1,HDG=0";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"UHZ_SENSOR_REQUEST", "name=v"},                          // missing vname
      {"UHZ_CONFIG_REQUEST", "width=10,pd=0.5"},                  // missing vname
      {"UHZ_CONFIG_REQUEST", "vname=v,width=10,pd=NaN"},          // NaN
      {"UHZ_CONFIG_REQUEST", "vname=v,width=1e999,pd=0.5"},       // 1e999
      {"NODE_REPORT", "NAME=v,X=nan,Y=0,SPD=1,HDG=0"},
      {"NODE_REPORT", "NAME=v,X=1,Y=1e999,SPD=1,HDG=0"},
      {"NODE_REPORT", huge},                                      // a 1 MB value
      {"UHZ_CLASSIFY_REQUEST", "vname=v,label=NOPE"},             // unknown label
      {"UHZ_CLASSIFY_REQUEST", "label=A"},                        // missing vname
      {"UHZ_CLASSIFY_REQUEST", "vname=v,label=A,priority=inf"},
      {"UHZ_SENSOR_CLEAR", "vname="},
      {"SOME_OTHER_VARIABLE", "vname=v"},                          // not ours: ignored
  };
  std::vector<std::string> warnings;
  const auto with_bad = run(bad, &warnings);
  const auto clean = run({});
  ASSERT_EQ(with_bad.size(), clean.size());
  for (std::size_t i = 0; i < clean.size(); ++i) {
    EXPECT_EQ(with_bad[i].variable, clean[i].variable) << i;
    EXPECT_EQ(with_bad[i].value, clean[i].value) << i;
  }
  EXPECT_GT(values_of(Outputs{clean, {}, {}, {}, {}}, "UHZ_HAZARD_REPORT").size(), 0u);
  EXPECT_TRUE(contains(warnings, "UHZ_SENSOR_REQUEST: missing field 'vname'; ignored: 'name=v'"));
  EXPECT_TRUE(
      contains(warnings, "UHZ_CONFIG_REQUEST: field 'pd' value 'NaN' is not a finite number"));
  EXPECT_TRUE(contains(warnings, "UHZ_CONFIG_REQUEST: field 'width' value '1e999'"));
  EXPECT_TRUE(contains(warnings, "NODE_REPORT: field 'X' value 'nan'"));
  EXPECT_TRUE(contains(warnings, "NODE_REPORT: value of " + std::to_string(huge.size()) +
                                     " bytes exceeds 65536; ignored"));
  EXPECT_TRUE(contains(warnings, "v classify request for unknown label: NOPE"));
  EXPECT_TRUE(contains(warnings, "UHZ_CLASSIFY_REQUEST: field 'priority' value 'inf'"));
  EXPECT_TRUE(contains(warnings, "UHZ_SENSOR_CLEAR: missing field 'vname'"));
  for (const auto& w : warnings) EXPECT_LT(w.size(), 400u) << "huge values are cut";
}

TEST(EngineMail, LatLonOnlyNodeReportIsAWarningOnly_T9) {
  Driver d(kField);
  const Outputs bad = d.mail("NODE_REPORT", "NAME=archie,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90");
  EXPECT_TRUE(bad.postings.empty());  // no UHZ_DEBUG (differences.md "No debug postings")
  ASSERT_EQ(bad.run_warnings.size(), 1u);
  EXPECT_EQ(bad.run_warnings[0],
            "NODE_REPORT: LAT/LON without X/Y cannot be placed (the mission file gives no "
            "LatOrigin and LongOrigin); ignored: "
            "'NAME=archie,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90'");
  EXPECT_FALSE(d.engine.find_vehicle("archie"));
  const Outputs good =
      d.mail("NODE_REPORT", "NAME=archie,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=123");
  EXPECT_TRUE(good.empty());
  ASSERT_TRUE(d.vehicle("archie").pose);
  EXPECT_EQ(d.vehicle("archie").pose->position_m, glm::dvec2(10, -5));
  EXPECT_EQ(d.vehicle("archie").pose->heading_deg, 90);
}

TEST(EngineMail, UnknownVariablesAreIgnoredSilently) {
  Driver d(kField);
  const Outputs out = d.mail("APPCAST_REQ", "node=all,app=all,duration=3,key=x,thresh=any");
  EXPECT_TRUE(out.empty());
}

TEST(EngineMail, StartUpPostsMarkersAndAspectAxes_Spec5_4_Visuals) {
  Driver d("sensor_config = width=25, exp=4, pclass=0.8\n"
           "default_benign_shape = square\n"
           "hazard = x=-52,y=-290,label=75,type=hazard\n"
           "hazard = x=-41,y=-246,label=82,type=benign\n"
           "hazard = x=1,y=2,label=h,type=benign,hr=0.73,color=orange,shape=diamond,width=3\n"
           "hazard = x=37,y=-207,label=99,type=benign,aspect=90,aspect_min=20,aspect_max=45\n"
           "hazard = x=0,y=0,label=z,type=hazard,aspect=0\n");
  const auto markers = values_of(d.all, "VIEW_MARKER");
  ASSERT_EQ(markers.size(), 5u);
  EXPECT_EQ(markers[0], "x=-52,y=-290,width=8,primary_color=green,type=triangle,label=75");
  EXPECT_EQ(markers[1],
            "x=-41,y=-246,width=8,primary_color=light_blue,type=square,label=82,"
            "fill_transparency=0.5");
  EXPECT_EQ(markers[2],
            "x=1,y=2,width=3,primary_color=orange,type=diamond,label=h,fill_transparency=0.27");
  const auto axes = values_of(d.all, "VIEW_SEGLIST");
  ASSERT_EQ(axes.size(), 2u);  // aspect 0 is drawn too
  // length 5 + 25 * 32.5 / 90 = 14.03 along heading 90 and 270.
  EXPECT_EQ(axes[0], "pts={51,-207:23,-207},edge_color=gray70,vertex_size=0,edge_size=1");
  EXPECT_EQ(axes[1], "pts={0,15:0,-15},edge_color=gray70,vertex_size=0,edge_size=1");
  // PMV_CONNECT posts them again.
  EXPECT_EQ(values_of(d.mail("PMV_CONNECT", "x"), "VIEW_MARKER"), markers);
}

TEST(EngineMail, NoMarkersWhenShowHazardsIsFalse) {
  Driver d(kField);
  EXPECT_TRUE(values_of(d.all, "VIEW_MARKER").empty());
  EXPECT_TRUE(d.mail("PMV_CONNECT", "x").postings.empty());
}

TEST(EngineMail, OptionsSummaryFirstIterationThenEveryInterval_Manual4_5_D21) {
  Driver d("sensor_config = width=25, exp=4, pclass=0.80\n"
           "sensor_config = width=50, exp=2, pclass=0.60\n"
           "sensor_config = width=10, exp=6, pclass=0.93\n"
           "hazard = x=0,y=0,label=a,type=hazard\noptions_summary_interval = 5\n");
  std::vector<double> times;
  for (double t = 0; t <= 12; t += 0.5) {
    for (const auto& v : values_of(d.tick_at(t), "UHZ_OPTIONS_SUMMARY")) {
      EXPECT_EQ(v, "width=25,exp=4,pclass=0.80:width=50,exp=2,pclass=0.60:width=10,exp=6,"
                   "pclass=0.93");
      times.push_back(t);
    }
  }
  EXPECT_EQ(times, (std::vector<double>{0, 5, 10}));
}

TEST(EngineMail, ClockStartingAtZeroBehavesLikeAnEpochClock_N11) {
  Driver d(quiet_block("hazard = x=0,y=0,label=a,type=hazard\nmin_reset_interval = 300\n"), {}, 1,
           0.0);
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=0.9");  // first width request at t = 0
  EXPECT_EQ(values_of(d.all, "UHZ_CONFIG_ACK").size(), 1u);
  EXPECT_FALSE(contains(d.all.events, "denied"));
  EXPECT_EQ(values_of(d.tick(), "UHZ_OPTIONS_SUMMARY").size(), 1u);
}

TEST(EngineMail, InterfaceListsIncludeSensorClear_D10) {
  bool clear = false;
  for (const auto& v : Engine::subscriptions()) clear = clear || v.name == "UHZ_SENSOR_CLEAR";
  EXPECT_TRUE(clear);
  EXPECT_EQ(Engine::publications().size(), 11u);
  for (const auto& v : Engine::publications()) EXPECT_FALSE(v.example.empty()) << v.name;
}

}  // namespace
}  // namespace hazard
