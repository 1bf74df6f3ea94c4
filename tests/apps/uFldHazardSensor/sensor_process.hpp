#pragma once
// Test support for uFldHazardSensor as a process: moosdb-lite on a free port with a log, the
// app started on a mission written for that port, and a scripted vehicle (libmoos's TcpClient)
// that posts mail and waits, bounded, for what the app posts. Every child process dies with the
// test process and is killed by its handle's destructor, so nothing is left behind on failure
// (tests/support: child_process.hpp, moosdb_server.hpp).

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "alog_files.hpp"
#include "base/text.hpp"
#include "child_process.hpp"
#include "moos/tcp_client.hpp"
#include "moosdb_server.hpp"
#include "scratch_files.hpp"
#include "sensor_on_bus.hpp"

namespace ufld_hazard_sensor::testing {

using test_support::Alog;
using test_support::Child;
using test_support::MoosdbServer;
using test_support::steady_now_s;

/// MOOS time runs 20x real time in the process tests, so a scenario takes seconds.
inline constexpr double kWarp = 20.0;
/// Real seconds for anything that should happen at once (connect, an answer) on a loaded box.
inline constexpr double kPatience_s = 10.0;

/// The mission for a server on `port` at time warp `warp`: globals (`extra_globals` last), then
/// `block` as uFldHazardSensor's block.
inline std::string process_mission(int port, const std::string& block,
                                   const std::string& extra_globals = {}, double warp = kWarp) {
  return "ServerHost   = 127.0.0.1\n"
         "ServerPort   = " + std::to_string(port) + "\n"
         "Community    = shoreside\n"
         "MOOSTimeWarp = " + std::to_string(static_cast<int>(warp)) + "\n" + extra_globals +
         "\n"
         "ProcessConfig = uFldHazardSensor\n"
         "{\n" + block + "}\n";
}

/// The app's name, the source of its postings in the server's log.
inline constexpr const char* kApp = "uFldHazardSensor";

/// Integers print without decimals under FMT: FMT(32, 1) = "32".
inline std::string n(int v) { return std::to_string(v); }

/// A NODE_REPORT at (x, y), speed 1 m/s, heading `heading` degrees.
inline std::string node_report(const std::string& name, double x, double y, double heading = 0) {
  return "NAME=" + name + ",X=" + base::fmt(x) + ",Y=" + base::fmt(y) + ",SPD=1,HDG=" +
         base::fmt(heading);
}

/// moosdb-lite (logging every posting), uFldHazardSensor and one scripted vehicle client.
class SensorProcess : public ::testing::Test {
 protected:
  void TearDown() override { stop_all(); }

  /// Starts the server, writes the mission and starts the app (with `app_args` after the
  /// mission file), then connects the vehicle client and waits for the app's first iteration
  /// (its first options summary).
  void start(const std::string& block, const std::vector<std::string>& app_args = {},
             const std::string& extra_globals = {}) {
    server.emplace(MOOSDB_LITE_PATH, server_args("db.alog"));
    ASSERT_TRUE(server->ok()) << "moosdb-lite did not start";
    test_support::write_file(dir / "m.moos",
                             process_mission(server->port(), block, extra_globals, warp) +
                                 extra_blocks);
    std::vector<std::string> args = {(dir / "m.moos").string()};
    args.insert(args.end(), app_args.begin(), app_args.end());
    app = Child::spawn(UFLD_HAZARD_SENSOR_PATH, args);
    ASSERT_TRUE(app.has_value());

    moos::TcpClientOptions o;
    o.host = "127.0.0.1";
    o.port = server->port();
    o.name = "vehicle_sim";
    o.time_warp = warp;
    vehicle = std::make_unique<moos::TcpClient>(o);
    ASSERT_TRUE(vehicle->start());
    ASSERT_TRUE(vehicle->wait_until_connected(kPatience_s));
    for (const char* var : {"UHZ_OPTIONS_SUMMARY", "UHZ_CONFIG_ACK_ALPHA", "UHZ_DETECTION_REPORT_ALPHA",
                            "UHZ_HAZARD_REPORT_ALPHA", "VIEW_POLYGON", "VIEW_MARKER"}) {
      ASSERT_TRUE(vehicle->register_variable(var));
    }
    ASSERT_TRUE(wait_for([](const moos::Message& m) { return m.key == "UHZ_OPTIONS_SUMMARY"; }))
        << "the app did not iterate; its stderr:\n" << app->stderr_text();
  }

