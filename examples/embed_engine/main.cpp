// A vehicle passes along a line of objects; the HazardSensor engine reports what it detects.
//
// The engine is driven as uFldHazardSensor drives it, through hazard::Driver: configuration
// entries (the lines of a `ProcessConfig = uFldHazardSensor` block), then mail (the variables
// the MOOS app would receive) and iterations at the app's tick. Its postings are what the app
// would publish; here they are printed.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "base/version.hpp"
#include "hazard/driver.hpp"

namespace {

// A block as a mission file would hold it: one sensor setting, eleven objects 20 m apart along
// x = 15, every second one a hazard.
std::vector<hazard::ConfigEntry> configuration() {
  std::vector<hazard::ConfigEntry> entries = {
      {"sensor_config", "width=25, exp=4, pclass=0.8", "embed.moos", 1},
      {"swath_length", "5", "embed.moos", 2},
      {"show_hazards", "false", "embed.moos", 3},
  };
  for (int i = 0; i <= 10; ++i) {
    const std::string type = i % 2 == 0 ? "hazard" : "benign";
    entries.push_back({"hazard", "x=15,y=" + std::to_string(20 * i) + ",label=" +
                                     std::to_string(100 + i) + ",type=" + type,
                       "embed.moos", 10 + i});
  }
  return entries;
}

// The engine reads no files itself: hazard_file names would come through this reader.
base::Result<std::string> no_files(const std::string&) { return base::Result<std::string>::fail("no file"); }

int print_detections(const hazard::TimedOutputs& timed) {
  int count = 0;
  for (const hazard::Posting& p : timed.outputs.postings) {
    if (p.variable != "UHZ_DETECTION_REPORT") continue;
    std::printf("t=%6.2f  %s  %s\n", timed.time_s, p.variable.c_str(), p.value.c_str());
    ++count;
  }
  return count;
}

}  // namespace

int main() {
  std::printf("HazardSensor engine %s\n", std::string(base::release_version()).c_str());
  hazard::EngineSetup setup = hazard::load_configuration(configuration(), no_files);
  for (const std::string& warning : setup.config_warnings) {
    std::fprintf(stderr, "configuration: %s\n", warning.c_str());
  }
  hazard::Driver driver(std::move(setup), hazard::SeedChoice{7, hazard::SeedSource::kCommandLine});

  int detections = print_detections(driver.start(0.0));
  driver.deliver({"UHZ_CONFIG_REQUEST", "vname=alpha,width=25,pd=0.9", 0.0});
  driver.deliver({"UHZ_SENSOR_REQUEST", "vname=alpha", 0.0});

  // alpha drives north along x = 0 at 2 m/s from y = -10 to y = 210; a node report and an
  // iteration every quarter second (AppTick 4).
  constexpr double kTick_s = 0.25;
  for (int k = 1; k * kTick_s <= 110.0; ++k) {
    const double t = k * kTick_s;
    const std::string report = "NAME=alpha,X=0,Y=" + std::to_string(-10.0 + 2.0 * t) +
                               ",SPD=2,HDG=0,TIME=" + std::to_string(t);
    detections += print_detections(driver.deliver({"NODE_REPORT", report, t}));
    detections += print_detections(driver.step(t));
  }
  std::printf("%d detections of 11 objects\n", detections);
  return detections > 0 ? 0 : 1;
}
