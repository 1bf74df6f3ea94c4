// uFldHazardSensor's app class on libmoos's in-process bus with a manual clock (as the app tests
// run it, tests/apps/uFldHazardSensor): a vehicle client posts what pHazardMgr and a simulator
// post (configuration requests, node reports at 10 Hz, sensor requests at 4 Hz, a classify
// request for every detection it reads), and the app cycles at AppTick 4. Everything a real
// cycle does but the socket: mail decoding into the backlog, the engine, the postings.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "HazardSensor.hpp"
#include "moos/bus.hpp"
#include "moos/clock.hpp"
#include "moos/command_line.hpp"
#include "moos/mission.hpp"
#include "scenario/reference_scenario.hpp"
#include "workloads.hpp"

namespace perf {

namespace {

struct SensorLoad {
  int objects = 0;
  double spacing_m = 0.0;
  Fleet fleet;
  double duration_s = 0.0;
  /// Steps of 0.05 MOOS s between the app's turns: 1 cycles on time; 20 lets a second of mail
  /// pile up, as when the machine keeps the sensor from its core (the backlog's path).
  int steps_per_turn = 1;
};

std::string mission_text() {
  return "Community = shoreside\n"
         "ProcessConfig = uFldHazardSensor\n"
         "{\n"
         "  AppTick = 4\n"
         "  CommsTick = 4\n"
         "  sensor_config = width=25, exp=4, pclass=0.8\n"
         "  sensor_config = width=50, exp=2, pclass=0.6\n"
         "  swath_length = 5\n"
         "  random_seed = 1\n"
         "  show_hazards = false\n"
         "  hazard_file = field.txt\n"
         "}\n";
}

std::uint64_t run_sensor(const SensorLoad& load) {
  ScratchFolder folder;
  folder.write("field.txt", hazard::grid_field_text(load.objects, load.spacing_m));
  const std::string mission_path = folder.write("m.moos", mission_text());
  std::vector<moos::MissionError> errors;
  std::optional<moos::MissionFile> mission = moos::MissionFile::load(mission_path, {}, &errors);
  if (!mission) throw std::runtime_error("cannot read " + mission_path);
  const std::vector<std::string> args = {"uFldHazardSensor", mission_path};
  moos::AppSettings settings = moos::resolve_app_settings(
      ufld_hazard_sensor::hazard_sensor_traits(), moos::parse_command_line(args), &*mission, errors);

  moos::ManualClock clock{moos::ManualClock::kDefaultStartUnix_s};
  moos::InProcessBus bus{clock, moos::InProcessBus::Options{"shoreside", 1.0}};
  settings.time_warp = bus.time_warp();
  std::unique_ptr<moos::BusClient> vehicle = bus.connect("vehicle");
  std::unique_ptr<moos::BusClient> comms = bus.connect(settings.moos_name);
  vehicle->register_variable("UHZ_DETECTION_REPORT");
  ufld_hazard_sensor::HazardSensorOptions options;
  options.os_seed = [] { return std::uint64_t{424242}; };
  ufld_hazard_sensor::HazardSensor app(std::move(options));
  if (!app.start(*comms, std::move(settings))) throw std::runtime_error("the sensor did not start");

  const Fleet& fleet = load.fleet;
  for (int v = 0; v < fleet.vehicles; ++v)
    vehicle->notify("UHZ_CONFIG_REQUEST", "vname=" + fleet.name(v) + ",width=25,pd=0.9");
  std::uint64_t sum = kChecksumStart;
  const int steps = static_cast<int>(load.duration_s * 20);  // 0.05 s each
  for (int k = 0; k <= steps; ++k) {
    const double t = k * 0.05;
    if (k % 2 == 0)
      for (int v = 0; v < fleet.vehicles; ++v) vehicle->notify("NODE_REPORT", fleet.node_report(v, t));
    if (k % 5 == 0)
      for (int v = 0; v < fleet.vehicles; ++v) vehicle->notify("UHZ_SENSOR_REQUEST", "vname=" + fleet.name(v));
    if (k % load.steps_per_turn == 0) app.run_for(0.05 * load.steps_per_turn);
    for (const moos::Message& m : vehicle->fetch()) {
      sum = checksum(sum, m.sval);
      vehicle->notify("UHZ_CLASSIFY_REQUEST",
                      "vname=" + field_value(m.sval, "vname") + ",label=" + field_value(m.sval, "label"));
    }
    if (k % 20 == 0) {
      for (const moos::Message& m : bus.postings()) sum = checksum(checksum(sum, m.key), m.sval);
      bus.clear_postings();
    }
  }
  return sum;
}

}  // namespace

// 10,000 objects 20 m apart (400 m² each, process_bench's default density), 10 vehicles in
// lanes 200 m apart, 60 MOOS seconds.
std::uint64_t sensor_sparse() {
  SensorLoad load;
  load.objects = 10000;
  load.spacing_m = 20.0;
  load.fleet.vehicles = 10;
  load.fleet.half_extent_m = 1000.0;
  load.fleet.lane_spacing_m = 200.0;
  load.duration_s = 60.0;
  return run_sensor(load);
}

// The dense field (25 m² per object, the density of 1M objects over 5 km x 5 km): 40,000
// objects 5 m apart, 100 vehicles in lanes 10 m apart, 20 MOOS seconds: about 250 detections
// and as many classify requests per MOOS second, 1,000 node reports and 400 sensor requests.
static SensorLoad dense_load() {
  SensorLoad load;
  load.objects = 40000;
  load.spacing_m = 5.0;
  load.fleet.vehicles = 100;
  load.fleet.half_extent_m = 500.0;
  load.fleet.lane_spacing_m = 10.0;
  load.duration_s = 20.0;
  return load;
}

std::uint64_t sensor_dense() { return run_sensor(dense_load()); }

// The dense field when the sensor was kept from its core: 20 MOOS seconds of the dense load
// (about 20,000 node reports, 8,000 sensor requests) arrive at once, and the backlog
// (mail_backlog.hpp) hands them to the engine 2,000 per iteration. Its cost must follow what it
// hands over, not what it holds: a sensor that fell behind must not fall further behind.
std::uint64_t sensor_dense_late() {
  SensorLoad load = dense_load();
  load.steps_per_turn = 400;
  return run_sensor(load);
}

}  // namespace perf
