// The mission launcher (missions/common/launch_lib.sh) through missions/jake/launch.sh: its
// command line, the real-MOOSDB mode (a clear error without MOOSDB on the PATH; the same mission
// on a stand-in MOOSDB, logged by pLogLite), and stopping, with no process left behind: Ctrl-C
// (SIGINT), SIGTERM, a process dying, the launcher itself killed with SIGKILL, the time limit.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>

#include "mission_run.hpp"

namespace mission_test {
namespace {

constexpr double kTestWarp = 400;
/// Real seconds the launcher may need to stop everything (5 s per group at most, see
/// ML_STOP_WAIT_S) and exit.
constexpr double kStopTimeout_s = 30;

std::vector<std::string> launch_args(const fs::path& run_dir, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"--bin-dir=" + std::string(APPS_DIR),
                                   "--run-dir=" + run_dir.string(), "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

/// Runs the launcher to the end; its exit code (nullopt: still running after `timeout_s`).
std::optional<int> run_launcher(const std::vector<std::string>& args, double timeout_s,
                                std::string* out = nullptr, std::string* err = nullptr) {
  const test_support::RunResult r = test_support::run_program(JAKE_LAUNCH, args, timeout_s);
  if (out) *out = r.out;
  if (err) *err = r.err;
  return r.exit_code;
}

/// Waits until the mission is deployed: every process is up (the progress watcher is started
/// after all of them connected) and a second has passed for DEPLOY_ALL.
bool wait_until_running(const fs::path& run_dir, double timeout_s) {
  const double deadline = steady_now_s() + timeout_s;
  while (steady_now_s() < deadline) {
    for (const auto& p : read_pids(run_dir)) {
      if (p.name != "progress-watch") continue;
      ::usleep(1000 * 1000);
      return true;
    }
    ::usleep(50 * 1000);
  }
  return false;
}

/// PATH set for the children started inside the scope, restored after.
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& path) : old_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    ::setenv("PATH", path.c_str(), 1);
  }
  ~ScopedPath() { ::setenv("PATH", old_.c_str(), 1); }
  ScopedPath(const ScopedPath&) = delete;
  ScopedPath& operator=(const ScopedPath&) = delete;
  const std::string& old() const { return old_; }

 private:
  std::string old_;
};

// ---- the command line --------------------------------------------------------------------

TEST(JakeLaunch, HelpListsTheOptionsAndExitsZero) {
  std::string out;
  ASSERT_EQ(run_launcher({"--help"}, 30, &out), 0);
  for (const char* o : {"WARP", "--seed=N", "--moosdb=lite", "--moosdb=real", "--bin-dir=DIR",
                        "--runs-dir=DIR", "--timeout=S", "Exit status"})
    EXPECT_NE(out.find(o), std::string::npos) << o;
}

TEST(JakeLaunch, BadCommandLinesExitTwoNamingTheProblem) {
  const fs::path dir = fresh_run_dir("usage");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"0"}, "outside (0, 400]"},        {{"401"}, "outside (0, 400]"},
      {{"fast"}, "is not a number"},      {{"--seed=x"}, "seed 'x'"},
      {{"--moosdb=fake"}, "lite or real"}, {{"--frobnicate"}, "unknown option '--frobnicate'"},
      {{"100", "200"}, "unexpected argument '200'"}, {{"--timeout=soon"}, "timeout 'soon'"},
  };
  for (const auto& [args, reason] : cases) {
    std::string err;
    EXPECT_EQ(run_launcher(launch_args(dir, args), 30, nullptr, &err), 2) << args[0];
    EXPECT_NE(err.find(reason), std::string::npos) << args[0] << ": " << err;
  }
  EXPECT_FALSE(fs::exists(dir));  // nothing was started, nothing was written
}

TEST(JakeLaunch, MissingBinariesAreAClearError) {
  std::string err;
  EXPECT_EQ(run_launcher({"--bin-dir=/nonexistent", "--run-dir=" + fresh_run_dir("nobin").string()},
                         30, nullptr, &err),
            2);
  EXPECT_NE(err.find("missing programs"), std::string::npos) << err;
  EXPECT_NE(err.find("--bin-dir"), std::string::npos) << err;
}

TEST(JakeLaunch, RealMoosdbWithoutMoosdbOnThePathIsAClearError) {
  if (std::system("PATH=/usr/bin:/bin command -v MOOSDB >/dev/null 2>&1") == 0)
    GTEST_SKIP() << "MOOS-IvP's MOOSDB is installed in /usr/bin";
  ScopedPath path("/usr/bin:/bin");
  std::string err;
  EXPECT_EQ(run_launcher(launch_args(fresh_run_dir("nomoosdb"), {"--moosdb=real"}), 30, nullptr, &err), 2);
  EXPECT_NE(err.find("--moosdb=real needs MOOS-IvP's MOOSDB on the PATH"), std::string::npos) << err;
}

// ---- the real-MOOSDB mode, on a stand-in --------------------------------------------------

