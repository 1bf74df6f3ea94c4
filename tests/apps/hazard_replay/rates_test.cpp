// End-to-end rates through the hazard_replay binary on generated logs (many straight passes
// over a field): fixed seeds, >= 100,000 trials per rate, 5-sigma binomial bounds.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

#include "hazard/dice.hpp"
#include "hazard/sensor_model.hpp"
#include "base/text.hpp"
#include "replay_support.hpp"

namespace hazard_replay {
namespace {

using test_support::ScratchDir;
using test_support::write_file;
using testing::Line;
using testing::mission;
using testing::node_report;
using testing::run;

double five_sigma(double p, double n) { return 5.0 * std::sqrt(p * (1.0 - p) / n); }


// `count` objects of one kind (label prefix `letter`) inside the swath at the origin.
std::string objects(char letter, int count, const std::string& spec, int& n) {
  std::string out;
  for (int i = 0; i < count; ++i, ++n) {
    out += "hazard = x=" + base::fmt(-40 + n % 81) + ",y=" + base::fmt(-40 + (n / 81) % 81) +
           ",label=" + letter + std::to_string(i) + "," + spec + "\n";
  }
  return out;
}

// W 50 to each side, 100 m long: every object at |x|, |y| <= 40 is inside at the origin.
const std::string kBlock =
    "  AppTick = 4\n  hazard_file = field.txt\n  sensor_config = width=50, exp=3, pclass=0.8\n"
    "  swath_length = 100\n  show_swath = false\n  show_hazards = false\n  show_detections = 0\n"
    "  min_classify_interval = 0\n  options_summary_interval = 100000\n";
const std::string kAspect = "aspect=60,aspect_min=10,aspect_max=50";  // heading 90: g = 0.5

std::string label_of(const std::string& value) {
  const auto at = value.find("label=") + 6;
  return value.substr(at, value.find(',', at) - at);
}

// Calls f(entry) for every line of an .alog file without holding it in memory.
template <class F>
void for_each_entry(const std::filesystem::path& path, F&& f) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto p = moos::parse_alog_line(line);
    if (p.kind == moos::AlogLineKind::kEntry) f(p.entry);
  }
}

TEST(ReplayRates, DetectionRatesEndToEnd) {
  ScratchDir dir;
  constexpr int kPerKind = 1000, kPasses = 100;  // 100,000 trials per rate
  int n = 0;
  std::string field = objects('h', kPerKind, "type=hazard", n);
  field += objects('b', kPerKind, "type=benign", n);
  field += objects('r', kPerKind, "type=benign,hr=0.3", n);
  field += objects('a', kPerKind, "type=benign," + kAspect, n);
  write_file(dir / "field.txt", field);
  write_file(dir / "m.moos", mission(kBlock + "  random_seed = 31337\n"));
  std::vector<Line> in = {{0, "UHZ_SENSOR_REQUEST", "vname=v1"},
                          {0, "UHZ_CONFIG_REQUEST", "vname=v1,width=50,pd=0.8"}};
  for (int pass = 0; pass < kPasses; ++pass) {  // straight passes east over the field
    in.push_back({1.0 + pass, "NODE_REPORT", node_report("v1", -500, 0, 90, 1.5)});
    in.push_back({1.5 + pass, "NODE_REPORT", node_report("v1", 0, 0, 90, 1.5)});
  }
  write_file(dir / "in.alog", testing::alog(in));
  const auto r = run(dir, {"m.moos", "in.alog", "--output=out.alog"}, false);
  ASSERT_EQ(r.exit_code, 0);
  std::map<char, int> detected;
  for_each_entry(dir / "out.alog", [&](const moos::AlogEntry& e) {
    if (e.variable == "UHZ_DETECTION_REPORT_V1") ++detected[label_of(e.value)[0]];
  });
  const double pd = 0.8, pfa = hazard::roc_false_alarm_probability(pd, 3);
  const std::map<char, double> expected = {
      {'h', pd},
      {'b', pfa},
      {'r', hazard::resemblance_false_alarm_probability(pfa, 0.3)},
      {'a', hazard::roc_false_alarm_probability(pd, hazard::degraded_exponent(3, 0.5))},
  };
  const double trials = kPerKind * kPasses;
  for (const auto& [kind, p] : expected) {
    const double q = hazard::detection_success_probability(p);
    EXPECT_NEAR(detected[kind] / trials, q, five_sigma(q, trials)) << kind;
  }
}

