// process_bench: plays V lawnmower vehicles against uFldHazardSensor through a MOOSDB and prints
// what the sensor costs; with the original uFldHazardSensor available, runs it on the same load
// and prints both side by side. See --help and docs/performance.md.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "base/text.hpp"
#include "bench_support.hpp"
#include "load_run.hpp"

namespace {

constexpr const char* kHelp = R"(Usage: process_bench [OPTIONS]

Plays V vehicles (lawnmower tracks, NODE_REPORT at --report-hz, UHZ_CONFIG_REQUEST,
UHZ_SENSOR_REQUEST, a UHZ_CLASSIFY_REQUEST per detection) against uFldHazardSensor through a
MOOSDB at a time warp, for a simulated duration, and prints the sensor's and the MOOSDB's CPU
seconds per simulated hour, the sensor's iterations per second against AppTick, its resident
memory, and the delay from a node report to its detection report. When the original
uFldHazardSensor is found (--original, or on PATH and not ours), it runs on the same field,
load and MOOSDB, and a ratio column is printed.

  --objects=N          objects in the field, half hazards (default 10000, at most 1000000)
  --vehicles=V         vehicles (default 1, at most 1000; 0 measures an idle sensor)
  --warp=W             MOOS time warp (default 50)
  --duration=S         simulated seconds of load (default 600)
  --report-hz=HZ       node reports per vehicle per MOOS second (default 10)
  --request-hz=HZ      UHZ_SENSOR_REQUEST per vehicle per MOOS second (default 4)
  --app-tick=HZ        the sensor's AppTick (default 4)
  --idle-app-tick=HZ   IdleAppTick for our sensor (opt-in: it skips AppTick slots while it has
                       nothing to do; default: not set, every slot is a cycle)
  --area-per-object=M2 field area per object, square metres (default 400: 10k objects in
                       2 km x 2 km)
  --markers            show_hazards = true (default false)
  --sensor=PATH        our uFldHazardSensor (default: the one built with this benchmark)
  --moosdb=PATH        the MOOSDB both sensors use (default: our moosdb-lite)
  --original=PATH|none the original uFldHazardSensor (default: uFldHazardSensor on PATH if it
                       is not ours)
  --gen-hazards=PATH   gen_hazards (default: the one built with this benchmark)
  --work-dir=DIR       where the field, missions and logs go and stay (default: a new /tmp
                       folder, removed at the end unless a run failed)
  --startup-timeout=S  real seconds a sensor may take to load its field (default 600)
  --csv=FILE           also append one line per run to FILE (a header first if it is new)

Soak options (bench/soak/run.sh; simulated seconds):
  --moosdb-log=FILE    the MOOSDB logs every posting to FILE (moosdb-lite --log), in the
                       run's folder (ours/FILE)
  --config-every=S     a UHZ_CONFIG_REQUEST per vehicle every S s (default: only the first)
  --classify-every=S   one UHZ_CLASSIFY_REQUEST per vehicle every S s for its newest
                       unclassified detection (default: one per detection at once)
  --drain=S            after the load, S s more of reading mail, sending nothing (default 0)
  --sample-every=S     every S s: resident memory of sensor and MOOSDB and the sensor's worst
                       iteration gap, one line each in the run's samples.csv (default: none)
)";

/// The samples file of a run (--sample-every), in the run's folder.
constexpr const char* kSamplesFile = "samples.csv";

struct Options {
  long long objects = 10000;
  bench::LoadSpec spec;
  double area_per_object_m2 = 400;
  std::string sensor = HAZARD_SENSOR_PROGRAM;
  std::string moosdb = HAZARD_MOOSDB_LITE_PROGRAM;
  std::string gen_hazards = HAZARD_GEN_HAZARDS_PROGRAM;
  std::string original;  // "" = look on PATH
  std::optional<double> idle_app_tick_hz;  // ours only
  std::string work_dir;
  std::string csv;
};

std::optional<double> positive(std::string_view text) {
  const auto v = base::parse_number(text);
  return v && *v > 0 ? v : std::nullopt;
}

