// UHZ_OPTIONS_SUMMARY: the summary of the configured options in configuration order (D21, T3),
// its parser and formatter.
#include <gtest/gtest.h>

#include "hazard/messages/options_summary.hpp"
#include "hazard/sensor_options.hpp"

namespace hazard {
namespace {

TEST(OptionsSummary, ManualBareBonesBlockInConfigOrder_D21_T3) {
  SensorOptions t;
  for (const char* line : {"width=25, exp=4, pclass=0.80", "width=50, exp=2, pclass=0.60",
                           "width=10, exp=6, pclass=0.93"}) {
    const auto p = parse_sensor_config(line);
    ASSERT_TRUE(p.option);
    ASSERT_TRUE(t.add(*p.option));
  }
  EXPECT_EQ(format_options_summary(t.summary()),
            "width=25,exp=4,pclass=0.80:width=50,exp=2,pclass=0.60:width=10,exp=6,pclass=0.93");
}

TEST(OptionsSummary, MaxAppendedWhenPositiveAndRoundTrips_D21) {
  const std::string text = "width=25,exp=4,pclass=0.85:width=10,exp=6,pclass=0.93,max=1";
  const auto p = parse_options_summary(text);
  ASSERT_TRUE(p) << p.error;
  ASSERT_EQ(p.value->options.size(), 2u);
  EXPECT_EQ(p.value->options[1].max_vehicles, 1);
  EXPECT_EQ(format_options_summary(*p.value), text);
  const auto original = parse_options_summary("width=50,exp=2,class=0.55");  // original key
  ASSERT_TRUE(original);
  EXPECT_EQ(original.value->options[0].pclass, "0.55");
  EXPECT_TRUE(parse_options_summary("").value->options.empty());
  EXPECT_FALSE(parse_options_summary("width=5,exp=x,pclass=0.9"));
  EXPECT_FALSE(parse_options_summary("width=5,pclass=0.9"));
}

}  // namespace
}  // namespace hazard
