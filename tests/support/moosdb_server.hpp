#pragma once
// moosdb-lite for one test: started on a free port, always stopped.
//
// Contract:
// - The server listens on 127.0.0.1 on the port given, or with 0 (the default) on a port the OS
//   picks (--moos_port=0), and reports it through --port-file: no fixed port is ever used, so
//   tests run in parallel. The binary's path comes from the suite (a compile definition).
// - The constructor waits up to kStartTimeout_s until the port file holds the port; when the
//   server exits first or the time runs out, the test fails naming why (with the server's
//   standard error) and ok() is false.
// - Its standard error goes to a file the test can read (stderr_text, wait_for_log).
// - local_client_options: what one of our clients needs to reach a server on this machine.
// - The destructor stops it (stop()). It is a Child (child_process.hpp), so it also dies with the
//   test process, and nothing is left behind even when a test fails.

#include <optional>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "moos/tcp_client.hpp"
#include "scratch_files.hpp"

namespace test_support {

class MoosdbServer {
 public:
  /// How long moosdb-lite may take to start listening, on a loaded 2-core machine.
  static constexpr double kStartTimeout_s = 10.0;
  /// How long it may take to exit after SIGTERM before it is killed.
  static constexpr double kStopTimeout_s = 5.0;

  /// Starts `binary` with `--moos_port=<port> --port-file=...` followed by `extra_args`.
  explicit MoosdbServer(const std::string& binary, const std::vector<std::string>& extra_args = {},
                        int port = 0);
  ~MoosdbServer() { stop(); }
  MoosdbServer(const MoosdbServer&) = delete;
  MoosdbServer& operator=(const MoosdbServer&) = delete;

  /// True once the server is listening (its port is known).
  bool ok() const { return port_ > 0; }
  int port() const { return port_; }
  std::string stderr_text() const;
  /// Waits (bounded by `timeout_s`) until the server's standard error contains `fragment`.
  bool wait_for_log(const std::string& fragment, double timeout_s) const;
  /// SIGTERM, wait up to kStopTimeout_s, then SIGKILL: the exit code when it exited by itself.
  std::optional<int> stop();
  /// The process, e.g. to kill it without a goodbye.
  Child& process() { return *child_; }

 private:
  ScratchDir dir_{"moosdb_lite"};
  std::optional<Child> child_;
  int port_ = 0;
};

/// Options of a TcpClient named `name` for a server on 127.0.0.1:`port`, the rest left default.
moos::TcpClientOptions local_client_options(int port, const std::string& name);

/// The port a server started another way (e.g. through a shell) wrote to `port_file`, once the
/// file holds a whole line; 0 when none came within `timeout_s`.
int wait_for_port_file(const fs::path& port_file, double timeout_s);

}  // namespace test_support
