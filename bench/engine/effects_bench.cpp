// The cost of each effect (docs/effects.md): per vehicle-update time and memory per
// object for a plain scene, each effect alone, and all effects together, printed as a Markdown
// table with ratios to the plain scene measured in the same run.
//
//   build/<dir>/bench/engine/effects_bench            (bench/reproduce.sh runs it)
//
// Scene: 100,000 objects on a 10 m jittered grid (3.2 km square), 4 vehicles driving straight
// lanes across it at 1.5 m/s with a node report every iteration, 4,000 iterations at 4 Hz.
// A vehicle update = its node report (parse, gates, track) plus its share of Engine::step.
// The plain scene has both gates `off`, no visuals, no hr or aspect data, sampling, no geodesy;
// each row adds one effect's switch (and the data it needs: hr on every benign object, an
// aspect triple on every object, LAT/LON-only node reports around an origin). Memory, counted
// by replacing the global operator new: bytes allocated once the engine is built (the field,
// its index, the engine) per object, and bytes added during the run (each vehicle's record:
// heading history, track, its per-object state for the objects it passed) per vehicle.
#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "hazard/dice.hpp"
#include "hazard/driver.hpp"
#include "scenario/reference_scenario.hpp"
#include "base/text.hpp"

// ---- counting allocator (this program only) -----------------------------------------------------

namespace {
std::size_t g_live_bytes = 0;
// Each block carries its size in a header; 16 bytes keep the default new alignment.
constexpr std::size_t kHeader = 16;
}  // namespace

void* operator new(std::size_t size) {
  void* p = std::malloc(size + kHeader);
  if (!p) throw std::bad_alloc();
  *static_cast<std::size_t*>(p) = size;
  g_live_bytes += size;
  return static_cast<char*>(p) + kHeader;
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept {
  if (!p) return;
  char* block = static_cast<char*>(p) - kHeader;
  g_live_bytes -= *reinterpret_cast<std::size_t*>(block);
  std::free(block);
}
void operator delete[](void* p) noexcept { operator delete(p); }
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
void operator delete[](void* p, std::size_t) noexcept { operator delete(p); }

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kObjects = 100000;
constexpr double kSpacing_m = 10.0;
constexpr int kVehicles = 4;
constexpr int kIterations = 4000;
constexpr double kTick_s = 0.25;
constexpr double kSpeed_mps = 1.5;
constexpr int kRepeats = 5;
constexpr double kLatOrigin = 42.358436, kLonOrigin = -71.087448;

struct Scene {
  const char* name;
  std::string config;   // lines added to the plain block
  bool hr = false;      // hr on every benign object
  bool aspect = false;  // an aspect triple on every object
  bool lat_lon = false; // LAT/LON-only node reports, with the mission origin
};

const char* kPlain =
    "sensor_config = width=25, exp=4, pclass=0.85\nmax_turn_rate = off\n"
    "max_vehicle_speed = off\nshow_swath = false\nshow_hazards = false\nshow_detections = 0\n";

// The shared jittered grid (reference_scenario.hpp), one object a line, every third a hazard;
// with `hr` and `aspect` each line gains the data that effect needs.
std::string field_text(bool hr, bool aspect) {
  const std::string grid = hazard::grid_field_text(kObjects, kSpacing_m);
  if (!hr && !aspect) return grid;
  std::string out;
  std::size_t start = 0;
  for (int n = 0; start < grid.size(); ++n) {
    const std::size_t end = grid.find('\n', start);
    out.append(grid, start, end - start);
    start = end + 1;
    const std::uint64_t h = hazard::mix64(static_cast<std::uint64_t>(n));
    if (hr && n % 3 != 0) out += ",hr=0.5";
    if (aspect) out += ",aspect=" + std::to_string(h % 180) + ",aspect_min=10,aspect_max=40";
    out += "\n";
  }
  return out;
}

std::vector<hazard::ConfigEntry> block(const Scene& s) {
  std::vector<hazard::ConfigEntry> out;
  int line = 0;
  for (const std::string& text : {std::string(kPlain), s.config, std::string("hazard_file = f\n")}) {
    std::size_t start = 0;
    while (start < text.size()) {
      const auto end = text.find('\n', start);
      const std::string l = text.substr(start, end - start);
      start = end + 1;
      const auto eq = l.find('=');
      if (eq == std::string::npos) continue;
      out.push_back({std::string(base::trim(l.substr(0, eq))),
                     std::string(base::trim(l.substr(eq + 1))), "bench.moos", ++line});
    }
  }
  return out;
}

// The node reports of every iteration, formatted before timing.
std::vector<std::vector<std::string>> reports(bool lat_lon) {
  const GeographicLib::LocalCartesian frame(kLatOrigin, kLonOrigin, 0.0);
  const double half_m = std::ceil(std::sqrt(static_cast<double>(kObjects))) * kSpacing_m / 2.0;
  std::vector<std::vector<std::string>> out(kIterations);
  for (int k = 0; k < kIterations; ++k) {
    for (int v = 0; v < kVehicles; ++v) {
      const double x = -half_m + 50 + k * kTick_s * kSpeed_mps;
      const double y = -half_m + (v + 1) * 2 * half_m / (kVehicles + 1);
      std::string pos;
      if (lat_lon) {
        double lat, lon, h;
        frame.Reverse(x, y, 0.0, lat, lon, h);
        pos = "LAT=" + base::fmt(lat, 10) + ",LON=" + base::fmt(lon, 10);
      } else {
        pos = "X=" + base::fmt(x, 2) + ",Y=" + base::fmt(y, 2);
      }
      out[k].push_back("NAME=v" + std::to_string(v) + "," + pos + ",SPD=1.5,HDG=90");
    }
  }
  return out;
}

struct Measured {
  double us_per_update = 0.0;
  double bytes_per_object = 0.0;
  double bytes_per_vehicle = 0.0;
  std::string effects;
};

// One timed run of a scene; the caller keeps the best of several rounds.
Measured measure_once(const Scene& s, const std::string& text,
                      const std::vector<std::vector<std::string>>& mail) {
  Measured m;
  const std::size_t before = g_live_bytes;
  hazard::MissionOrigin origin;
  if (s.lat_lon) origin = {kLatOrigin, kLonOrigin, std::string("42.358436"), std::string("-71.087448")};
  auto driver = std::make_unique<hazard::Driver>(
      hazard::load_configuration(block(s), [&](const std::string&) { return base::Result<std::string>::ok(text); }, origin),
      hazard::SeedChoice{1, hazard::SeedSource::kCommandLine});
  driver->start(0);
  const std::size_t built = g_live_bytes;
  for (int v = 0; v < kVehicles; ++v) {
    driver->deliver(hazard::Mail{"UHZ_SENSOR_REQUEST", "vname=v" + std::to_string(v), 0});
  }
  std::size_t postings = 0;
  const auto t0 = Clock::now();
  for (int k = 0; k < kIterations; ++k) {
    const double now = (k + 1) * kTick_s;
    for (const std::string& report : mail[k]) {
      postings += driver->deliver(hazard::Mail{"NODE_REPORT", report, now}).outputs.postings.size();
    }
    postings += driver->step(now).outputs.postings.size();
  }
  const double us = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  m.us_per_update = us / (kIterations * kVehicles);
  m.bytes_per_object = static_cast<double>(built - before) / kObjects;
  m.bytes_per_vehicle = static_cast<double>(g_live_bytes - built) / kVehicles;
  for (auto name : driver->engine().effects().active_names()) {
    m.effects += (m.effects.empty() ? "" : ", ") + std::string(name);
  }
  if (postings == 0) std::fprintf(stderr, "%s: no postings\n", s.name);
  return m;
}

}  // namespace

