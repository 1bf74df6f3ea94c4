// One parser and one formatter per message; round trips keep each pair in sync (style 10).
#include <gtest/gtest.h>

#include "hazard/messages/classify_request.hpp"
#include "hazard/messages/config_ack.hpp"
#include "hazard/messages/config_request.hpp"
#include "hazard/messages/detection_report.hpp"
#include "hazard/messages/hazard_report.hpp"
#include "hazard/messages/node_report.hpp"
#include "hazard/messages/sensor_clear.hpp"
#include "hazard/messages/sensor_request.hpp"
#include "hazard/messages/view_circle.hpp"
#include "hazard/messages/view_marker.hpp"
#include "hazard/messages/view_polygon.hpp"
#include "hazard/messages/view_seglist.hpp"

namespace hazard {
namespace {

TEST(NodeReportMessage, ValidReportOfT9) {
  const auto p =
      parse_node_report("NAME=archie,X=10,Y=-5,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90,TIME=123");
  ASSERT_TRUE(p) << p.error;
  EXPECT_EQ(p.value->name, "archie");
  EXPECT_EQ(p.value->x_m, 10);
  EXPECT_EQ(p.value->y_m, -5);
  EXPECT_EQ(p.value->speed_mps, 1.5);
  EXPECT_EQ(p.value->heading_deg, 90);
  EXPECT_EQ(p.value->lat_deg, 43.8);
  EXPECT_EQ(p.value->time_s, 123);
}

TEST(NodeReportMessage, LatLonOnlyIsInvalid_T9) {
  const auto p = parse_node_report("NAME=archie,LAT=43.8,LON=-70.3,SPD=1.5,HDG=90");
  EXPECT_FALSE(p);
  EXPECT_NE(p.error.find("LAT/LON"), std::string::npos);
}

TEST(NodeReportMessage, KeysAnyCaseAliasesBracesAndHeadingNormalised) {
  const auto p = parse_node_report(
      "name=b,x=1,y=2,speed=3,heading=-90,MODE={A,B},COLOR=red,LENGTH=4");
  ASSERT_TRUE(p) << p.error;
  EXPECT_EQ(p.value->speed_mps, 3);
  EXPECT_EQ(p.value->heading_deg, 270);
}

TEST(NodeReportMessage, MalformedFieldsAreNamed) {
  EXPECT_EQ(parse_node_report("X=1,Y=2,SPD=1,HDG=0").error, "missing field 'NAME'");
  EXPECT_EQ(parse_node_report("NAME=a,Y=2,SPD=1,HDG=0").error, "missing field 'X'");
  EXPECT_EQ(parse_node_report("NAME=a,X=1,Y=2,HDG=0").error, "missing field 'SPD'");
  EXPECT_EQ(parse_node_report("NAME=a,X=1,Y=2,SPD=1").error, "missing field 'HDG'");
  EXPECT_EQ(parse_node_report("NAME=a,X=nan,Y=2,SPD=1,HDG=0").error,
            "field 'X' value 'nan' is not a finite number");
  EXPECT_EQ(parse_node_report("NAME=a,X=1,Y=1e999,SPD=1,HDG=0").error,
            "field 'Y' value '1e999' is not a finite number");
  EXPECT_EQ(parse_node_report("NAME=a,X=1,Y=2,SPD=fast,HDG=0").error,
            "field 'SPD' value 'fast' is not a finite number");
}

TEST(NodeReportMessage, RoundTrip) {
  NodeReport r;
  r.name = "betty";
  r.x_m = -12.25;
  r.y_m = 300.5;
  r.speed_mps = 1.2;
  r.heading_deg = 271.5;
  r.lat_deg = 43.82537;
  r.lon_deg = -70.33034;
  r.time_s = 1234.5;
  r.type = "kayak";
  const std::string text = format_node_report(r);
  EXPECT_EQ(text, "NAME=betty,X=-12.25,Y=300.5,SPD=1.2,HDG=271.5,LAT=43.82537,LON=-70.33034,"
                  "TIME=1234.5,TYPE=kayak");
  const auto back = parse_node_report(text);
  ASSERT_TRUE(back);
  EXPECT_EQ(format_node_report(*back.value), text);
}

TEST(RequestMessages, SensorRequestAndClear) {
  EXPECT_EQ(parse_sensor_request("vname=archie").value->vname, "archie");
  EXPECT_EQ(format_sensor_request({"archie"}), "vname=archie");
  EXPECT_EQ(parse_sensor_request("vname=").error, "missing field 'vname'");
  EXPECT_EQ(parse_sensor_request("name=archie").error, "missing field 'vname'");
  EXPECT_EQ(parse_sensor_clear(format_sensor_clear({"archie"})).value->vname, "archie");
  EXPECT_FALSE(parse_sensor_clear(""));
}

TEST(RequestMessages, ConfigRequestForms_Manual4_4) {
  const auto full = parse_config_request("vname=archie, width=32, pd=0.95");
  ASSERT_TRUE(full);
  EXPECT_EQ(full.value->width_m, 32);
  EXPECT_EQ(full.value->pd, 0.95);
  const auto pd_only = parse_config_request("vname=archie, pd=0.75");
  ASSERT_TRUE(pd_only);
  EXPECT_FALSE(pd_only.value->width_m);
  const auto empty_width = parse_config_request("vname=archie,width=,pd=0.75");
  ASSERT_TRUE(empty_width);
  EXPECT_FALSE(empty_width.value->width_m);
  const auto width_only = parse_config_request("vname=archie,width=25");
  ASSERT_TRUE(width_only);
  EXPECT_FALSE(width_only.value->pd);
  EXPECT_EQ(format_config_request(*full.value), "vname=archie,width=32,pd=0.95");
  EXPECT_EQ(format_config_request(*pd_only.value), "vname=archie,pd=0.75");
}

TEST(RequestMessages, ConfigRequestRejections_Rulings) {
  EXPECT_EQ(parse_config_request("width=25,pd=0.9").error, "missing field 'vname'");
  EXPECT_EQ(parse_config_request("vname=a,pd=1.2").error,
            "field 'pd' value '1.2' is outside [0, 1]");
  EXPECT_EQ(parse_config_request("vname=a,width=-5,pd=0.9").error,
            "field 'width' value '-5' is not > 0");
  EXPECT_EQ(parse_config_request("vname=a,width=0").error, "field 'width' value '0' is not > 0");
  EXPECT_EQ(parse_config_request("vname=a,pd=NaN").error,
            "field 'pd' value 'NaN' is not a finite number");
  EXPECT_EQ(parse_config_request("vname=a").error, "neither 'width' nor 'pd' given");
}

TEST(RequestMessages, ClassifyRequestForms_Manual3_2) {
  const auto plain = parse_classify_request("vname=archie,label=152");
  ASSERT_TRUE(plain);
  EXPECT_FALSE(plain.value->priority);
  EXPECT_EQ(plain.value->action, ClassifyAction::kNormal);
  const auto top = parse_classify_request("vname=archie,label=152,priority=100,action=top");
  ASSERT_TRUE(top);
  EXPECT_EQ(top.value->priority, 100);
  EXPECT_EQ(top.value->action, ClassifyAction::kTop);
  const auto clear = parse_classify_request("vname=archie,action=clear");
  ASSERT_TRUE(clear);
  EXPECT_EQ(clear.value->action, ClassifyAction::kClear);
  for (const auto* text : {"vname=archie,label=152", "vname=archie,label=152,priority=95",
                           "vname=archie,label=152,priority=100,action=top",
                           "vname=archie,action=clear"}) {
    EXPECT_EQ(format_classify_request(*parse_classify_request(text).value), text);
  }
}

TEST(RequestMessages, ClassifyRequestRejections) {
  EXPECT_EQ(parse_classify_request("label=1").error, "missing field 'vname'");
  EXPECT_EQ(parse_classify_request("vname=a").error, "missing field 'label'");
  EXPECT_EQ(parse_classify_request("vname=a,label=1,priority=high").error,
            "field 'priority' value 'high' is not a finite number");
  EXPECT_EQ(parse_classify_request("vname=a,label=1,action=bottom").error,
            "field 'action' value 'bottom' is neither 'top' nor 'clear'");
}

TEST(AckMessage, FormatOfD22AndStrictParse) {
  const ConfigAck ack{"archie", 25, 0.9, 0.6561, 0.8};
  EXPECT_EQ(format_config_ack(ack), "vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.8");
  const auto back = parse_config_ack(format_config_ack(ack));
  ASSERT_TRUE(back);
  EXPECT_EQ(back.value->vname, "archie");
  EXPECT_EQ(back.value->pfa, 0.656);
  EXPECT_EQ(parse_config_ack("width=25,pd=0.9,pfa=0.656,pclass=0.8").error,
            "missing field 'vname'");  // D22: the manager needs vname
  EXPECT_EQ(parse_config_ack("vname=a,width=25,pd=0.9,pfa=0.656,pclass=0.8,extra=1").error,
            "unexpected key 'extra'");
  EXPECT_EQ(parse_config_ack("vname=a,width=25,pd=0.9,pclass=0.8").error, "missing field 'pfa'");
}

TEST(ReportMessages, DetectionReportVariants_D24) {
  DetectionReport r{std::string("archie"), -52, -290, "75", {}, {}, {}};
  EXPECT_EQ(format_detection_report(r), "vname=archie,x=-52,y=-290,label=75");
  r.vname.reset();
  EXPECT_EQ(format_detection_report(r), "x=-52,y=-290,label=75");
  r.aspect_deg = 57;
  r.aspect_min_deg = 20;
  r.aspect_max_deg = 45;
  r.x_m = -293.60001;
  const std::string text = format_detection_report(r);
  EXPECT_EQ(text, "x=-293.6,y=-290,label=75,aspect=57,aspect_min=20,aspect_max=45");
  const auto back = parse_detection_report("vname=archie," + text);
  ASSERT_TRUE(back);
  EXPECT_EQ(back.value->vname, "archie");
  EXPECT_EQ(back.value->aspect_max_deg, 45);
  EXPECT_EQ(format_detection_report(*back.value), "vname=archie," + text);
  EXPECT_FALSE(parse_detection_report("x=1,y=2"));
  EXPECT_FALSE(parse_detection_report("x=1,label=2"));
}

TEST(ReportMessages, HazardReportVariants_D25) {
  HazardReport r{std::string("archie"), -52, -290, "75", ObjectType::kHazard, {}, {}, {}};
  EXPECT_EQ(format_hazard_report(r), "vname=archie,x=-52,y=-290,label=75,type=hazard");
  r.vname.reset();
  r.type = ObjectType::kBenign;
  EXPECT_EQ(format_hazard_report(r), "x=-52,y=-290,label=75,type=benign");
  const auto back = parse_hazard_report("x=-52,y=-290,label=75,type=benign,aspect=3");
  ASSERT_TRUE(back);
  EXPECT_EQ(back.value->type, ObjectType::kBenign);
  EXPECT_EQ(back.value->aspect_deg, 3);
  EXPECT_FALSE(parse_hazard_report("x=1,y=2,label=3"));
  EXPECT_FALSE(parse_hazard_report("x=1,y=2,label=3,type=inert"));
}

TEST(VisualMessages, PolygonRoundTrip) {
  const std::string text =
      "pts={25,2.5:25,-2.5:-25,-2.5:-25,2.5},label=sensor_swath_archie,msg=0.90/0.66,"
      "edge_color=green,fill_color=white,vertex_size=0,edge_size=0,fill_transparency=0.2";
  const auto p = parse_view_polygon(text);
  ASSERT_TRUE(p) << p.error;
  EXPECT_EQ(p.value->points.size(), 4u);
  EXPECT_EQ(format_view_polygon(*p.value), text);
  EXPECT_FALSE(parse_view_polygon("label=x"));
  EXPECT_FALSE(parse_view_polygon("pts={1,2:x,4}"));
}

TEST(VisualMessages, CircleRoundTrip) {
  for (const std::string text :
       {"x=-52,y=-290,radius=10,vertices=12,duration=60,edge_color=white,fill_color=white,"
        "time=12.5,vertex_size=0,edge_size=1,fill_transparency=0.3",
        "x=1,y=2,radius=10,vertices=5,edge_color=yellow,fill_color=pink,time=40,vertex_size=0,"
        "edge_size=2,fill_transparency=0.5"}) {
    const auto c = parse_view_circle(text);
    ASSERT_TRUE(c) << c.error;
    EXPECT_EQ(format_view_circle(*c.value), text);
  }
  EXPECT_FALSE(parse_view_circle("y=1,radius=3"));
}

TEST(VisualMessages, MarkerAndSeglistRoundTrip) {
  for (const std::string text :
       {"x=-52,y=-290,width=8,primary_color=green,type=triangle,label=75",
        "x=-41,y=-246,width=8,primary_color=light_blue,type=triangle,label=82,"
        "fill_transparency=0.5"}) {
    const auto m = parse_view_marker(text);
    ASSERT_TRUE(m) << m.error;
    EXPECT_EQ(format_view_marker(*m.value), text);
  }
  const std::string seg = "pts={37,-192:37,-222},edge_color=gray70,vertex_size=0,edge_size=1";
  const auto s = parse_view_seglist(seg);
  ASSERT_TRUE(s) << s.error;
  EXPECT_EQ(format_view_seglist(*s.value), seg);
}

}  // namespace
}  // namespace hazard
