// UHZ_SENSOR_REQUEST: parser and formatter.
#include <gtest/gtest.h>

#include "hazard/messages/sensor_request.hpp"

namespace hazard {
namespace {

TEST(RequestMessages, SensorRequest) {
  EXPECT_EQ(parse_sensor_request("vname=archie").value->vname, "archie");
  EXPECT_EQ(format_sensor_request({"archie"}), "vname=archie");
  EXPECT_EQ(parse_sensor_request("vname=").error, "missing field 'vname'");
  EXPECT_EQ(parse_sensor_request("name=archie").error, "missing field 'vname'");
}

}  // namespace
}  // namespace hazard
