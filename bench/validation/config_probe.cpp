// config_probe: posts a fixed list of UHZ_CONFIG_REQUESTs to the original uFldHazardSensor and
// to ours, each through its own MOOSDB on a fresh port, and prints what each acknowledged, side
// by side as a markdown table (docs/validation.md, "Where the rulings differ"). Every request
// shows one ruling of docs/differences.md: the width choice (D3), the default setting (D4), the
// reset window (D11), the acknowledgements (D22), who may configure a vehicle.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "base/text.hpp"
#include "bench_support.hpp"
#include "moos/tcp_client.hpp"

namespace {

constexpr const char* kHelp = R"(Usage: config_probe --original=PATH [OPTIONS]

Posts the same UHZ_CONFIG_REQUESTs to the original uFldHazardSensor and to ours (the manual's
five sensor settings, widths 18/30/50/65/80, min_reset_interval 300 s) and prints the
acknowledgements each posted after each request.

  --original=PATH    the original uFldHazardSensor (required)
  --sensor=PATH      ours (default: the one built with this benchmark)
  --moosdb=PATH      the MOOSDB (default: our moosdb-lite)
  --work-dir=DIR     where the missions and logs go (default: a new /tmp folder)
)";

/// One request: the text, and the community it comes from (the vehicle's own unless given).
struct Probe {
  std::string text;
  std::string community;
  std::string ruling;
};

const std::vector<Probe>& probes() {
  static const std::vector<Probe> list = {
      {"vname=v1,width=45,pd=0.9", "v1", "D3: width between two settings"},
      {"vname=v2,pd=0.9", "v2", "D4, D22: pd only, no setting yet"},
      {"vname=v2,width=65,pd=0.8", "v2", "D4: width after the default setting"},
      {"vname=v1,width=18,pd=0.7", "v1", "D11: width inside the reset window"},
      {"vname=v3,width=30,pd=0.9", "shoreside", "sender's community is not the vehicle"},
  };
  return list;
}

constexpr double kWarp = 10;
constexpr double kWait_real_s = 1.5;     // after each request: acks come within a tick or two
constexpr double kStartup_real_s = 30;

std::string mission(int port) {
  std::string text = "ServerHost = localhost\nServerPort = " + std::to_string(port) + "\n";
  text += "Community = shoreside\nMOOSTimeWarp = " + base::format_g(kWarp) + "\n\n";
  text += "ProcessConfig = uFldHazardSensor\n{\n  AppTick = 4\n  CommsTick = 4\n";
  text += "  sensor_config = width=80, exp=2, pclass=0.60\n";
  text += "  sensor_config = width=65, exp=4, pclass=0.75\n";
  text += "  sensor_config = width=50, exp=6, pclass=0.85\n";
  text += "  sensor_config = width=30, exp=12, pclass=0.93\n";
  text += "  sensor_config = width=18, exp=20, pclass=0.97\n";
  text += "  min_reset_interval = 300\n  show_hazards = false\n";
  text += "  hazard = x=0,y=0,label=1,type=hazard\n}\n";
  return text;
}