int main() {
  const std::vector<Scene> scenes = {
      {"plain", ""},
      {"speed gate", "max_vehicle_speed = 2\n"},
      {"turn blackout", "max_turn_rate = 1.5\n"},
      {"resemblance", "", true},
      {"aspect", "", false, true},
      {"swept swath", "swath_sweep = true\n"},
      {"sub-steps (4)", "swath_substeps = 4\n"},
      {"geodesy (enu)", "", false, false, true},
      {"swath visuals", "show_swath = true\n"},
      {"detection visuals", "show_detections = 60\n"},
      {"hazard markers", "show_hazards = true\n"},
      {"all together",
       "max_vehicle_speed = 2\nmax_turn_rate = 1.5\nswath_sweep = true\nshow_swath = true\n"
       "show_detections = 60\nshow_hazards = true\n",
       true, true, true},
  };
  std::printf("Effects: %d objects, %d vehicles, %d iterations at 4 Hz; best of %d rounds "
              "(each round runs every scene once)\n\n",
              kObjects, kVehicles, kIterations, kRepeats);
  std::vector<std::string> texts;
  std::vector<std::vector<std::vector<std::string>>> mails;
  for (const Scene& s : scenes) {
    texts.push_back(field_text(s.hr, s.aspect));
    mails.push_back(reports(s.lat_lon));
  }
  std::vector<Measured> best(scenes.size());
  for (int round = 0; round < kRepeats; ++round) {
    for (std::size_t i = 0; i < scenes.size(); ++i) {
      const Measured m = measure_once(scenes[i], texts[i], mails[i]);
      if (round == 0 || m.us_per_update < best[i].us_per_update) best[i] = m;
    }
  }
  std::printf("| Scene | Active effects | us per vehicle update | x plain | bytes per object | "
              "bytes per vehicle |\n");
  std::printf("|---|---|---:|---:|---:|---:|\n");
  double plain = 0.0, plain_bytes = 0.0;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const Scene& s = scenes[i];
    const Measured& m = best[i];
    if (plain == 0.0) {
      plain = m.us_per_update;
      plain_bytes = m.bytes_per_object;
    }
    std::printf("| %s | %s | %.2f | %.2f | %.0f (%+.0f) | %.0f |\n", s.name,
                m.effects.empty() ? "none" : m.effects.c_str(), m.us_per_update,
                m.us_per_update / plain, m.bytes_per_object, m.bytes_per_object - plain_bytes,
                m.bytes_per_vehicle);
  }
  return 0;
}
