// The app class on libmoos's in-process bus with a manual clock, its HTTP side over loopback:
// the page's files, the event stream (hello, retained state, live mail, clock), the buttons.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <mutex>
#include <thread>

#include "WebViewer.hpp"
#include "WebViewer_Info.hpp"
#include "app_on_bus.hpp"
#include "bounded_http_server.hpp"
#include "child_process.hpp"
#include "raw_http.hpp"
#include "web_files.hpp"

namespace web_viewer {
namespace {

using mission_test::Bus;
using mission_test::mission_text;

/// Reads /events in a thread of its own until it is destroyed or the stream ends.
class EventReader {
 public:
  explicit EventReader(int port) : stream_(port) {
    thread_ = std::thread([this] {
      while (!stop_ && stream_.read(0.05)) {
        std::lock_guard<std::mutex> lock(mutex_);
        text_ = stream_.text();
      }
      ended_ = true;
    });
  }
  ~EventReader() {
    stop_ = true;
    thread_.join();
  }
  /// Waits (bounded) until the stream holds `fragment`.
  bool wait_for(const std::string& fragment, double timeout_s = 10.0) const {
    const double end = test_support::steady_now_s() + timeout_s;
    while (test_support::steady_now_s() < end) {
      if (text().find(fragment) != std::string::npos) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }
  std::string text() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return text_;
  }
  bool ended() const { return ended_; }

