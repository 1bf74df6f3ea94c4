#pragma once
// A scripted fake MOOSDB on 127.0.0.1 and the TcpClient test fixture around it, shared by the
// TcpClient tests (tcp_client_test.cpp: the protocol; tcp_client_bounds_test.cpp: inbox bounds
// and send batching). Every wait is bounded; the server socket is closed by RAII.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <thread>

#include "moos/app.hpp"
#include "moos/codec.hpp"
#include "moos/tcp_client.hpp"
#include "child_process.hpp"

namespace moos {
namespace test {
std::string hex_bytes(const std::string& spaced_hex);  // comms_test.cpp

constexpr double kT0 = 1700000000.0;
constexpr double kWait_s = 5.0;  // upper bound for anything that should happen quickly

using test_support::steady_now_s;

/// A one-connection-at-a-time TCP server driven by the test.
class FakeServer {
 public:
  FakeServer() {
    listen_ = ::socket(AF_INET, SOCK_STREAM, 0);
    const int one = 1;
    setsockopt(listen_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in sa{};
    sa.sin_family = AF_INET;
    sa.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    sa.sin_port = 0;
    ::bind(listen_, reinterpret_cast<sockaddr*>(&sa), sizeof sa);
    ::listen(listen_, 8);
    socklen_t len = sizeof sa;
    getsockname(listen_, reinterpret_cast<sockaddr*>(&sa), &len);
    port_ = ntohs(sa.sin_port);
  }
  ~FakeServer() {
    drop();
    ::close(listen_);
  }
  int port() const { return port_; }

  bool accept(double timeout_s = kWait_s) {
    drop();
    pollfd p{listen_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout_s * 1000)) <= 0) return false;
    conn_ = ::accept(listen_, nullptr, nullptr);
    buffer_.clear();
    return conn_ >= 0;
  }
  void drop() {
    if (conn_ >= 0) ::close(conn_);
    conn_ = -1;
  }

  std::optional<std::string> read_exact(std::size_t n, double timeout_s = kWait_s) {
    const double deadline = steady_now_s() + timeout_s;
    while (buffer_.size() < n) {
      if (!fill(deadline)) return std::nullopt;
    }
    std::string out = buffer_.substr(0, n);
    buffer_.erase(0, n);
    return out;
  }
  std::optional<std::string> read_packet_bytes(double timeout_s = kWait_s) {
    auto header = read_exact(4, timeout_s);
    if (!header) return std::nullopt;
    std::uint32_t total = 0;
    for (int i = 3; i >= 0; --i) total = (total << 8) | static_cast<unsigned char>((*header)[static_cast<std::size_t>(i)]);
    auto rest = read_exact(total - 4, timeout_s);
    if (!rest) return std::nullopt;
    return *header + *rest;
  }
  std::optional<std::vector<Message>> read_packet(double timeout_s = kWait_s) {
    auto bytes = read_packet_bytes(timeout_s);
    if (!bytes) return std::nullopt;
    return decode_packet(*bytes);
  }
  /// Reads packets until one holds a message that is not TIMING; returns all its messages.
  std::optional<std::vector<Message>> read_non_timing(double timeout_s = kWait_s) {
    const double deadline = steady_now_s() + timeout_s;
    while (steady_now_s() < deadline) {
      auto pkt = read_packet(deadline - steady_now_s());
      if (!pkt) return std::nullopt;
      for (const auto& m : *pkt)
        if (m.type != msg_type::kTiming) return pkt;
    }
    return std::nullopt;
  }
  void send(const std::vector<Message>& messages) { send_bytes(encode_packet(messages)); }
  void send_bytes(const std::string& bytes) {
    ::send(conn_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
  }
  /// True once the peer has closed (EOF) within the timeout.
  bool peer_closed(double timeout_s = kWait_s) {
    const double deadline = steady_now_s() + timeout_s;
    while (steady_now_s() < deadline) {
      pollfd p{conn_, POLLIN, 0};
      if (::poll(&p, 1, 50) > 0) {
        char buf[4096];
        const ssize_t n = ::recv(conn_, buf, sizeof buf, 0);
        if (n <= 0) return true;
      }
    }
    return false;
  }

 private:
  bool fill(double deadline) {
    const double left = deadline - steady_now_s();
    if (left <= 0 || conn_ < 0) return false;
    pollfd p{conn_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left * 1000) + 1) <= 0) return false;
    char buf[65536];
    const ssize_t n = ::recv(conn_, buf, sizeof buf, 0);
    if (n <= 0) return false;
    buffer_.append(buf, static_cast<std::size_t>(n));
    return true;
  }

  int listen_ = -1;
  int conn_ = -1;
  int port_ = 0;
  std::string buffer_;
};

inline Message welcome(double skew, const std::string& community = "alpha",
                const std::string& host = "dbhost") {
  Message w;
  w.type = msg_type::kWelcome;
  w.data_type = data_type::kDouble;
  w.source_aux = "hostname=" + host;
  w.community = community;
  w.time = kT0;
  w.dval = skew;
  w.sval = "asynchronous";
  return w;
}

inline Message timing_echo(double client_time, double server_time, double delay_s = 0.0) {
  Message t;
  t.type = msg_type::kTiming;
  t.data_type = data_type::kDouble;
  t.key = "_async_timing";
  t.time = client_time;
  t.dval = server_time;
  t.dval2 = delay_s;
  return t;
}

class TcpClientTest : public ::testing::Test {
 protected:
  TcpClientOptions options(const std::string& name = "pTest") {
    TcpClientOptions o;
    o.host = "127.0.0.1";
    o.port = server.port();
    o.name = name;
    o.clock = &clock;
    o.own_hostname = "clienthost";
    return o;
  }
  /// Accepts, checks the banner and identification, answers WELCOME.
  void handshake(double skew = 0.001) {
    ASSERT_TRUE(server.accept());
    ASSERT_TRUE(server.read_exact(32).has_value());
    ASSERT_TRUE(server.read_packet().has_value());
    server.send({welcome(skew)});
  }
  /// Starts `client`, answers its handshake and waits until it is connected.
  void connect(TcpClient& client) {
    ASSERT_TRUE(client.start());
    ASSERT_NO_FATAL_FAILURE(handshake());
    ASSERT_TRUE(client.wait_until_connected(kWait_s));
  }
  /// Waits up to kWait_s until `client` has dropped at least `messages` unread messages.
  static void wait_for_drops(const TcpClient& client, std::uint64_t messages) {
    const double deadline = steady_now_s() + kWait_s;
    while (client.mail_dropped() < messages && steady_now_s() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }

  ManualClock clock{kT0};
  FakeServer server;
};

}  // namespace test
}  // namespace moos
