// The Jake demo with its view (missions/common/launch_lib.sh, ML_VIEWER): the launcher starts
// pWebViewer, prints its URL while the mission runs, and after the run writes view.html and
// says how to replay; --no-view runs the same mission without it, and both print the same
// score table.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "child_process.hpp"
#include "scratch_files.hpp"

namespace {

using test_support::read_file;
using test_support::ScratchDir;

constexpr double kLaunchTimeout_s = 240;

test_support::RunResult launch(const test_support::fs::path& run_dir, const std::string& extra) {
  std::vector<std::string> args = {"--bin-dir=" + std::string(APPS_DIR), "--run-dir=" + run_dir.string(),
                                   "--quiet", "--no-picture"};
  if (!extra.empty()) args.push_back(extra);
  return test_support::run_program(JAKE_LAUNCH, args, kLaunchTimeout_s);
}

/// The score table's form: its heading, then each row's vehicle and sensor columns. (The counts
/// differ from run to run at warp 400 with or without the view: the mission's timing is the
/// machine's.)
std::vector<std::string> score_table_form(const std::string& out) {
  std::vector<std::string> form;
  const auto start = out.find("vehicle ");
  if (start == std::string::npos) return form;
  std::istringstream lines(out.substr(start, out.find("\n\n", start) - start));
  std::string line;
  std::getline(lines, line);
  form.push_back(line);
  while (std::getline(lines, line)) {
    std::istringstream columns(line);
    std::string vehicle, sensor;
    columns >> vehicle >> sensor;
    form.push_back(vehicle + " " + sensor);
  }
  return form;
}

// The printed URL carries the run's token (the page's buttons need it).
TEST(WebViewerDemo, PrintsTheUrlWritesViewHtmlAndKeepsTheScoreTable) {
  ScratchDir dir("pwv_demo");
  const auto viewed = launch(dir / "viewed", "");
  ASSERT_EQ(viewed.exit_code, 0) << viewed.out << viewed.err;
  EXPECT_TRUE(std::regex_search(viewed.err, std::regex(R"(\[jake\] live view: http://127\.0\.0\.1:\d+/\?token=[0-9a-f]{32} )")))
      << viewed.err;
  const std::string html_path = (dir / "viewed" / "view.html").string();
  EXPECT_NE(viewed.out.find("View: " + html_path), std::string::npos) << viewed.out;
  EXPECT_NE(viewed.out.find("--replay=" + (dir / "viewed" / "jake.alog").string()), std::string::npos);
  const std::string html = read_file(html_path);
  EXPECT_NE(html.find(R"(window.VIEWER_REPLAY = {"hello":{"type":"hello","app":"pWebViewer","community":"jake")"),
            std::string::npos);
  EXPECT_NE(html.find(R"("var":"HAZARDSET_EVAL")"), std::string::npos);
  // The viewer heard the mission live: its AppCast counted postings.
  EXPECT_NE(read_file(dir / "viewed" / "logs" / "pWebViewer.out").find("serving http://127.0.0.1:"),
            std::string::npos);

  const auto plain = launch(dir / "plain", "--no-view");
  ASSERT_EQ(plain.exit_code, 0) << plain.out << plain.err;
  EXPECT_EQ(plain.err.find("live view"), std::string::npos);
  EXPECT_FALSE(test_support::fs::exists(dir / "plain" / "view.html"));
  const auto form = score_table_form(plain.out);
  ASSERT_EQ(form.size(), 3u) << plain.out;
  EXPECT_EQ(form[1], "archie 25/0.9/0.656/0.85");
  EXPECT_EQ(score_table_form(viewed.out), form);
  EXPECT_NE(viewed.out.find("Mission score (betty's report): "), std::string::npos);
}

}  // namespace
