// Only the effects a scene calls for (effects.hpp): for every effect, a scene that does
// not use it gives byte-identical outputs (every posting, event and warning of every call) with
// the effect's switch on or off, and a scene that uses it changes exactly the outcomes it should.
// An effect that is off allocates nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <GeographicLib/LocalCartesian.hpp>

#include "hazard/dice.hpp"
#include "hazard/driver.hpp"
#include "scenario/reference_scenario.hpp"
#include "hazard/sensor_model.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::entries;
using testing::node_report;

// ---- a scene: a configuration block, timed mail, iterations at 4 Hz ------------------------------

struct Scene {
  std::string block;
  std::vector<TimedMail> mail;  // sorted by time
  double end_s = 0.0;
  MissionOrigin origin;
};

struct SceneRun {
  std::string text;                    // every output of every engine call, in order
  std::vector<std::string> decisions;  // "vehicle label pass purpose outcome", in order
  std::set<std::string> detected;      // labels of detection reports
};

std::string serialise(const Outputs& o) {
  std::string s;
  for (const auto& p : o.postings) s += "P " + p.variable + "=" + p.value + "\n";
  for (const auto& e : o.events) s += "E " + e + "\n";
  for (const auto& w : o.run_warnings) s += "W " + w + "\n";
  for (const auto& w : o.retracted_run_warnings) s += "R " + w + "\n";
  for (const auto& w : o.config_warnings) s += "C " + w + "\n";
  return s;
}

SceneRun run(const Scene& scene, const std::string& switch_line) {
  hazard::Driver driver(load_configuration(entries(scene.block + switch_line),
                                   [](const std::string&) { return base::Result<std::string>::fail("no file"); }, scene.origin),
                SeedChoice{77, SeedSource::kCommandLine});
  SceneRun r;
  driver.set_decision_observer(
      [&](const Decision& d) { r.decisions.push_back(testing::decision_tuple(d)); });
  r.text = serialise(driver.start(0).outputs);
  constexpr double kTick_hz = 4.0;
  play_mail(
      driver, scene.mail, kTick_hz, scene.end_s,
      [&](const Outputs& out) { r.text += serialise(out); },
      [&](const Outputs& out) {
        r.text += serialise(out);
        for (const auto& p : out.postings) {
          if (p.variable == "UHZ_DETECTION_REPORT") r.detected.insert(testing::label_of(p.value));
        }
      });
  EXPECT_TRUE(driver.engine().invariant_violations().empty());
  return r;
}

const std::string kBase =
    "sensor_config = width=25, exp=4, pclass=0.8\nswath_length = 10\n"
    "min_classify_interval = 0\nshow_detections = 30\n";

// One vehicle `v` east along y = `y` from x0 to x1 at `speed` m/s and `heading`, a node report
// every `interval_s`; sensor requests every 100 s; then a classification request per label.
void drive(Scene& s, double y, double x0, double x1, double speed, double interval_s,
           double heading = 90.0, double t0 = 0.0) {
  double t = t0;
  for (double x = x0; x <= x1; x += speed * interval_s, t += interval_s) {
    s.mail.push_back({t, "NODE_REPORT", node_report("v", x, y, heading, speed)});
  }
  for (double r = t0; r <= t; r += 100) s.mail.push_back({r, "UHZ_SENSOR_REQUEST", "vname=v"});
  s.end_s = std::max(s.end_s, t + 5);
}

void finish(Scene& s, const std::vector<std::string>& labels) {
  for (const auto& l : labels) s.mail.push_back({s.end_s, "UHZ_CLASSIFY_REQUEST", "vname=v,label=" + l});
  s.end_s += 0.25 * static_cast<double>(labels.size()) + 1;
  std::stable_sort(s.mail.begin(), s.mail.end(),
                   [](const TimedMail& a, const TimedMail& b) { return a.time_s < b.time_s; });
}

// Objects on a 10 m grid along the track, every lateral offset well inside W = 25.
std::vector<std::string> grid(Scene& s, const std::string& extra_every_third = {}) {
  std::vector<std::string> labels;
  int n = 0;
  for (double x = 0; x <= 200; x += 10) {
    for (double y : {-15.0, -5.0, 5.0, 15.0}) {
      const std::string label = "g" + std::to_string(n);
      s.block += "hazard = x=" + base::fmt(x) + ",y=" + base::fmt(y) + ",label=" + label + ",type=" +
                 (n % 3 ? "benign" : "hazard") + (n % 3 == 2 ? extra_every_third : "") + "\n";
      labels.push_back(label);
      ++n;
    }
  }
  return labels;
}

