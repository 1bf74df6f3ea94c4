#pragma once
// Test support: uFldHazardSensor (the app class) on libmoos's in-process bus with a manual
// clock, so start-up, mail and iterations are instant and exact. A scratch folder
// (tests/support) holds the mission file and hazard files, so hazard_file paths and file:line
// warnings are real.

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "HazardSensor.hpp"
#include "moos/app.hpp"
#include "moos/bus.hpp"
#include "moos/clock.hpp"
#include "moos/command_line.hpp"
#include "moos/mission.hpp"
#include "base/text.hpp"
#include "scratch_files.hpp"

namespace ufld_hazard_sensor::testing {

/// A mission file: the globals, then `ProcessConfig = <app>` with `block` (lines as written).
/// The block's first line is line 6 of the file (kFirstBlockLine).
inline std::string mission_text(const std::string& block, const std::string& app = "uFldHazardSensor") {
  return "// uFldHazardSensor app tests\n"
         "Community = shoreside\n"
         "\n"
         "ProcessConfig = " + app + "\n"
         "{\n" + block + "}\n";
}
inline constexpr int kFirstBlockLine = 6;

/// True if `part` occurs in `text`.
inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The MOOS application framework's own postings (APPCAST, <APPNAME>_STATUS, _ITER_GAP,
/// _ITER_LEN): what the app posts besides what the engine decides.
inline bool is_framework_posting(const std::string& var) {
  return var == "APPCAST" || base::ends_with(var, "_STATUS") ||
         base::ends_with(var, "_ITER_GAP") || base::ends_with(var, "_ITER_LEN");
}

/// The app started on a bus (community "shoreside", warp 1) at ManualClock's default epoch.
class SensorOnBus : public ::testing::Test {
 protected:
  static constexpr double kT0 = moos::ManualClock::kDefaultStartUnix_s;

  /// Writes m.moos with `block` into the scratch folder, resolves the settings as main would
  /// (libmoos's command line and mission reader) and starts the app.
  void start(const std::string& block, HazardSensorOptions options = {},
             std::vector<std::string> args = {}) {
    start_mission(mission_text(block), std::move(options), std::move(args));
  }

  /// As start(), with the whole mission file given.
  void start_mission(const std::string& mission_file, HazardSensorOptions options = {},
                     std::vector<std::string> args = {}) {
    test_support::write_file(dir / "m.moos", mission_file);
    std::vector<moos::MissionError> errors;
    mission = moos::MissionFile::load((dir / "m.moos").string(), {}, &errors);
    ASSERT_TRUE(mission.has_value());
    args.insert(args.begin(), {"uFldHazardSensor", (dir / "m.moos").string()});
    moos::AppSettings settings = moos::resolve_app_settings(
        hazard_sensor_traits(), moos::parse_command_line(args), &*mission, errors);
    settings.time_warp = bus.time_warp();
    if (options.os_seed == nullptr) options.os_seed = [] { return std::uint64_t{424242}; };
    app.emplace(std::move(options));
    comms = bus.connect(settings.moos_name);
    ASSERT_TRUE(comms);
    ASSERT_TRUE(app->start(*comms, std::move(settings)));
  }

  /// Runs the app's cycles for `moos_s` seconds (at its AppTick).
  void run_for(double moos_s) { app->run_for(moos_s); }

  void post(const std::string& var, const std::string& value) {
    ASSERT_TRUE(vehicle->notify(var, value));
  }

  /// The values the app posted to `var`, in order.
  std::vector<std::string> values_of(const std::string& var) const {
    std::vector<std::string> out;
    for (const auto& m : bus.postings_of(var)) {
      if (m.source == app->settings().moos_name) out.push_back(m.sval);
    }
    return out;
  }

  const hazard::Engine& engine() const { return *app->engine(); }
  const moos::AppCast& appcast() const { return app->appcast(); }

  test_support::ScratchDir dir{"uhz_app"};
  moos::ManualClock clock{kT0};
  moos::InProcessBus bus{clock, moos::InProcessBus::Options{"shoreside", 1.0}};
  std::unique_ptr<moos::BusClient> vehicle = bus.connect("vehicle");
  std::unique_ptr<moos::BusClient> comms;
  std::optional<moos::MissionFile> mission;
  std::optional<HazardSensor> app;
};

}  // namespace ufld_hazard_sensor::testing
