// The event hub's bounds (a slow browser never holds the MOOS side), the replay log reader and
// the self-contained export.
#include <gtest/gtest.h>

#include "event_hub.hpp"
#include "export_html.hpp"
#include "replay_log.hpp"
#include "scratch_files.hpp"

namespace web_viewer {
namespace {

EventHub hub_with(std::size_t max_clients, std::size_t max_queued, std::vector<std::string> first = {"hello"}) {
  return EventHub(max_clients, max_queued, [first] { return first; });
}

TEST(EventHub, AClientGetsItsFirstEventsThenEveryPublishedOne) {
  EventHub hub = hub_with(2, 10, {"hello", "kept"});
  hub.publish("before");  // nobody listening: lost, as the retained state covers it
  auto client = hub.subscribe();
  ASSERT_TRUE(client);
  hub.publish("live1");
  hub.publish("live2");
  EXPECT_EQ(client->take(0.0), (std::vector<std::string>{"hello", "kept", "live1", "live2"}));
  EXPECT_EQ(client->take(0.0), std::vector<std::string>());
}

TEST(EventHub, AClientThatFallsBehindIsDroppedAndCounted) {
  EventHub hub = hub_with(2, 3, {"hello", "a", "b", "c", "d"});  // first events do not count
  auto slow = hub.subscribe();
  auto fast = hub.subscribe();
  for (int i = 0; i < 3; ++i) {
    hub.publish("e" + std::to_string(i));
    fast->take(0.0);
  }
  EXPECT_EQ(hub.dropped(), 0u);
  hub.publish("e3");  // slow holds 3 live events: one more would exceed the bound
  EXPECT_EQ(hub.dropped(), 1u);
  EXPECT_EQ(hub.clients(), 1u);
  EXPECT_FALSE(slow->take(0.0));
  EXPECT_EQ(fast->take(0.0), std::vector<std::string>{"e3"});
}

TEST(EventHub, NoMoreThanMaxClientsAndCloseEndsEveryStream) {
  EventHub hub = hub_with(1, 10);
  auto one = hub.subscribe();
  EXPECT_TRUE(one);
  EXPECT_FALSE(hub.subscribe());
  hub.unsubscribe(one);
  auto two = hub.subscribe();
  ASSERT_TRUE(two);
  hub.close_all();
  EXPECT_FALSE(two->take(1.0));
  EXPECT_EQ(hub.served(), 2u);
}

TEST(ReplayLog, KeepsWatchedPostingsWithMoosTimesAndNumbers) {
  test_support::ScratchDir dir("pwv_replay");
  test_support::write_file(dir / "run.alog",
                           "%% LOG FILE: run.alog\n%% LOGSTART 1000.5\n%%%%%%%%\n"
                           "0.250 NODE_REPORT sim NAME=archie,X=1,Y=2\n"
                           "0.500 DB_UPTIME MOOSDB 1\n"
                           "1.000 UHZ_MISSION_SCORE metric 86.5\n"
                           "this line is not a posting\n"
                           "2.000 VIEW_MARKER sensor x=1, y=2, label=a\n");
  std::string error;
  const auto log = read_replay_log((dir / "run.alog").string(), {"NODE_REPORT", "VIEW_MARKER", "UHZ_MISSION_SCORE"}, {}, &error);
  ASSERT_TRUE(log) << error;
  ASSERT_EQ(log->mail.size(), 3u);
  EXPECT_EQ(log->mail[0].var, "NODE_REPORT");
  EXPECT_DOUBLE_EQ(log->mail[0].time_s, 1000.75);
  EXPECT_TRUE(log->mail[1].is_double);
  EXPECT_EQ(log->mail[1].dval, 86.5);
  EXPECT_EQ(log->mail[2].sval, "x=1, y=2, label=a");
  EXPECT_EQ(log->malformed, 1u);
}

// Times no clock wrote and over-long lines are skipped, one warning each kind with its count:
// a 1e300 time would have put the page's clock beyond any other posting.
TEST(ReplayLog, UnusableTimesAndLongLinesAreSkippedWithOneWarningEach) {
  test_support::ScratchDir dir("pwv_replay");
  const std::string path = (dir / "run.alog").string();
  test_support::write_file(path, "0.1 NODE_REPORT a NAME=x\nnan NODE_REPORT a NAME=x\n"
                                 "-inf NODE_REPORT a NAME=x\n1e300 NODE_REPORT a NAME=x\n"
                                 "%% 3 lines dropped\n0.2 NODE_REPORT a NAME=" +
                                 std::string(100, 'y') + "\n0.3 NODE_REPORT a NAME=z\n");
  ReplayLimits limits;
  limits.max_line_bytes = 64;
  std::string error;
  const auto log = read_replay_log(path, {"NODE_REPORT"}, limits, &error);
  ASSERT_TRUE(log) << error;
  ASSERT_EQ(log->mail.size(), 2u);
  EXPECT_EQ(log->mail[1].sval, "NAME=z");
  EXPECT_EQ(log->malformed, 0u);
  EXPECT_EQ(log->unusable_times, 3u);
  ASSERT_EQ(log->warnings.size(), 2u);
  EXPECT_EQ(log->warnings[0],
            path + ": 3 lines with unusable times (not finite, or beyond 1e10 s) skipped");
  EXPECT_EQ(log->warnings[1], path + ": 1 lines over 64 bytes skipped");
}

TEST(ReplayLog, BoundsAreErrorsNamingTheFile) {
  test_support::ScratchDir dir("pwv_replay");
  const std::string path = (dir / "big.alog").string();
  test_support::write_file(path, "0.1 NODE_REPORT a NAME=x\n0.2 NODE_REPORT a NAME=x\n0.3 NODE_REPORT a NAME=x\n");
  std::string error;
  ReplayLimits limits;
  limits.max_lines = 2;
  EXPECT_FALSE(read_replay_log(path, {"NODE_REPORT"}, limits, &error));
  EXPECT_EQ(error, path + ":3: more than 2 lines");
  limits = ReplayLimits{};
  limits.max_file_bytes = 10;
  EXPECT_FALSE(read_replay_log(path, {"NODE_REPORT"}, limits, &error));
  EXPECT_NE(error.find("more than the limit of 10"), std::string::npos);
  limits = ReplayLimits{};
  limits.max_mail = 1;
  EXPECT_FALSE(read_replay_log(path, {"NODE_*"}, limits, &error));
  EXPECT_NE(error.find(":2: more than 1 watched postings"), std::string::npos);
  EXPECT_FALSE(read_replay_log((dir / "missing.alog").string(), {}, {}, &error));
  EXPECT_NE(error.find("cannot read"), std::string::npos);
}

TEST(ExportHtml, InlinesStylesModulesAndTheReplayData) {
  const std::vector<WebFile> files = {
      {"index.html",
       "<html><head><link rel=\"stylesheet\" href=\"viewer.css\"></head>"
       "<body><script type=\"module\" src=\"viewer.js\"></script></body></html>"},
      {"lib/state.js", "export const k = 1;"},
      {"viewer.css", "body { margin: 0 }"},
      {"viewer.js", "import { k } from './lib/state.js';\nconsole.log(k);"},
  };
  std::string error;
  const auto html = export_html(files, R"({"hello":{},"mail":[]})", &error);
  ASSERT_TRUE(html) << error;
  EXPECT_NE(html->find("<style>\nbody { margin: 0 }\n</style>"), std::string::npos);
  EXPECT_NE(html->find("<script type=\"module\">import \"pwv/viewer.js\";</script>"), std::string::npos);
  EXPECT_NE(html->find("window.VIEWER_REPLAY = {\"hello\":{},\"mail\":[]};"), std::string::npos);
  // The import map holds every module, its relative imports renamed.
  EXPECT_NE(html->find("\"pwv/lib/state.js\":\"data:text/javascript;base64," +
                       base64("export const k = 1;") + "\""),
            std::string::npos);
  EXPECT_NE(html->find(base64("import { k } from 'pwv/lib/state.js';\nconsole.log(k);")), std::string::npos);
  EXPECT_EQ(html->find("src=\"viewer.js\""), std::string::npos);
  EXPECT_LT(html->find("importmap"), html->find("<script type=\"module\">"));
}

TEST(ExportHtml, NeedsAnIndex) {
  std::string error;
  EXPECT_FALSE(export_html({}, "{}", &error));
  EXPECT_EQ(error, "the page has no index.html");
}

TEST(ExportHtml, Base64OfEveryTailLength) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}

}  // namespace
}  // namespace web_viewer
