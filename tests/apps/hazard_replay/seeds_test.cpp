// hazard_replay --seeds=A..B: one JSON line per seed, each the same counts as that seed's own
// replay (its .alog's detection and hazard reports).
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "base/text.hpp"
#include "hazard/messages/node_report.hpp"
#include "replay_support.hpp"

namespace hazard_replay {
namespace {

using test_support::alog_entries;
using test_support::ScratchDir;
using test_support::write_file;

// Ten benign and ten hazard objects on a line the vehicle drives along twice; every detection
// asks for a classification, so both counts move with the seed.
void make_study(const ScratchDir& dir) {
  std::string field;
  for (int i = 0; i < 20; ++i) {
    field += "hazard = x=" + std::to_string(i * 10) + ",y=5,label=o" + std::to_string(i) +
             (i % 2 ? ",type=hazard\n" : ",type=benign\n");
  }
  write_file(dir / "field.txt", field);
  write_file(dir / "m.moos", testing::mission("  hazard_file = field.txt\n"
                                              "  sensor_config = width=25, exp=4, pclass=0.7\n"
                                              "  show_hazards = false\n"
                                              "  min_classify_interval = 0\n"));
  std::vector<testing::Line> lines = {{0.0, "UHZ_SENSOR_REQUEST", "vname=v"}};
  for (int k = 0; k <= 280; ++k) {
    hazard::NodeReport r;
    r.name = "v";
    r.x_m = k <= 140 ? k * 1.5 - 10 : (280 - k) * 1.5 - 10;
    r.y_m = 0;
    r.speed_mps = 1.5;
    r.heading_deg = k <= 140 ? 90 : 270;
    lines.push_back({k * 1.0, "NODE_REPORT", hazard::format_node_report(r)});
    for (int i = 0; i < 20; ++i)
      lines.push_back({k + 0.5, "UHZ_CLASSIFY_REQUEST", "vname=v,label=o" + std::to_string(i)});
  }
  write_file(dir / "in.alog", testing::alog(lines));
}

std::string expected_line(const ScratchDir& dir, int seed) {
  const auto r = testing::run(dir, {"m.moos", "in.alog", "--seed=" + std::to_string(seed)});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  int detections = 0, classifications = 0;
  for (const moos::AlogEntry& e : alog_entries(r.out)) {
    detections += e.variable == "UHZ_DETECTION_REPORT";
    classifications += e.variable == "UHZ_HAZARD_REPORT";
  }
  return "{\"seed\":" + std::to_string(seed) + ",\"detections\":" + std::to_string(detections) +
         ",\"classifications\":" + std::to_string(classifications) + "}";
}

TEST(ReplaySeeds, OneLinePerSeedMatchingEachSeedsOwnReplay) {
  ScratchDir dir;
  make_study(dir);
  const auto r = testing::run(dir, {"m.moos", "in.alog", "--seeds=3..6"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string_view> lines = base::split(base::trim(r.out), '\n');
  ASSERT_EQ(lines.size(), 4u) << r.out;
  std::set<std::string> distinct;
  for (int seed = 3; seed <= 6; ++seed) {
    const std::string want = expected_line(dir, seed);
    EXPECT_EQ(lines[static_cast<std::size_t>(seed - 3)], want);
    distinct.insert(want.substr(want.find(',')));
  }
  EXPECT_GT(distinct.size(), 1u);  // the seed matters in this study
  EXPECT_EQ(testing::run(dir, {"m.moos", "in.alog", "--seeds=3..6"}).out, r.out);
}

}  // namespace
}  // namespace hazard_replay