/// The acknowledgements one sensor posted after each probe ("VAR = value", in arrival order).
std::optional<std::vector<std::vector<std::string>>> run(const std::string& sensor,
                                                         const std::string& moosdb,
                                                         const std::string& dir) {
  const auto port = bench::free_tcp_port();
  if (!port) return std::nullopt;
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/mission.moos") << mission(*port);
  bench::Process db, app;
  if (!db.start(moosdb, {"mission.moos"}, dir, dir + "/moosdb")) return std::nullopt;
  moos::TcpClientOptions options;
  options.port = *port;
  options.name = "uConfigProbe";
  options.time_warp = kWarp;
  moos::TcpClient client(options);
  std::mutex mutex;
  std::vector<moos::Message> inbox;
  client.set_on_mail([&] {
    auto mail = client.fetch();
    std::lock_guard<std::mutex> lock(mutex);
    for (auto& m : mail) inbox.push_back(std::move(m));
  });
  client.register_wildcard("UHZ_CONFIG_ACK*");
  client.register_variable("APPCAST");
  std::vector<std::vector<std::string>> acks;
  const auto take = [&] {
    std::lock_guard<std::mutex> lock(mutex);
    return std::exchange(inbox, {});
  };
  const auto finish = [&](bool ok) -> std::optional<std::vector<std::vector<std::string>>> {
    app.stop(5);
    client.close();
    db.stop(5);
    if (!ok) return std::nullopt;
    return acks;
  };
  if (!client.start() || !client.wait_until_connected(15)) return finish(false);
  if (!app.start(sensor, {"mission.moos", "uFldHazardSensor"}, dir, dir + "/sensor"))
    return finish(false);
  // Ready when it iterates: its first APPCAST answers this request.
  const double deadline = bench::steady_now_s() + kStartup_real_s;
  bool ready = false;
  while (!ready && bench::steady_now_s() < deadline) {
    client.notify("APPCAST_REQ", "node=shoreside,app=uFldHazardSensor,duration=3,key=probe,thresh=any");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    for (const auto& m : take()) ready = ready || m.key == "APPCAST";
  }
  if (!ready) return finish(false);
  for (const auto& probe : probes()) {
    moos::Message m = moos::make_string_notify("UHZ_CONFIG_REQUEST", probe.text, std::string(),
                                               moos::kUnsetDouble);
    m.community = probe.community;
    client.post(std::move(m));
    std::this_thread::sleep_for(std::chrono::duration<double>(kWait_real_s));
    acks.emplace_back();
    for (const auto& a : take())
      if (base::starts_with(a.key, "UHZ_CONFIG_ACK")) acks.back().push_back(a.key + " = " + a.sval);
  }
  return finish(true);
}

std::string cell(const std::vector<std::string>& acks) {
  if (acks.empty()) return "(none)";
  std::string text;
  for (const auto& a : acks) text += (text.empty() ? "`" : "<br>`") + a + "`";
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  using moos::SwitchKind;
  using moos::switch_rule;
  static const moos::SwitchTable table = bench::bench_switch_table(
      {switch_rule("--original", SwitchKind::kText, "a program"),
       switch_rule("--sensor", SwitchKind::kText, "a program"),
       switch_rule("--moosdb", SwitchKind::kText, "a program"),
       switch_rule("--work-dir", SwitchKind::kText, "a folder")});
  const auto switches = bench::read_switches("config_probe", argc, argv, table, kHelp);
  if (!switches) return 2;
  const auto original = switches->text("--original");
  if (!original) {
    std::cerr << "config_probe: --original=PATH is required (see --help)\n";
    return 2;
  }
  const std::string ours = bench::absolute_program(switches->text("--sensor").value_or(HAZARD_SENSOR_PROGRAM));
  const std::string moosdb =
      bench::absolute_program(switches->text("--moosdb").value_or(HAZARD_MOOSDB_LITE_PROGRAM));
  const std::string dir = bench::work_folder(switches->text("--work-dir").value_or(""),
                                             "config_probe", std::cerr);
  if (dir.empty()) return 1;
  const auto theirs = run(bench::absolute_program(*original), moosdb, dir + "/original");
  const auto mine = run(ours, moosdb, dir + "/ours");
  if (!theirs || !mine) {
    std::cerr << "config_probe: a sensor did not start or answer (see " << dir << ")\n";
    return 1;
  }
  std::cout << "| request (from community) | ruling | original | ours |\n|---|---|---|---|\n";
  for (std::size_t i = 0; i < probes().size(); ++i) {
    const auto& p = probes()[i];
    std::cout << "| `" << p.text << "` (" << p.community << ") | " << p.ruling << " | "
              << cell((*theirs)[i]) << " | " << cell((*mine)[i]) << " |\n";
  }
  return 0;
}
