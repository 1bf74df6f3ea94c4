#pragma once
// Starts the moosdb-lite binary for one test and always stops it.
//
// Contract:
// - The server listens on 127.0.0.1 on a port the OS picks (--moos_port=0) and reports it
//   through --port-file; no fixed port is ever used, so tests run in parallel.
// - Its standard error goes to a file the test can read (stderr_text, wait_for_log).
// - The destructor sends SIGTERM, waits up to kStopTimeout_s, then SIGKILLs. The child also
//   asks the kernel to kill it if the test process dies (PR_SET_PDEATHSIG), so no server
//   outlives a crashed test.

#include <sys/types.h>

#include <string>
#include <vector>

namespace moosdb_lite::test {

inline constexpr double kStartTimeout_s = 10.0;
inline constexpr double kStopTimeout_s = 5.0;

/// A private temporary folder, removed with everything in it by the destructor.
class ScopedDir {
 public:
  ScopedDir();
  ~ScopedDir();
  ScopedDir(const ScopedDir&) = delete;
  ScopedDir& operator=(const ScopedDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

class ServerProcess {
 public:
  /// Starts the server with `--moos_port=0 --port-file=...` plus `extra_args`.
  explicit ServerProcess(const std::vector<std::string>& extra_args = {});
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  /// True once the server is listening (port known).
  bool ok() const { return port_ > 0; }
  int port() const { return port_; }
  std::string stderr_text() const;
  /// Waits until the server's stderr contains `fragment` (bounded by `timeout_s`).
  bool wait_for_log(const std::string& fragment, double timeout_s) const;

  /// SIGTERM and wait; returns the exit status (or -1 if it had to be killed).
  int stop();

 private:
  pid_t pid_ = -1;
  int port_ = 0;
  ScopedDir dir_;
  std::string stderr_path_;
};

/// Runs the server binary with `args` to completion (for --help and bad command lines),
/// bounded by kStartTimeout_s; returns the exit status and fills stdout/stderr.
int run_server_to_exit(const std::vector<std::string>& args, std::string* out, std::string* err);

/// Seconds since the epoch.
double now_s();

}  // namespace moosdb_lite::test
