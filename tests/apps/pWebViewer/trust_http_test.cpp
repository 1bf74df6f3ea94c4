// The viewer's trust model over raw sockets (docs/viewer.md, "Trust model"): a request by a
// Host name the server does not go by learns nothing; a POST from another origin or site, or
// without the run's token, presses nothing; slow clients of one address cannot keep the page
// from another one.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bounded_http_server.hpp"
#include "child_process.hpp"
#include "event_hub.hpp"
#include "http_server.hpp"
#include "raw_http.hpp"

namespace web_viewer {
namespace {

using raw_http::body_of;
using raw_http::connect_to;
using raw_http::raw_exchange;
using raw_http::read_reply;
using raw_http::status_of;

constexpr const char* kSecret = "GROUND_TRUTH_x51_y11";

class TrustHttp : public ::testing::Test {
 protected:
  void SetUp() override {
    HttpOptions options;
    options.port = 0;
    options.allowed_hosts = {"viewer.lab.example"};
    server.set_replay_json(std::string("{\"mail\":\"") + kSecret + "\"}");
    std::string error;
    ASSERT_TRUE(server.start(options, &error)) << error;
    port = server.port();
  }
  std::string own_host() const { return "127.0.0.1:" + std::to_string(port); }
  std::string get(const std::string& target, const std::string& host_lines) const {
    return "GET " + target + " HTTP/1.1\r\n" + host_lines + "Connection: close\r\n\r\n";
  }
  std::string post(const std::string& extra_headers) const {
    return "POST /button/1 HTTP/1.1\r\nHost: " + own_host() + "\r\n" + extra_headers +
           "Content-Length: 0\r\nConnection: close\r\n\r\n";
  }
  std::string token_line() const { return "X-Viewer-Token: " + server.token() + "\r\n"; }

  EventHub hub{4, 100, [] { return std::vector<std::string>{std::string("data ") + kSecret}; }};
  std::atomic<int> presses{0};
  HttpServer server{hub, [this](int) {
                      ++presses;
                      return true;
                    }};
  int port = 0;
};

// DNS rebinding: a page of evil.test whose name now resolves to 127.0.0.1 reaches the port,
// but its requests carry Host: evil.test:PORT.
TEST_F(TrustHttp, AHostNameTheServerDoesNotGoByIsRefusedAndNothingLeaks_Hardening) {
  const std::string p = std::to_string(port);
  const std::vector<std::string> foreign = {
      "Host: evil.test:" + p + "\r\n", "Host: 127.0.0.1.evil.test:" + p + "\r\n",
      "Host: 127.0.0.1:" + std::to_string(port == 65535 ? 1 : port + 1) + "\r\n",
      "Host: 127.0.0.1\r\n",  // port 80
      "Host: localhost:" + p + "@evil.test\r\n", "Host: 10.1.2.3:" + p + "\r\n",
      "Host: 127.0.0.1:" + p + "\r\nHost: evil.test:" + p + "\r\n", ""};
  for (const std::string& host : foreign) {
    for (const std::string target : {"/replay.json", "/events", "/index.html"}) {
      const std::string reply = raw_exchange(port, get(target, host), 2.0);
      EXPECT_EQ(status_of(reply), 421) << host << target << ": " << reply.substr(0, 80);
      EXPECT_EQ(reply.find(kSecret), std::string::npos) << host << target;
      EXPECT_EQ(reply.find("<html"), std::string::npos) << host << target;
    }
  }
  EXPECT_EQ(hub.served(), 0u);
  EXPECT_EQ(server.refused_hosts(), 3 * foreign.size());  // counted for the AppCast
  for (const std::string host : {"127.0.0.1:", "localhost:", "LocalHost:", "[::1]:", "viewer.lab.example:"}) {
    const std::string reply = raw_exchange(port, get("/replay.json", "Host: " + host + p + "\r\n"));
    EXPECT_EQ(status_of(reply), 200) << host;
    EXPECT_NE(reply.find(kSecret), std::string::npos) << host;
  }
}

// A cross-site form post or fetch from any page the user opens: only the page of this server,
// holding the token it was opened with, can press a button.
TEST_F(TrustHttp, APostFromAnotherOriginOrWithoutTheTokenPressesNothing_Hardening) {
  const std::string own_origin = "Origin: http://" + own_host() + "\r\n";
  const std::vector<std::string> refused = {
      "Origin: http://evil.test\r\n" + token_line(),
      "Origin: null\r\n" + token_line(),
      "Origin: http://127.0.0.1:1\r\n" + token_line(),
      "Sec-Fetch-Site: cross-site\r\n" + token_line(),
      "Sec-Fetch-Site: same-site\r\n" + token_line(),
      own_origin + "Sec-Fetch-Site: same-origin\r\n",  // no token
      own_origin + "X-Viewer-Token: " + std::string(32, '0') + "\r\n",
      own_origin + "X-Viewer-Token: " + server.token().substr(0, 31) + "\r\n",
      own_origin + "X-Viewer-Token: " + server.token() + "0\r\n",
      own_origin + "X-Viewer-Token:\r\n",
  };
  for (const std::string& headers : refused) {
    const std::string reply = raw_exchange(port, post(headers));
    EXPECT_EQ(status_of(reply), 403) << headers << reply.substr(0, 80);
    EXPECT_NE(body_of(reply).find("refused"), std::string::npos) << reply;
  }
  EXPECT_EQ(presses.load(), 0);
  EXPECT_EQ(server.refused_posts(), refused.size());
  // The page's own press: same origin, its token.
  EXPECT_EQ(status_of(raw_exchange(port, post(own_origin + "Sec-Fetch-Site: same-origin\r\n" + token_line()))), 204);
  EXPECT_EQ(presses.load(), 1);
  EXPECT_EQ(status_of(raw_exchange(port, post(token_line()))), 204);  // curl: no Origin
  EXPECT_EQ(presses.load(), 2);
}

// A refused POST's body is never read as a further request on the same connection.
TEST_F(TrustHttp, ARefusedPostsBodyIsNeverReadAsARequest_Hardening) {
  const std::string smuggled = "POST /button/1 HTTP/1.1\r\nHost: " + own_host() + "\r\n" + token_line() +
                               "Content-Length: 0\r\n\r\n";
  const std::string request = "POST /button/1 HTTP/1.1\r\nHost: " + own_host() +
                              "\r\nContent-Type: text/plain\r\nContent-Length: " +
                              std::to_string(smuggled.size()) + "\r\n\r\n" + smuggled;
  const std::string reply = raw_exchange(port, request, 2.0);
  EXPECT_EQ(status_of(reply), 403);
  EXPECT_EQ(reply.find("HTTP/1.1", 1), std::string::npos) << reply;  // one answer only
  EXPECT_EQ(presses.load(), 0);
}

/// A client that sends a request head one header line every `period_s` until the server closes
/// the connection or it is told to stop.
class Trickler {
 public:
  Trickler(int port, const char* source, double period_s)
      : fd_(connect_to(port, source)), start_s_(test_support::steady_now_s()) {
    thread_ = std::thread([this, port, period_s] { run(port, period_s); });
  }
  ~Trickler() {
    stop_ = true;
    thread_.join();
    if (fd_ >= 0) ::close(fd_);
  }
  bool closed() const { return closed_; }
  int status() const { return status_; }
  double closed_after_s() const { return closed_after_s_; }

