// The held width through the hazard_replay binary: a width limited by max=1 is held from the moment
// it is granted (docs/differences.md D20), so replaying a log gives what the sensor gives.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "hazard/engine.hpp"
#include "hazard/messages/config_ack.hpp"
#include "replay_support.hpp"

namespace hazard_replay {
namespace {

using test_support::alog_entries;
using test_support::ScratchDir;
using test_support::write_file;
using testing::alog;
using testing::Line;
using testing::mission;
using testing::node_report;
using testing::run;

std::string width_request(const std::string& vname) {
  return "vname=" + vname + ",width=25,pd=0.9";
}

TEST(ReplayHeldWidth, AMaxWidthIsHeldFromItsGrantUntil600sWithoutARequest) {
  ScratchDir dir;
  write_file(dir / "m.moos", mission("  AppTick = 1\n"
                                     "  sensor_config = width=10, exp=4, pclass=0.8\n"
                                     "  sensor_config = width=25, exp=4, pclass=0.8, max=1\n"
                                     "  sensor_config = width=50, exp=4, pclass=0.8\n"
                                     "  hazard = x=1000,y=1000,label=far,type=hazard\n"
                                     "  show_hazards = false\n  show_swath = false\n"));
  // A is granted 25 m and then only sends node reports; B asks a second later, C just before
  // A's hold ends, D when it has ended (600 s with no configuration or sensor request from A).
  const double hold_s = hazard::kWidthHoldWindow_s;
  std::vector<Line> in = {{0.0, "UHZ_CONFIG_REQUEST", width_request("a")},
                          {1.0, "UHZ_CONFIG_REQUEST", width_request("b")},
                          {hold_s - 1.0, "UHZ_CONFIG_REQUEST", width_request("c")},
                          {hold_s, "UHZ_CONFIG_REQUEST", width_request("d")}};
  for (double t = 0.5; t <= hold_s + 1.0; t += 1.0)
    in.push_back({t, "NODE_REPORT", node_report("a", 0, t)});
  write_file(dir / "in.alog", alog(in));

  const auto r = run(dir, {"m.moos", "in.alog", "--seed=1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::map<std::string, double> granted_m;  // vehicle -> width of its (only) ack
  for (const auto& e : alog_entries(r.out)) {
    if (e.variable != "UHZ_CONFIG_ACK") continue;
    const auto ack = hazard::parse_config_ack(e.value);
    ASSERT_TRUE(ack) << e.value;
    granted_m[ack.value->vname] = ack.value->width_m;
  }
  EXPECT_EQ(granted_m["a"], 25);
  EXPECT_EQ(granted_m["b"], 10);  // 25 is held by A: the next lower free width
  EXPECT_EQ(granted_m["c"], 10);
  EXPECT_EQ(granted_m["d"], 25);  // A's hold has ended
}

}  // namespace
}  // namespace hazard_replay
