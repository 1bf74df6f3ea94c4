// Sensor settings per vehicle: requests, acks, default, reset window, max (manual 4;
// differences.md D3, D4, D11, D20, D22, D23, "Settings"; T2).
#include <gtest/gtest.h>

#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::Driver;
using testing::values_of;

// The original m10_jake options (D33): widths 5/10/25/50.
const std::string kJakeOriginal =
    "sensor_config = width=50, exp=2, pclass=0.55\n"
    "sensor_config = width=25, exp=4, pclass=0.63\n"
    "sensor_config = width=10, exp=6, pclass=0.70\n"
    "sensor_config = width=5, exp=8, pclass=0.88, max=1\n"
    "hazard = x=1000,y=1000,label=far,type=hazard\n"
    "show_swath = false\nshow_hazards = false\n";

const std::string kFiveOptions =
    "sensor_config = width=80, exp=2, pclass=0.60\n"
    "sensor_config = width=65, exp=4, pclass=0.75\n"
    "sensor_config = width=50, exp=6, pclass=0.85\n"
    "sensor_config = width=30, exp=12, pclass=0.93\n"
    "sensor_config = width=18, exp=20, pclass=0.97\n"
    "hazard = x=1000,y=1000,label=far,type=hazard\n";

TEST(EngineSettings, FirstSensedVehicleGetsDefaultWidthAndAck_D4_T2) {
  Driver d(kJakeOriginal);
  d.sensor_on("archie");
  d.pose("archie", 0, 0);
  const Outputs out = d.tick();
  EXPECT_EQ(values_of(out, "UHZ_CONFIG_ACK"),
            std::vector<std::string>{"vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.63"});
  EXPECT_EQ(values_of(out, "UHZ_CONFIG_ACK_ARCHIE"),
            std::vector<std::string>{"vname=archie,width=25,pd=0.9,pfa=0.656,pclass=0.63"});
  // Not before both a sensor request and a node report exist (differences.md "Automatic default").
  Driver e(kJakeOriginal);
  e.pose("betty", 0, 0);
  EXPECT_TRUE(values_of(e.tick(), "UHZ_CONFIG_ACK").empty());
  e.sensor_on("carl");
  EXPECT_TRUE(values_of(e.tick(), "UHZ_CONFIG_ACK").empty());
}

TEST(EngineSettings, DefaultOfFiveOptionsIsThirty_D4_T2) {
  Driver d(kFiveOptions);
  d.sensor_on("archie");
  d.pose("archie", 0, 0);
  EXPECT_EQ(values_of(d.tick(), "UHZ_CONFIG_ACK_ARCHIE"),
            std::vector<std::string>{"vname=archie,width=30,pd=0.9,pfa=0.282,pclass=0.93"});
}

TEST(EngineSettings, WidthRequestsAckComputedNumbers_T2_D23) {
  Driver d(kJakeOriginal);
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=50,pd=0.86");
  d.mail("UHZ_CONFIG_REQUEST", "vname=betty,width=10,pd=0.86");
  EXPECT_EQ(values_of(d.all, "UHZ_CONFIG_ACK_ARCHIE"),
            std::vector<std::string>{"vname=archie,width=50,pd=0.86,pfa=0.74,pclass=0.55"});
  EXPECT_EQ(values_of(d.all, "UHZ_CONFIG_ACK_BETTY"),
            std::vector<std::string>{"vname=betty,width=10,pd=0.86,pfa=0.405,pclass=0.7"});
  Driver f(kFiveOptions);
  f.mail("UHZ_CONFIG_REQUEST", "vname=archie, width=32, pd=0.95");  // the manual's example
  EXPECT_EQ(values_of(f.all, "UHZ_CONFIG_ACK"),
            std::vector<std::string>{"vname=archie,width=30,pd=0.95,pfa=0.54,pclass=0.93"});
}