std::optional<Options> parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto eq = arg.find('=');
    const std::string name = arg.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : arg.substr(eq + 1);
    std::optional<double> number = positive(value);
    bool ok = true;
    if (name == "--help" || name == "-h") {
      std::cout << kHelp;
      std::exit(0);
    } else if (name == "--objects") {
      const auto n = base::parse_integer(value, 1, 1000000);
      ok = n.has_value();
      if (ok) o.objects = *n;
    } else if (name == "--vehicles") {
      const auto n = base::parse_integer(value, 0, 1000);
      ok = n.has_value();
      if (ok) o.spec.vehicles = static_cast<int>(*n);
    } else if (name == "--warp") {
      ok = number && *number <= 400;
      if (ok) o.spec.time_warp = *number;
    } else if (name == "--duration") {
      ok = number.has_value();
      if (ok) o.spec.duration_s = *number;
    } else if (name == "--report-hz") {
      ok = number.has_value();
      if (ok) o.spec.report_hz = *number;
    } else if (name == "--request-hz") {
      ok = number.has_value();
      if (ok) o.spec.request_hz = *number;
    } else if (name == "--app-tick") {
      ok = number.has_value();
      if (ok) o.spec.app_tick_hz = *number;
    } else if (name == "--idle-app-tick") {
      ok = number.has_value();
      if (ok) o.idle_app_tick_hz = *number;
    } else if (name == "--area-per-object") {
      ok = number.has_value();
      if (ok) o.area_per_object_m2 = *number;
    } else if (name == "--startup-timeout") {
      ok = number.has_value();
      if (ok) o.spec.startup_timeout_real_s = *number;
    } else if (name == "--config-every") {
      ok = number.has_value();
      if (ok) o.spec.config_every_s = *number;
    } else if (name == "--classify-every") {
      ok = number.has_value();
      if (ok) o.spec.classify_every_s = *number;
    } else if (name == "--drain") {
      ok = number.has_value();
      if (ok) o.spec.drain_s = *number;
    } else if (name == "--sample-every") {
      ok = number.has_value();
      if (ok) o.spec.sample_every_s = *number;
    } else if (name == "--moosdb-log" && !value.empty()) {
      o.spec.moosdb_log = value;
    } else if (arg == "--markers") {
      o.spec.show_hazards = true;
    } else if (name == "--sensor" && !value.empty()) {
      o.sensor = value;
    } else if (name == "--moosdb" && !value.empty()) {
      o.moosdb = value;
    } else if (name == "--original" && !value.empty()) {
      o.original = value;
    } else if (name == "--gen-hazards" && !value.empty()) {
      o.gen_hazards = value;
    } else if (name == "--work-dir" && !value.empty()) {
      o.work_dir = value;
    } else if (name == "--csv" && !value.empty()) {
      o.csv = value;
    } else {
      ok = false;
    }
    if (!ok) {
      std::cerr << "process_bench: bad argument '" << base::excerpt(arg, 80) << "' (see --help)\n";
      return std::nullopt;
    }
  }
  // The processes run in their own folders: relative program paths would break there.
  for (std::string* program : {&o.sensor, &o.moosdb, &o.gen_hazards, &o.original})
    *program = bench::absolute_program(*program);
  o.spec.samples_csv = kSamplesFile;
  o.spec.field_side_m = std::sqrt(static_cast<double>(o.objects) * o.area_per_object_m2);
  return o;
}

/// The original sensor to compare with: --original, or uFldHazardSensor on PATH unless that is
/// ours; "" for none.
std::string original_sensor(const Options& o) {
  if (o.original == "none") return {};
  if (!o.original.empty()) return o.original;
  const std::string found = bench::find_on_path("uFldHazardSensor");
  if (found.empty() || bench::canonical_path(found) == bench::canonical_path(o.sensor)) return {};
  return found;
}

