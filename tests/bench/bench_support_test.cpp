// /proc parsing, percentiles, ports and child processes of bench/process/bench_support.
#include "bench_support.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

TEST(RunNsFromSchedstat, TakesTheFirstOfThreeFields) {
  EXPECT_EQ(bench::run_ns_from_schedstat("27203456 1024 311\n"), 27203456u);
  EXPECT_FALSE(bench::run_ns_from_schedstat("27203456 1024").has_value());
  EXPECT_FALSE(bench::run_ns_from_schedstat("x 1 2").has_value());
  EXPECT_FALSE(bench::run_ns_from_schedstat("").has_value());
}

TEST(ReadProcUsage, CountsThisProcessesCpuToTheNanosecond) {
  const auto before = bench::read_proc_usage(::getpid());
  ASSERT_TRUE(before.has_value());
  volatile double sink = 0;
  for (int i = 0; i < 3000000; ++i) sink = sink + std::sqrt(static_cast<double>(i));
  const auto after = bench::read_proc_usage(::getpid());
  ASSERT_TRUE(after.has_value());
  const double spent_s = after->cpu_s - before->cpu_s;
  EXPECT_GT(spent_s, 0.0);
  // Clock ticks would show 0 or a multiple of 10 ms; schedstat shows the loop's own time.
  const double hundredths = spent_s * 100;
  EXPECT_GT(std::fabs(hundredths - std::round(hundredths)), 1e-6);
}

TEST(CpuTicksFromStat, SumsUtimeAndStimeAfterTheCommandName) {
  // A command name with a blank and a ')' inside: only the last ')' ends it.
  const std::string line =
      "4242 (my prog) x) S 1 4242 4242 0 -1 4194560 120 0 0 0 731 69 0 0 20 0 3 0 100 1000 200";
  EXPECT_EQ(bench::cpu_ticks_from_stat(line), 800u);
}

TEST(CpuTicksFromStat, RefusesTruncatedOrNonNumericLines) {
  EXPECT_FALSE(bench::cpu_ticks_from_stat("4242 (prog) S 1 2 3"));
  EXPECT_FALSE(bench::cpu_ticks_from_stat("4242 prog S 1 4242 4242 0 -1 1 1 1 1 1 7 8"));
  EXPECT_FALSE(bench::cpu_ticks_from_stat(
      "1 (p) S 1 1 1 0 -1 4194560 120 0 0 0 seven 69 0 0 20 0 3 0 100 1000 200"));
}

TEST(StatusKb, ReadsTheNamedFieldOnly) {
  const std::string status =
      "Name:\tsensor\nVmPeak:\t  9000 kB\nVmHWM:\t    5120 kB\nVmRSS:\t    4096 kB\n";
  EXPECT_EQ(bench::status_kb(status, "VmRSS"), 4096);
  EXPECT_EQ(bench::status_kb(status, "VmHWM"), 5120);
  EXPECT_FALSE(bench::status_kb(status, "VmSwap"));
  EXPECT_FALSE(bench::status_kb("VmRSS:\t 12 pages\n", "VmRSS"));
}

TEST(ReadProcUsage, SeesThisProcess) {
  const auto usage = bench::read_proc_usage(::getpid());
  ASSERT_TRUE(usage);
  EXPECT_GT(usage->rss_kb, 0);
  EXPECT_GE(usage->hwm_kb, usage->rss_kb);
  EXPECT_GE(usage->cpu_s, 0.0);
}

TEST(NominalTickCost, ScalesAnAppThatMissesItsTickToTheTickItWasAskedFor) {
  // The original at 100k x 10: 343 CPU s per simulated hour while iterating 0.1 times of 4.
  EXPECT_DOUBLE_EQ(bench::cpu_per_h_at_nominal_tick(343.0, 0.1, 4.0), 343.0 * 40);
  EXPECT_DOUBLE_EQ(bench::cpu_per_h_at_nominal_tick(100.0, 2.0, 4.0), 200.0);
}

