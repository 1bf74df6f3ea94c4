// Per-iteration cost of the engine (design "Scale"): a field of 10,000 or 1,000,000 objects on a
// 10 m jittered grid, and 1 or 10 vehicles driving straight lanes across it at 1.5 m/s with a
// node report each iteration (4 Hz), the app's default visuals, both gates on. One benchmark
// iteration = every vehicle's node report + Engine::step.
//
//   build/<dir>/bench/engine/engine_bench --benchmark_min_time=2
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "hazard/driver.hpp"
#include "hazard/messages/node_report.hpp"
#include "scenario/reference_scenario.hpp"

namespace {

constexpr double kSpacing_m = 10.0;
constexpr double kTick_s = 0.25;      // AppTick 4
constexpr double kSpeed_mps = 1.5;

struct Scene {
  std::unique_ptr<hazard::Driver> driver;
  double half_extent_m = 0.0;
};

// Building a 1,000,000-object field takes a while: once per size.
const std::string& field_text(int objects) {
  static std::map<int, std::string> cache;
  auto it = cache.find(objects);
  if (it == cache.end()) {
    it = cache.emplace(objects, hazard::grid_field_text(objects, kSpacing_m)).first;
  }
  return it->second;
}

Scene make_scene(int objects, int vehicles) {
  std::vector<hazard::ConfigEntry> config = {
      {"sensor_config", "width=25, exp=4, pclass=0.85", "bench", 1},
      {"sensor_config", "width=50, exp=2, pclass=0.60", "bench", 2},
      {"random_seed", "1", "bench", 3},
      {"show_hazards", "false", "bench", 4},  // a million markers at start-up is not the point
      {"hazard_file", "field.txt", "bench", 5},
  };
  const std::string& text = field_text(objects);
  Scene s;
  s.driver = std::make_unique<hazard::Driver>(
      hazard::load_configuration(config, [&](const std::string&) { return base::Result<std::string>::ok(text); }),
      hazard::SeedChoice{1, hazard::SeedSource::kCommandLine});
  s.half_extent_m = std::ceil(std::sqrt(static_cast<double>(objects))) * kSpacing_m / 2.0;
  s.driver->start(0);
  for (int v = 0; v < vehicles; ++v) {
    const std::string vname = "vname=v" + std::to_string(v);
    s.driver->deliver(hazard::Mail{"UHZ_SENSOR_REQUEST", vname, 0});
  }
  return s;
}

void BM_EngineIteration(benchmark::State& state) {
  const int objects = static_cast<int>(state.range(0));
  const int vehicles = static_cast<int>(state.range(1));
  Scene scene = make_scene(objects, vehicles);
  std::vector<std::string> names;
  for (int v = 0; v < vehicles; ++v) names.push_back("v" + std::to_string(v));
  const double lane_spacing_m = 2.0 * scene.half_extent_m / (vehicles + 1);
  double now = 0.0;
  long k = 0;
  std::size_t postings = 0;
  for (auto _ : state) {
    now += kTick_s;
    // Lanes west to east; a vehicle that leaves the field starts its lane again.
    const double travelled_m = std::fmod(k++ * kTick_s * kSpeed_mps, 2.0 * scene.half_extent_m);
    for (int v = 0; v < vehicles; ++v) {
      hazard::NodeReport r;
      r.name = names[v];
      r.x_m = -scene.half_extent_m + travelled_m;
      r.y_m = -scene.half_extent_m + (v + 1) * lane_spacing_m;
      r.speed_mps = kSpeed_mps;
      r.heading_deg = 90;
      scene.driver->deliver(hazard::Mail{"NODE_REPORT", hazard::format_node_report(r), now});
      if (k % 2000 == 0) {
        scene.driver->deliver(hazard::Mail{"UHZ_SENSOR_REQUEST", "vname=" + names[v], now});
      }
    }
    const hazard::Outputs out = scene.driver->step(now).outputs;
    postings += out.postings.size();
    benchmark::DoNotOptimize(out);
  }
  state.counters["postings/iter"] =
      benchmark::Counter(static_cast<double>(postings) / static_cast<double>(k));
}

BENCHMARK(BM_EngineIteration)
    ->ArgNames({"objects", "vehicles"})
    ->Args({10000, 1})
    ->Args({10000, 10})
    ->Args({1000000, 1})
    ->Args({1000000, 10})
    ->Unit(benchmark::kMicrosecond);

// The shared reference survey (tests/support/scenario) replayed at 4 Hz, whole run per iteration.
void BM_ReferenceSurveyReplay(benchmark::State& state) {
  const hazard::Scenario s = hazard::reference_survey(2.0);
  for (auto _ : state) {
    hazard::Driver driver(
        hazard::load_configuration(s.config, [](const std::string&) { return base::Result<std::string>::fail("no file"); }),
        hazard::SeedChoice{2024, hazard::SeedSource::kRandomSeed});
    hazard::play_mail(driver, s.mail, 4.0, s.end_time_s, {},
                      [](const hazard::Outputs& out) { benchmark::DoNotOptimize(out); });
  }
}
BENCHMARK(BM_ReferenceSurveyReplay)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