bool generate_field(const Options& o, const std::string& path) {
  const std::string side = base::fix(o.spec.field_side_m, 1);
  const long long hazards = o.objects / 2;
  bench::Process gen;
  if (!gen.start(o.gen_hazards,
                 {"--polygon=0,0:0," + side + ":" + side + "," + side + ":" + side + ",0",
                  "--objects=" + std::to_string(hazards) + ",hazard",
                  "--objects=" + std::to_string(o.objects - hazards) + ",benign", "--seed=1",
                  "--output=" + path},
                 ".", path + ".gen"))
    return false;
  const double deadline = bench::steady_now_s() + 300;
  while (gen.running() && bench::steady_now_s() < deadline) ::usleep(10000);
  gen.stop(1);
  return std::filesystem::exists(path);
}

using Runs = std::vector<std::pair<std::string, bench::LoadResult>>;

void print_table(const Options& o, const Runs& runs) {
  std::cout << "\nload: " << o.objects << " objects x " << o.spec.vehicles << " vehicles, warp "
            << base::format_g(o.spec.time_warp) << ", " << base::format_g(o.spec.duration_s)
            << " simulated s, node reports " << base::format_g(o.spec.report_hz)
            << " Hz, AppTick " << base::format_g(o.spec.app_tick_hz) << ", markers "
            << (o.spec.show_hazards ? "on" : "off") << ", MOOSDB " << o.moosdb << "\n";
  auto row = [&](const std::string& what, auto value_of, bool ratio) {
    std::vector<std::string> cells;
    for (const auto& run : runs) cells.push_back(run.second.ok ? value_of(run.second) : "failed");
    if (ratio && cells.size() == 2) {
      const auto ours = base::parse_number(cells[0]);
      const auto theirs = base::parse_number(cells[1]);
      if (ours && theirs && *ours > 0 && *theirs > 0)
        cells.push_back(base::fix(*theirs / *ours, 1) + "x");
    }
    std::cout << bench::table_line(what, cells) << "\n";
  };
  std::vector<std::string> header;
  for (const auto& run : runs) header.push_back(run.first);
  if (runs.size() == 2) header.push_back("original / ours");
  std::cout << bench::table_line("", header) << "\n";
  using bench::cell;
  using R = bench::LoadResult;
  row("sensor CPU s / simulated hour", [](const R& r) { return cell(r.sensor_cpu_per_h, 2); },
      true);
  // With IdleAppTick ours skips slots on purpose: there is no missed tick to scale to.
  if (!o.idle_app_tick_hz)
    row("  at its nominal tick", [&](const R& r) {
      return cell(bench::cpu_per_h_at_nominal_tick(r.sensor_cpu_per_h, r.iterations_per_s,
                                                   o.spec.app_tick_hz), 2); }, true);
  row("sensor share of a core",
      [](const R& r) { return cell(100 * r.sensor_cpu_share, 3) + "%"; }, false);
  row("MOOSDB CPU s / simulated hour", [](const R& r) { return cell(r.moosdb_cpu_per_h, 2); },
      true);
  row("iterations / s (nominal " + base::format_g(o.spec.app_tick_hz) + ")",
      [](const R& r) { return cell(r.iterations_per_s, 2); }, false);
  row("sensor VmRSS / VmHWM MB", [](const R& r) {
    return cell(r.sensor_rss_kb / 1024.0, 1) + "/" + cell(r.sensor_hwm_kb / 1024.0, 1); }, true);
  row("MOOSDB VmHWM MB", [](const R& r) { return cell(r.moosdb_hwm_kb / 1024.0, 1); }, true);
  row("delay p50 ms (report->detection)", [](const R& r) { return cell(r.delay_p50_ms, 1); }, true);
  row("delay p99 ms", [](const R& r) { return cell(r.delay_p99_ms, 1); }, true);
  row("detections (matched)", [](const R& r) {
    return std::to_string(r.detections) + " (" + std::to_string(r.matched) + ")"; }, false);
  row("hazard reports", [](const R& r) { return std::to_string(r.hazard_reports); }, false);
  row("node reports sent / nominal", [](const R& r) {
    return std::to_string(r.reports_sent) + "/" + base::fix(r.reports_nominal, 0); }, false);
  row("start-up s (load + first ACKs)", [](const R& r) { return cell(r.startup_real_s, 1); }, true);
  for (const auto& run : runs)
    if (!run.second.ok) std::cout << run.first << " failed: " << run.second.error << "\n";
}