 private:
  raw_http::EventStream stream_;
  std::thread thread_;
  mutable std::mutex mutex_;
  std::string text_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> ended_{false};
};

class ViewerOnBus : public ::testing::Test {
 protected:
  bool start(const std::string& block = "") {
    app.emplace();
    return bus.start(*app, kAppName, mission_text(kAppName, "  http_port = 0\n" + block));
  }
  raw_http::Reply get(const std::string& target) const {
    return raw_http::request(app->http_port(), "GET", target);
  }
  raw_http::Reply post(const std::string& target, const std::string& headers = "") const {
    return raw_http::request(app->http_port(), "POST", target, headers);
  }
  std::string token_line() const { return "X-Viewer-Token: " + app->token() + "\r\n"; }
  Bus bus;
  std::optional<WebViewer> app;
};

// The printed URL must open in a browser: an IPv6 literal goes in brackets, as in a Host header.
TEST(ServerUrl, AnIpv6BindAddressIsBracketedAndAnIpv4OneIsNot) {
  EXPECT_EQ(server_url("::1", 8080), "http://[::1]:8080/");
  EXPECT_EQ(server_url("fe80::1", 80), "http://[fe80::1]:80/");
  EXPECT_EQ(server_url("[::1]", 8080), "http://[::1]:8080/");
  EXPECT_EQ(server_url("127.0.0.1", 8080), "http://127.0.0.1:8080/");
  EXPECT_EQ(server_url("Viewer.Example", 9000), "http://viewer.example:9000/");
}

TEST_F(ViewerOnBus, ServesThePageFilesOnLoopback) {
  ASSERT_TRUE(start());
  ASSERT_GT(app->http_port(), 0);
  EXPECT_EQ(app->url(), "http://127.0.0.1:" + std::to_string(app->http_port()) + "/");
  ASSERT_FALSE(web_files().empty());
  for (const WebFile& f : web_files()) {
    const auto res = get("/" + std::string(f.path));
    EXPECT_EQ(res.status, 200) << f.path;
    EXPECT_EQ(res.body, std::string(f.bytes)) << f.path;
    EXPECT_EQ(res.header("Content-Type"), std::string(content_type(f.path)));
  }
  const auto index = get("/?token=" + app->token());
  EXPECT_EQ(index.status, 200);
  EXPECT_EQ(index.body, std::string(find_web_file("index.html")->bytes));
  EXPECT_EQ(get("/no-such-file.js").status, 404);
  EXPECT_EQ(get("/../CMakeLists.txt").status, 404);
  EXPECT_EQ(get("/replay.json").status, 404);  // live mode
}

TEST_F(ViewerOnBus, ANewPageGetsHelloThenTheRetainedStateThenLiveMail) {
  ASSERT_TRUE(start());
  app->run_for(1.0);
  bus.post("VIEW_MARKER", "x=1,y=2,label=gone");
  bus.post("VIEW_MARKER", "x=5,y=6,label=kept");
  bus.post("VIEW_MARKER", "label=gone,active=false");
  bus.post("HAZARD_SEARCH_SCORE", 86.5);
  bus.post("DEPLOY_ALL", "true");  // not watched
  app->run_for(1.0);

  EventReader reader(app->http_port());
  ASSERT_TRUE(reader.wait_for("label=kept"));
  const std::string first = reader.text();
  EXPECT_EQ(first.rfind("data: {\"type\":\"hello\",\"app\":\"pWebViewer\",\"community\":\"jake\"", 0), 0u) << first;
  EXPECT_NE(first.find("\"lat_origin\":43.8253,\"lon_origin\":-70.3304"), std::string::npos);
  EXPECT_EQ(first.find("label=gone"), std::string::npos);  // removed before the page came
  EXPECT_NE(first.find(R"("var":"HAZARD_SEARCH_SCORE","val":86.5,"src":"peer")"), std::string::npos);
  EXPECT_EQ(first.find("DEPLOY_ALL"), std::string::npos);

  bus.post("NODE_REPORT", "NAME=archie,X=10,Y=20,HDG=90");
  app->run_for(1.5);
  EXPECT_TRUE(reader.wait_for("NAME=archie,X=10,Y=20,HDG=90"));
  EXPECT_TRUE(reader.wait_for("{\"type\":\"clock\""));
}

TEST_F(ViewerOnBus, AsksForAppCastsAndAnnouncesItself) {
  ASSERT_TRUE(start());
  app->run_for(1.0);
  EXPECT_EQ(bus.values_of("PMV_CONNECT", kAppName), std::vector<std::string>{kAppName});
  EXPECT_EQ(bus.values_of("APPCAST_REQ", kAppName),
            std::vector<std::string>{"node=all,app=all,duration=30,key=pWebViewer,thresh=any"});
  app->run_for(kAppCastRequestPeriod_s);
  EXPECT_EQ(bus.values_of("APPCAST_REQ", kAppName).size(), 2u);
}

TEST_F(ViewerOnBus, AButtonPostsItsAssignmentsAndTheHelloNamesIt) {
  ASSERT_TRUE(start("  button_one = DEPLOY # DEPLOY_ALL=true # SPEED=2.5\n"));
  EXPECT_EQ(app->page_url(), app->url() + "?token=" + app->token());
  EXPECT_EQ(app->token().size(), 32u);
  EXPECT_EQ(post("/button/1", token_line()).status, 204);
  EXPECT_EQ(post("/button/1").status, 403);  // no token: not posted
  EXPECT_EQ(post("/button/2", token_line()).status, 404);
  EXPECT_EQ(post("/button/0", token_line()).status, 404);
  app->run_for(1.0);
  EXPECT_EQ(bus.values_of("DEPLOY_ALL", kAppName), std::vector<std::string>{"true"});
  EXPECT_EQ(bus.values_of("SPEED", kAppName), std::vector<std::string>{std::to_string(2.5)});

  EventReader reader(app->http_port());
  EXPECT_TRUE(reader.wait_for(R"("buttons":[{"index":1,"label":"DEPLOY"}])"));
}

TEST_F(ViewerOnBus, WithoutButtonsEveryPressIsNotFound) {
  ASSERT_TRUE(start());
  EXPECT_EQ(post("/button/1", token_line()).status, 404);
  app->run_for(1.0);
  EXPECT_TRUE(bus.values_of("DEPLOY_ALL", kAppName).empty());
}

TEST_F(ViewerOnBus, MoreStreamsThanMaxClientsAreRefused) {
  ASSERT_TRUE(start("  max_clients = 1\n"));
  EventReader first(app->http_port());
  ASSERT_TRUE(first.wait_for("hello"));
  EXPECT_EQ(get("/events").status, 503);
}

/// A browser that asks for the event stream and then never reads (a raw socket).
class StalledReader {
 public:
  explicit StalledReader(int port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    int small = 4096;  // a small receive buffer: the server's writes block sooner
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
    const std::string request = "GET /events HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n\r\n";
    connected_ = connected_ && ::send(fd_, request.data(), request.size(), 0) == static_cast<ssize_t>(request.size());
  }
  ~StalledReader() { ::close(fd_); }
  bool connected() const { return connected_; }

