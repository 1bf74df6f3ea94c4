// UHZ_CONFIG_REQUEST: the forms of manual 4.4 and the rejections of differences.md "Settings".
#include <gtest/gtest.h>

#include "hazard/messages/config_request.hpp"

namespace hazard {
namespace {

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

}  // namespace
}  // namespace hazard
