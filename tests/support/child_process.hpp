#pragma once
// Child processes for the process tests: a program started with its output captured, waited for
// with a bound, and never left running.
//
// Contract:
// - Child::spawn forks and executes `program` with `args` (argv[0] is `program`, no shell). The
//   child's standard output and error go to two files in the Child's own scratch folder (no pipe
//   can fill up and block it), or to /dev/null when `keep_output` is false; `working_dir`, when
//   given, is its current folder; `max_file_bytes`, when given, is its soft RLIMIT_FSIZE (an
//   unprivileged full disk: writes past it fail, with EFBIG once SIGXFSZ is ignored; the test
//   may raise it again with prlimit). An exec that fails ends the child with kExecFailed.
// - The child asks the kernel for SIGKILL when the test process dies (PR_SET_PDEATHSIG) and
//   checks that its parent did not die before it asked; the handle's destructor kills (SIGKILL)
//   and reaps a child still running. So no child outlives a test that passes, fails or crashes.
// - Every wait is bounded: wait() polls until the child exits or the timeout passes.
// - run_program is spawn, wait up to the deadline, SIGKILL at the deadline, then both outputs.

#include <sys/types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "scratch_files.hpp"

namespace test_support {

/// Exit code of a child whose exec failed (the shell's "command not found").
inline constexpr int kExecFailed = 127;

struct SpawnOptions {
  std::string working_dir;   ///< the child's current folder; empty: the test's
  bool keep_output = true;   ///< false: standard output and error go to /dev/null
  std::optional<std::uint64_t> max_file_bytes;  ///< the child's soft RLIMIT_FSIZE
};

/// A running (or finished) child process.
class Child {
 public:
  /// Starts the child; nullopt if fork fails.
  static std::optional<Child> spawn(const std::string& program, const std::vector<std::string>& args,
                                    const SpawnOptions& options = {});
  Child(Child&& other) noexcept;
  Child& operator=(Child&& other) noexcept;
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child();

  /// Waits up to `timeout_s` real seconds for the child to exit: its exit code, or nullopt when
  /// it is still running (see running()) or was killed by a signal.
  std::optional<int> wait(double timeout_s);
  /// True until the child has been reaped.
  bool running() const { return pid_ > 0; }
  /// SIGKILL and reap (nothing if it has been reaped already).
  void kill_now();
  /// SIGTERM, wait up to `timeout_s`, then SIGKILL: the exit code when it exited by itself.
  std::optional<int> stop(double timeout_s = 5.0);
  /// What the child wrote so far ("" with keep_output = false).
  std::string stdout_text() const;
  std::string stderr_text() const;
  pid_t pid() const { return pid_; }

 private:
  explicit Child(ScratchDir dir) : dir_(std::move(dir)) {}
  ScratchDir dir_;
  pid_t pid_ = -1;
};

struct RunResult {
  std::optional<int> exit_code;  ///< nullopt when not started, killed, or still running at the deadline
  bool timed_out = false;        ///< still running at the deadline (then killed)
  std::string out;               ///< standard output
  std::string err;               ///< standard error
};

/// Runs `program` with `args` to its end, killing it at `deadline_s` real seconds.
RunResult run_program(const std::string& program, const std::vector<std::string>& args,
                      double deadline_s, const SpawnOptions& options = {});

/// Seconds on a monotonic clock, for deadlines and durations.
double steady_now_s();

}  // namespace test_support