TEST(NominalTickCost, LeavesAnAppThatKeepsItsTickAsMeasured) {
  EXPECT_DOUBLE_EQ(bench::cpu_per_h_at_nominal_tick(2.5, 4.0, 4.0), 2.5);
  EXPECT_DOUBLE_EQ(bench::cpu_per_h_at_nominal_tick(2.5, 3.97, 4.0), 2.5);  // within 1 %
}

// The original at 100k x 100 answered no AppCast request in the window: its measured CPU is
// only what one core gives, so no figure (the table's "-"), not a ratio against that cap.
TEST(NominalTickCost, HasNoFigureWhenTheIterationsAreUnknown) {
  EXPECT_TRUE(std::isnan(bench::cpu_per_h_at_nominal_tick(363.0, -1.0, 4.0)));
  EXPECT_TRUE(std::isnan(bench::cpu_per_h_at_nominal_tick(363.0, 0.0, 4.0)));
  EXPECT_EQ(bench::cell(bench::cpu_per_h_at_nominal_tick(363.0, 0.0, 4.0), 2), "-");
}

/// read_switches over `args` (argv[0] added) with a two-switch benchmark table.
std::optional<moos::SwitchValues> read(std::vector<std::string> args) {
  static const moos::SwitchTable table = bench::bench_switch_table(
      {moos::switch_rule("--count", moos::SwitchKind::kInteger, "a whole number in [1, 10]",
                         {1, 10}),
       moos::switch_rule("--name", moos::SwitchKind::kText, "a name")});
  args.insert(args.begin(), "bench");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return bench::read_switches("bench", static_cast<int>(argv.size()), argv.data(), table, "");
}

TEST(BenchSwitches, ReadTypedValues) {
  const auto v = read({"--count=3", "--name=x"});
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->integer("--count"), 3);
  EXPECT_EQ(v->text("--name"), "x");
}

TEST(BenchSwitches, RefuseOutOfRangeUnknownAndFreeArguments) {
  EXPECT_FALSE(read({"--count=0"}).has_value());
  EXPECT_FALSE(read({"--count=3.5"}).has_value());
  EXPECT_FALSE(read({"--name"}).has_value());
  EXPECT_FALSE(read({"--other=1"}).has_value());
  EXPECT_FALSE(read({"stray"}).has_value());
}

TEST(Percentile, IsNearestRank) {
  std::vector<double> values;
  for (int i = 100; i >= 1; --i) values.push_back(i);  // unsorted on purpose
  EXPECT_EQ(bench::percentile(values, 0.5), 50);
  EXPECT_EQ(bench::percentile(values, 0.99), 99);
  EXPECT_EQ(bench::percentile(values, 1.0), 100);
  EXPECT_EQ(bench::percentile(values, 0.0), 1);
  EXPECT_EQ(bench::percentile({7, 3, 5}, 0.5), 5);
  EXPECT_EQ(bench::percentile({7, 3, 5}, 0.99), 7);
  EXPECT_TRUE(std::isnan(bench::percentile({}, 0.5)));
}

TEST(FreeTcpPort, GivesAUsablePort) {
  const auto port = bench::free_tcp_port();
  ASSERT_TRUE(port);
  EXPECT_GT(*port, 0);
  EXPECT_LE(*port, 65535);
}

TEST(FindOnPath, FindsAShellAndNotANonsenseName) {
  EXPECT_FALSE(bench::find_on_path("sh").empty());
  EXPECT_TRUE(bench::find_on_path("no-such-program-for-bench-tests").empty());
}

TEST(Process, StopsAChildThatIgnoresNothingAndReportsTheSigintExit) {
  bench::Process child;
  char dir[] = "/tmp/bench_tests.XXXXXX";
  ASSERT_NE(::mkdtemp(dir), nullptr);
  ASSERT_TRUE(child.start("/bin/sleep", {"30"}, dir, std::string(dir) + "/sleep"));
  EXPECT_TRUE(child.running());
  EXPECT_TRUE(child.stop(5));
  EXPECT_FALSE(child.running());
  std::filesystem::remove_all(dir);
}