// The plain survey: slow, straight, a report every iteration, no hr, no aspect.
Scene plain_scene() {
  Scene s;
  s.block = kBase;
  const auto labels = grid(s);
  drive(s, 0, -50, 250, 1.5, 0.25);
  finish(s, labels);
  return s;
}

void expect_identical(const Scene& s, const std::string& on, const std::string& off) {
  const SceneRun a = run(s, on), b = run(s, off);
  EXPECT_FALSE(a.decisions.empty());
  EXPECT_EQ(a.text, b.text) << "'" << on << "' vs '" << off << "'";
}

// ---- scenes that do not use an effect: byte-identical either way ------------------------------------

TEST(EffectSwitches, UnusedEffectsGiveByteIdenticalOutputsEitherWay) {
  const Scene s = plain_scene();
  expect_identical(s, "max_vehicle_speed = 2\n", "max_vehicle_speed = off\n");  // 1.5 m/s
  expect_identical(s, "max_turn_rate = 1.5\n", "max_turn_rate = off\n");        // no turns
  expect_identical(s, "ignore_resemblances = false\n", "ignore_resemblances = true\n");  // no hr
  expect_identical(s, "ignore_aspect = false\n", "ignore_aspect = true\n");  // no aspect triple
  expect_identical(s, "swath_sweep = true\n", "swath_sweep = false\n");      // dense reports
  expect_identical(s, "swath_substeps = 4\n", "swath_substeps = 0\n");
  Scene with_origin = s;  // X/Y reports only
  with_origin.origin = MissionOrigin{42.0, -71.0, std::string("42"), std::string("-71")};
  EXPECT_EQ(run(with_origin, "").text, run(s, "").text);
  expect_identical(with_origin, "geodesy = enu\n", "geodesy = off\n");
}

TEST(EffectSwitches, UnusedVisualsGiveByteIdenticalOutputsEitherWay) {
  Scene no_vehicle = plain_scene();  // no sensing vehicle: no swath to draw
  no_vehicle.mail.erase(std::remove_if(no_vehicle.mail.begin(), no_vehicle.mail.end(),
                                       [](const TimedMail& m) {
                                         return m.variable == "UHZ_SENSOR_REQUEST";
                                       }),
                        no_vehicle.mail.end());
  EXPECT_EQ(run(no_vehicle, "show_swath = true\n").text, run(no_vehicle, "show_swath = false\n").text);
  Scene blind = plain_scene();  // pd 0 and pfa 0: nothing detected, nothing classified
  blind.mail.insert(blind.mail.begin(), {0.0, "UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=0"});
  EXPECT_EQ(run(blind, "show_detections = 30\n").text, run(blind, "show_detections = 0\n").text);
  Scene empty;  // no objects: no markers
  empty.block = kBase;
  drive(empty, 0, 0, 20, 1.5, 0.25);
  finish(empty, {});
  EXPECT_EQ(run(empty, "show_hazards = true\n").text, run(empty, "show_hazards = false\n").text);
}

// ---- scenes that use an effect: exactly the outcomes it should change -------------------------------

// The lines of a run's text without the postings of `variable` and without configuration
// warnings (a switch written twice in a block is itself a warning).
std::vector<std::string> without_visual(const std::string& text, const std::string& variable) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const auto end = text.find('\n', start);
    const std::string line = text.substr(start, end - start);
    if (line.rfind("P " + variable + "=", 0) != 0 && line.rfind("C ", 0) != 0) {
      lines.push_back(line);
    }
    start = end + 1;
  }
  return lines;
}

TEST(EffectSwitches, VisualSwitchesRemoveExactlyTheirPostings) {
  const Scene s = plain_scene();
  const SceneRun on = run(s, "show_hazards = true\nshow_swath = true\n");
  EXPECT_EQ(without_visual(on.text, "VIEW_POLYGON"),
            without_visual(run(s, "show_hazards = true\nshow_swath = false\n").text, ""));
  EXPECT_EQ(without_visual(on.text, "VIEW_MARKER"),
            without_visual(run(s, "show_hazards = false\nshow_swath = true\n").text, ""));
  EXPECT_EQ(without_visual(on.text, "VIEW_CIRCLE"),
            without_visual(run(s, "show_hazards = true\nshow_detections = 0\n").text, ""));
}

