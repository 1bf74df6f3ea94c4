#pragma once
// Test support for whole-mission tests: running a mission's launch.sh as a child process, reading
// its run folder (pids.txt, the .alog, summary.json), and checking that no process is left.
// Every child gets SIGKILL if the test process dies (tests/support's Child), and the launcher
// gives its own processes the same parent-death signal, so a failing test leaves nothing behind.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/types.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "alog_files.hpp"
#include "child_process.hpp"
#include "moos/alog.hpp"
#include "scratch_files.hpp"

namespace mission_test {

namespace fs = std::filesystem;

using test_support::Child;
using test_support::read_alog;
using test_support::read_file;
using test_support::steady_now_s;

/// "name pid" lines of the launcher's pids.txt, in start order.
struct ProcessEntry {
  std::string name;
  pid_t pid = -1;
};

inline std::vector<ProcessEntry> read_pids(const fs::path& run_dir) {
  std::vector<ProcessEntry> out;
  std::ifstream in(run_dir / "pids.txt");
  ProcessEntry e;
  while (in >> e.name >> e.pid) out.push_back(e);
  return out;
}

/// The command line of a live process ("" if it does not exist).
inline std::string cmdline_of(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/cmdline", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (char& c : text)
    if (c == '\0') c = ' ';
  return text;
}

/// Processes whose command line mentions `needle` (the run folder): what a launcher left behind.
inline std::vector<std::string> processes_mentioning(const std::string& needle) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    const std::string cmd = cmdline_of(static_cast<pid_t>(std::stol(name)));
    if (cmd.find(needle) != std::string::npos) out.push_back(name + ": " + cmd);
  }
  return out;
}

/// The launcher's own pid (the first line of pids.txt), -1 if absent.
inline pid_t launcher_pid(const std::vector<ProcessEntry>& entries) {
  for (const auto& e : entries)
    if (e.name == "launcher") return e.pid;
  return -1;
}

/// True while some process the launcher started is still alive as it was started: its command
/// line names the run folder (every app reads the run's mission file; moosdb-lite logs there) or
/// it is this launcher's progress watcher (a pid reused by an unrelated process does not count).
inline bool any_alive(const std::vector<ProcessEntry>& entries, const std::string& run_dir) {
  const std::string watcher = "mission-progress-" + std::to_string(launcher_pid(entries));
  for (const auto& e : entries) {
    if (e.name == "launcher") continue;
    const std::string cmd = cmdline_of(e.pid);
    if (cmd.find(run_dir) != std::string::npos || cmd.find(watcher) != std::string::npos) return true;
  }
  return false;
}

/// Waits up to `timeout_s` for every process of pids.txt to be gone.
inline bool all_gone_within(const std::vector<ProcessEntry>& entries, const std::string& run_dir,
                            double timeout_s) {
  const double deadline = steady_now_s() + timeout_s;
  while (any_alive(entries, run_dir)) {
    if (steady_now_s() > deadline) return false;
    ::usleep(50 * 1000);
  }
  return true;
}

/// `key=value` fields of a MOOS string (commas inside {...} do not split).
inline std::map<std::string, std::string> fields(const std::string& text) {
  std::map<std::string, std::string> out;
  int depth = 0;
  std::string part;
  auto flush = [&] {
    const auto eq = part.find('=');
    if (eq != std::string::npos) out[part.substr(0, eq)] = part.substr(eq + 1);
    part.clear();
  };
  for (char c : text) {
    if (c == '{') ++depth;
    if (c == '}') --depth;
    if (c == ',' && depth == 0) {
      flush();
    } else {
      part += c;
    }
  }
  flush();
  return out;
}

/// Ground truth: label -> "hazard" / "benign", from `hazard = ...` lines.
inline std::map<std::string, std::string> read_truth(const fs::path& hazard_file) {
  std::map<std::string, std::string> out;
  std::ifstream in(hazard_file);
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find("//"));
    if (line.rfind("hazard = ", 0) != 0) continue;
    auto f = fields(line.substr(9));
    out[f["label"]] = f["type"];
  }
  return out;
}

/// This test process's folder for run folders: /tmp/mission_test_<pid>.
inline fs::path run_dirs_base() {
  return fs::temp_directory_path() / ("mission_test_" + std::to_string(::getpid()));
}

/// A unique, not yet existing folder under run_dirs_base() (the launcher creates it).
inline fs::path fresh_run_dir(const std::string& what) {
  fs::create_directories(run_dirs_base());
  static int counter = 0;
  return run_dirs_base() / (what + "-" + std::to_string(counter++));
}

/// After the last test: the run folders are removed when every test passed, and kept (named on
/// standard error) when one failed, so that its log can be read.
class RunFolderCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    if (!fs::exists(run_dirs_base(), ec)) return;
    if (::testing::UnitTest::GetInstance()->Passed()) {
      fs::remove_all(run_dirs_base(), ec);
    } else {
      std::fprintf(stderr, "run folders kept in %s\n", run_dirs_base().c_str());
    }
  }
};
inline ::testing::Environment* const kRunFolderCleanup =
    ::testing::AddGlobalTestEnvironment(new RunFolderCleanup);

/// Exact binomial tail probabilities of X ~ Binomial(n, p): P(X <= k) and P(X >= k).
inline double binomial_pmf(int n, int k, double p) {
  double log_choose = std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
  if (p <= 0.0) return k == 0 ? 1.0 : 0.0;
  if (p >= 1.0) return k == n ? 1.0 : 0.0;
  return std::exp(log_choose + k * std::log(p) + (n - k) * std::log1p(-p));
}
inline double binomial_cdf_at_most(int n, int k, double p) {
  double s = 0.0;
  for (int i = 0; i <= k && i <= n; ++i) s += binomial_pmf(n, i, p);
  return s;
}
inline double binomial_cdf_at_least(int n, int k, double p) {
  double s = 0.0;
  for (int i = std::max(k, 0); i <= n; ++i) s += binomial_pmf(n, i, p);
  return s;
}
/// One tail of a normal distribution beyond 5 standard deviations: the team's 5-sigma rule,
/// applied to exact binomial tails on small counts.
inline constexpr double kFiveSigmaTail = 2.87e-7;

}  // namespace mission_test