/// Appends one line per run to `path`, for plots and studies (plot_performance.py reads it).
bool append_csv(const Options& o, const Runs& runs, const std::string& path) {
  const bool fresh = !std::filesystem::exists(path);
  std::ofstream out(path, std::ios::app);
  if (fresh)
    out << "program,objects,vehicles,warp,simulated_s,markers,ok,sensor_cpu_s_per_h,"
           "moosdb_cpu_s_per_h,iterations_per_s,app_tick,sensor_rss_kb,sensor_hwm_kb,"
           "delay_p50_ms,delay_p99_ms,detections,startup_s,sensor_cpu_s_per_h_nominal_tick\n";
  for (const auto& [label, r] : runs)
    out << label << ',' << o.objects << ',' << o.spec.vehicles << ','
        << base::format_g(o.spec.time_warp) << ',' << base::format_g(o.spec.duration_s) << ','
        << (o.spec.show_hazards ? 1 : 0) << ',' << (r.ok ? 1 : 0) << ',' << base::fix(r.sensor_cpu_per_h, 3) << ','
        << base::fix(r.moosdb_cpu_per_h, 3) << ',' << base::fix(r.iterations_per_s, 3) << ','
        << base::format_g(o.spec.app_tick_hz) << ',' << r.sensor_rss_kb << ',' << r.sensor_hwm_kb
        << ',' << base::fix(r.delay_p50_ms, 2) << ',' << base::fix(r.delay_p99_ms, 2) << ','
        << r.detections << ',' << base::fix(r.startup_real_s, 2) << ','
        << base::fix(o.idle_app_tick_hz ? r.sensor_cpu_per_h
                                        : bench::cpu_per_h_at_nominal_tick(
                                              r.sensor_cpu_per_h, r.iterations_per_s,
                                              o.spec.app_tick_hz), 3) << '\n';
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char** argv) {
  auto options = parse(argc, argv);
  if (!options) return 1;
  Options& o = *options;
  const bool temporary = o.work_dir.empty();  // removed at the end unless a run failed
  o.work_dir = bench::work_folder(o.work_dir, "process_bench", std::cerr);
  if (o.work_dir.empty()) return 1;
  const std::string field = o.work_dir + "/hazards.txt";
  std::cerr << "process_bench: field of " << o.objects << " objects, "
            << base::fix(o.spec.field_side_m, 0) << " m square, in " << o.work_dir << "\n";
  if (!generate_field(o, field)) {
    std::cerr << "process_bench: " << o.gen_hazards << " did not write " << field << "\n";
    return 1;
  }
  Runs runs;
  bench::Target ours{"ours", o.sensor, o.moosdb, field, o.work_dir + "/ours", o.idle_app_tick_hz};
  runs.emplace_back("ours", bench::run_load(o.spec, ours, std::cerr));
  const std::string original = original_sensor(o);
  if (!original.empty()) {
    // The original's swath reaches swath_length fore and aft (D1), ours half of it.
    bench::LoadSpec spec = o.spec;
    spec.swath_half_length_m = spec.swath_length_m;
    bench::Target theirs{"original", original, o.moosdb, field, o.work_dir + "/original", {}};
    runs.emplace_back("original", bench::run_load(spec, theirs, std::cerr));
  } else {
    std::cerr << "process_bench: no original uFldHazardSensor (give --original=PATH); ours only\n";
  }
  print_table(o, runs);
  if (!o.csv.empty() && !append_csv(o, runs, o.csv))
    std::cerr << "process_bench: cannot write " << o.csv << "\n";
  for (const auto& run : runs)
    if (!run.second.ok) {
      std::cerr << "process_bench: logs kept in " << o.work_dir << "\n";
      return 2;
    }
  if (temporary) std::filesystem::remove_all(o.work_dir);
  return 0;
}
