// The pWebViewer binary: live against moosdb-lite on an OS-chosen port, --replay and --export of
// a small .alog, its command-line errors and its information texts (golden/).
#include <gtest/gtest.h>

#include <csignal>
#include <regex>
#include <thread>

#include "child_process.hpp"
#include "moosdb_server.hpp"
#include "raw_http.hpp"
#include "scratch_files.hpp"

namespace {

namespace raw_http = web_viewer::raw_http;

using test_support::Child;
using test_support::read_file;
using test_support::ScratchDir;
using test_support::write_file;

constexpr const char* kAlog =
    "%% LOG FILE: run.alog\n%% LOGSTART 1700000000\n%%%%%%%%\n"
    "1.000 NODE_REPORT uSimSurveyVehicle NAME=archie,X=-180,Y=-40,HDG=180\n"
    "1.500 DB_UPTIME MOOSDB 1.5\n"
    "2.000 VIEW_MARKER uFldHazardSensor x=51,y=11.3,width=8,type=triangle,label=12\n"
    "3.000 HAZARD_SEARCH_SCORE uFldHazardMetric 86.5\n";

/// Waits (bounded) until the child printed the URL; its port and token, or 0.
struct Served {
  int port = 0;
  std::string token;
};
Served served(const Child& child, double timeout_s = 10.0) {
  const std::regex url(R"(serving http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]{32})[ \n])");
  const double end = test_support::steady_now_s() + timeout_s;
  while (test_support::steady_now_s() < end) {
    std::smatch m;
    const std::string out = child.stdout_text();
    if (std::regex_search(out, m, url)) return {std::stoi(m[1].str()), m[2].str()};
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return {};
}

int served_port(const Child& child) { return served(child).port; }

TEST(WebViewerProcess, LiveAgainstMoosdbLite) {
  test_support::MoosdbServer db(MOOSDB_LITE_PATH);
  ASSERT_TRUE(db.ok());
  ScratchDir dir("pwv_live");
  write_file(dir / "m.moos", "ServerHost = localhost\nServerPort = " + std::to_string(db.port()) +
                                 "\nCommunity = shoreside\nProcessConfig = pWebViewer\n{\n  http_port = 0\n}\n");
  auto viewer = Child::spawn(PWEBVIEWER_PATH, {(dir / "m.moos").string()});
  ASSERT_TRUE(viewer);
  const int port = served_port(*viewer);
  ASSERT_GT(port, 0) << viewer->stderr_text();
  ASSERT_TRUE(db.wait_for_log("pWebViewer", 10.0)) << db.stderr_text();
  const auto poke = test_support::run_program(
      MOOS_CLI_PATH, {"poke", "--port=" + std::to_string(db.port()), "VIEW_CIRCLE=x=1,y=2,radius=5,label=c1"}, 20.0);
  ASSERT_EQ(poke.exit_code, 0) << poke.err;
  const std::string events = raw_http::read_events(port, "label=c1");
  EXPECT_NE(events.find(R"("community":"shoreside","time":)"), std::string::npos) << events;
  EXPECT_NE(events.find(R"("var":"VIEW_CIRCLE","val":"x=1,y=2,radius=5,label=c1")"), std::string::npos) << events;
  EXPECT_EQ(viewer->stop(), 0);
}

TEST(WebViewerProcess, ReplayServesTheLogsWatchedMail) {
  ScratchDir dir("pwv_replay");
  write_file(dir / "run.alog", kAlog);
  // The mission file only chooses a free port (http_port = 0); the log alone would do.
  write_file(dir / "m.moos", "ProcessConfig = pWebViewer\n{\n  http_port = 0\n}\n");
  auto with_mission = Child::spawn(PWEBVIEWER_PATH, {(dir / "m.moos").string(), "--replay=" + (dir / "run.alog").string()});
  ASSERT_TRUE(with_mission);
  const Served url = served(*with_mission);
  const int port = url.port;
  ASSERT_GT(port, 0) << with_mission->stderr_text();
  EXPECT_NE(with_mission->stdout_text().find("(replay of "), std::string::npos);
  const auto replay = raw_http::request(port, "GET", "/replay.json");
  EXPECT_EQ(replay.status, 200);
  EXPECT_EQ(replay.body.rfind(R"({"hello":{"type":"hello","app":"pWebViewer","community":"replay",)"
                               R"("time":1700000001,"warp":1,"mode":"replay","buttons":[],"trail_length":200,)"
                               R"("unlabelled_ring":2000},"mail":[)", 0), 0u)
      << replay.body;
  EXPECT_NE(replay.body.find(R"({"type":"mail","var":"HAZARD_SEARCH_SCORE","val":86.5,"src":"uFldHazardMetric","time":1700000003})"),
            std::string::npos);
  EXPECT_EQ(replay.body.find("DB_UPTIME"), std::string::npos);
  EXPECT_EQ(raw_http::request(port, "POST", "/button/1").status, 403);  // no token
  EXPECT_EQ(raw_http::request(port, "POST", "/button/1", "X-Viewer-Token: " + url.token + "\r\n").status, 404);
  EXPECT_NE(raw_http::read_events(port, "\"mode\":\"replay\"").find("\"mode\":\"replay\""), std::string::npos);
  EXPECT_EQ(with_mission->stop(), 0);
}

TEST(WebViewerProcess, ExportWritesOneSelfContainedPage) {
  ScratchDir dir("pwv_export");
  write_file(dir / "run.alog", kAlog);
  write_file(dir / "m.moos", "Community = jake\nLatOrigin = 43.8253\nLongOrigin = -70.3304\n");
  const auto run = test_support::run_program(
      PWEBVIEWER_PATH, {(dir / "m.moos").string(), "--export=" + (dir / "run.alog").string(),
                        "--output=" + (dir / "view.html").string()}, 30.0);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("wrote " + (dir / "view.html").string() + " (3 postings of "), std::string::npos);
  const std::string html = read_file(dir / "view.html");
  EXPECT_NE(html.find(R"(window.VIEWER_REPLAY = {"hello":{"type":"hello","app":"pWebViewer","community":"jake",)"),
            std::string::npos);
  EXPECT_NE(html.find(R"("lat_origin":43.8253,"lon_origin":-70.3304)"), std::string::npos);
  EXPECT_NE(html.find(R"("val":"NAME=archie,X=-180,Y=-40,HDG=180")"), std::string::npos);
  EXPECT_NE(html.find("<script type=\"importmap\">"), std::string::npos);
  // Nothing is fetched: no src= or href= of a page file is left.
  EXPECT_EQ(html.find("src=\"viewer.js\""), std::string::npos);
  EXPECT_EQ(html.find("href=\"viewer.css\""), std::string::npos);
}

TEST(WebViewerProcess, OfflineCommandLineErrors) {
  ScratchDir dir("pwv_errors");
  auto run = test_support::run_program(PWEBVIEWER_PATH, {"--export=x.alog"}, 20.0);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--export needs --output=FILE.html"), std::string::npos);
  run = test_support::run_program(PWEBVIEWER_PATH, {"--export=x.alog", "--replay=x.alog"}, 20.0);
  EXPECT_EQ(run.exit_code, 2);
  run = test_support::run_program(
      PWEBVIEWER_PATH, {"--export=" + (dir / "missing.alog").string(), "--output=" + (dir / "v.html").string()}, 20.0);
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("missing.alog: cannot read the log"), std::string::npos);
}

class WebViewerInfoText : public ::testing::TestWithParam<std::pair<std::string, std::string>> {};

TEST_P(WebViewerInfoText, MatchesTheGoldenFile) {
  const auto [flag, golden] = GetParam();
  const auto run = test_support::run_program(PWEBVIEWER_PATH, {flag}, 20.0);
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, read_file(std::string(PWEBVIEWER_GOLDEN_DIR) + "/" + golden));
}

INSTANTIATE_TEST_SUITE_P(Switches, WebViewerInfoText,
                         ::testing::Values(std::make_pair("--help", "help.txt"),
                                           std::make_pair("--example", "example.txt"),
                                           std::make_pair("--interface", "interface.txt"),
                                           std::make_pair("--version", "version.txt")));

}  // namespace
