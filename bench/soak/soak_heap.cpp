// What the sensor's engine holds over a soak (docs/robustness.md "Soak"). A diagnosis
// tool, not a benchmark with a target: it replays the mail the sensor received in a soak (the
// run's .alog, written by moosdb-lite) through hazard::Driver, built from the run's
// uFldHazardSensor block, stepping at the AppTick, and prints every `--every` simulated seconds
// the heap and the per-(vehicle, object) state the sensor keeps (pass counts and credits).
//
//   build/release/bench/soak/soak_heap WORK_DIR [--app-tick=4] [--every=1800]
//
// WORK_DIR is the soak's --work-dir: ours/mission.moos and ours/db.alog. Heap: glibc mallinfo2,
// in use (uordblks + hblkhd: the chunks handed out, headers and rounding included) and held
// (arena + hblkhd: in use plus what the allocator keeps free; the process's RSS follows it).
// The seed is the block's (seed_random = false: 1, as in the soak), so the dice and the
// detections are the run's; the timing differs (mail is taken at its logged time, iterations
// exactly every 1/AppTick simulated seconds).
#include <malloc.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "base/file.hpp"
#include "base/text.hpp"
#include "hazard/driver.hpp"
#include "moos/alog.hpp"
#include "moos/mission.hpp"

namespace {

constexpr const char* kSensor = "uFldHazardSensor";

struct Heap {
  double in_use_mb = 0;
  double held_mb = 0;
};

Heap heap() {
  const struct mallinfo2 m = mallinfo2();
  return {static_cast<double>(m.uordblks + m.hblkhd) / 1048576.0,
          static_cast<double>(m.arena + m.hblkhd) / 1048576.0};
}

bool sensor_mail(const std::string& variable) {
  for (const char* v : {"NODE_REPORT", "UHZ_SENSOR_REQUEST", "UHZ_CONFIG_REQUEST",
                        "UHZ_CLASSIFY_REQUEST", "UHZ_SENSOR_CLEAR"}) {
    if (variable == v) return true;
  }
  return false;
}

void print_row(const hazard::Engine& e, double time_s) {
  std::size_t records = 0, with_credits = 0, credits = 0, slots = 0;
  for (hazard::VehicleId id : e.vehicles_by_name()) {
    const hazard::VehicleState& v = e.vehicle(id);
    records += v.objects.size();
    for (const auto& entry : v.objects) {
      credits += entry.second.credits.size;
      with_credits += entry.second.credits.empty() ? 0 : 1;
    }
    slots += v.credits.slots();
  }
  const Heap h = heap();
  std::printf("| %.0f | %.2f | %.2f | %zu | %zu | %zu | %zu |\n", time_s, h.in_use_mb, h.held_mb,
              records, with_credits, credits, slots);
  std::fflush(stdout);
}

std::optional<hazard::Driver> make_driver(const std::string& mission_path) {
  std::vector<moos::MissionError> errors;
  const auto mission = moos::MissionFile::load(mission_path, {}, &errors);
  const moos::ProcessBlock* block = mission ? mission->block(kSensor) : nullptr;
  if (!block) {
    std::fprintf(stderr, "soak_heap: no %s block in %s\n", kSensor, mission_path.c_str());
    return std::nullopt;
  }
  std::vector<hazard::ConfigEntry> entries;
  for (const moos::ConfigLine& l : block->lines) {
    entries.push_back({l.key, l.value, l.file, l.line});
  }
  // A relative hazard_file is found next to the mission file, as the sensor finds it.
  const std::filesystem::path folder = mission->directory();
  hazard::EngineSetup setup = hazard::load_configuration(entries, [&](const std::string& path) {
    const std::filesystem::path p(path);
    return base::read_file_text((p.is_relative() ? folder / p : p).string());
  });
  const hazard::SeedChoice seed =
      hazard::resolve_seed(std::nullopt, setup.config, [] { return hazard::kUnseededSeed; });
  return hazard::Driver(std::move(setup), seed);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: soak_heap WORK_DIR [--app-tick=4] [--every=1800]\n");
    return 2;
  }
  const std::string work = argv[1];
  double app_tick = 4, every_s = 1800;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto [key, value] = std::make_pair(arg.substr(0, arg.find('=')),
                                             arg.substr(arg.find('=') + 1));
    const std::optional<double> number = base::parse_number(value);
    if (!number || *number <= 0 || (key != "--app-tick" && key != "--every")) {
      std::fprintf(stderr, "soak_heap: bad option '%s'\n", arg.c_str());
      return 2;
    }
    (key == "--app-tick" ? app_tick : every_s) = *number;
  }
  std::optional<hazard::Driver> d = make_driver(work + "/ours/mission.moos");
  if (!d) return 1;
  std::ifstream alog(work + "/ours/db.alog");
  if (!alog) {
    std::fprintf(stderr, "soak_heap: cannot read %s/ours/db.alog\n", work.c_str());
    return 1;
  }
  std::printf("| simulated s | heap in use MB | heap held MB | records | with credits | credits "
              "| pool slots |\n|---|---|---|---|---|---|---|\n");
  const double tick_s = 1.0 / app_tick;
  double next_step_s = tick_s, next_row_s = 0;
  d->start(0);
  auto step_until = [&](double time_s) {
    for (; next_step_s <= time_s; next_step_s += tick_s) {
      d->step(next_step_s);
      if (next_step_s >= next_row_s) {
        print_row(d->engine(), next_step_s);
        next_row_s += every_s;
      }
    }
  };
  std::string line;
  while (std::getline(alog, line)) {
    const moos::AlogParse p = moos::parse_alog_line(line);
    if (p.kind != moos::AlogLineKind::kEntry || p.entry.source == kSensor) continue;
    if (!sensor_mail(p.entry.variable)) continue;
    step_until(p.entry.time_s);
    d->deliver(hazard::Mail{p.entry.variable, p.entry.value, p.entry.time_s});
  }
  print_row(d->engine(), next_step_s - tick_s);
  return 0;
}
