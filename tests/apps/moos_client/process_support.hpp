#pragma once
// Child processes for the process tests: moosdb-lite on a free port, and moos-cli runs.
// Every child gets SIGKILL when the test process dies (PR_SET_PDEATHSIG), and every handle
// kills and reaps its child in its destructor, so no process is left behind even on failure.

#include <sys/types.h>

#include <optional>
#include <string>
#include <vector>

namespace moos::process_test {

/// A running child process with its standard output and error captured in files.
class Child {
 public:
  /// Starts `path` with `args` (argv[1..]); nullopt if fork/exec fails.
  static std::optional<Child> spawn(const std::string& path, const std::vector<std::string>& args);
  Child(Child&& other) noexcept;
  Child& operator=(Child&& other) noexcept;
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child();

  /// Waits up to `timeout_s` for the child to exit; its exit code, or nullopt (still running
  /// or killed by a signal).
  std::optional<int> wait(double timeout_s);
  /// SIGKILL and reap.
  void kill_now();
  /// SIGTERM, wait up to `timeout_s`, then SIGKILL.
  void stop(double timeout_s = 5.0);
  std::string stdout_text() const;
  std::string stderr_text() const;
  pid_t pid() const { return pid_; }

 private:
  Child() = default;
  pid_t pid_ = -1;
  bool reaped_ = false;
  std::string out_path_;
  std::string err_path_;
};

/// moosdb-lite listening on 127.0.0.1. `port` 0 lets it choose a free port.
class Server {
 public:
  /// Starts the server and waits (bounded) until it reports its port; nullopt on failure.
  static std::optional<Server> start(int port = 0, const std::vector<std::string>& extra = {});
  int port() const { return port_; }
  Child& process() { return *child_; }

 private:
  std::optional<Child> child_;
  int port_ = 0;
};

/// Runs moos-cli with `args`; waits up to `timeout_s`. Returns the child (exited or killed).
Child run_cli(const std::vector<std::string>& args, double timeout_s, std::optional<int>* exit_code);

double steady_now_s();

}  // namespace moos::process_test
