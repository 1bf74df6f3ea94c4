// UHZ_SENSOR_CLEAR: parser and formatter.
#include <gtest/gtest.h>

#include "hazard/messages/sensor_clear.hpp"

namespace hazard {
namespace {

TEST(RequestMessages, SensorClear) {
  EXPECT_EQ(parse_sensor_clear(format_sensor_clear({"archie"})).value->vname, "archie");
  EXPECT_FALSE(parse_sensor_clear(""));
}

}  // namespace
}  // namespace hazard
