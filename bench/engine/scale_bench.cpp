// What a big field costs: bytes per object, the idle iteration, the iteration with
// 1, 10 and 100 vehicles, and the digest rate (node reports per CPU second through
// hazard::Driver, as hazard_replay feeds it), for 1e3 to 1e6 objects laid out uniformly or in
// clusters. A harness, not a test: it prints a table (docs/performance.md, "The engine at scale").
//
//   build/release/bench/engine/scale_bench                 # every row (1e6 rows take a minute)
//   build/release/bench/engine/scale_bench 1000000         # only fields of this size
//
// Bytes per object: the heap in use (glibc mallinfo2: uordblks + hblkhd) after the Driver is
// built minus before, divided by the objects; the field's text is held outside the measurement.
#include <malloc.h>
#include <time.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <optional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "base/text.hpp"
#include "hazard/driver.hpp"
#include "hazard/messages/node_report.hpp"
#include "scenario/reference_scenario.hpp"

namespace {

constexpr double kSpacing_m = 10.0;   // uniform: 100 m² per object
constexpr double kTick_s = 0.25;      // AppTick 4
constexpr double kSpeed_mps = 1.5;
constexpr int kIterations = 400;      // 100 simulated seconds per row
constexpr int kIdleIterations = 20000;
constexpr int kClusters = 50;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

// Small blocks in use plus the big ones glibc maps on their own.
std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

// The same area as the uniform field, the objects in kClusters Gaussian clusters (sigma a tenth
// of the side), fixed seed; labels as the uniform field's.
std::string clustered_field_text(int objects) {
  const double side_m = std::ceil(std::sqrt(static_cast<double>(objects))) * kSpacing_m;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> centre(-side_m / 2, side_m / 2);
  std::vector<std::pair<double, double>> centres(kClusters);
  for (auto& c : centres) c = {centre(rng), centre(rng)};
  std::normal_distribution<double> spread(0.0, side_m / 10);
  std::string text;
  for (int i = 0; i < objects; ++i) {
    const auto& c = centres[static_cast<std::size_t>(i % kClusters)];
    char line[160];
    std::snprintf(line, sizeof line, "hazard = x=%.1f,y=%.1f,label=o%d,type=%s\n",
                  c.first + spread(rng), c.second + spread(rng), i,
                  i % 3 == 0 ? "hazard" : "benign");
    text += line;
  }
  return text;
}

std::unique_ptr<hazard::Driver> make_driver(const std::string& text) {
  const std::vector<hazard::ConfigEntry> config = {
      {"sensor_config", "width=25, exp=4, pclass=0.85", "bench", 1},
      {"random_seed", "1", "bench", 2},
      {"show_hazards", "false", "bench", 3},
      {"hazard_file", "field.txt", "bench", 4},
  };
  return std::make_unique<hazard::Driver>(
      hazard::load_configuration(config, [&](const std::string&) { return base::Result<std::string>::ok(text); }),
      hazard::SeedChoice{1, hazard::SeedSource::kCommandLine});
}

struct Cost {
  double us_per_iteration = 0;
  double reports_per_cpu_s = 0;
};

// `vehicles` mow lanes west to east across the field, a node report each per iteration.
Cost drive(hazard::Driver& d, int objects, int vehicles, double& now) {
  const double half_m = std::ceil(std::sqrt(static_cast<double>(objects))) * kSpacing_m / 2;
  const double lane_m = 2 * half_m / (vehicles + 1);
  for (int v = 0; v < vehicles; ++v)
    d.deliver(hazard::Mail{"UHZ_SENSOR_REQUEST", "vname=v" + std::to_string(v), now});
  const double start = cpu_seconds();
  for (int k = 0; k < kIterations; ++k) {
    now += kTick_s;
    const double x = -half_m + std::fmod(k * kTick_s * kSpeed_mps, 2 * half_m);
    for (int v = 0; v < vehicles; ++v) {
      hazard::NodeReport r;
      r.name = "v" + std::to_string(v);
      r.x_m = x;
      r.y_m = -half_m + (v + 1) * lane_m;
      r.speed_mps = kSpeed_mps;
      r.heading_deg = 90;
      d.deliver(hazard::Mail{"NODE_REPORT", hazard::format_node_report(r), now});
    }
    d.step(now);
  }
  const double cpu = cpu_seconds() - start;
  return {cpu * 1e6 / kIterations, vehicles * kIterations / cpu};
}

double idle_us(hazard::Driver& d, double& now) {
  const double start = cpu_seconds();
  for (int k = 0; k < kIdleIterations; ++k) d.step(now += kTick_s);
  return (cpu_seconds() - start) * 1e6 / kIdleIterations;
}

void row(int objects, bool clustered) {
  const std::string text =
      clustered ? clustered_field_text(objects) : hazard::grid_field_text(objects, kSpacing_m);
  const std::size_t before = heap_in_use();
  const double load_start = cpu_seconds();
  std::unique_ptr<hazard::Driver> d = make_driver(text);
  const double load_s = cpu_seconds() - load_start;
  const double bytes = static_cast<double>(heap_in_use() - before) / objects;
  double now = 0;
  d->start(now);
  const double idle = idle_us(*d, now);
  std::printf("| %d | %s | %.0f | %.2f | %.2f |", objects, clustered ? "clustered" : "uniform",
              bytes, load_s, idle);
  for (int vehicles : {1, 10, 100}) {
    const Cost c = drive(*d, objects, vehicles, now);
    std::printf(" %.0f / %.2g |", c.us_per_iteration, c.reports_per_cpu_s);
  }
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::optional<std::uint64_t> only =
      argc > 1 ? base::parse_unsigned(argv[1]) : std::optional<std::uint64_t>(0);
  if (argc > 2 || !only) {
    std::fprintf(stderr, "usage: scale_bench [OBJECTS] (1000, 10000, 100000 or 1000000)\n");
    return 2;
  }
  std::printf("| objects | layout | bytes/object | load CPU s | idle iteration µs |"
              " 1 vehicle: µs/iteration / reports per CPU s | 10 vehicles | 100 vehicles |\n"
              "|---|---|---|---|---|---|---|---|\n");
  for (int objects : {1000, 10000, 100000, 1000000}) {
    if (*only != 0 && static_cast<std::uint64_t>(objects) != *only) continue;
    for (bool clustered : {false, true}) row(objects, clustered);
  }
  return 0;
}
