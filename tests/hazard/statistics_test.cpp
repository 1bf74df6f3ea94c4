// Rates through the engine, fixed seeds, >= 100,000 trials each, 5-sigma binomial bounds
// (manual 3.1, 3.2, 6.1, 6.2, 7.1, 7.2; differences.md D5, D6, D7).
#include <gtest/gtest.h>

#include <map>

#include "hazard/dice.hpp"
#include "hazard/sensor_model.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::five_sigma;
using testing::label_of;
using testing::type_of;

// Objects inside a 2 x 50 m wide, 100 m long swath around the origin (heading 90: along x),
// `per_category` of each kind; category = the label's first letter.
std::string category_field(int per_category, const std::map<char, std::string>& kinds) {
  std::string out;
  int n = 0;
  for (const auto& [letter, spec] : kinds) {
    for (int i = 0; i < per_category; ++i, ++n) {
      out += "hazard = x=" + base::fmt(-40 + (n % 81)) + ",y=" + base::fmt(-40 + (n / 81) % 81) +
             ",label=" + letter + std::to_string(i) + "," + spec + "\n";
    }
  }
  return out;
}

const std::string kBlock =
    "sensor_config = width=50, exp=3, pclass=0.8\nswath_length = 100\nmin_classify_interval = 0\n"
    "max_turn_rate = off\nmax_vehicle_speed = off\nshow_swath = false\nshow_hazards = false\n"
    "show_detections = 0\noptions_summary_interval = 1000000\n";

// Heading 90 vs aspect 60 with window [10, 50]: difference 30, degradation g = 0.5.
const std::string kAspect = "aspect=60,aspect_min=10,aspect_max=50";

TEST(Statistics, DetectionRatesMatchTheModel_Manual3_1_6_1_7_1_D5) {
  constexpr int kPerCategory = 1000, kPasses = 100;  // 100,000 trials per category
  const std::string field = category_field(
      kPerCategory, {{'h', "type=hazard"}, {'b', "type=benign"}, {'r', "type=benign,hr=0.3"},
                     {'a', "type=benign," + kAspect}, {'g', "type=hazard," + kAspect}});
  EngineSetup setup = testing::setup_from(kBlock + field);
  hazard::Driver driver(std::move(setup), SeedChoice{20240601, SeedSource::kCommandLine});
  driver.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", 0});
  driver.deliver(Mail{"UHZ_CONFIG_REQUEST", "vname=v,width=50,pd=0.8", 0});
  std::map<char, int> detected;
  for (int pass = 0; pass < kPasses; ++pass) {
    for (const double x : {0.0, 1000.0}) {  // over the field, then away
      const double t = pass;
      driver.deliver(Mail{"NODE_REPORT", testing::node_report("v", x, 0, 90), t});
      const Outputs out = driver.step(pass).outputs;
      for (const auto& r : testing::values_of(out, "UHZ_DETECTION_REPORT_V")) {
        ++detected[label_of(r)[0]];
      }
    }
  }
  const double n = kPerCategory * kPasses;
  const double pd = 0.8, pfa = roc_false_alarm_probability(pd, 3);  // 0.512
  const std::map<char, double> expected = {
      {'h', pd},                                                          // hazards: pd
      {'b', pfa},                                                         // pd^exp
      {'r', resemblance_false_alarm_probability(pfa, 0.3)},               // (pfa + hr) / 2
      {'a', roc_false_alarm_probability(pd, degraded_exponent(3, 0.5))},  // pd^(exp - g(exp-1))
      {'g', pd},                                                          // aspect: not hazards
  };
  for (const auto& [category, p] : expected) {
    const double q = hazard::detection_success_probability(p);
    EXPECT_NEAR(detected[category] / n, q, five_sigma(q, n)) << category << " p=" << p;
  }
}

TEST(Statistics, ClassificationRatesMatchTheModel_Manual3_2_6_2_7_2) {
  // pd 1: every hazard and every benign object without hr is detected (pfa 1); resemblance
  // objects are detected with (1 + 0.3) / 2. Each detection is one credit, each credit one answer.
  constexpr int kVehicles = 100, kPasses = 10;
  // 100 vehicles x 10 passes over 100 objects = 100,000 credits per rate: plain pc pools 50
  // hazards ('h') and 50 benign objects ('b'); the resemblance rate uses 160 objects ('r',
  // detected with 0.65, so about 104,000 credits); aspect 100 hazards ('a').
  std::string field = category_field(50, {{'h', "type=hazard"}, {'b', "type=benign"}});
  field += category_field(160, {{'r', "type=benign,hr=0.3"}});
  field += category_field(100, {{'a', "type=hazard," + kAspect}});
  hazard::Driver driver(testing::setup_from(kBlock + field),
                        SeedChoice{77, SeedSource::kCommandLine});
  std::vector<std::string> names;
  for (int i = 0; i < kVehicles; ++i) names.push_back("v" + std::to_string(i));
  double t = 0;
  for (const auto& v : names) {
    driver.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=" + v, t});
    driver.deliver(Mail{"UHZ_CONFIG_REQUEST", "vname=" + v + ",width=50,pd=1", t});
  }
  std::map<std::string, std::vector<std::string>> credits;  // vehicle -> labels detected
  for (int pass = 0; pass < kPasses; ++pass) {
    for (const double x : {0.0, 1000.0}) {
      for (const auto& v : names) {
        driver.deliver(Mail{"NODE_REPORT", testing::node_report(v, x, 0, 90), t});
      }
      const Outputs out = driver.step(t).outputs;
      for (const auto& p : out.postings) {
        if (p.variable != "UHZ_DETECTION_REPORT") continue;  // vname=V,x=..,y=..,label=L
        credits[testing::report_field(p.value, "vname")].push_back(label_of(p.value));
      }
      t += 1;
    }
  }
  std::size_t most = 0;
  for (const auto& [v, labels] : credits) {
    most = std::max(most, labels.size());
    for (const auto& l : labels) {
      driver.deliver(Mail{"UHZ_CLASSIFY_REQUEST", "vname=" + v + ",label=" + l, t});
    }
  }
  std::map<char, int> answers, correct;
  for (std::size_t i = 0; i < most + 1; ++i) {
    const Outputs out = driver.step(t).outputs;
    for (const auto& p : out.postings) {
      if (p.variable != "UHZ_HAZARD_REPORT") continue;
      const char letter = label_of(p.value)[0];
      const char category = letter == 'b' ? 'h' : letter;  // plain pc pools both types
      const bool truth_hazard = letter == 'h' || letter == 'a';
      ++answers[category];
      correct[category] += (type_of(p.value) == "hazard") == truth_hazard;
    }
  }
  const std::map<char, double> expected = {
      {'h', 0.8},                                                   // pc
      {'r', resemblance_classification_probability(0.8, 0.3)},     // pc + (1-pc)(1-hr)
      {'a', aspect_classification_probability(0.8, 0.5)},          // 0.5 + (1-g)(pc-0.5)
  };
  for (const auto& [category, p] : expected) {
    const double n = answers[category];
    EXPECT_GE(n, 100000) << category;
    const double q = hazard::classification_success_probability(p);
    EXPECT_NEAR(correct[category] / n, q, five_sigma(q, n)) << category << " p=" << p;
  }
}

}  // namespace
}  // namespace hazard