TEST(EngineSettings, RequestBetweenOptionsPicksNextLower_D3) {
  Driver d(kFiveOptions);
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=45,pd=0.9");
  d.mail("UHZ_CONFIG_REQUEST", "vname=b,width=5,pd=0.9");
  d.mail("UHZ_CONFIG_REQUEST", "vname=c,width=500,pd=0.9");
  EXPECT_EQ(d.vehicle("a").setting->width_m, 30);
  EXPECT_EQ(d.vehicle("b").setting->width_m, 18);
  EXPECT_EQ(d.vehicle("c").setting->width_m, 80);
}

TEST(EngineSettings, WidthInsideResetWindowKeepsWidthAppliesPd_D11) {
  Driver d(kJakeOriginal + "min_reset_interval = 100\n");
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=50,pd=0.9");
  d.now = 50;
  const Outputs out = d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=10,pd=0.5");
  EXPECT_EQ(values_of(out, "UHZ_CONFIG_ACK"),
            std::vector<std::string>{"vname=archie,width=50,pd=0.5,pfa=0.25,pclass=0.55"});
  EXPECT_TRUE(contains(out.events, "Sensor reset denied (too soon) for vehicle: archie"));
  const VehicleCounters& c = d.vehicle("archie").counters;
  EXPECT_EQ(c.width_attempts, 2);
  EXPECT_EQ(c.width_resets, 1);
  EXPECT_EQ(c.pd_resets, 1);
  d.now = 100;  // the window has passed
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=10,pd=0.5");
  EXPECT_EQ(d.vehicle("archie").setting->width_m, 10);
  EXPECT_EQ(d.vehicle("archie").counters.width_resets, 2);
}

TEST(EngineSettings, PdOnlyUpdatesAreNeverRateLimited_D11) {
  Driver d(kJakeOriginal);
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=50,pd=0.9");
  for (double pd : {0.1, 0.2, 0.3}) {
    const Outputs out = d.mail("UHZ_CONFIG_REQUEST", "vname=archie,pd=" + base::fmt(pd));
    ASSERT_EQ(values_of(out, "UHZ_CONFIG_ACK").size(), 1u);
    EXPECT_EQ(d.vehicle("archie").setting->pd, pd);
  }
  EXPECT_EQ(d.vehicle("archie").counters.pd_resets, 3);
}

TEST(EngineSettings, DefaultDoesNotOpenTheResetWindow_D4) {
  Driver d(kJakeOriginal);  // min_reset_interval 300
  d.sensor_on("archie");
  d.pose("archie", 0, 0);
  d.tick();  // default 25
  d.now = 1;
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=50,pd=0.86");
  EXPECT_EQ(d.vehicle("archie").setting->width_m, 50);
  EXPECT_EQ(d.vehicle("archie").counters.width_resets, 2);  // the default counts
}

TEST(EngineSettings, UnchangedWidthIsAPdOnlyUpdate_Rulings) {
  Driver d(kJakeOriginal);
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=50,pd=0.9");
  d.now = 10;
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=60,pd=0.7");  // resolves to 50 again
  EXPECT_EQ(d.vehicle("archie").setting->pd, 0.7);
  EXPECT_FALSE(contains(d.all.events, "denied"));
  EXPECT_EQ(*d.vehicle("archie").width_window_start_s, 0);  // not restarted
}

TEST(EngineSettings, WidthWithoutPdKeepsPd_Rulings) {
  Driver d(kJakeOriginal + "min_reset_interval = 0\n");
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=25");
  EXPECT_EQ(d.vehicle("a").setting->pd, kDefaultPd);
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,pd=0.5");
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=50");
  EXPECT_EQ(d.vehicle("a").setting->width_m, 50);
  EXPECT_EQ(d.vehicle("a").setting->pd, 0.5);
}

TEST(EngineSettings, PdOnlyWithoutSettingGetsDefaultWidthInOneAck_Rulings) {
  Driver d(kJakeOriginal);
  const Outputs out = d.mail("UHZ_CONFIG_REQUEST", "vname=archie,pd=0.75");
  EXPECT_EQ(values_of(out, "UHZ_CONFIG_ACK"),
            std::vector<std::string>{"vname=archie,width=25,pd=0.75,pfa=0.316,pclass=0.63"});
  // ... and it did not open the window either.
  d.now = 1;
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=10,pd=0.75");
  EXPECT_EQ(d.vehicle("archie").setting->width_m, 10);
}