TEST(JakeLaunch, RealModeRunsTheSameMissionOnAStandInMoosdbLoggedByPLogLite) {
  // A MOOSDB that takes the real one's command line (the mission file) is moosdb-lite.
  const fs::path bin = fresh_run_dir("standin");
  fs::create_directories(bin);
  {
    std::ofstream script(bin / "MOOSDB");
    script << "#!/bin/sh\nexec \"" << MOOSDB_LITE_PATH << "\" \"$@\"\n";
  }
  ::chmod((bin / "MOOSDB").c_str(), 0755);
  ScopedPath path(bin.string() + ":" + (std::getenv("PATH") ? std::getenv("PATH") : ""));
  const fs::path run_dir = fresh_run_dir("real");
  std::string out, err;
  ASSERT_EQ(run_launcher(launch_args(run_dir, {"--moosdb=real", "--warp=400", "--no-picture"}), 170,
                         &out, &err),
            0)
      << out << err;
  const auto processes = read_pids(run_dir);
  ASSERT_GE(processes.size(), 3u);
  EXPECT_EQ(processes[1].name, "MOOSDB");
  EXPECT_EQ(processes[2].name, "pLogLite");
  // pLogLite wrote the mission's log: the grader's evaluation of betty's report is in it.
  bool graded = false;
  for (const auto& e : read_alog(run_dir / "jake.alog").entries)
    graded = graded || (e.variable == "HAZARDSET_EVAL_BETTY" && e.source == "uFldHazardMetric");
  EXPECT_TRUE(graded);
  EXPECT_NE(out.find("MOOSDB real"), std::string::npos) << out;
  EXPECT_FALSE(any_alive(processes, run_dir.string()));
}

// ---- stopping ------------------------------------------------------------------------------

void expect_everything_stops_after(int signal, int expected_exit, const std::string& what) {
  const fs::path run_dir = fresh_run_dir(what);
  // Warp 100: long enough that the mission is still running when the signal comes.
  auto child = Child::spawn(JAKE_LAUNCH, launch_args(run_dir, {"--warp=100", "--no-picture"}));
  ASSERT_TRUE(child);
  ASSERT_TRUE(wait_until_running(run_dir, 60)) << child->stderr_text();
  const auto processes = read_pids(run_dir);
  ASSERT_GE(processes.size(), 9u);  // launcher, moosdb-lite, 6 apps, the watcher
  ASSERT_TRUE(any_alive(processes, run_dir.string()));
  ::kill(child->pid(), signal);
  EXPECT_EQ(child->wait(kStopTimeout_s), expected_exit) << child->stderr_text();
  EXPECT_TRUE(all_gone_within(processes, run_dir.string(), 2.0));
  EXPECT_EQ(processes_mentioning(run_dir.string()), std::vector<std::string>{});
  EXPECT_NE(child->stderr_text().find("stopping every process"), std::string::npos);
}

TEST(JakeLaunch, CtrlCStopsEveryProcessAndExits130) { expect_everything_stops_after(SIGINT, 130, "sigint"); }

TEST(JakeLaunch, SigtermStopsEveryProcessAndExits143) { expect_everything_stops_after(SIGTERM, 143, "sigterm"); }

TEST(JakeLaunch, AProcessDyingStopsTheMission) {
  const fs::path run_dir = fresh_run_dir("death");
  auto child = Child::spawn(JAKE_LAUNCH, launch_args(run_dir, {"--warp=100", "--no-picture"}));
  ASSERT_TRUE(child);
  ASSERT_TRUE(wait_until_running(run_dir, 60)) << child->stderr_text();
  const auto processes = read_pids(run_dir);
  pid_t sensor = -1;
  for (const auto& p : processes)
    if (p.name == "uFldHazardSensor") sensor = p.pid;
  ASSERT_GT(sensor, 0);
  ::kill(sensor, SIGKILL);
  EXPECT_EQ(child->wait(kStopTimeout_s), 1);
  const std::string err = child->stderr_text();
  EXPECT_NE(err.find("uFldHazardSensor (pid " + std::to_string(sensor) + ") exited"), std::string::npos) << err;
  EXPECT_NE(err.find("the mission failed"), std::string::npos) << err;
  EXPECT_TRUE(all_gone_within(processes, run_dir.string(), 2.0));
}

TEST(JakeLaunch, AKilledLauncherTakesItsProcessesAlong) {
  // SIGKILL cannot be trapped: the processes' parent-death signal (setpriv --pdeathsig) ends
  // them when the launcher goes.
  if (std::system("setpriv --help 2>/dev/null | grep -q -- --pdeathsig") != 0)
    GTEST_SKIP() << "setpriv without --pdeathsig";
  const fs::path run_dir = fresh_run_dir("sigkill");
  auto child = Child::spawn(JAKE_LAUNCH, launch_args(run_dir, {"--warp=100", "--no-picture"}));
  ASSERT_TRUE(child);
  ASSERT_TRUE(wait_until_running(run_dir, 60)) << child->stderr_text();
  const auto processes = read_pids(run_dir);
  child->kill_now();
  EXPECT_TRUE(all_gone_within(processes, run_dir.string(), 5.0));
  EXPECT_EQ(processes_mentioning(run_dir.string()), std::vector<std::string>{});
}

TEST(JakeLaunch, TheTimeLimitStopsTheMission) {
  const fs::path run_dir = fresh_run_dir("timeout");
  std::string err;
  EXPECT_EQ(run_launcher(launch_args(run_dir, {"--warp=10", "--timeout=3", "--no-picture"}), 60,
                         nullptr, &err),
            1);
  EXPECT_NE(err.find("time limit of 3 s reached"), std::string::npos) << err;
  EXPECT_FALSE(any_alive(read_pids(run_dir), run_dir.string()));
}

}  // namespace
}  // namespace mission_test
