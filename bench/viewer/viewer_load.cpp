// viewer_load: the traffic of a busy mission for pWebViewer's CPU benchmark (cpu_bench.sh,
// docs/viewer.md "Benchmarks"). One MOOS client posts, paced on MOOS time:
//   - NODE_REPORT for `--vehicles` vehicles at 4 Hz each (circles of 100 m, 2 m/s);
//   - per vehicle every 5 s an unlabelled VIEW_CIRCLE with duration 10 (a detection);
//   - 200 labelled VIEW_MARKERs at the start (a hazard field), then one marker moved per second;
// for `--sim-seconds` MOOS seconds, then exits 0 (1 when it cannot connect or a post fails).
//
//   viewer_load --port=P [--warp=50] [--vehicles=10] [--sim-seconds=3600]

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <thread>

#include "base/text.hpp"
#include "moos/command_line.hpp"
#include "moos/limits.hpp"
#include "moos/tcp_client.hpp"

namespace {

constexpr double kReportPeriod_s = 0.25;
constexpr double kCirclePeriod_s = 5.0;
constexpr int kMarkers = 200;

std::string node_report(int vehicle, double t_s) {
  const double angle = t_s * 0.02 + vehicle;  // 2 m/s on a 100 m circle
  const double x = 100.0 * std::cos(angle) + 250.0 * vehicle;
  const double y = 100.0 * std::sin(angle);
  return "NAME=v" + std::to_string(vehicle) + ",X=" + base::fix(x, 2) + ",Y=" + base::fix(y, 2) +
         ",SPD=2,HDG=" + base::fix(base::norm360(90.0 - angle * 57.29578), 1) +
         ",TYPE=kayak,LENGTH=4,TIME=" + base::fix(t_s, 2);
}

std::string marker(int index, double shift_m) {
  return "x=" + base::fix(index % 20 * 25.0 + shift_m, 1) + ",y=" + base::fix(-50.0 - index / 20 * 25.0, 1) +
         ",width=8,type=triangle,primary_color=green,label=m" + std::to_string(index);
}

// The load's switches, on libmoos's one command-line parser.
moos::SwitchTable switch_table() {
  using moos::SwitchKind;
  moos::SwitchTable t;
  t.rules = {moos::switch_rule("--port", SwitchKind::kInteger, "not a port", moos::kConnectPortRange),
             moos::switch_rule("--warp", SwitchKind::kNumber, "not a warp", moos::kTimeWarpRange),
             moos::switch_rule("--vehicles", SwitchKind::kInteger, "not a count", moos::kPositive),
             moos::switch_rule("--sim-seconds", SwitchKind::kNumber, "not seconds", moos::kPositive)};
  t.bad_value = [](const std::string& arg, const moos::SwitchRule& r) { return arg + ": " + r.problem; };
  t.unknown = [](const std::string& arg) { return arg + ": unknown switch"; };
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const moos::SwitchValues switches =
      moos::parse_switches(std::vector<std::string>(argv + 1, argv + argc), switch_table());
  for (const std::string& error : switches.errors) std::cerr << "viewer_load: " << error << "\n";
  if (!switches.errors.empty()) return 2;
  auto number = [&](const char* flag, double fallback) {
    return switches.number(flag).value_or(fallback);
  };
  moos::TcpClientOptions options;
  options.host = "127.0.0.1";
  options.port = static_cast<int>(number("--port", 9000));
  options.name = "viewer_load";
  options.time_warp = number("--warp", 50);
  options.tw_delay_factor_ms = 0.0;
  const int vehicles = static_cast<int>(number("--vehicles", 10));
  const double sim_s = number("--sim-seconds", 3600);

  moos::TcpClient client(options);
  if (!client.start() || !client.wait_until_connected(5.0)) {
    std::cerr << "viewer_load: cannot connect to port " << options.port << "\n";
    return 1;
  }
  bool ok = true;
  for (int i = 0; i < kMarkers; ++i) ok = client.notify("VIEW_MARKER", marker(i, 0.0)) && ok;

  const auto start = std::chrono::steady_clock::now();
  long posts = kMarkers;
  for (long tick = 0; ok && tick * kReportPeriod_s < sim_s; ++tick) {
    const double t = tick * kReportPeriod_s;
    std::this_thread::sleep_until(start + std::chrono::duration<double>(t / options.time_warp));
    for (int v = 0; v < vehicles; ++v) ok = client.notify("NODE_REPORT", node_report(v, t)) && ok;
    posts += vehicles;
    if (std::fmod(t, kCirclePeriod_s) == 0.0) {
      for (int v = 0; v < vehicles; ++v)
        ok = client.notify("VIEW_CIRCLE", "x=" + base::fix(250.0 * v, 1) +
                                              ",y=0,radius=10,duration=10,edge_color=yellow,fill_transparency=0.3") && ok;
      posts += vehicles;
    }
    if (std::fmod(t, 1.0) == 0.0) {
      ok = client.notify("VIEW_MARKER", marker(static_cast<int>(t) % kMarkers, 5.0)) && ok;
      ++posts;
    }
  }
  ok = client.flush(10.0) && ok;
  client.close();
  std::cout << "viewer_load: " << posts << " postings over " << sim_s << " simulated s\n";
  return ok ? 0 : 1;
}
