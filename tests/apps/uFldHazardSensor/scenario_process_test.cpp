// uFldHazardSensor as a process on moosdb-lite: a scripted vehicle drives a straight
// track over known objects and sends the request messages; the payloads the app posts are
// checked against values computed by hand below, and the same inputs replayed through
// hazard_replay (same seed) give the same postings: the app adds nothing the engine did not
// decide. The held width: a max=1 width is held from its grant, before any sensor request.
#include <gtest/gtest.h>
#include <signal.h>

#include <map>

#include "hazard/engine.hpp"
#include "hazard/messages/config_ack.hpp"
#include "base/text.hpp"
#include "base/text.hpp"
#include "sensor_process.hpp"

namespace ufld_hazard_sensor {
namespace {

using test_support::Alog;
using test_support::Child;
using test_support::write_file;
using testing::is_framework_posting;
using testing::kPatience_s;
using testing::SensorProcess;
using testing::kApp;
using testing::n;
using testing::node_report;

// ---- hand computations ----------------------------------------------------------------------------

/// The swath of scenario A at (0, y), heading 0 (differences.md D1, D2, T1): W = 20 m to each side,
/// swath_length 4 m in total (2 m fore and aft); corners front-starboard, rear-starboard,
/// rear-port, front-port = (20, y+2) (20, y-2) (-20, y-2) (-20, y+2), FMT(., 1). The label is
/// FIX(pd, 2) alone (show_pd true, show_pfa false by default, D15); fill white (sensor on:
/// heading constant, so turn rate 0 <= 1.5 deg/s; SPD 1 <= 2 m/s).
std::string swath_a(int y) {
  return "pts={20," + n(y + 2) + ":20," + n(y - 2) + ":-20," + n(y - 2) + ":-20," + n(y + 2) +
         "},label=sensor_swath_alpha,msg=1.00,edge_color=green,fill_color=white,vertex_size=0,"
         "edge_size=0,fill_transparency=0.2";
}

/// ",time=<v>" removed: the engine's time in a circle is the only thing that legitimately
/// differs between two runs of the same inputs.
std::string without_time(const std::string& circle) {
  const auto at = circle.find(",time=");
  if (at == std::string::npos) return circle;
  const auto end = circle.find(',', at + 1);
  return circle.substr(0, at) + (end == std::string::npos ? "" : circle.substr(end));
}

/// What the app posted, per variable, in order (framework bookkeeping aside).
std::map<std::string, std::vector<std::string>> app_postings(const Alog& log) {
  std::map<std::string, std::vector<std::string>> out;
  for (const auto& e : log.entries) {
    if (e.source == kApp && !is_framework_posting(e.variable)) out[e.variable].push_back(e.value);
  }
  return out;
}

/// The comparable form of one run's postings. What legitimately depends on the iteration grid
/// (when iterations fall between the inputs), not on the inputs, is taken out:
/// - circles lose their time, and detection circles (12 vertices) and classification circles
///   (5 vertices) are compared as two sequences: an answer released one tick earlier or later
///   may fall before or after the next detection;
/// - the swath and the options summary, posted every iteration or interval, lose their
///   consecutive repeats (how often they repeat depends on the grid).
std::map<std::string, std::vector<std::string>> comparable(std::map<std::string, std::vector<std::string>> p) {
  for (auto& c : p["VIEW_CIRCLE"]) {
    c = without_time(c);
    const bool detection = c.find(",vertices=12,") != std::string::npos;
    p[detection ? "VIEW_CIRCLE (detections)" : "VIEW_CIRCLE (classifications)"].push_back(c);
  }
  p.erase("VIEW_CIRCLE");
  for (const char* var : {"VIEW_POLYGON", "UHZ_OPTIONS_SUMMARY"}) {
    auto& v = p[var];
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }
  for (auto it = p.begin(); it != p.end();) it = it->second.empty() ? p.erase(it) : std::next(it);
  return p;
}

// ---- the replay ----------------------------------------------------------------------------------

/// Runs hazard_replay on the inputs the app received (the server's log, subscribed variables
/// only) with the same mission, up to the app's last posting; returns its postings per variable.
std::map<std::string, std::vector<std::string>> replay(const test_support::ScratchDir& dir, const Alog& log) {
  std::vector<std::string> subscribed;
  for (const auto& v : hazard::Engine::subscriptions()) subscribed.emplace_back(v.name);
  std::string input = moos::alog_header("input.alog", log.logstart_s);
  double until_s = 0.0;
  for (const auto& e : log.entries) {
    if (e.source == kApp) until_s = std::max(until_s, e.time_s);
    if (e.source != kApp && std::find(subscribed.begin(), subscribed.end(), e.variable) != subscribed.end())
      input += moos::format_alog_line(e);
  }
  write_file(dir / "input.alog", input);
  auto r = Child::spawn(HAZARD_REPLAY_PATH,
                        {(dir / "m.moos").string(), (dir / "input.alog").string(),
                         "--until=" + base::fix(until_s, 3), "--output=" + (dir / "replay.alog").string()});
  EXPECT_TRUE(r.has_value());
  if (!r) return {};
  EXPECT_EQ(r->wait(60.0), 0) << r->stderr_text();
  std::map<std::string, std::vector<std::string>> out;
  for (const auto& e : test_support::read_alog(dir / "replay.alog").entries)
    out[e.variable].push_back(e.value);
  return out;
}

// ---- scenario A: certain outcomes, exact payloads ---------------------------------------------------

// pd = 1 and pclass = 1.0 make every outcome certain (detection iff u < pd with u in [0, 1);
// answer correct iff v <= pclass, docs/differences.md): the payloads below are exact.
const char* kBlockA =
    "  AppTick = 4\n"
    "  CommsTick = 4\n"
    "  random_seed = 7\n"
    "  min_reset_interval = 0\n"
    "  min_classify_interval = 0\n"
    "  options_summary_interval = 5\n"
    "  show_detections = 30\n"
    "  swath_length = 4\n"
    "  sensor_config = width=20, exp=2, pclass=1.0\n"
    "  sensor_config = width=10, exp=4, pclass=0.90\n"
    "  hazard = x=5,y=31,label=h1,type=hazard\n"
    "  hazard = x=-12.3456,y=61,label=b1,type=benign\n"
    "  hazard = x=14,y=91.25,label=h2,type=hazard\n";

// Width request 15: not an option, so the next lower one, 10 (D3): exp 4, pclass 0.90.
// pfa = 0.9^4 = 0.6561; the ack prints width FMT(10,1) = "10", pd FMT(0.9,3) = "0.9",
// pfa FMT(0.6561,3) = "0.656", pclass FMT(0.90,3) = "0.9" (D22, D23).
const std::string kAck1 = "vname=alpha,width=10,pd=0.9,pfa=0.656,pclass=0.9";
// Width 20 (min_reset_interval 0: allowed), pd 1: pfa = 1^2 = 1; pclass 1.0 -> "1".
const std::string kAck2 = "vname=alpha,width=20,pd=1,pfa=1,pclass=1";

// Objects, FMT(., 2): h1 (5, 31); b1 (-12.3456 -> "-12.35", 61); h2 (14, 91.25).
// Along the track x = 0, y = 0, 2, ..., 100 (heading 0) an object is inside when
// |y_obj - y| <= 2 and |x_obj| <= 20: h1 at y = 30, 32 (entry at 30); b1 at 60, 62; h2 at 90, 92.
// No object is within 0.75 m of an edge.
const std::vector<std::string> kDetectionsA = {"x=5,y=31,label=h1", "x=-12.35,y=61,label=b1",
                                               "x=14,y=91.25,label=h2"};
// Classification: the true type (pclass 1), D25.
const std::vector<std::string> kAnswersA = {"x=5,y=31,label=h1,type=hazard",
                                            "x=-12.35,y=61,label=b1,type=benign",
                                            "x=14,y=91.25,label=h2,type=hazard"};
// Circles (docs/messages.md; D19): radius 10; detection 12 vertices, white, duration =
// show_detections
// (30); classification 5 vertices, yellow (hazard) / green (benign), no duration.
std::string circle(const std::string& at, int vertices, const std::string& color, bool duration) {
  return at + ",radius=10,vertices=" + n(vertices) + (duration ? ",duration=30" : "") + ",edge_color=" +
         color + ",fill_color=" + color + ",vertex_size=0,edge_size=1,fill_transparency=0.3";
}
// Markers (manual 7.6, D17, D18): width 8, triangles, hazards green, benign light_blue with
// fill 1 - 0.5 (no hr).
const std::vector<std::string> kMarkersA = {
    "x=5,y=31,width=8,primary_color=green,type=triangle,label=h1",
    "x=-12.35,y=61,width=8,primary_color=light_blue,type=triangle,label=b1,fill_transparency=0.5",
    "x=14,y=91.25,width=8,primary_color=green,type=triangle,label=h2"};
// File order, pclass= keys, values as written (D21).
const std::string kSummaryA = "width=20,exp=2,pclass=1.0:width=10,exp=4,pclass=0.90";

TEST_F(SensorProcess, ScriptedVehicleGetsTheHandComputedPayloads) {
  start(kBlockA);
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=15,pd=0.9");
  ASSERT_TRUE(wait_for_value("UHZ_CONFIG_ACK_ALPHA", kAck1));
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=1");
  ASSERT_TRUE(wait_for_value("UHZ_CONFIG_ACK_ALPHA", kAck2));
  post("UHZ_SENSOR_REQUEST", "vname=alpha");
  for (int y = 0; y <= 100; y += 2) {
    post("NODE_REPORT", node_report("alpha", 0, y));
    ASSERT_TRUE(wait_for_value("VIEW_POLYGON", swath_a(y))) << "y " << y;
    sleep_ticks(1.5);  // so that hazard_replay's 4 Hz grid also samples every pose
  }
  for (const char* label : {"h1", "b1", "h2"}) post("UHZ_CLASSIFY_REQUEST", std::string("vname=alpha,label=") + label);
  for (const auto& answer : kAnswersA) ASSERT_TRUE(wait_for_value("UHZ_HAZARD_REPORT_ALPHA", answer)) << answer;
  // A second request for h1 has no detection credit left: refused, nothing posted (D7, D37).
  post("UHZ_CLASSIFY_REQUEST", "vname=alpha,label=h1");
  post("PMV_CONNECT", "pMarineViewer");
  for (const auto& marker : kMarkersA) ASSERT_TRUE(wait_for_value("VIEW_MARKER", marker)) << marker;
  sleep_ticks(4);

  const Alog log = stop_and_read_log();
  EXPECT_EQ(app_exit, 0) << app->stderr_text();
  auto posted = app_postings(log);
  EXPECT_EQ(posted["UHZ_CONFIG_ACK"], (std::vector<std::string>{kAck1, kAck2}));  // D22
  EXPECT_EQ(posted["UHZ_CONFIG_ACK_ALPHA"], (std::vector<std::string>{kAck1, kAck2}));
  std::vector<std::string> general, hazard_general;
  for (const auto& d : kDetectionsA) general.push_back("vname=alpha," + d);  // D24
  for (const auto& a : kAnswersA) hazard_general.push_back("vname=alpha," + a);  // D25
  EXPECT_EQ(posted["UHZ_DETECTION_REPORT"], general);
  EXPECT_EQ(posted["UHZ_DETECTION_REPORT_ALPHA"], kDetectionsA);
  EXPECT_EQ(posted["UHZ_HAZARD_REPORT"], hazard_general);
  EXPECT_EQ(posted["UHZ_HAZARD_REPORT_ALPHA"], kAnswersA);

  std::vector<std::string> markers = kMarkersA;  // start-up, then PMV_CONNECT
  markers.insert(markers.end(), kMarkersA.begin(), kMarkersA.end());
  EXPECT_EQ(posted["VIEW_MARKER"], markers);
  EXPECT_TRUE(posted["VIEW_SEGLIST"].empty());  // no object has an aspect

  // Circles: three detections during the track, then three answers.
  const std::vector<std::string> at = {"x=5,y=31", "x=-12.35,y=61", "x=14,y=91.25"};
  const std::vector<std::string> expected_circles = {
      circle(at[0], 12, "white", true),   circle(at[1], 12, "white", true),
      circle(at[2], 12, "white", true),   circle(at[0], 5, "yellow", false),
      circle(at[1], 5, "green", false),   circle(at[2], 5, "yellow", false)};
  std::vector<std::string> circles;
  for (const auto& e : log.entries) {
    if (e.source != kApp || e.variable != "VIEW_CIRCLE") continue;
    circles.push_back(without_time(e.value));
    // time = the engine's MOOS time (FMT(., 2)) of the iteration that posted it.
    const auto t = base::parse_number(e.value.substr(e.value.find(",time=") + 6,
                                                       e.value.find(",vertex_size") - e.value.find(",time=") - 6));
    ASSERT_TRUE(t.has_value()) << e.value;
    EXPECT_NEAR(*t, log.logstart_s + e.time_s, 1.0) << e.value;
  }
  EXPECT_EQ(circles, expected_circles);

  // The swath at every pose, in order, once the vehicle was sensing (D12).
  std::vector<std::string> swaths;
  for (int y = 0; y <= 100; y += 2) swaths.push_back(swath_a(y));
  EXPECT_EQ(comparable(posted)["VIEW_POLYGON"], swaths);

  // The options summary: always the same text, first at the first iteration and then about
  // options_summary_interval (5 s) apart. The log stamps a posting when notify() runs, a few
  // real milliseconds after the iteration started (x20 warp), hence the margin of one tick
  // (0.25 s); the exact timing is checked on the bus.
  std::vector<double> summary_times;
  for (const auto& e : log.entries) {
    if (e.source != kApp || e.variable != "UHZ_OPTIONS_SUMMARY") continue;
    EXPECT_EQ(e.value, kSummaryA);
    summary_times.push_back(e.time_s);
  }
  ASSERT_GE(summary_times.size(), 3u);
  for (std::size_t i = 1; i < summary_times.size(); ++i) EXPECT_GE(summary_times[i] - summary_times[i - 1], 5.0 - 0.25);

  // The same inputs through hazard_replay: the same postings.
  EXPECT_EQ(comparable(replay(dir, log)), comparable(posted));
}

// ---- scenario B: outcomes decided by the dice --------------------------------------------------------

std::string block_b() {
  std::string b =
      "  AppTick = 4\n"
      "  random_seed = 3\n"
      "  min_classify_interval = 2\n"
      "  swath_length = 4\n"
      "  sensor_config = width=20, exp=2, pclass=0.7\n"
      "  sensor_config = width=10, exp=4, pclass=0.90\n";
  // 40 objects 5 m apart along y, at half-metre offsets so no pose (even y) is within 0.5 m of
  // an edge; every third a hazard; some resemblance and aspect data.
  for (int i = 0; i < 40; ++i) {
    b += "  hazard = x=" + base::fmt((i % 2 ? 9.0 : -7.0) + 0.5 * (i % 3)) + ",y=" + base::fmt(5.0 * i + 3.5) +
         ",label=o" + n(i) + ",type=" + (i % 3 == 0 ? "hazard" : "benign") + (i % 4 == 1 ? ",hr=0.4" : "") +
         (i % 5 == 2 ? ",aspect=45,aspect_min=10,aspect_max=40" : "") + "\n";
  }
  return b;
}

TEST_F(SensorProcess, SameInputsThroughHazardReplayGiveTheSamePostings) {
  start(block_b());
  post("UHZ_CONFIG_REQUEST", "vname=alpha,width=20,pd=0.6");
  // pfa = 0.6^2 = 0.36 (D23).
  ASSERT_TRUE(wait_for_value("UHZ_CONFIG_ACK_ALPHA", "vname=alpha,width=20,pd=0.6,pfa=0.36,pclass=0.7"));
  post("UHZ_SENSOR_REQUEST", "vname=alpha");
  int requested = 0;
  for (int y = 0; y <= 200; y += 2) {
    post("NODE_REPORT", node_report("alpha", 0, y));
    ASSERT_TRUE(wait_for([&](const moos::Message& m) {
      // Classify what is detected. One priority for all: the answers then come in request
      // order whenever they are released (with mixed priorities, which requests wait together
      // in the queue would depend on the iteration grid).
      if (m.key == "UHZ_DETECTION_REPORT_ALPHA") {
        const auto from = m.sval.find("label=") + 6;
        const auto label = m.sval.substr(from, m.sval.find(',', from) - from);
        vehicle->notify("UHZ_CLASSIFY_REQUEST", "vname=alpha,label=" + label + ",priority=70");
        ++requested;
      }
      return m.key == "VIEW_POLYGON" && base::starts_with(m.sval, "pts={20," + n(y + 2) + ":");
    })) << "y " << y;
    sleep_ticks(1.5);
  }
  // One answer per min_classify_interval (2 s) per vehicle (D9).
  ASSERT_TRUE(wait_for_count("UHZ_HAZARD_REPORT_ALPHA", static_cast<std::size_t>(requested)));

  const Alog log = stop_and_read_log();
  EXPECT_EQ(app_exit, 0) << app->stderr_text();
  const auto posted = app_postings(log);
  // The dice decided: some objects were missed and some answers were wrong (seed 3 is fixed,
  // so these counts are too).
  const auto& detections = posted.at("UHZ_DETECTION_REPORT_ALPHA");
  EXPECT_GT(detections.size(), 5u);
  EXPECT_LT(detections.size(), 40u);
  int wrong = 0;
  for (const auto& answer : posted.at("UHZ_HAZARD_REPORT_ALPHA")) {
    const int i = std::stoi(answer.substr(answer.find("label=o") + 7));
    wrong += answer.find(i % 3 == 0 ? ",type=benign" : ",type=hazard") != std::string::npos ? 1 : 0;
  }
  EXPECT_GT(wrong, 0);
  EXPECT_EQ(comparable(replay(dir, log)), comparable(posted));
}

// ---- the held width: a width limited by max=1 is held from the moment it is granted ---------

TEST_F(SensorProcess, AMaxWidthIsHeldFromItsGrantUntil600sWithoutARequest) {
  warp = 100.0;  // 600 MOOS seconds in 6 real ones
  start("  sensor_config = width=10, exp=4, pclass=0.8\n"
        "  sensor_config = width=25, exp=4, pclass=0.8, max=1\n"
        "  sensor_config = width=50, exp=4, pclass=0.8\n"
        "  hazard = x=1000,y=1000,label=far,type=hazard\n"
        "  options_summary_interval = 1\n  show_hazards = false\n  show_swath = false\n");
  ASSERT_TRUE(vehicle->register_variable("UHZ_CONFIG_ACK"));
  // The width each vehicle is granted: its UHZ_CONFIG_ACK (mail of the app, with its MOOS time).
  auto granted = [&](const std::string& vname) -> std::optional<moos::Message> {
    const std::string prefix = "vname=" + vname + ",";
    if (!wait_for([&](const moos::Message& m) {
          return m.key == "UHZ_CONFIG_ACK" && m.sval.rfind(prefix, 0) == 0;
        })) {
      return std::nullopt;
    }
    return mail[seen - 1];
  };
  auto width_of = [](const moos::Message& ack) {
    return hazard::parse_config_ack(ack.sval).value->width_m;
  };
  auto request_25 = [&](const std::string& vname) {
    post("UHZ_CONFIG_REQUEST", "vname=" + vname + ",width=25,pd=0.9");
  };

  request_25("alpha");
  const auto alpha = granted("alpha");
  ASSERT_TRUE(alpha) << app->stderr_text();
  EXPECT_EQ(width_of(*alpha), 25);
  post("NODE_REPORT", "NAME=alpha,X=0,Y=0,SPD=1,HDG=0");  // alpha only ever sends node reports
  request_25("bravo");
  const auto bravo = granted("bravo");
  ASSERT_TRUE(bravo);
  EXPECT_EQ(width_of(*bravo), 10);  // 25 is held by alpha: the next lower free width
  EXPECT_LT(bravo->time - alpha->time, hazard::kWidthHoldWindow_s / 2);

  // Wait (alpha moving) until the app's clock is past 600 s after alpha's grant.
  const double freed_s = alpha->time + hazard::kWidthHoldWindow_s + 1.0;
  double y = 0.0;
  auto alpha_moves_until_freed = [&](const moos::Message& m) {
    if (m.key != "UHZ_OPTIONS_SUMMARY") return false;  // one a MOOS second
    post("NODE_REPORT", "NAME=alpha,X=0,Y=" + base::fmt(++y) + ",SPD=1,HDG=0");
    return m.time >= freed_s;
  };
  ASSERT_TRUE(wait_for(alpha_moves_until_freed, hazard::kWidthHoldWindow_s / warp + kPatience_s));
  request_25("delta");
  const auto delta = granted("delta");
  ASSERT_TRUE(delta);
  EXPECT_EQ(width_of(*delta), 25);  // alpha's hold has ended: granted
}

}  // namespace
}  // namespace ufld_hazard_sensor