TEST(ReplayRates, ClassificationRatesEndToEnd) {
  ScratchDir dir;
  // pd 1: all detected except resemblance objects (0.65). 100 vehicles x 10 passes.
  constexpr int kVehicles = 100, kPasses = 10;
  int n = 0;
  std::string field = objects('h', 50, "type=hazard", n);
  field += objects('b', 50, "type=benign", n);
  field += objects('r', 160, "type=benign,hr=0.3", n);
  field += objects('a', 100, "type=hazard," + kAspect, n);
  write_file(dir / "field.txt", field);
  write_file(dir / "m.moos", mission(kBlock + "  random_seed = 4711\n"));
  std::vector<Line> in;
  for (int v = 0; v < kVehicles; ++v) {
    const std::string name = "v" + std::to_string(v);
    in.push_back({0, "UHZ_SENSOR_REQUEST", "vname=" + name});
    in.push_back({0, "UHZ_CONFIG_REQUEST", "vname=" + name + ",width=50,pd=1"});
    for (int pass = 0; pass < kPasses; ++pass) {
      in.push_back({1.0 + pass, "NODE_REPORT", node_report(name, -500, 0, 90, 1.5)});
      in.push_back({1.5 + pass, "NODE_REPORT", node_report(name, 0, 0, 90, 1.5)});
    }
    in.push_back({1.0 + kPasses, "NODE_REPORT", node_report(name, 500, 0, 90, 1.5)});  // and away
  }
  // Detected objects are known only to the replay; ask for every object once per pass: the
  // requests without a credit (undetected resemblance objects) are refused with a warning.
  const double ask_s = kPasses + 2.0;
  for (int v = 0; v < kVehicles; ++v) {
    for (int pass = 0; pass < kPasses; ++pass) {
      int m = 0;
      for (auto [letter, count] : {std::pair{'h', 50}, std::pair{'b', 50}, std::pair{'r', 160},
                                   std::pair{'a', 100}}) {
        for (int i = 0; i < count; ++i, ++m) {
          in.push_back({ask_s, "UHZ_CLASSIFY_REQUEST",
                        "vname=v" + std::to_string(v) + ",label=" + letter + std::to_string(i)});
        }
      }
    }
  }
  in.push_back({ask_s + kPasses * 360 / 4.0 + 10, "UHZ_SENSOR_REQUEST", "vname=v0"});
  write_file(dir / "in.alog", testing::alog(in));
  const auto r = run(dir, {"m.moos", "in.alog", "--output=out.alog"}, false);
  ASSERT_EQ(r.exit_code, 0);
  std::map<char, int> answers, correct;
  for_each_entry(dir / "out.alog", [&](const moos::AlogEntry& e) {
    if (e.variable != "UHZ_HAZARD_REPORT") return;
    const char letter = label_of(e.value)[0];
    const char rate = letter == 'b' ? 'h' : letter;  // plain pc pools hazards and benign
    const bool truth_hazard = letter == 'h' || letter == 'a';
    ++answers[rate];
    correct[rate] += (e.value.find("type=hazard") != std::string::npos) == truth_hazard;
  });
  const std::map<char, double> expected = {
      {'h', 0.8},
      {'r', hazard::resemblance_classification_probability(0.8, 0.3)},
      {'a', hazard::aspect_classification_probability(0.8, 0.5)},
  };
  for (const auto& [rate, p] : expected) {
    const double trials = answers[rate];
    EXPECT_GE(trials, 100000) << rate;
    const double q = hazard::classification_success_probability(p);
    EXPECT_NEAR(correct[rate] / trials, q, five_sigma(q, trials)) << rate;
  }
}

}  // namespace
}  // namespace hazard_replay