TEST(EngineSettings, FullWidthGivesNextLowerFree_D20) {
  Driver d(kJakeOriginal + "min_reset_interval = 0\n");
  d.sensor_on("a");
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=5,pd=0.9");
  d.sensor_on("b");
  d.mail("UHZ_CONFIG_REQUEST", "vname=b,width=5,pd=0.9");  // 5 is full (max=1), nothing lower
  EXPECT_EQ(d.vehicle("a").setting->width_m, 5);
  EXPECT_EQ(d.vehicle("b").setting->width_m, 10);          // next higher free
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=25,pd=0.9");  // a releases 5
  d.mail("UHZ_CONFIG_REQUEST", "vname=b,width=5,pd=0.9");
  EXPECT_EQ(d.vehicle("b").setting->width_m, 5);
}

TEST(EngineSettings, InactiveHoldersDoNotFillAWidth_D20) {
  Driver d(kJakeOriginal);
  d.sensor_on("a");
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=5,pd=0.9");
  d.now = kSensorActiveWindow_s;  // a's last sensor request is now 600 s old
  d.mail("UHZ_CONFIG_REQUEST", "vname=b,width=5,pd=0.9");
  EXPECT_EQ(d.vehicle("b").setting->width_m, 5);
}

// The held width (docs/differences.md D20): a max=1 width is held from the moment it is
// granted, before any sensor request, until kWidthHoldWindow_s pass with no configuration or
// sensor request from its holder. `max_width` carries max=1; the vehicles only send node reports.
struct HeldWidthRun {
  double b_width_m = 0.0;          // B asks for max_width one second after A got it
  double c_width_before_m = 0.0;   // C asks just before A's hold ends
  double d_width_m = 0.0;          // D asks when it has ended
};

HeldWidthRun held_width_run(const std::string& max_width) {
  std::string block;
  for (const char* w : {"5", "10", "25"}) {
    block += std::string("sensor_config = width=") + w + ", exp=4, pclass=0.8" +
             (w == max_width ? ", max=1" : "") + "\n";
  }
  Driver d(block + "hazard = x=1000,y=1000,label=far,type=hazard\nshow_swath = false\n"
                   "show_hazards = false\n");
  HeldWidthRun r;
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=" + max_width + ",pd=0.9");
  EXPECT_EQ(base::fmt(d.vehicle("a").setting->width_m), max_width);
  auto node_reports_until = [&](double t_s) {  // the vehicles move; none asks for the sensor
    for (; d.now < t_s; d.now += 1.0) {
      for (const char* v : {"a", "b", "c", "d"}) d.pose(v, 0, d.now);
      d.tick();
    }
    d.now = t_s;
  };
  node_reports_until(1.0);
  d.mail("UHZ_CONFIG_REQUEST", "vname=b,width=" + max_width + ",pd=0.9");
  r.b_width_m = d.vehicle("b").setting->width_m;
  node_reports_until(kWidthHoldWindow_s - 1.0);
  d.mail("UHZ_CONFIG_REQUEST", "vname=c,width=" + max_width + ",pd=0.9");
  r.c_width_before_m = d.vehicle("c").setting->width_m;
  node_reports_until(kWidthHoldWindow_s);  // 600 s with no configuration or sensor request from A
  d.mail("UHZ_CONFIG_REQUEST", "vname=d,width=" + max_width + ",pd=0.9");
  r.d_width_m = d.vehicle("d").setting->width_m;
  EXPECT_FALSE(d.vehicle("a").last_sensor_request_s);  // A never asked for its sensor
  return r;
}

TEST(EngineSettings, AGrantedMaxWidthIsHeldBeforeAnySensorRequest) {
  const HeldWidthRun r = held_width_run("25");
  EXPECT_EQ(r.b_width_m, 10);        // the next lower free width
  EXPECT_EQ(r.c_width_before_m, 10);
  EXPECT_EQ(r.d_width_m, 25);  // A's hold ended: granted
}

