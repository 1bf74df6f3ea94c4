// Physically meaningful ranges (ranges.hpp): configuration values and mail fields
// beyond them are refused with a warning naming the value; the boundary itself is accepted.
#include <gtest/gtest.h>

#include <string>

#include "hazard/messages/classify_request.hpp"
#include "hazard/messages/config_request.hpp"
#include "hazard/messages/node_report.hpp"
#include "hazard/messages/sensor_request.hpp"
#include "hazard/ranges.hpp"
#include "hazard/sensor_options.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::quiet_block;

std::string error_of(std::string_view node_report) { return parse_node_report(node_report).error; }

TEST(Ranges, NodeReportSpeedMustLieInZeroToTheBound) {
  EXPECT_EQ(error_of("NAME=a,X=0,Y=0,SPD=-1.5,HDG=0"),
            "field 'SPD' value '-1.5' is outside [0, 1000] m/s");
  EXPECT_EQ(error_of("NAME=a,X=0,Y=0,SPEED=1e300,HDG=0"),
            "field 'SPD' value '1e300' is outside [0, 1000] m/s");
  EXPECT_TRUE(parse_node_report("NAME=a,X=0,Y=0,SPD=1000,HDG=0"));
  EXPECT_TRUE(parse_node_report("NAME=a,X=0,Y=0,SPD=0,HDG=0"));
}

TEST(Ranges, NodeReportPositionWithinTheBound) {
  EXPECT_EQ(error_of("NAME=a,X=9e307,Y=0,SPD=1,HDG=0"),
            "field 'X' value '9e307', field 'Y' value '0': beyond 100000000 m from the origin "
            "(kMaxNodeCoordinate_m)");
  EXPECT_FALSE(parse_node_report("NAME=a,X=0,Y=-100000001,SPD=1,HDG=0"));
  EXPECT_TRUE(parse_node_report("NAME=a,X=-100000000,Y=100000000,SPD=1,HDG=0"));
  EXPECT_NE(error_of("NAME=a,X=0,Y=0,SPD=1,HDG=nan").find("not a finite number"),
            std::string::npos);
}

TEST(Ranges, VehicleNamesAreBoundedAndFreeOfControlBytes) {
  EXPECT_EQ(error_of(std::string("NAME=a\nforged,X=0,Y=0,SPD=1,HDG=0")),
            "field 'NAME' value 'a\\x0Aforged' contains a control byte");
  EXPECT_FALSE(parse_sensor_request(std::string("vname=a\0b", 9)));
  EXPECT_FALSE(parse_config_request("vname=a\x1b[2J,pd=0.5"));
  EXPECT_FALSE(parse_classify_request("vname=a\x7f,label=A"));
  const std::string longest(kMaxVehicleNameBytes, 'n');
  EXPECT_TRUE(parse_sensor_request("vname=" + longest));
  EXPECT_NE(parse_sensor_request("vname=" + longest + "n").error.find("longer than 128 bytes"),
            std::string::npos);
}

TEST(Ranges, WidthsAboveTheBoundAreRefusedInConfigurationAndRequests) {
  EXPECT_EQ(parse_sensor_config("width=1e308,exp=2,pclass=0.8").error,
            "field 'width' value '1e308' is above 1000000 m (kMaxSwathWidth_m)");
  EXPECT_FALSE(parse_sensor_config("width=1e6,exp=2,pclass=0.8").error.size());
  EXPECT_EQ(parse_config_request("vname=v,width=1e308,pd=0.5").error,
            "field 'width' value '1e308' is above 1000000 m (kMaxSwathWidth_m)");
  EXPECT_TRUE(parse_config_request("vname=v,width=1e6,pd=0.5"));
}

// Through the engine: a refused value changes nothing and is one warning naming it.
TEST(Ranges, RefusedMailChangesNothing) {
  testing::Driver d(quiet_block("sensor_config = width=1e308, exp=2, pclass=0.8\n"));
  EXPECT_TRUE(contains(d.all.config_warnings, "'1e308' is above 1000000 m"));
  d.pose("v", 1, 2, 0, 1);
  const Outputs out = d.pose("v", 50, 60, 0, -3);
  EXPECT_TRUE(contains(out.run_warnings, "NODE_REPORT"));
  EXPECT_TRUE(contains(out.run_warnings, "value '-3' is outside [0, 1000] m/s"));
  EXPECT_EQ(d.vehicle("v").pose->position_m.x, 1.0);
  EXPECT_EQ(d.vehicle("v").pose->speed_mps, 1.0);
}

}  // namespace
}  // namespace hazard
