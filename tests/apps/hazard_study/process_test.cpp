// The hazard_study binary: golden --help and --version, a bad command line (usage error, exit 2,
// nothing on standard output), an unreadable mission (exit 1), and --alog writing a log that
// the readers take.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "child_process.hpp"
#include "scratch_files.hpp"

namespace hazard_study {
namespace {

using test_support::read_file;

test_support::RunResult run(const std::vector<std::string>& args) {
  return test_support::run_program(HAZARD_STUDY_PATH, args, 60.0);
}

std::string golden(const std::string& name) {
  return read_file(std::string(HAZARD_STUDY_GOLDEN_DIR) + "/" + name);
}

const std::string kJake = std::string(HAZARD_SOURCE_DIR) + "/missions/jake/jake.moos";

TEST(StudyProcess, HelpAndVersionAreGolden) {
  auto r = run({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, golden("help.txt"));
  EXPECT_EQ(run({"-h"}).out, golden("help.txt"));
  r = run({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, golden("version.txt"));
}

TEST(StudyProcess, ABadCommandLineIsAUsageError) {
  const auto r = run({kJake, "--seeds=3"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err.rfind("hazard_study: --seeds needs A..B", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("Usage: hazard_study"), std::string::npos);
}

TEST(StudyProcess, AMissingMissionIsExit1NamingIt) {
  const auto r = run({"/nonexistent/m.moos"});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "hazard_study: /nonexistent/m.moos: cannot read the mission file\n");
}

TEST(StudyProcess, AlogHoldsEveryPostingOfTheMission) {
  test_support::ScratchDir dir("study");
  const auto r = run({kJake, "--seed=4", "--max-time=600", "--alog=" + (dir / "m.alog").string()});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::string log = read_file(dir / "m.alog");
  EXPECT_EQ(log.rfind("%% LOG FILE:", 0), 0u);
  for (const char* var : {" NODE_REPORT ", " DEPLOY_ALL ", " VIEW_POLYGON ", " UHZ_CONFIG_ACK "})
    EXPECT_NE(log.find(var), std::string::npos) << var;
  const auto bad = run({kJake, "--seed=4", "--max-time=10", "--alog=/nonexistent/x.alog"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_EQ(bad.err.rfind("hazard_study: --alog: ", 0), 0u) << bad.err;
}

}  // namespace
}  // namespace hazard_study
