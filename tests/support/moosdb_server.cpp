#include "moosdb_server.hpp"

#include <chrono>
#include <cstdlib>
#include <thread>

#include <gtest/gtest.h>

namespace test_support {

namespace {

constexpr std::chrono::milliseconds kPollInterval{10};
/// How long one look for the exit lasts while waiting for the port file.
constexpr double kExitPoll_s = 0.01;

}  // namespace

MoosdbServer::MoosdbServer(const std::string& binary, const std::vector<std::string>& extra_args,
                           int port) {
  const fs::path port_file = dir_ / "port";
  std::vector<std::string> args = {"--moos_port=" + std::to_string(port),
                                   "--port-file=" + port_file.string()};
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  child_ = Child::spawn(binary, args);
  if (!child_) {
    ADD_FAILURE() << "cannot start " << binary;
    return;
  }
  const double deadline = steady_now_s() + kStartTimeout_s;
  while (steady_now_s() < deadline) {
    // The server writes the port and a newline to a temporary file and renames it: a line
    // means the whole number is there.
    const std::string text = read_file(port_file);
    if (!text.empty() && text.back() == '\n') {
      port_ = std::atoi(text.c_str());
      return;
    }
    child_->wait(kExitPoll_s);
    if (!child_->running()) {
      ADD_FAILURE() << binary << " exited at start-up: " << stderr_text();
      return;
    }
  }
  ADD_FAILURE() << binary << " did not write its port within " << kStartTimeout_s << " s: "
                << stderr_text();
}

int wait_for_port_file(const fs::path& port_file, double timeout_s) {
  for (const double deadline = steady_now_s() + timeout_s; steady_now_s() < deadline;) {
    // The server writes the port and a newline to a temporary file and renames it.
    const std::string text = read_file(port_file);
    if (!text.empty() && text.back() == '\n') return std::atoi(text.c_str());
    std::this_thread::sleep_for(kPollInterval);
  }
  return 0;
}

moos::TcpClientOptions local_client_options(int port, const std::string& name) {
  moos::TcpClientOptions options;
  options.host = "127.0.0.1";
  options.port = port;
  options.name = name;
  return options;
}

std::optional<int> MoosdbServer::stop() {
  if (!child_) return std::nullopt;
  return child_->stop(kStopTimeout_s);
}

std::string MoosdbServer::stderr_text() const { return child_ ? child_->stderr_text() : std::string(); }

bool MoosdbServer::wait_for_log(const std::string& fragment, double timeout_s) const {
  const double deadline = steady_now_s() + timeout_s;
  do {
    if (stderr_text().find(fragment) != std::string::npos) return true;
    std::this_thread::sleep_for(kPollInterval);
  } while (steady_now_s() < deadline);
  return false;
}

}  // namespace test_support
