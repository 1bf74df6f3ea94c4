// uFldHazardSensor under faults, as processes on moosdb-lite: the database killed
// and restarted under a running sensor, a vehicle process killed mid-pass, and a client that
// stops reading. In each the sensor must go on serving everyone else, with its state intact.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <map>

#include "../moosdb_lite/raw_client.hpp"
#include "base/text.hpp"
#include "sensor_process.hpp"
#include "wire_messages.hpp"

namespace ufld_hazard_sensor {
namespace {

using test_support::Alog;
using test_support::Child;
using test_support::MoosdbServer;
using test_support::steady_now_s;
using testing::kPatience_s;
using testing::SensorProcess;

using testing::kApp;
using testing::n;
using testing::node_report;

/// What the app posted of `variable` in `log`, in order.
std::vector<std::string> posted(const Alog& log, const std::string& variable) {
  std::vector<std::string> out;
  for (const auto& e : log.entries)
    if (e.source == kApp && e.variable == variable) out.push_back(e.value);
  return out;
}

// ---- (a) the database killed and restarted on the same port ----------------------------------

// Two widths: a vehicle that lost its setting would get the default (the first, 20 m) and see
// b1 (15 m to the side); with its requested 10 m it sees h1 and h2 only. pd = 1 and
// pclass = 1.0: every outcome is certain.
const char* kRestartBlock =
    "  AppTick = 4\n"
    "  CommsTick = 4\n"
    "  random_seed = 7\n"
    "  min_reset_interval = 0\n"
    "  min_classify_interval = 0\n"
    "  options_summary_interval = 1\n"
    "  swath_length = 4\n"
    "  sensor_config = width=20, exp=2, pclass=1.0\n"
    "  sensor_config = width=10, exp=4, pclass=1.0\n"
    "  hazard = x=5,y=31,label=h1,type=hazard\n"
    "  hazard = x=-15,y=61,label=b1,type=benign\n"
    "  hazard = x=5,y=91,label=h2,type=hazard\n";
const std::vector<std::string> kRestartMarkers = {
    "x=5,y=31,width=8,primary_color=green,type=triangle,label=h1",
    "x=-15,y=61,width=8,primary_color=light_blue,type=triangle,label=b1,fill_transparency=0.5",
    "x=5,y=91,width=8,primary_color=green,type=triangle,label=h2"};

class DatabaseRestart : public SensorProcess {
 protected:
  /// alpha drives north along x = 0 from `from_y` to `to_y`, waiting for each swath (10 m).
  void drive(int from_y, int to_y) {
    for (int y = from_y; y <= to_y; y += 2) {
      post("NODE_REPORT", node_report("alpha", 0, y));
      ASSERT_TRUE(wait_for([&](const moos::Message& m) {
        return m.key == "VIEW_POLYGON" && base::starts_with(m.sval, "pts={10," + n(y + 2) + ":");
      })) << "no 10 m swath at y " << y;
    }
  }

  /// Waits (bounded) until `var` = `value` is among all the mail, seen or not (a detection may
  /// arrive before the swath a drive waits for).
  bool received(const std::string& var, const std::string& value) {
    const double deadline = steady_now_s() + kPatience_s;
    auto has = [&] {
      return std::any_of(mail.begin(), mail.end(),
                         [&](const moos::Message& m) { return m.key == var && m.sval == value; });
    };
    while (!has() && steady_now_s() < deadline) {
      wait_for([](const moos::Message&) { return false; }, 0.01);
    }
    return has();
  }

