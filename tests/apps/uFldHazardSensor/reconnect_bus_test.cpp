// uFldHazardSensor when its database connection is lost and made again, on the
// in-process bus: the field's visuals are posted again after every reconnect, never twice to
// the connection start-up served, and the engine's state is kept. The same with real processes
// and a killed moosdb-lite: fault_process_test.cpp.
#include <gtest/gtest.h>

#include "sensor_on_bus.hpp"

namespace ufld_hazard_sensor {
namespace {

using testing::SensorOnBus;

constexpr double kTick_s = 0.25;  // AppTick 4

// Two objects, one with an aspect (a VIEW_SEGLIST too), and two widths: the default (first)
// 20 m and the 10 m alpha asks for.
std::string block(bool show_hazards) {
  return std::string("  AppTick = 4\n  min_reset_interval = 0\n") +
         "  show_hazards = " + (show_hazards ? "true" : "false") + "\n"
         "  sensor_config = width=20, exp=2, pclass=1.0\n"
         "  sensor_config = width=10, exp=4, pclass=0.90\n"
         "  hazard = x=5,y=31,label=h1,type=hazard\n"
         "  hazard = x=40,y=0,label=a1,type=benign,aspect=0,aspect_min=20,aspect_max=70\n";
}

class SensorReconnect : public SensorOnBus {
 protected:
  /// The connection is lost for a second, then made again, and the app cycles once more.
  void lose_and_restore_connection() {
    comms->simulate_disconnect();
    run_for(1.0);
    ASSERT_TRUE(comms->simulate_reconnect());
    run_for(kTick_s);
  }
};

TEST_F(SensorReconnect, EveryReconnectPostsTheFieldsVisualsAgain_Hardening) {
  start(block(true));
  run_for(1.0);
  const auto markers = values_of("VIEW_MARKER");
  const auto seglists = values_of("VIEW_SEGLIST");
  ASSERT_EQ(markers.size(), 2u);  // start-up only: its own connection gets nothing twice
  ASSERT_EQ(seglists.size(), 1u);

  lose_and_restore_connection();
  auto again = values_of("VIEW_MARKER");
  ASSERT_EQ(again.size(), 4u);
  EXPECT_EQ(std::vector<std::string>(again.begin() + 2, again.end()), markers);
  EXPECT_EQ(values_of("VIEW_SEGLIST").size(), 2u);
  EXPECT_EQ(values_of("VIEW_SEGLIST").back(), seglists.front());

  lose_and_restore_connection();
  EXPECT_EQ(values_of("VIEW_MARKER").size(), 6u);
  run_for(2.0);
  EXPECT_EQ(values_of("VIEW_MARKER").size(), 6u);  // once per reconnect, not per iteration
}

TEST_F(SensorReconnect, WithoutShowHazardsAReconnectPostsNoMarkers_Hardening) {
  start(block(false));
  run_for(1.0);
  lose_and_restore_connection();
  EXPECT_TRUE(values_of("VIEW_MARKER").empty());
  EXPECT_TRUE(values_of("VIEW_SEGLIST").empty());
}

TEST_F(SensorReconnect, AReconnectKeepsTheVehiclesSettings_Hardening) {
  start(block(true));
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=10,pd=0.9");
  run_for(kTick_s);
  const std::string ack = "vname=alpha,width=10,pd=0.9,pfa=0.656,pclass=0.9";
  ASSERT_EQ(values_of("UHZ_CONFIG_ACK_ALPHA"), std::vector<std::string>{ack});
  lose_and_restore_connection();
  // The database (the same one here) answers the re-sent registration with the variable's
  // last value, as a MOOSDB does: the same request once more, and the same ack.
  ASSERT_EQ(values_of("UHZ_CONFIG_ACK_ALPHA"), (std::vector<std::string>{ack, ack}));
  // A pd-only request keeps the width: 10 m, as set before the reconnect (a new engine would
  // give the default, 20 m). pfa = 0.8^4 = 0.4096.
  post("UHZ_CONFIG_REQUEST", "vname=alpha,pd=0.8");
  run_for(kTick_s);
  EXPECT_EQ(values_of("UHZ_CONFIG_ACK_ALPHA").back(),
            "vname=alpha,width=10,pd=0.8,pfa=0.41,pclass=0.9");
  EXPECT_TRUE(engine().invariant_violations().empty());
}

}  // namespace
}  // namespace ufld_hazard_sensor
