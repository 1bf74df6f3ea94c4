// UHZ_DETECTION_REPORT: the variants of D24.
#include <gtest/gtest.h>

#include "hazard/messages/detection_report.hpp"
#include "hazard/messages/hazard_report.hpp"

namespace hazard {
namespace {

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

// The engine formats a report once and derives the general variant with with_vname: it must be
// exactly what the format functions write with vname set, for both report kinds.
TEST(ReportMessages, WithVnameIsTheGeneralVariant) {
  DetectionReport d{std::nullopt, -293.60001, 12.5, "obj_17", 57.0, 20.0, 45.0};
  const std::string vehicle = format_detection_report(d);
  d.vname = "archie";
  EXPECT_EQ(with_vname("archie", vehicle), format_detection_report(d));
  HazardReport h{std::nullopt, 1.0, -2.0, "75", ObjectType::kHazard, {}, {}, {}};
  const std::string for_vehicle = format_hazard_report(h);
  h.vname = "a_long_vehicle_name_past_small_strings";
  EXPECT_EQ(with_vname(*h.vname, for_vehicle), format_hazard_report(h));
}

}  // namespace
}  // namespace hazard
