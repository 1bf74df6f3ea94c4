// UHZ_HAZARD_REPORT: the variants of D25.
#include <gtest/gtest.h>

#include "hazard/messages/hazard_report.hpp"

namespace hazard {
namespace {

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

}  // namespace
}  // namespace hazard