TEST(Process, EscalatesToSigkillForAChildThatIgnoresSigint) {
  bench::Process child;
  char dir[] = "/tmp/bench_tests.XXXXXX";
  ASSERT_NE(::mkdtemp(dir), nullptr);
  ASSERT_TRUE(child.start("/bin/sh", {"-c", "trap '' INT TERM; touch trapped; exec sleep 30"}, dir,
                          std::string(dir) + "/stubborn"));
  // Signals sent before the trap is in place would end it at once (ignored signals stay
  // ignored across exec, so no orphaned sleep is left behind).
  const std::string marker = std::string(dir) + "/trapped";
  for (int i = 0; i < 1000 && ::access(marker.c_str(), F_OK) != 0; ++i) ::usleep(5000);
  ASSERT_EQ(::access(marker.c_str(), F_OK), 0);
  EXPECT_FALSE(child.stop(0.2));
  EXPECT_FALSE(child.running());
  std::filesystem::remove_all(dir);
}

}  // namespace

namespace {

TEST(Cell, DashesWhatWasNotMeasured) {
  EXPECT_EQ(bench::cell(2.456, 2), "2.46");
  EXPECT_EQ(bench::cell(0, 1), "0.0");
  EXPECT_EQ(bench::cell(-1, 2), "-");
  EXPECT_EQ(bench::cell(std::nan(""), 2), "-");
}

TEST(TableLine, PadsTheLabelAndEveryCell) {
  const std::string line = bench::table_line("cpu", {"1.50", "82.00"});
  EXPECT_EQ(line.size(), bench::kLabelColumns + 2 * bench::kCellColumns);
  EXPECT_EQ(line.substr(0, 3), "cpu");
  EXPECT_EQ(line.substr(bench::kLabelColumns, 4), "1.50");
  EXPECT_EQ(line.substr(bench::kLabelColumns + bench::kCellColumns, 5), "82.00");
  // A cell wider than its column still leaves a blank before the next one.
  const std::string wide(20, 'w');
  EXPECT_EQ(bench::table_line("x", {wide, "y"}).substr(bench::kLabelColumns + 20, 2), " y");
}

TEST(AbsoluteProgram, AnchorsPathsAndLeavesBareNamesToPath) {
  EXPECT_EQ(bench::absolute_program("MOOSDB"), "MOOSDB");
  EXPECT_EQ(bench::absolute_program("/usr/bin/env"), "/usr/bin/env");
  const std::string anchored = bench::absolute_program("build/x");
  EXPECT_EQ(anchored.front(), '/');
  EXPECT_EQ(anchored.substr(anchored.size() - 8), "/build/x");
  EXPECT_EQ(bench::absolute_program(""), "");
}

}  // namespace

namespace {

TEST(WorkFolder, MakesATemporaryFolderOrTheOneAskedFor) {
  std::ostringstream err;
  const std::string temporary = bench::work_folder("", "bench_tests", err);
  ASSERT_FALSE(temporary.empty());
  EXPECT_EQ(temporary.rfind("/tmp/bench_tests.", 0), 0u);
  EXPECT_TRUE(std::filesystem::is_directory(temporary));
  const std::string nested = temporary + "/a/b";
  EXPECT_EQ(bench::work_folder(nested, "bench_tests", err), nested);
  EXPECT_TRUE(std::filesystem::is_directory(nested));
  EXPECT_TRUE(err.str().empty());
  std::filesystem::remove_all(temporary);
}

TEST(WorkFolder, SaysWhyWhenItCannot) {
  std::ostringstream err;
  EXPECT_EQ(bench::work_folder("/proc/no-folders-here", "bench_tests", err), "");
  EXPECT_NE(err.str().find("cannot create the folder /proc/no-folders-here"), std::string::npos);
}

}  // namespace