TEST(EffectSwitches, SpeedGateRemovesExactlyThePassesMadeTooFast_Manual9) {
  // x < 100 at 3 m/s (above the 2 m/s limit), then 1.5 m/s.
  Scene s;
  s.block = kBase;
  grid(s);
  drive(s, 0, -50, 99, 3.0, 0.25);
  drive(s, 0, 100, 250, 1.5, 0.25, 90, 60);
  finish(s, {});
  const SceneRun gated = run(s, "max_vehicle_speed = 2\n"), free = run(s, "max_vehicle_speed = off\n");
  // Kept: the objects still inside the swath at the first slow report (x = 100, L/2 = 5), which
  // enter then with the same pass and die; lost: every object passed over only while too fast.
  std::vector<std::string> slow_only;
  for (const auto& d : free.decisions) {
    const int n = std::stoi(d.substr(3));  // "v gN ..."
    if (n / 4 * 10 >= 95) slow_only.push_back(d);
  }
  EXPECT_LT(slow_only.size(), free.decisions.size());
  EXPECT_EQ(gated.decisions, slow_only);
}

TEST(EffectSwitches, TurnGateRemovesExactlyThePassesMadeWhileTurning_Manual8) {
  // Straight east to x = 95, then swinging the heading 10 deg per report (40 deg/s) over the
  // objects at x 100-120, then straight again: only those are lost with the gate on.
  Scene s;
  s.block = kBase;
  grid(s);
  double t = 0;
  for (double x = -50; x <= 250; x += 0.375, t += 0.25) {
    const bool turning = x >= 95 && x <= 125;
    const double heading = turning ? 90 + (static_cast<long>(x / 0.375) % 2 ? 10 : -10) : 90;
    s.mail.push_back({t, "NODE_REPORT", node_report("v", x, 0, heading, 1.5)});
  }
  for (double r = 0; r <= t; r += 100) s.mail.push_back({r, "UHZ_SENSOR_REQUEST", "vname=v"});
  s.end_s = t + 5;
  finish(s, {});
  const SceneRun gated = run(s, "max_turn_rate = 1.5\n"), free = run(s, "max_turn_rate = off\n");
  // The blackout lasts from x = 95 to 2 s (3 m) after the swinging stops; the swinging swath
  // reaches L/2 + 15 sin(10 deg) = 7.6 m along the track. Objects farther than that from
  // x in [95, 128] must keep exactly their decisions; some inside it must lose theirs.
  auto far_from_turn = [](const std::vector<std::string>& decisions) {
    std::vector<std::string> out;
    for (const auto& d : decisions) {
      const double x = std::stoi(d.substr(3)) / 4 * 10;
      if (x < 87 || x > 136) out.push_back(d);
    }
    return out;
  };
  EXPECT_EQ(far_from_turn(gated.decisions), far_from_turn(free.decisions));
  EXPECT_LT(gated.decisions.size(), free.decisions.size());
}

// Detection outcome of pass 1 of `label` for vehicle v under seed 77 at threshold p.
bool detects(const std::string& label, double p) {
  return detection_succeeds(Dice(77).detection_u(hash_name("v"), hash_name(label), 1), p);
}

TEST(EffectSwitches, ResemblanceChangesExactlyTheBenignObjectsWithHr_Manual6_1) {
  Scene s;
  s.block = kBase;
  const auto labels = grid(s, ",hr=0.9");  // every third object: benign with hr
  drive(s, 0, -50, 250, 1.5, 0.25);
  finish(s, {});
  const SceneRun on = run(s, "ignore_resemblances = false\n"), off = run(s, "ignore_resemblances = true\n");
  const double pfa = roc_false_alarm_probability(0.9, 4);
  int changed = 0;
  for (std::size_t n = 0; n < labels.size(); ++n) {
    const bool with_hr = n % 3 == 2, hazard = n % 3 == 0;
    const double p_on = hazard ? 0.9 : with_hr ? resemblance_false_alarm_probability(pfa, 0.9) : pfa;
    const double p_off = hazard ? 0.9 : pfa;
    EXPECT_EQ(on.detected.count(labels[n]) == 1, detects(labels[n], p_on)) << labels[n];
    EXPECT_EQ(off.detected.count(labels[n]) == 1, detects(labels[n], p_off)) << labels[n];
    changed += detects(labels[n], p_on) != detects(labels[n], p_off);
    if (!with_hr) {
      EXPECT_EQ(on.detected.count(labels[n]), off.detected.count(labels[n]));
    }
  }
  EXPECT_GT(changed, 0);
}

