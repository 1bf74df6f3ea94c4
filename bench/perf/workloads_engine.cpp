// The engine alone (hazard::Driver, no MOOS): the reference survey over its sparse 200-object
// field, and a dense field under a 100-vehicle fleet that asks for a classification of every
// detection.
#include <stdexcept>
#include <string>
#include <vector>

#include "hazard/driver.hpp"
#include "scenario/reference_scenario.hpp"
#include "workloads.hpp"

namespace perf {

namespace {

std::uint64_t add_outputs(std::uint64_t sum, const hazard::Outputs& out) {
  for (const hazard::Posting& p : out.postings) sum = checksum(checksum(sum, p.variable), p.value);
  return sum;
}

// The dense case at engine level: 40,000 objects 5 m apart (25 m² each, the density of 1M
// objects over 5 km x 5 km), 100 vehicles in lanes 10 m apart, node reports at 10 Hz, a sensor
// request per vehicle per iteration (as pHazardMgr posts them), a classify request for every
// detection, AppTick 4, for 30 MOOS seconds.
constexpr int kDenseObjects = 40000;
constexpr double kDenseSpacing_m = 5.0;
constexpr int kDenseVehicles = 100;
constexpr double kDenseDuration_s = 30.0;

}  // namespace

std::uint64_t engine_survey() {
  const hazard::Scenario s = hazard::reference_survey(10.0);
  std::uint64_t sum = kChecksumStart;
  for (int run = 0; run < 4; ++run) {
    hazard::Driver driver(
        hazard::load_configuration(s.config, [](const std::string&) { return base::Result<std::string>::fail("no file"); }),
        hazard::SeedChoice{static_cast<std::uint64_t>(2024 + run), hazard::SeedSource::kRandomSeed});
    auto keep = [&sum](const hazard::Outputs& out) { sum = add_outputs(sum, out); };
    hazard::play_mail(driver, s.mail, 4.0, s.end_time_s, keep, keep);
  }
  return sum;
}

std::uint64_t gate_selftest() {
  const hazard::Scenario s = hazard::reference_survey(1.0);
  hazard::Driver driver(
      hazard::load_configuration(s.config, [](const std::string&) { return base::Result<std::string>::fail("no file"); }),
      hazard::SeedChoice{2024, hazard::SeedSource::kRandomSeed});
  std::uint64_t sum = kChecksumStart;
  auto keep = [&sum](const hazard::Outputs& out) { sum = add_outputs(sum, out); };
  hazard::play_mail(driver, s.mail, 4.0, s.end_time_s, keep, keep);
  return sum;
}

std::uint64_t engine_dense() {
  const std::string field = hazard::grid_field_text(kDenseObjects, kDenseSpacing_m);
  const std::vector<hazard::ConfigEntry> config = {
      {"sensor_config", "width=25, exp=4, pclass=0.8", "perf", 1},
      {"swath_length", "5", "perf", 2},
      {"random_seed", "1", "perf", 3},
      {"show_hazards", "false", "perf", 4},
      {"hazard_file", "field.txt", "perf", 5},
  };
  hazard::Driver driver(
      hazard::load_configuration(config, [&](const std::string&) { return base::Result<std::string>::ok(field); }),
      hazard::SeedChoice{1, hazard::SeedSource::kRandomSeed});
  Fleet fleet;
  fleet.vehicles = kDenseVehicles;
  fleet.half_extent_m = 500.0;
  fleet.lane_spacing_m = 10.0;
  std::uint64_t sum = add_outputs(kChecksumStart, driver.start(0).outputs);
  std::vector<std::string> requests;
  auto handle = [&](const hazard::TimedOutputs& timed) {
    sum = add_outputs(sum, timed.outputs);
    for (const hazard::Posting& p : timed.outputs.postings) {
      if (p.variable != "UHZ_DETECTION_REPORT") continue;
      requests.push_back("vname=" + field_value(p.value, "vname") +
                         ",label=" + field_value(p.value, "label"));
    }
  };
  for (int tenth = 0; tenth <= static_cast<int>(kDenseDuration_s * 10); ++tenth) {
    const double now = tenth / 10.0;
    for (int v = 0; v < fleet.vehicles; ++v) {
      const std::string report = fleet.node_report(v, now);
      handle(driver.deliver(hazard::Mail{"NODE_REPORT", report, now}));
    }
    if (tenth % 5 != 0 && tenth % 5 != 2) continue;  // iterations at 0, 0.25, 0.5, ... (4 Hz)
    const double tick = tenth % 5 == 0 ? now : now + 0.05;
    std::vector<std::string> asked;
    asked.swap(requests);
    for (const std::string& r : asked) handle(driver.deliver(hazard::Mail{"UHZ_CLASSIFY_REQUEST", r, tick}));
    for (int v = 0; v < fleet.vehicles; ++v) {
      const std::string request = "vname=" + fleet.name(v);
      handle(driver.deliver(hazard::Mail{"UHZ_SENSOR_REQUEST", request, tick}));
    }
    handle(driver.step(tick));
  }
  return sum;
}

}  // namespace perf