  /// SIGKILL for moosdb-lite (no goodbye to anyone), then a new one on the same port.
  void kill_and_restart_server() {
    const int port = server->port();
    server->process().kill_now();
    server.reset();
    server.emplace(MOOSDB_LITE_PATH, server_args("db2.alog"), port);
    ASSERT_TRUE(server->ok()) << "moosdb-lite did not start again on port " << port;
  }
};

TEST_F(DatabaseRestart, SensorReconnectsReregistersRepostsItsMarkersAndKeepsItsState_Hardening) {
  start(kRestartBlock);
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=10,pd=1");
  ASSERT_TRUE(wait_for_value("UHZ_CONFIG_ACK_ALPHA", "vname=alpha,width=10,pd=1,pfa=1,pclass=1"));
  post("UHZ_SENSOR_REQUEST", "vname=alpha");
  drive(0, 40);
  ASSERT_TRUE(received("UHZ_DETECTION_REPORT_ALPHA", "x=5,y=31,label=h1"));
  const std::uint64_t connections = vehicle->connection_count();

  kill_and_restart_server();
  const double deadline = steady_now_s() + kPatience_s;
  while (vehicle->connection_count() == connections && steady_now_s() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_GT(vehicle->connection_count(), connections) << "the vehicle did not reconnect";
  // The sensor's mail through the new database: it reconnected and posts again.
  ASSERT_TRUE(wait_for([](const moos::Message& m) { return m.key == "UHZ_OPTIONS_SUMMARY"; }))
      << app->stderr_text();
  EXPECT_TRUE(app->running());

  // Its registrations reached the new database (it hears the vehicle), and the detection credit
  // of h1, earned before the restart, still buys an answer.
  post("UHZ_CLASSIFY_REQUEST", "vname=alpha,label=h1");
  ASSERT_TRUE(wait_for_value("UHZ_HAZARD_REPORT_ALPHA", "x=5,y=31,label=h1,type=hazard"));
  drive(42, 100);  // the 10 m swath: the setting survived
  ASSERT_TRUE(received("UHZ_DETECTION_REPORT_ALPHA", "x=5,y=91,label=h2"));

  stop_all();
  EXPECT_EQ(app_exit, 0) << app->stderr_text();
  const Alog log = test_support::read_alog(dir / "db2.alog");
  // The new database got the field's markers once, and nothing of the old configuration was
  // asked or acknowledged again.
  EXPECT_EQ(posted(log, "VIEW_MARKER"), kRestartMarkers);
  EXPECT_TRUE(posted(log, "UHZ_CONFIG_ACK").empty());
  EXPECT_EQ(posted(log, "UHZ_DETECTION_REPORT_ALPHA"), std::vector<std::string>{"x=5,y=91,label=h2"});
  EXPECT_EQ(posted(log, "UHZ_HAZARD_REPORT_ALPHA"),
            std::vector<std::string>{"x=5,y=31,label=h1,type=hazard"});
}

// ---- (b) a vehicle process killed mid-pass ----------------------------------------------------

/// A uSimSurveyVehicle block: deployed at once, north along x = `x_m` at 1.5 m/s.
std::string vehicle_block(const std::string& name, int x_m) {
  return "\nProcessConfig = uSimSurveyVehicle_" + name + "\n{\n  AppTick = 4\n  CommsTick = 4\n"
         "  vname = " + name + "\n  deploy = true\n  speed = 1.5\n"
         "  start_x = " + n(x_m) + "\n  start_y = 0\n  start_heading = 0\n"
         "  waypoints = pts={" + n(x_m) + ",0:" + n(x_m) + ",5000}\n}\n";
}

TEST_F(SensorProcess, AVehicleKilledMidPassLeavesTheOtherServed_Hardening) {
  warp = 40.0;  // 60 m of track per real second
  std::string block = "  AppTick = 4\n  random_seed = 5\n  swath_length = 4\n"
                      "  show_hazards = false\n"
                      "  sensor_config = width=20, exp=2, pclass=0.9\n";
  // Hazards every 5 m along betty's lane (x = 100) and archie's (x = 0).
  for (int y = 10; y <= 2000; y += 5)
    for (int x : {0, 100})
      block += "  hazard = x=" + n(x + 3) + ",y=" + n(y) + ",label=h" + n(x) + "_" + n(y) + ",type=hazard\n";
  extra_blocks = vehicle_block("archie", 0) + vehicle_block("betty", 100);
  start(block);
  ASSERT_TRUE(vehicle->register_variable("UHZ_DETECTION_REPORT"));
  const std::string mission = (dir / "m.moos").string();
  auto archie = Child::spawn(USIM_SURVEY_VEHICLE_PATH, {mission, "uSimSurveyVehicle_archie"});
  auto betty = Child::spawn(USIM_SURVEY_VEHICLE_PATH, {mission, "uSimSurveyVehicle_betty"});
  ASSERT_TRUE(archie && betty);

  std::map<std::string, int> detections;  // per vehicle
  bool archie_alive = true;
  auto watch = [&](const moos::Message& m) {
    if (m.key == "UHZ_DETECTION_REPORT") ++detections[m.sval.substr(0, m.sval.find(','))];
    return false;
  };
  // Keeps the live vehicles' sensors on and counts detections, until `done` or `real_s` passed.
  auto serve = [&](double real_s, const std::function<bool()>& done) {
    const double end = steady_now_s() + real_s;
    while (steady_now_s() < end && !done()) {
      post("UHZ_SENSOR_REQUEST", "vname=betty");
      if (archie_alive) post("UHZ_SENSOR_REQUEST", "vname=archie");
      wait_for(watch, 0.05);
    }
  };
  const auto never = [] { return false; };
  serve(kPatience_s, [&] { return detections["vname=archie"] > 0 && detections["vname=betty"] > 0; });
  ASSERT_GT(detections["vname=archie"], 0) << archie->stderr_text();
  ASSERT_GT(detections["vname=betty"], 0) << betty->stderr_text();

  archie->kill_now();  // mid-pass, without a goodbye
  archie_alive = false;
  serve(2.0, never);  // the sensor lets archie's leftovers pass
  const int archie_after_kill = detections["vname=archie"];
  const int betty_mid = detections["vname=betty"];
  serve(kPatience_s, [&] { return detections["vname=betty"] >= betty_mid + 5; });
  serve(1.0, never);
  EXPECT_EQ(detections["vname=archie"], archie_after_kill);  // nothing new for a dead vehicle
  EXPECT_GE(detections["vname=betty"], betty_mid + 5) << "betty is no longer served";
  EXPECT_TRUE(app->running()) << app->stderr_text();
  EXPECT_TRUE(betty->running());
}

// ---- (c) a client that stops reading -----------------------------------------------------------

/// The server's log lines about `client` (`client "NAME" (peer): ...`) other than its
/// connection: a warning, a throttle or a drop.
std::vector<std::string> actions_on(const MoosdbServer& server, const std::string& client) {
  std::vector<std::string> out;
  const std::string log = server.stderr_text();  // the split's views point into it
  for (const auto& line : base::split(log, '\n'))
    if (line.find("\"" + client + "\" (") != std::string::npos &&
        line.find("): connected") == std::string::npos)
      out.emplace_back(line);
  return out;
}

TEST_F(SensorProcess, AClientThatStopsReadingIsDroppedAloneAndTheSensorGoesOn_Hardening) {
  // A small output bound, so that the stuck client reaches it in a second.
  server_extra_args = {"--max-output-bytes=300000", "--moos_timeout=60"};
  std::string block = "  AppTick = 4\n  random_seed = 5\n  min_reset_interval = 0\n"
                      "  sensor_config = width=20, exp=2, pclass=0.9\n";
  for (int i = 0; i < 400; ++i)
    block += "  hazard = x=" + n(i) + ",y=" + n(2 * i) + ",label=o" + n(i) + ",type=hazard\n";
  start(block);

  // Registers for every variable of every client, then never reads (a tiny receive buffer).
  moosdb_lite::test::RawClient stuck;
  ASSERT_TRUE(stuck.connect(server->port(), 4096));
  ASSERT_TRUE(stuck.send_bytes(
      moos::protocol_banner() +
      moos::encode_packet({moos::test::identification("pStuck", true, moosdb_lite::test::moos_now())}) +
      moos::encode_packet({moos::test::wildcard("AppPattern=*,VarPattern=*,Interval=0", "pStuck")})));

  // The vehicle asks for the markers again and again: about 30 kB each time, to every reader.
  // What it got of the start-up markers depends on whether it registered before the app posted
  // them; it has all it will get once the first options summary (start() waits for it) is in.
  const auto markers_so_far = [&] {
    return static_cast<std::size_t>(std::count_if(
        mail.begin(), mail.end(), [](const moos::Message& m) { return m.key == "VIEW_MARKER"; }));
  };
  const std::size_t at_start = markers_so_far();
  std::size_t asked = 0;
  const double deadline = steady_now_s() + 4 * kPatience_s;
  while (actions_on(*server, "pStuck").empty() && steady_now_s() < deadline) {
    post("PMV_CONNECT", "pMarineViewer");
    ++asked;
    ASSERT_TRUE(wait_for_count("VIEW_MARKER", at_start + 400 * asked))
        << "the vehicle stopped getting markers after " << asked << " requests";
  }
  ASSERT_FALSE(actions_on(*server, "pStuck").empty())
      << "moosdb-lite never acted on the stuck client:\n" << server->stderr_text();

  // Everyone else is still served: the sensor answers, the vehicle gets every marker.
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=0.9");
  ASSERT_TRUE(wait_for_value("UHZ_CONFIG_ACK_ALPHA", "vname=alpha,width=20,pd=0.9,pfa=0.81,pclass=0.9"));
  post("PMV_CONNECT", "pMarineViewer");
  EXPECT_TRUE(wait_for_count("VIEW_MARKER", at_start + 400 * (asked + 1)));
  EXPECT_TRUE(app->running()) << app->stderr_text();
  EXPECT_TRUE(actions_on(*server, kApp).empty()) << server->stderr_text();
  EXPECT_TRUE(actions_on(*server, "vehicle_sim").empty()) << server->stderr_text();
}

}  // namespace
}  // namespace ufld_hazard_sensor