TEST(EffectSwitches, AspectChangesExactlyTheBenignAspectObjects_D5) {
  // Heading 90 against aspect 0 (difference 90 >= aspect_max 40): fully degraded, exp' = 1.
  Scene s;
  s.block = kBase;
  const auto labels = grid(s, ",aspect=0,aspect_min=10,aspect_max=40");
  s.block += "hazard = x=50,y=10,label=h_aspect,type=hazard,aspect=0,aspect_min=10,aspect_max=40\n";
  drive(s, 0, -50, 250, 1.5, 0.25);
  finish(s, {});
  const SceneRun on = run(s, "ignore_aspect = false\n"), off = run(s, "ignore_aspect = true\n");
  const double pfa = roc_false_alarm_probability(0.9, 4), degraded = roc_false_alarm_probability(0.9, 1);
  int changed = 0;
  for (std::size_t n = 0; n < labels.size(); ++n) {
    const bool aspect = n % 3 == 2, hazard = n % 3 == 0;
    const double p_on = hazard ? 0.9 : aspect ? degraded : pfa;
    EXPECT_EQ(on.detected.count(labels[n]) == 1, detects(labels[n], p_on)) << labels[n];
    EXPECT_EQ(off.detected.count(labels[n]) == 1, detects(labels[n], hazard ? 0.9 : pfa));
    changed += on.detected.count(labels[n]) != off.detected.count(labels[n]);
  }
  EXPECT_GT(changed, 0);
  EXPECT_EQ(on.detected.count("h_aspect"), off.detected.count("h_aspect"));  // hazards: pd
}

TEST(EffectSwitches, SweepingAddsExactlyTheObjectsPassedOverBetweenReports) {
  // Reports every 5 s at 2 m/s: poses 10 m apart (x = -10, 0, 10, ...) with a swath 6 m long.
  // Objects `a` sit 1 m from a pose (every method sees them); objects `b` halfway between two
  // poses, 5 m from each (beyond L/2 = 3): only the sweep sees them.
  Scene s;
  s.block = "sensor_config = width=25, exp=4, pclass=0.8\nswath_length = 6\n"
            "min_classify_interval = 0\n";
  std::vector<std::string> between, at_pose;
  for (int i = 0; i < 20; ++i) {
    between.push_back("b" + std::to_string(i));
    at_pose.push_back("a" + std::to_string(i));
    s.block += "hazard = x=" + base::fmt(5 + 10 * i) + ",y=3,label=" + between.back() + ",type=hazard\n";
    s.block += "hazard = x=" + base::fmt(10 * i + 1) + ",y=-3,label=" + at_pose.back() + ",type=benign\n";
  }
  drive(s, 0, -10, 210, 2.0, 5.0);
  finish(s, {});
  const SceneRun swept = run(s, "swath_sweep = true\n"), sampled = run(s, "swath_sweep = false\n");
  std::set<std::string> swept_labels, sampled_labels;
  for (const auto& d : swept.decisions) swept_labels.insert(d.substr(2, d.find(' ', 2) - 2));
  for (const auto& d : sampled.decisions) sampled_labels.insert(d.substr(2, d.find(' ', 2) - 2));
  EXPECT_EQ(sampled_labels, std::set<std::string>(at_pose.begin(), at_pose.end()));
  std::set<std::string> all(at_pose.begin(), at_pose.end());
  all.insert(between.begin(), between.end());
  EXPECT_EQ(swept_labels, all);
  // What sampling saw, sweeping saw the same way (same pass, same die).
  for (const auto& d : sampled.decisions) {
    EXPECT_NE(std::find(swept.decisions.begin(), swept.decisions.end(), d), swept.decisions.end()) << d;
  }
}