 private:
  int fd_ = -1;
  bool connected_ = false;
};

TEST_F(ViewerOnBus, ABrowserThatFallsBehindIsDroppedAndTheOthersKeepTheirStream) {
  ASSERT_TRUE(start("  max_queued = 100\n"));
  StalledReader stalled(app->http_port());
  ASSERT_TRUE(stalled.connected());
  EventReader reader(app->http_port());
  ASSERT_TRUE(reader.wait_for("hello"));
  const double end = test_support::steady_now_s() + 20.0;
  const std::string big(30000, 'x');
  int posted = 0;
  // Far more than the stalled socket's buffers and the 100 queued events hold.
  while (app->feed()->hub().dropped() == 0 && test_support::steady_now_s() < end) {
    for (int i = 0; i < 20; ++i) bus.post("VIEW_POINT", "x=1,y=2,msg=" + big + ",label=p" + std::to_string(posted++));
    app->run_for(0.5);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(app->feed()->hub().dropped(), 1u);
  EXPECT_NE(app->terminal_report().find("1 dropped for falling behind"), std::string::npos);
  // The reading browser still gets what comes next.
  bus.post("VIEW_POINT", "x=1,y=2,label=after");
  app->run_for(0.5);
  EXPECT_TRUE(reader.wait_for("label=after", 20.0));
}

// A queue too long to fill: the stalled browser is dropped, and counted, when a write to it
// waits out the write timeout.
TEST_F(ViewerOnBus, ABrowserThatTakesNothingForTheWriteTimeoutIsDroppedAndCounted) {
  ASSERT_TRUE(start("  max_queued = 10000000\n"));
  StalledReader stalled(app->http_port());
  ASSERT_TRUE(stalled.connected());
  const double end = test_support::steady_now_s() + 4 * BoundedHttpServer::kWriteTimeout_ms / 1000.0;
  const std::string big(30000, 'x');
  int posted = 0;
  while (app->feed()->hub().dropped() == 0 && test_support::steady_now_s() < end) {
    for (int i = 0; i < 20; ++i) bus.post("VIEW_POINT", "x=1,y=2,msg=" + big + ",label=p" + std::to_string(posted++));
    app->run_for(0.5);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(app->feed()->hub().dropped(), 1u);
  EXPECT_EQ(app->feed()->hub().clients(), 0u);
}

TEST_F(ViewerOnBus, AnAddressInUseEndsStartUp) {
  ASSERT_TRUE(start());
  const int taken = app->http_port();
  std::optional<WebViewer> second;
  second.emplace();
  Bus other;
  EXPECT_FALSE(other.start(*second, kAppName,
                           mission_text(kAppName, "  http_port = " + std::to_string(taken) + "\n")));
}

TEST(WebViewerInfo, ExampleLinesAreAcceptedByTheConfigurationReader) {
  std::vector<moos::ConfigLine> lines;
  std::istringstream example(example_text());
  for (std::string text; std::getline(example, text);) {
    const auto eq = text.find('=');
    const auto comment = text.find("//");
    if (eq == std::string::npos || comment < eq || text.find("ProcessConfig") != std::string::npos) continue;
    std::string key = text.substr(0, eq);
    key.erase(0, key.find_first_not_of(' '));
    key.erase(key.find_last_not_of(' ') + 1);
    if (key == "AppTick" || key == "CommsTick") continue;
    std::string value = text.substr(eq + 1, comment == std::string::npos ? std::string::npos : comment - eq - 1);
    value.erase(0, value.find_first_not_of(' '));
    value.erase(value.find_last_not_of(' ') + 1);
    lines.push_back({key, value, "example", 0});
  }
  EXPECT_GE(lines.size(), 14u);
  std::vector<std::string> warnings;
  read_viewer_config(lines, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

}  // namespace
}  // namespace web_viewer
