// What one (vehicle, object) pair costs (docs/robustness.md "Soak"): the engine keeps,
// per object a vehicle has had in its swath, its pass count and its unused detection credits
// (differences.md "Credits"). A harness, not a test: it prints one table row per load.
//
//   build/release/bench/engine/pair_state_bench
//
// Each row: kVehicles vehicles each drive `passes` legs over their own strip of kStripObjects
// hazards (1 m grid, 40 m wide, inside the 25 m half-width swath), leaving the swath between
// legs, so every leg is one pass over every object of the strip. With pd 1 every pass grants a
// credit; with pd 0 none (pass counts only). Bytes: the heap in use (glibc mallinfo2: uordblks
// + hblkhd, so the allocator's chunk headers and rounding count) after the legs minus before,
// divided by the pairs met. Pairs and credits are counted through the decision observer (a
// detection die per pair and pass), not read from the engine's containers, so the same
// program measures any layout of the per-pair state.
#include <malloc.h>

#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "hazard/driver.hpp"
#include "hazard/messages/node_report.hpp"
#include "scenario/config_text.hpp"

namespace {

constexpr int kVehicles = 10;
constexpr int kStripColumns = 250;  // along x, 1 m apart
constexpr int kStripRows = 40;      // across, 1 m apart: y in [-20, 19] around the lane
constexpr int kStripObjects = kStripColumns * kStripRows;
constexpr double kLaneSpacing_m = 100.0;
constexpr double kStep_m = 2.0;  // per iteration; below the 5 m swath length, so nothing is skipped
constexpr double kTick_s = 0.25;

std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

double lane_y(int vehicle) { return vehicle * kLaneSpacing_m; }
std::string vehicle_name(int vehicle) { return "v" + std::to_string(vehicle); }

std::string strips_field_text() {
  std::string text;
  char line[128];
  for (int v = 0; v < kVehicles; ++v) {
    for (int column = 0; column < kStripColumns; ++column) {
      for (int row = 0; row < kStripRows; ++row) {
        std::snprintf(line, sizeof line, "hazard = x=%d,y=%g,label=v%dc%dr%d,type=hazard\n",
                      column, lane_y(v) - 20 + row, v, column, row);
        text += line;
      }
    }
  }
  return text;
}

// The vehicles' pd (0 or 1) comes with their configuration requests (row()).
constexpr const char* kSensorBlock =
    "sensor_config = width=25, exp=4, pclass=0.85\n"
    "random_seed = 1\n"
    "show_hazards = false\n"
    "show_detections = 0\n"
    "hazard_file = strips.txt\n";

std::unique_ptr<hazard::Driver> make_driver(const std::string& field_text) {
  hazard::EngineSetup setup = hazard::load_configuration(
      hazard::config_entries(kSensorBlock, "pair_state_bench"),
      [&field_text](const std::string&) { return base::Result<std::string>::ok(field_text); });
  const hazard::SeedChoice seed{1, hazard::SeedSource::kCommandLine};
  return std::make_unique<hazard::Driver>(std::move(setup), seed);
}

void report_all(hazard::Driver& d, double x_m, double now) {
  for (int v = 0; v < kVehicles; ++v) {
    hazard::NodeReport r;
    r.name = vehicle_name(v);
    r.x_m = x_m;
    r.y_m = lane_y(v);
    r.speed_mps = 1.5;
    r.heading_deg = 90;
    d.deliver(hazard::Mail{"NODE_REPORT", hazard::format_node_report(r), now});
  }
}

struct Tally {
  std::uint64_t pairs = 0;    // first detection dice (pass 1)
  std::uint64_t credits = 0;  // detections (each grants a credit below kMaxCreditsPerObject)
};

void row(const std::string& text, int passes, double pd) {
  std::unique_ptr<hazard::Driver> d = make_driver(text);
  Tally tally;
  d->set_decision_observer([&tally](const hazard::Decision& decision) {
    if (decision.purpose != hazard::DiePurpose::kDetection) return;
    if (decision.pass == 1) ++tally.pairs;
    if (decision.outcome) ++tally.credits;
  });
  double now = 0;
  d->start(now);
  const double away_m = -1000;
  report_all(*d, away_m, now);
  for (int v = 0; v < kVehicles; ++v) {
    const std::string name = vehicle_name(v);
    d->deliver(hazard::Mail{"UHZ_CONFIG_REQUEST",
                            "vname=" + name + ",width=25,pd=" + std::to_string(pd), now});
  }
  d->step(now += kTick_s);
  const std::size_t before = heap_in_use();
  for (int leg = 0; leg < passes; ++leg) {
    for (int v = 0; v < kVehicles; ++v)
      d->deliver(hazard::Mail{"UHZ_SENSOR_REQUEST", "vname=" + vehicle_name(v), now});
    for (double x = -10; x <= kStripColumns + 10; x += kStep_m) {
      now += kTick_s;
      report_all(*d, x, now);
      d->step(now);
    }
    now += kTick_s;
    report_all(*d, away_m, now);  // every object leaves the swath: the next leg is a new pass
    d->step(now);
  }
  const double bytes = static_cast<double>(heap_in_use() - before);
  const double pairs = static_cast<double>(tally.pairs);
  std::printf("| %d | %g | %llu | %.2f | %.0f |\n", passes, pd,
              static_cast<unsigned long long>(tally.pairs),
              static_cast<double>(tally.credits) / pairs, bytes / pairs);
  std::fflush(stdout);
}

}  // namespace

int main() {
  const std::string text = strips_field_text();
  std::printf("%d vehicles, %d objects each in their strip\n\n", kVehicles, kStripObjects);
  std::printf("| passes | pd | pairs | credits per pair | bytes per pair |\n");
  std::printf("|---|---|---|---|---|\n");
  row(text, 1, 0.0);
  for (int passes : {1, 2, 4, 16}) row(text, passes, 1.0);
  return 0;
}
