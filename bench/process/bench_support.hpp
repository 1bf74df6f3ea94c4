#pragma once
// What the process benchmarks (bench/process, bench/moosdb) share: the cost of a running process
// read from /proc, percentiles, free ports, programs found on PATH, and child processes that are
// always stopped with bounded waits.
//
// Contract:
// - cpu_ticks_from_stat parses one /proc/<pid>/stat line: utime + stime (fields 14 and 15) in
//   clock ticks; the command name in parentheses may hold blanks and ')' (the LAST ')' ends it).
// - run_ns_from_schedstat parses a /proc/<pid>/task/<tid>/schedstat line: its first field,
//   nanoseconds on a CPU (exact, where /proc/<pid>/stat counts 10-ms clock ticks).
// - status_kb reads a "Field:   123 kB" line of /proc/<pid>/status (VmRSS, VmHWM).
// - percentile is nearest-rank: the smallest value with at least `fraction` of the values at or
//   below it; NaN for no values. fraction is clamped to [0, 1].
// - Process::start forks and execs (no shell) with output to two files; stop() sends SIGINT,
//   then SIGTERM, then SIGKILL, each after a bounded wait, and reaps. The destructor stops a
//   process still running, so no child outlives the benchmark.

#include <sys/types.h>

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "moos/command_line.hpp"

namespace bench {

/// Seconds on a monotonic clock.
double steady_now_s();

/// utime + stime of a /proc/<pid>/stat line, in clock ticks; nullopt if malformed.
std::optional<unsigned long long> cpu_ticks_from_stat(std::string_view stat_line);
/// Nanoseconds on a CPU from a schedstat line ("run_ns wait_ns slices"); nullopt if malformed.
std::optional<unsigned long long> run_ns_from_schedstat(std::string_view schedstat_line);
/// The value in kB of `field` ("VmRSS", "VmHWM") in /proc/<pid>/status text.
std::optional<long long> status_kb(std::string_view status_text, std::string_view field);

struct ProcUsage {
  /// CPU seconds of the process's live threads (schedstat, exact), or user + system clock ticks
  /// of /proc/<pid>/stat where schedstat is missing; a thread that ended takes its time along.
  double cpu_s = 0;
  long long rss_kb = 0;  ///< resident set now
  long long hwm_kb = 0;  ///< resident set high-water mark
};
/// Reads /proc/<pid>; nullopt if the process is gone.
std::optional<ProcUsage> read_proc_usage(pid_t pid);

/// A benchmark's switch table: `rules` and --help, with one wording of refused arguments.
moos::SwitchTable bench_switch_table(std::vector<moos::SwitchRule> rules);
/// Reads argv with `table`. --help prints `help` and exits 0; the first refused argument (or a
/// free one) is printed as "PROGRAM: problem (see --help)" and gives nullopt.
std::optional<moos::SwitchValues> read_switches(const char* program, int argc, char** argv,
                                                const moos::SwitchTable& table,
                                                const char* help);

/// Nearest-rank percentile of `values` (copied and sorted); NaN if empty.
double percentile(std::vector<double> values, double fraction);

/// CPU seconds per simulated hour had the app kept its nominal tick: `cpu_per_h` scaled by
/// AppTick / achieved iterations per MOOS second (CPU per iteration x nominal iterations). An app
/// that saturates a core cannot show its cost per simulated hour, only this; for one that keeps
/// its tick (within 1 %) it is `cpu_per_h`. NaN when the iterations are unknown (<= 0): an app
/// too slow to answer both AppCast requests has no figure, not its measured (capped) one.
double cpu_per_h_at_nominal_tick(double cpu_per_h, double iterations_per_s, double app_tick_hz);

/// A TCP port on 127.0.0.1 that was free a moment ago (bound to port 0, then released).
std::optional<int> free_tcp_port();
/// The first executable `name` in a PATH folder, "" if none.
std::string find_on_path(const std::string& name);
/// The canonical path of an existing file, "" if it does not exist.
std::string canonical_path(const std::string& path);

/// A program path with a '/' made absolute (children run in other folders); a bare name, found
/// on PATH by exec, unchanged.
std::string absolute_program(const std::string& program);
/// The folder a benchmark works in: `requested` (created if needed) or, when that is empty, a
/// new /tmp/<stem>.XXXXXX. "" (with the reason on `err`) if it cannot be made.
std::string work_folder(const std::string& requested, const std::string& stem, std::ostream& err);

/// A table cell: "-" for a negative or NaN value (not measured), else the value to `decimals`.
std::string cell(double value, int decimals);
/// One line of a result table: `label` in kLabelColumns, then each cell in kCellColumns (a
/// longer cell pushes the next one right by at least one blank).
inline constexpr std::size_t kLabelColumns = 34;
inline constexpr std::size_t kCellColumns = 16;
std::string table_line(std::string label, const std::vector<std::string>& cells);

/// A child process with its standard output and error in files.
class Process {
 public:
  Process() = default;
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;
  ~Process();

  /// Starts `program` with `args` in `working_dir`; output to `log_stem`.out and .err. False
  /// (with error()) if fork fails or the process is already running.
  bool start(const std::string& program, const std::vector<std::string>& args,
             const std::string& working_dir, const std::string& log_stem);
  bool running();
  pid_t pid() const { return pid_; }
  /// SIGINT, up to `grace_s` for it to exit, then SIGTERM and SIGKILL (1 s each). True if it
  /// exited on the SIGINT.
  bool stop(double grace_s);
  const std::string& error() const { return error_; }

 private:
  bool wait_exit(double timeout_s);
  pid_t pid_ = -1;
  std::string error_;
};

}  // namespace bench
