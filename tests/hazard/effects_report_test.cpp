// Effects chosen from the scene, and the report body (docs/uFldHazardSensor.md, D32; seeds:
// docs/configuration.md).
#include <gtest/gtest.h>

#include "hazard/report.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::Driver;
using testing::setup_from;

std::vector<std::string> names(const Effects& e) {
  std::vector<std::string> out;
  for (auto n : e.active_names()) out.emplace_back(n);
  return out;
}

TEST(Effects, OnlyWhatTheSceneUses) {
  const EngineSetup plain = setup_from("sensor_config = width=5,exp=2,pclass=0.9\n"
                                       "hazard = x=0,y=0,label=a,type=hazard\n"
                                       "hazard = x=0,y=0,label=b,type=hazard,hr=0.5\n");
  const Effects e = choose_effects(plain.config, plain.field);
  // Defaults: both gates on, resemblance off (hr only on a hazard), no aspect, all visuals.
  EXPECT_EQ(names(e), (std::vector<std::string>{"speed_gate", "turn_blackout", "swath_visuals",
                                                 "detection_visuals", "hazard_markers"}));
  const EngineSetup rich = setup_from(
      "max_turn_rate = off\nmax_vehicle_speed = off\nshow_swath = false\nshow_hazards = false\n"
      "show_detections = 0\nhazard = x=0,y=0,label=a,type=benign,hr=0.2\n"
      "hazard = x=0,y=0,label=b,type=benign,aspect=3,aspect_min=1,aspect_max=2\n");
  EXPECT_EQ(names(choose_effects(rich.config, rich.field)),
            (std::vector<std::string>{"resemblance", "aspect"}));
  const EngineSetup ignoring = setup_from(
      "ignore_resemblances = true\nhazard = x=0,y=0,label=a,type=benign,hr=0.2\n"
      "hazard = x=0,y=0,label=b,type=benign,aspect=3\n");  // partial triple: no aspect effect
  const Effects i = choose_effects(ignoring.config, ignoring.field);
  EXPECT_FALSE(i.resemblance);
  EXPECT_FALSE(i.aspect);
  EXPECT_FALSE(i.swept_swath);
  EXPECT_FALSE(i.geodesy);
}

TEST(Effects, NoHeadingHistoryWithoutTheTurnGate) {
  Driver off(testing::quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"));
  off.pose("v", 0, 0);
  EXPECT_FALSE(off.vehicle("v").heading_history.has_value());
  Driver on("max_turn_rate = 2\nsensor_config = width=5,exp=2,pclass=0.9\n"
            "hazard = x=0,y=0,label=a,type=hazard\n");
  on.pose("v", 0, 0);
  EXPECT_TRUE(on.vehicle("v").heading_history.has_value());
}

TEST(Report, BodyWithSeedEffectsOptionsAndVehicles_Spec11_D32) {
  Driver d("hazard_file = hazards.txt\n"
           "sensor_config = width=25, exp=4, pclass=0.85\n"
           "sensor_config = width=50, exp=2, pclass=0.60\n"
           "sensor_config = width=10, exp=6, pclass=0.93, max=1\n"
           "min_classify_interval = 0\nshow_hazards = false\n",
           {{"hazards.txt", "hazard = x=0,y=0,label=a,type=hazard\n"
                            "hazard = x=1,y=0,label=b,type=benign\n"
                            "hazard = x=2,y=0,label=c,type=benign\n"}},
           /*seed=*/31, /*start_s=*/100);
  d.sensor_on("archie");
  d.mail("UHZ_CONFIG_REQUEST", "vname=archie,width=50,pd=1");
  d.now = 112;
  d.pose("archie", 0, 0, 90);
  d.tick();
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=archie,label=a");
  d.mail("UHZ_CLASSIFY_REQUEST", "vname=archie,label=zz");
  d.tick();
  const std::string body = format_report(collect_report_data(d.engine));
  const std::string expected =
      "Hazard File: (hazards.txt) \n"
      "     Hazard: 1\n"
      "     Benign: 2\n"
      "       Seed: 31 (command line)\n"
      "    Effects: speed_gate, turn_blackout, swath_visuals, detection_visuals\n"
      "\n"
      "============================================\n"
      "Sensor Configuration Options\n"
      "============================================\n"
      "Width  Exp  Classify  Max\n"
      "-----  ---  --------  ---\n"
      "10.0   6.0  0.930     1\n"
      "25.0   4.0  0.850     0\n"
      "50.0   2.0  0.600     0\n"
      "\n"
      "============================================\n"
      "Sensor Settings / Stats for known vehicles:\n"
      "============================================\n"
      "Vehicle  Swath                        Try Swath  Swath   Pd\n"
      "Name     Width  Pd     Pfa    Pclass  Resets     Resets  Resets\n"
      "-------  -----  -----  -----  ------  ---------  ------  ------\n"
      "archie   50.0   1.000  1.000  0.600   1          1(0)    0(-)\n"
      "\n"
      "Vehicle  Sensor              FA    Det   Classify  Classify\n"
      "Name     Reqs    Detections  Rate  Rate  Requests  Answers\n"
      "-------  ------  ----------  ----  ----  --------  --------\n"
      "archie   1       3           1.00  1.00  2         1\n";
  EXPECT_EQ(body, expected);
}

TEST(Report, HazardFileLabels) {
  ReportData d;
  EXPECT_NE(format_report(d).find("Hazard File: (None provided.) \n"), std::string::npos);
  d.hazard_files = {{"a.txt", true, {}}, {"b.txt", false, {}}};
  EXPECT_NE(format_report(d).find("Hazard File: (a.txt, Error reading: b.txt) \n"),
            std::string::npos);
  EXPECT_NE(format_report(d).find("Effects: none"), std::string::npos);
}

// A file name from the mission may hold control bytes: escaped in the report.
TEST(Report, HazardFileNamesAreEscaped_Hardening) {
  ReportData d;
  d.hazard_files = {{"a\x1b[2J.txt", true, {}}, {"b\r.txt", false, {}}};
  EXPECT_NE(format_report(d).find("Hazard File: (a\\x1B[2J.txt, Error reading: b\\x0D.txt) \n"),
            std::string::npos)
      << format_report(d);
}

TEST(Report, RatesAreNotAvailableWithoutChances) {
  ReportData d;
  d.vehicles.push_back({"v", SensorSetting{}, VehicleCounters{}});
  EXPECT_NE(format_report(d).find("n/a   n/a"), std::string::npos);
}

}  // namespace
}  // namespace hazard