TEST(EffectSwitches, GeodesyPlacesLatLonReportsWhereTheEquivalentXYReportsAre) {
  const GeodeticOrigin origin{42.358436, -71.087448};
  const LocalProjection enu(origin, GeodesyMode::kEnu);
  Scene xy = plain_scene(), ll = plain_scene();
  ll.origin = MissionOrigin{origin.lat_deg, origin.lon_deg, std::string("42.358436"),
                            std::string("-71.087448")};
  // The same poses written as LAT/LON (inverse of the enu projection to 1e-10 deg, 0.01 mm).
  GeographicLib::LocalCartesian lc(origin.lat_deg, origin.lon_deg, 0.0);
  for (TimedMail& m : ll.mail) {
    if (m.variable != "NODE_REPORT") continue;
    const NodeReport r = *parse_node_report(m.value).value;
    double lat, lon, h;
    lc.Reverse(r.x_m, r.y_m, 0.0, lat, lon, h);
    m.value = "NAME=v,LAT=" + base::fmt(lat, 10) + ",LON=" + base::fmt(lon, 10) + ",SPD=1.5,HDG=90";
  }
  const SceneRun a = run(xy, ""), b = run(ll, "");
  EXPECT_EQ(a.decisions, b.decisions);
  const SceneRun none = run(ll, "geodesy = off\n");
  EXPECT_TRUE(none.decisions.empty());  // nothing placed: the vehicle is never seen
  EXPECT_NE(none.text.find("cannot be placed (geodesy = off)"), std::string::npos);
}

// ---- the switches themselves (differences.md "Validation", D36, D38) ----------------------------

TEST(EffectSwitches, ExtensionParametersAreValidatedNamingFileLineAndValue) {
  const EngineSetup s = testing::setup_from(
      "swath_substeps = 2.5\nswath_substeps = 101\nswath_substeps = -1\ngeodesy = mercator\n"
      "ignore_aspect = maybe\nswath_sweep = yes\nswath_substeps = 3\n");
  const auto& w = s.config_warnings;
  EXPECT_TRUE(testing::contains(
      w, "test.moos:1: parameter 'swath_substeps' value '2.5': not a whole number; ignored"));
  EXPECT_TRUE(testing::contains(
      w, "test.moos:2: parameter 'swath_substeps' value '101': outside [0, 100]; ignored"));
  EXPECT_TRUE(testing::contains(
      w, "test.moos:3: parameter 'swath_substeps' value '-1': outside [0, 100]"));
  EXPECT_TRUE(testing::contains(w, "test.moos:4: parameter 'geodesy' value 'mercator': not one "
                                   "of tangent, enu, azimuthal, utm, off"));
  EXPECT_TRUE(testing::contains(w, "test.moos:5: parameter 'ignore_aspect' value 'maybe'"));
  EXPECT_TRUE(testing::contains(
      w, "swath_substeps = 3 is ignored: swath_sweep = true sweeps the swath exactly"));
  EXPECT_EQ(s.config.swath_substeps, 3);
  EXPECT_EQ(s.config.geodesy, GeodesyMode::kEnu);  // the default stays
  EXPECT_TRUE(s.config.swath_sweep);
  const Effects e = choose_effects(s.config, s.field);
  EXPECT_TRUE(e.swept_swath);
  EXPECT_FALSE(e.swath_substeps);  // sweeping wins
}

// ---- what is off is not allocated ------------------------------------------------------------------

TEST(EffectSwitches, AnEffectThatIsOffAllocatesNothing) {
  testing::Driver d(testing::quiet_block("hazard = x=0,y=0,label=a,type=hazard\n"));
  d.sensor_on("v");
  for (int k = 0; k < 10; ++k) {
    d.pose("v", k, 0);
    d.tick_at(k);
  }
  const VehicleState& v = d.vehicle("v");
  EXPECT_FALSE(v.heading_history.has_value());  // no turn gate
  EXPECT_EQ(v.track.capacity(), 0u);            // no sweep, no sub-steps
  EXPECT_FALSE(d.engine.placement().projection.has_value());  // no geodesy
  EXPECT_TRUE(d.engine.effects().active_names().empty());
  testing::Driver on(testing::quiet_block("max_turn_rate = 2\nswath_sweep = true\n"
                                          "hazard = x=0,y=0,label=a,type=hazard\n"));
  on.sensor_on("v");
  on.pose("v", 0, 0);
  on.tick_at(1);
  EXPECT_TRUE(on.vehicle("v").heading_history.has_value());
  EXPECT_EQ(on.vehicle("v").track.size(), 1u);
  EXPECT_EQ(on.engine.effects().active_names(),
            (std::vector<std::string_view>{"turn_blackout", "swept_swath"}));
}

}  // namespace
}  // namespace hazard
