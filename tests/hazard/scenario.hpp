#pragma once
// Test helpers shared by the engine suites: configuration blocks written as text, the engine's
// Driver with a manual clock, and output filters. Header-only (one test executable).

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "hazard/config.hpp"
#include "hazard/driver.hpp"
#include "hazard/engine.hpp"
#include "hazard/messages/node_report.hpp"
#include "scenario/config_text.hpp"
#include "scenario/node_report_text.hpp"
#include "base/text.hpp"

namespace hazard::testing {

/// "key = value" lines (one per line, `//` comments and blank lines skipped) as config entries
/// of file "test.moos".
inline std::vector<ConfigEntry> entries(std::string_view block) {
  return config_entries(block, "test.moos");
}

/// A hazard-file reader for a block that names no hazard file.
inline base::Result<std::string> no_files(const std::string& path) {
  return base::Result<std::string>::fail("'" + path + "' is not among the test's files");
}

/// Loads a block; `files` maps hazard_file paths to their text.
inline EngineSetup setup_from(std::string_view block,
                        const std::map<std::string, std::string>& files = {}) {
  return load_configuration(entries(block),
                            [files](const std::string& path) {
                              const auto it = files.find(path);
                              if (it == files.end()) return no_files(path);
                              return base::Result<std::string>::ok(it->second);
                            });
}

/// A block with every gate and visual off, one option (W 25, exp 4, pclass 0.8), swath_length
/// 10 and no classify interval; `extra` lines are appended (later lines win, with a warning).
inline std::string quiet_block(std::string_view extra = {}) {
  return "sensor_config = width=25, exp=4, pclass=0.8\n"
         "swath_length = 10\n"
         "min_classify_interval = 0\n"
         "max_turn_rate = off\n"
         "max_vehicle_speed = off\n"
         "show_swath = false\n"
         "show_hazards = false\n"
         "show_detections = 0\n" +
         std::string(extra);
}

inline std::vector<std::string> values_of(const Outputs& out, std::string_view variable) {
  std::vector<std::string> v;
  for (const Posting& p : out.postings) {
    if (p.variable == variable) v.push_back(p.value);
  }
  return v;
}

inline void append(Outputs& into, const Outputs& from) {
  into.postings.insert(into.postings.end(), from.postings.begin(), from.postings.end());
  into.events.insert(into.events.end(), from.events.begin(), from.events.end());
  into.run_warnings.insert(into.run_warnings.end(), from.run_warnings.begin(),
                           from.run_warnings.end());
  into.retracted_run_warnings.insert(into.retracted_run_warnings.end(),
                                     from.retracted_run_warnings.begin(),
                                     from.retracted_run_warnings.end());
  into.config_warnings.insert(into.config_warnings.end(), from.config_warnings.begin(),
                              from.config_warnings.end());
}

/// The value of `key` in a report's key=value text: after the first "<key>=", up to the next ','
/// (label_of, type_of: keys no other key of the report ends with).
inline std::string report_field(const std::string& report, const std::string& key) {
  const auto at = report.find(key + "=") + key.size() + 1;
  return report.substr(at, report.find(',', at) - at);
}
inline std::string label_of(const std::string& report) { return report_field(report, "label"); }
inline std::string type_of(const std::string& report) { return report_field(report, "type"); }

inline bool contains(const std::vector<std::string>& texts, std::string_view needle) {
  for (const auto& t : texts) {
    if (t.find(needle) != std::string::npos) return true;
  }
  return false;
}

/// A hazard::Driver with a manual clock; every output is also collected in `all`.
class Driver {
 public:
  explicit Driver(std::string_view block, const std::map<std::string, std::string>& files = {},
                  std::uint64_t seed = 1, double start_s = 0.0)
      : driver(setup_from(block, files), SeedChoice{seed, SeedSource::kCommandLine}),
        engine(driver.engine()),
        now(start_s) {
    append(all, driver.start(now).outputs);
  }
  Driver(const Driver&) = delete;
  Driver& operator=(const Driver&) = delete;

  Outputs mail(std::string_view variable, std::string_view value) {
    Outputs out = driver.deliver(Mail{variable, value, now}).outputs;
    append(all, out);
    return out;
  }
  Outputs tick() {
    Outputs out = driver.step(now).outputs;
    append(all, out);
    const auto violations = engine.invariant_violations();
    EXPECT_TRUE(violations.empty()) << violations.front();
    return out;
  }
  /// Advances the clock and runs one iteration.
  Outputs tick_at(double t) {
    now = t;
    return tick();
  }
  Outputs pose(const std::string& name, double x, double y, double heading_deg = 0.0,
               double speed_mps = 1.0) {
    return mail("NODE_REPORT", node_report(name, x, y, heading_deg, speed_mps));
  }
  Outputs sensor_on(const std::string& name) {
    return mail("UHZ_SENSOR_REQUEST", "vname=" + name);
  }
  /// Gives `name` the width and pd written (as text), switches its sensor on and senses once
  /// at the origin, heading north.
  void sense_at_origin(const std::string& name, const std::string& width, const std::string& pd) {
    mail("UHZ_CONFIG_REQUEST", "vname=" + name + ",width=" + width + ",pd=" + pd);
    sensor_on(name);
    pose(name, 0, 0);
    tick();
  }

  const VehicleState& vehicle(std::string_view name) const {
    return engine.vehicle(*engine.find_vehicle(name));
  }

  hazard::Driver driver;
  const Engine& engine;  ///< the driver's, for inspection
  double now;
  Outputs all;
};

/// The first label "<prefix><i>" (i = 0, 1, ...) whose pass-1 dice for `vehicle` under `seed`
/// satisfy wanted(u, v), u the detection die and v the classification die: tests that need a
/// given outcome pick their object this way instead of hard-coding one.
template <class Wanted>
std::string first_label(std::uint64_t seed, const std::string& vehicle, const std::string& prefix,
                        Wanted wanted) {
  constexpr int kMaxTries = 1000000;
  const Dice dice(seed);
  const std::uint64_t v = hash_name(vehicle);
  for (int i = 0; i < kMaxTries; ++i) {
    const std::string label = prefix + std::to_string(i);
    const std::uint64_t l = hash_name(label);
    if (wanted(dice.detection_u(v, l, 1), dice.classification_v(v, l, 1))) return label;
  }
  ADD_FAILURE() << "no label with the wanted dice";
  return prefix;
}

/// One die outcome as "vehicle label pass detect|classify 0|1" (what the determinism checks
/// compare and hash).
inline std::string decision_tuple(const Decision& d) {
  return std::string(d.vehicle) + " " + std::string(d.label) + " " + std::to_string(d.pass) +
         (d.purpose == DiePurpose::kDetection ? " detect " : " classify ") +
         (d.outcome ? "1" : "0");
}

/// Binomial 5-sigma check helper: |k/n - p| <= 5 sqrt(p(1-p)/n).
/// The unused credits `v` holds for object `id`, oldest first (empty when it holds none).
inline std::vector<Credit> credits_of(const VehicleState& v, ObjectId id) {
  const auto record = v.objects.find(id);
  if (record == v.objects.end()) return {};
  return v.credits.to_vector(record->second.credits);
}

/// How many objects `v` holds at least one unused credit for.
inline std::size_t objects_with_credits(const VehicleState& v) {
  std::size_t n = 0;
  for (const auto& entry : v.objects) n += entry.second.credits.empty() ? 0 : 1;
  return n;
}

inline double five_sigma(double p, double n) { return 5.0 * std::sqrt(p * (1.0 - p) / n); }

}  // namespace hazard::testing