  /// moosdb-lite's arguments (its port aside): the log `log_name` in the scratch folder, the
  /// warp, the community, then server_extra_args.
  std::vector<std::string> server_args(const std::string& log_name) const {
    std::vector<std::string> args = {"--log=" + (dir / log_name).string(),
                                     "--moos_time_warp=" + std::to_string(static_cast<int>(warp)),
                                     "--moos_community=shoreside"};
    args.insert(args.end(), server_extra_args.begin(), server_extra_args.end());
    return args;
  }

  void post(const std::string& var, const std::string& value) { ASSERT_TRUE(vehicle->notify(var, value)); }

  /// Waits (bounded) until a message satisfying `pred` arrives after the ones already seen;
  /// true if it did. All mail is kept in `mail`.
  bool wait_for(const std::function<bool(const moos::Message&)>& pred, double timeout_s = kPatience_s) {
    const double deadline = steady_now_s() + timeout_s;
    while (steady_now_s() < deadline) {
      for (auto& m : vehicle->fetch()) mail.push_back(std::move(m));
      for (; seen < mail.size(); ++seen) {
        if (pred(mail[seen])) {
          ++seen;
          return true;
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }

  /// Waits (bounded) until `count` messages of `var` have arrived in all (seen or not).
  bool wait_for_count(const std::string& var, std::size_t count, double timeout_s = kPatience_s) {
    const double deadline = steady_now_s() + timeout_s;
    while (steady_now_s() < deadline) {
      for (auto& m : vehicle->fetch()) mail.push_back(std::move(m));
      const auto n = std::count_if(mail.begin(), mail.end(), [&](const moos::Message& m) { return m.key == var; });
      if (static_cast<std::size_t>(n) >= count) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return false;
  }

  bool wait_for_value(const std::string& var, const std::string& value) {
    return wait_for([&](const moos::Message& m) { return m.key == var && m.sval == value; });
  }

  /// Sleeps `ticks` iterations of the app (AppTick 4 Hz, in real time at kWarp).
  static void sleep_ticks(double ticks) {
    std::this_thread::sleep_for(std::chrono::duration<double>(ticks / 4.0 / kWarp));
  }

  /// Stops the vehicle, the app (SIGTERM: it must exit 0) and the server (which flushes its
  /// log), and reads the log.
  Alog stop_and_read_log() {
    stop_all();
    return test_support::read_alog(dir / "db.alog");
  }

  void stop_all() {
    if (vehicle) vehicle->close();
    vehicle.reset();
    if (app && app->running()) app_exit = app->stop(kPatience_s);
    if (server) server->stop();
  }

  /// The time warp of server, app and vehicle; a test may raise it before start() (a scenario
  /// that spans MOOS minutes).
  double warp = kWarp;
  /// More moosdb-lite switches, and more ProcessConfig blocks for the mission (other
  /// processes a test starts itself), both set before start().
  std::vector<std::string> server_extra_args;
  std::string extra_blocks;
  test_support::ScratchDir dir{"uhz_process"};
  std::optional<MoosdbServer> server;
  std::optional<Child> app;
  std::optional<int> app_exit;
  std::unique_ptr<moos::TcpClient> vehicle;
  std::vector<moos::Message> mail;
  std::size_t seen = 0;
};

}  // namespace ufld_hazard_sensor::testing
