// hazard_replay's whole run (hazard_replay::run, as main calls it): reading the mission and the
// field, mapping the log, the replay loop and the .alog it writes, over a fixed log of a
// 100-vehicle fleet mowing lanes with 10 Hz node reports.
#include <cstdio>
#include <ostream>
#include <streambuf>
#include <stdexcept>
#include <string>

#include "replay.hpp"
#include "scenario/reference_scenario.hpp"
#include "workloads.hpp"

namespace perf {

namespace {

// 100,000 objects 20 m apart (400 m² each, replay_rate.sh's density; a 1M field's loading would
// be most of the count), 100 vehicles in lanes 60 m apart, 30 MOOS seconds: 30,000 node reports.
constexpr int kObjects = 100000;
constexpr double kSpacing_m = 20.0;
constexpr int kVehicles = 100;
constexpr int kTenths = 300;

/// A stream buffer that only checksums what is written.
class ChecksumBuffer : public std::streambuf {
 public:
  std::uint64_t sum = kChecksumStart;

 protected:
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) {
      const char ch = static_cast<char>(c);
      sum = checksum(sum, std::string_view(&ch, 1));
    }
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    sum = checksum(sum, std::string_view(s, static_cast<std::size_t>(n)));
    return n;
  }
};

std::string log_text(const Fleet& fleet) {
  std::string log = "%% LOGSTART 1700000000.0\n";
  char time[32];
  for (int v = 0; v < fleet.vehicles; ++v) log += "0.000 UHZ_SENSOR_REQUEST bench vname=" + fleet.name(v) + "\n";
  for (int k = 1; k <= kTenths; ++k) {
    std::snprintf(time, sizeof time, "%.3f", k / 10.0);
    for (int v = 0; v < fleet.vehicles; ++v)
      log += std::string(time) + " NODE_REPORT bench " + fleet.node_report(v, k / 10.0) + "\n";
  }
  return log;
}

}  // namespace

std::uint64_t replay_log() {
  ScratchFolder folder;
  folder.write("field.txt", hazard::grid_field_text(kObjects, kSpacing_m));
  Fleet fleet;
  fleet.vehicles = kVehicles;
  fleet.half_extent_m = 3160.0;
  fleet.lane_spacing_m = 60.0;
  hazard_replay::Options options;
  options.config_path = folder.write("m.moos",
                                     "ServerPort = 9000\n"
                                     "Community = shoreside\n"
                                     "ProcessConfig = uFldHazardSensor\n"
                                     "{\n"
                                     "  AppTick = 4\n"
                                     "  hazard_file = field.txt\n"
                                     "  sensor_config = width=25, exp=4, pclass=0.8\n"
                                     "  swath_length = 5\n"
                                     "  random_seed = 1\n"
                                     "  show_hazards = false\n"
                                     "}\n");
  options.input_path = folder.write("in.alog", log_text(fleet));
  ChecksumBuffer alog, diagnostics;
  std::ostream out(&alog), err(&diagnostics);
  const int status = hazard_replay::run(options, out, err);
  if (status != 0) throw std::runtime_error("hazard_replay::run returned " + std::to_string(status));
  return alog.sum;
}

}  // namespace perf
