// hazard_replay --output=FILE where FILE is not a plain new file (base/output_file.hpp): a
// device stays a device, a FIFO's reader gets the postings as they are replayed, a link stays a
// link, a full device or a folder is an error naming it with exit 1.
#include <gtest/gtest.h>

#include <string>

#include "output_targets.hpp"
#include "replay_support.hpp"

namespace hazard_replay {
namespace {

using test_support::ScratchDir;
using test_support::WriteEnd;

const std::vector<testing::Line> kInput = {
    {0.0, "UHZ_SENSOR_REQUEST", "vname=v1"},
    {0.5, "NODE_REPORT", testing::node_report("v1", 0, -100)},
    {2.0, "NODE_REPORT", testing::node_report("v1", 0, 0)},
    {9.0, "NODE_REPORT", testing::node_report("v1", 0, 100)}};

class ReplayOutputTargets : public ::testing::Test {
 protected:
  void SetUp() override {
    test_support::write_file(dir_ / "m.moos",
                             testing::mission("  AppTick = 4\n  hazard_file = hazards.txt\n"
                                              "  sensor_config = width=25, exp=4, pclass=0.8\n"));
    test_support::write_file(dir_ / "hazards.txt", "hazard = x=0,y=0,label=a,type=hazard\n");
    test_support::write_file(dir_ / "in.alog", testing::alog(kInput));
    std::filesystem::create_directories(dir_ / "out");
  }

  WriteEnd write_to(const std::string& path) const {
    const auto r = testing::run(dir_, {"m.moos", "in.alog", "--seed=11", "--output=" + path});
    return {r.exit_code, r.err};
  }
  test_support::WriteTo writer() const {
    return [this](const std::string& path) { return write_to(path); };
  }
  test_support::CheckBytes is_the_replay() const {
    const std::string expected = testing::run(dir_, {"m.moos", "in.alog", "--seed=11"}).out;
    return [expected](const std::string& bytes) {
      EXPECT_FALSE(expected.empty());
      EXPECT_EQ(bytes, expected);
    };
  }

  ScratchDir dir_{"replay_output"};
};

TEST_F(ReplayOutputTargets, ANullDeviceStaysADevice) {
  test_support::check_null_device(dir_ / "out", "null", writer());
}

TEST_F(ReplayOutputTargets, AFullDeviceExitsOneNamingIt) {
  test_support::check_full_device(dir_ / "out", "full", writer());
}

TEST_F(ReplayOutputTargets, AFifoWithAReaderGetsThePostings) {
  test_support::check_fifo_with_reader(dir_ / "out", "fifo", writer(), is_the_replay());
}

TEST_F(ReplayOutputTargets, AFifoWithoutAReaderExitsOneAfterTheWait) {
  test_support::check_fifo_without_reader(dir_ / "out", "fifo", writer());
}

TEST_F(ReplayOutputTargets, ASymlinkStaysALinkAndItsFileGetsThePostings) {
  test_support::check_symlink(dir_ / "out", "out.alog", writer(), is_the_replay());
}

TEST_F(ReplayOutputTargets, ARegularFileIsReplacedByARename) {
  test_support::check_regular_file(dir_ / "out", "out.alog", writer(), is_the_replay());
}

TEST_F(ReplayOutputTargets, ADirectoryExitsOneNamingIt) {
  test_support::check_directory(dir_ / "out", "folder", writer());
}

TEST_F(ReplayOutputTargets, AFailedReplayLeavesAnExistingFileAsItWas) {
  test_support::write_file(dir_ / "out" / "kept.alog", "old\n");
  const auto r = testing::run(dir_, {"m.moos", "missing.alog",
                                     "--output=" + (dir_ / "out" / "kept.alog").string()});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(test_support::read_file(dir_ / "out" / "kept.alog"), "old\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_ / "out"),
                          std::filesystem::directory_iterator()), 1);
}

}  // namespace
}  // namespace hazard_replay
