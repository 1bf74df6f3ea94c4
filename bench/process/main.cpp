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

const moos::SwitchTable& switch_table() {
  using moos::SwitchKind;
  using moos::switch_rule;
  static const moos::SwitchTable table = [] {
    const std::string positive = "a number above 0";
    return bench::bench_switch_table({
        switch_rule("--objects", SwitchKind::kInteger, "a whole number in [1, 1000000]", {1, 1e6}),
        switch_rule("--vehicles", SwitchKind::kInteger, "a whole number in [0, 1000]", {0, 1000}),
        switch_rule("--warp", SwitchKind::kNumber, "a number in (0, 400]", {0, 400, true, false}),
        switch_rule("--duration", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--report-hz", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--request-hz", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--app-tick", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--idle-app-tick", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--area-per-object", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--startup-timeout", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--config-every", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--classify-every", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--drain", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--sample-every", SwitchKind::kNumber, positive, moos::kPositive),
        switch_rule("--markers", SwitchKind::kFlag, "no value"),
        switch_rule("--moosdb-log", SwitchKind::kText, "a file name"),
        switch_rule("--sensor", SwitchKind::kText, "a program"),
        switch_rule("--moosdb", SwitchKind::kText, "a program"),
        switch_rule("--original", SwitchKind::kText, "a program or none"),
        switch_rule("--gen-hazards", SwitchKind::kText, "a program"),
        switch_rule("--work-dir", SwitchKind::kText, "a folder"),
        switch_rule("--csv", SwitchKind::kText, "a file name")});
  }();
  return table;
}

std::optional<Options> parse(int argc, char** argv) {
  const auto switches = bench::read_switches("process_bench", argc, argv, switch_table(), kHelp);
  if (!switches) return std::nullopt;
  const moos::SwitchValues& v = *switches;
  Options o;
  auto set = [&](const char* name, auto& field) {
    if (const auto value = v.number(name)) field = *value;
  };
  auto set_text = [&](const char* name, std::string& field) {
    if (const auto value = v.text(name)) field = *value;
  };
  if (const auto n = v.integer("--objects")) o.objects = *n;
  if (const auto n = v.integer("--vehicles")) o.spec.vehicles = static_cast<int>(*n);
  set("--warp", o.spec.time_warp);
  set("--duration", o.spec.duration_s);
  set("--report-hz", o.spec.report_hz);
  set("--request-hz", o.spec.request_hz);
  set("--app-tick", o.spec.app_tick_hz);
  if (const auto hz = v.number("--idle-app-tick")) o.idle_app_tick_hz = *hz;
  set("--area-per-object", o.area_per_object_m2);
  set("--startup-timeout", o.spec.startup_timeout_real_s);
  set("--config-every", o.spec.config_every_s);
  set("--classify-every", o.spec.classify_every_s);
  set("--drain", o.spec.drain_s);
  set("--sample-every", o.spec.sample_every_s);
  o.spec.show_hazards = v.has("--markers");
  set_text("--moosdb-log", o.spec.moosdb_log);
  set_text("--sensor", o.sensor);
  set_text("--moosdb", o.moosdb);
  set_text("--original", o.original);
  set_text("--gen-hazards", o.gen_hazards);
  set_text("--work-dir", o.work_dir);
  set_text("--csv", o.csv);
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

/// CPU s per simulated hour at the nominal tick (bench::cpu_per_h_at_nominal_tick). With
/// --idle-app-tick ours skips slots on purpose: there is no missed tick to scale to, so the
/// measured figure (and the table leaves the row out).
double nominal_tick_cpu_per_h(const Options& o, const bench::LoadResult& r) {
  if (o.idle_app_tick_hz) return r.sensor_cpu_per_h;
  return bench::cpu_per_h_at_nominal_tick(r.sensor_cpu_per_h, r.iterations_per_s,
                                          o.spec.app_tick_hz);
}

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
  if (!o.idle_app_tick_hz)
    row("  at its nominal tick",
        [&](const R& r) { return cell(nominal_tick_cpu_per_h(o, r), 2); }, true);
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
        << base::fix(nominal_tick_cpu_per_h(o, r), 3) << '\n';
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