 private:
  void run(int port, double period_s) {
    if (fd_ < 0) return;
    const std::string start = "GET /index.html HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n";
    ::send(fd_, start.data(), start.size(), MSG_NOSIGNAL);
    for (int line = 0; !stop_; ++line) {
      // Wait one period, watching for the server's answer or close.
      const std::string reply = read_reply_until_closed(period_s);
      if (closed_) {
        status_ = status_of(reply);
        return;
      }
      const std::string header = "X-Slow-" + std::to_string(line) + ": x\r\n";
      if (::send(fd_, header.data(), header.size(), MSG_NOSIGNAL) < 0) {
        closed_after_s_ = test_support::steady_now_s() - start_s_;
        closed_ = true;
        return;
      }
    }
  }
  /// What arrives within `wait_s`; sets closed_ when the server closed the connection.
  std::string read_reply_until_closed(double wait_s) {
    std::string reply;
    const double end = test_support::steady_now_s() + wait_s;
    timeval tick{0, 50000};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tick, sizeof tick);
    char buffer[512];
    while (!stop_ && test_support::steady_now_s() < end) {
      const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
      if (n > 0) reply.append(buffer, static_cast<std::size_t>(n));
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        closed_after_s_ = test_support::steady_now_s() - start_s_;
        closed_ = true;
        break;
      }
    }
    return reply;
  }

  int fd_;
  double start_s_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> closed_{false};
  std::atomic<int> status_{-1};
  std::atomic<double> closed_after_s_{0.0};
};

// One header line a second never trips the 5 s read timeout; the request's deadline ends it.
TEST_F(TrustHttp, ATrickledRequestHeadIsCutAtItsDeadline_Hardening) {
  constexpr double kDeadline_s = BoundedHttpServer::kRequestDeadline_ms / 1000.0;
  Trickler slow(port, nullptr, 1.0);
  const double end = test_support::steady_now_s() + 2 * kDeadline_s;
  while (!slow.closed() && test_support::steady_now_s() < end)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(slow.closed());
  EXPECT_GT(slow.closed_after_s(), kDeadline_s - 0.5);
  EXPECT_LT(slow.closed_after_s(), kDeadline_s + 2.0);
  EXPECT_EQ(slow.status(), 408);
}

// Slow clients of one address (a line every 2 s, more of them than the pool has threads) hold
// at most kMaxConnectionsPerAddress threads; the rest are refused at once, and a client of
// another address is served all along.
TEST_F(TrustHttp, SlowClientsOfOneAddressCannotKeepThePageFromAnother_Hardening) {
  const std::size_t threads = HttpOptions{}.max_clients + HttpServer::kSpareThreads;
  std::vector<std::unique_ptr<Trickler>> slow;
  for (std::size_t i = 0; i < threads + 8; ++i) {
    slow.push_back(std::make_unique<Trickler>(port, "127.0.0.2", 2.0));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  std::size_t refused = 0;
  for (const auto& s : slow) refused += s->closed() && s->status() == 503 ? 1 : 0;
  EXPECT_EQ(refused, slow.size() - BoundedHttpServer::kMaxConnectionsPerAddress);
  const std::string page = "GET /index.html HTTP/1.1\r\nHost: " + own_host() + "\r\nConnection: close\r\n\r\n";
  for (int i = 0; i < 5; ++i) {
    const double start = test_support::steady_now_s();
    EXPECT_EQ(status_of(raw_exchange(port, page, 3.0, "127.0.0.3")), 200) << i;
    EXPECT_LT(test_support::steady_now_s() - start, 1.0) << i;
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
}

}  // namespace
}  // namespace web_viewer