TEST(EngineSettings, AHeldSmallestWidthGivesTheNextHigher) {
  const HeldWidthRun r = held_width_run("5");
  EXPECT_EQ(r.b_width_m, 10);  // nothing lower is free: the next higher
  EXPECT_EQ(r.c_width_before_m, 10);
  EXPECT_EQ(r.d_width_m, 5);
}

TEST(EngineSettings, ConfigurationAndSensorRequestsRenewTheHold) {
  Driver d(kJakeOriginal + "min_reset_interval = 0\n");
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=5,pd=0.9");
  d.now = 500;
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,pd=0.8");  // a pd-only request is a configuration request
  d.now = 1000;
  d.sensor_on("a");
  d.now = 1599;  // 599 s after A's sensor request
  d.mail("UHZ_CONFIG_REQUEST", "vname=b,width=5,pd=0.9");
  EXPECT_EQ(d.vehicle("b").setting->width_m, 10);
  d.now = 1600;
  d.mail("UHZ_CONFIG_REQUEST", "vname=b,width=5,pd=0.9");
  EXPECT_EQ(d.vehicle("b").setting->width_m, 5);
}

TEST(EngineSettings, EveryOptionFullKeepsSettingWithWarning_Rulings) {
  Driver d("sensor_config = width=5, exp=2, pclass=0.9, max=1\n"
           "sensor_config = width=10, exp=2, pclass=0.9, max=1\n"
           "hazard = x=0,y=0,label=a,type=hazard\nmin_reset_interval = 0\n");
  for (const char* v : {"a", "b", "c"}) d.sensor_on(v);
  d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=5,pd=0.9");
  d.mail("UHZ_CONFIG_REQUEST", "vname=b,width=10,pd=0.9");
  const Outputs c_first = d.mail("UHZ_CONFIG_REQUEST", "vname=c,width=10,pd=0.9");
  EXPECT_EQ(d.vehicle("c").setting->width_m, 5);  // none: the smallest
  EXPECT_TRUE(contains(c_first.run_warnings, "Every sensor option is full"));
  const Outputs a_again = d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=10,pd=0.4");
  EXPECT_EQ(d.vehicle("a").setting->width_m, 5);
  EXPECT_EQ(d.vehicle("a").setting->pd, 0.4);
  EXPECT_TRUE(contains(a_again.run_warnings, "keeps its current setting"));
  EXPECT_EQ(values_of(a_again, "UHZ_CONFIG_ACK").size(), 1u);
}

TEST(EngineSettings, NoOptionsMeansNoSettingAndNoDetections_D26) {
  Driver d("hazard = x=0,y=0,label=a,type=hazard\n");
  const Outputs req = d.mail("UHZ_CONFIG_REQUEST", "vname=a,width=5,pd=0.9");
  EXPECT_TRUE(values_of(req, "UHZ_CONFIG_ACK").empty());
  EXPECT_TRUE(contains(req.run_warnings, "no sensor_config options exist"));
  d.sensor_on("a");
  d.pose("a", 0, 0);
  const Outputs step = d.tick();
  EXPECT_TRUE(values_of(step, "UHZ_DETECTION_REPORT").empty());
  EXPECT_TRUE(contains(step.run_warnings, "No sensor setting for a"));
  EXPECT_TRUE(d.tick().run_warnings.empty());  // said once
  EXPECT_TRUE(contains(d.all.config_warnings, "no sensor_config"));
}

TEST(EngineSettings, CommunityIsNotChecked_Clarifications) {
  Driver d(kJakeOriginal);
  // Whoever posts it, vname decides the vehicle.
  EXPECT_EQ(values_of(d.mail("UHZ_CONFIG_REQUEST", "vname=zed,width=10,pd=0.9"),
                      "UHZ_CONFIG_ACK_ZED")
                .size(),
            1u);
}

}  // namespace
}  // namespace hazard
