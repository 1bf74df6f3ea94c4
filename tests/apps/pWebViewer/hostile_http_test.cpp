// Hostile requests against the viewer's HTTP side (issue 12): any local process can reach the
// port, so each request below gets a clear status, nothing outside the embedded page is served,
// no request body is kept beyond a small bound, and the page is still served afterwards.
// Raw sockets, so that no client library normalises the request first.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <string>

#include "child_process.hpp"
#include "event_hub.hpp"
#include "http_server.hpp"
#include "web_files.hpp"

namespace web_viewer {
namespace {

/// Sends `request` on a fresh connection and returns what the server answers until it closes
/// the connection or `timeout_s` passes.
std::string raw_exchange(int port, const std::string& request, double timeout_s = 5.0) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  std::string reply;
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
      ::send(fd, request.data(), request.size(), MSG_NOSIGNAL) >= 0) {
    timeval tick{0, 100000};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tick, sizeof tick);
    const double end = test_support::steady_now_s() + timeout_s;
    char buffer[4096];
    while (test_support::steady_now_s() < end) {
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n == 0) break;
      if (n > 0) reply.append(buffer, static_cast<std::size_t>(n));
    }
  }
  ::close(fd);
  return reply;
}

/// The status line's code ("HTTP/1.1 404 Not Found" gives 404), or 0.
int status_of(const std::string& reply) {
  if (reply.size() < 12 || reply.compare(0, 5, "HTTP/") != 0) return 0;
  return std::stoi(reply.substr(9, 3));
}

std::string get(const std::string& target) {
  return "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
}

class HostileHttp : public ::testing::Test {
 protected:
  void SetUp() override {
    HttpOptions options;
    options.port = 0;
    std::string error;
    ASSERT_TRUE(server.start(options, &error)) << error;
    port = server.port();
  }
  /// The page is still served: the server survived the request.
  void expect_still_serving() {
    EXPECT_EQ(status_of(raw_exchange(port, get("/index.html"))), 200);
  }
  EventHub hub{2, 10, [] { return std::vector<std::string>{}; }};
  int presses = 0;
  HttpServer server{hub, [this](int) {
                      ++presses;
                      return true;
                    }};
  int port = 0;
};

TEST_F(HostileHttp, PathTraversalGetsNotFoundAndNoFileOfTheDisk) {
  for (const std::string target :
       {"/../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/..%2f..%2fetc%2fpasswd",
        "/....//....//etc/passwd", "//etc/passwd", "/index.html/../../../etc/passwd"}) {
    const std::string reply = raw_exchange(port, get(target));
    const int status = status_of(reply);
    EXPECT_TRUE(status == 404 || status == 400) << target << ": " << reply.substr(0, 80);
    EXPECT_EQ(reply.find("root:"), std::string::npos) << target;
  }
  expect_still_serving();
}

TEST_F(HostileHttp, AnUnknownRouteOrMethodGetsAnErrorStatus) {
  EXPECT_EQ(status_of(raw_exchange(port, get("/no-such-page"))), 404);
  const int deleted = status_of(raw_exchange(
      port, "DELETE /index.html HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n"));
  EXPECT_GE(deleted, 400) << deleted;
  EXPECT_LT(deleted, 500) << deleted;
  const int garbage = status_of(raw_exchange(port, "\x01\x02 nonsense\r\n\r\n"));
  EXPECT_TRUE(garbage == 400 || garbage == 0) << garbage;  // 0: closed without an answer
  expect_still_serving();
}

TEST_F(HostileHttp, AnOverlongTargetOrQueryGets414) {
  EXPECT_EQ(status_of(raw_exchange(port, get("/index.html?q=" + std::string(100000, 'q')))), 414);
  EXPECT_EQ(status_of(raw_exchange(port, get("/" + std::string(20000, 'p')))), 414);
  expect_still_serving();
}

TEST_F(HostileHttp, AButtonNumberOutsideTheRangeIsNotFoundAndPressesNothing) {
  for (const std::string n : {"0", "1001", "99999999999999999999999", "-1", "1x"}) {
    const std::string reply = raw_exchange(
        port, "POST /button/" + n +
                  " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\nConnection: close\r\n\r\n");
    EXPECT_EQ(status_of(reply), 404) << n;
  }
  EXPECT_EQ(presses, 0);
  expect_still_serving();
}

// A body over the bound is refused with 413 and discarded as it arrives, never kept: without
// the bound httplib keeps every byte a client sends in memory before the handler runs.
TEST_F(HostileHttp, ARequestBodyOverTheBoundIsRefused_Issue12) {
  const std::size_t over = HttpServer::kMaxRequestBodyBytes + 1;
  const std::string reply = raw_exchange(
      port, "POST /button/1 HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: " +
                std::to_string(over) + "\r\nConnection: close\r\n\r\n" + std::string(over, 'b'));
  EXPECT_EQ(status_of(reply), 413) << reply.substr(0, 80);
  EXPECT_EQ(presses, 0);
  const std::string small = raw_exchange(
      port, "POST /button/1 HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 2\r\nConnection: "
            "close\r\n\r\nok");
  EXPECT_EQ(status_of(small), 204);
  EXPECT_EQ(presses, 1);
}

}  // namespace
}  // namespace web_viewer
