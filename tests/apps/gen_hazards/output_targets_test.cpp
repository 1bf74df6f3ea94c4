// gen_hazards --output=FILE where FILE is not a plain new file (base/output_file.hpp): a device
// stays a device, a FIFO's reader gets the field, a link stays a link, a full device or a folder
// is an error naming it with exit 1.
#include <gtest/gtest.h>

#include <string>

#include "child_process.hpp"
#include "options.hpp"
#include "output_targets.hpp"
#include "scratch_files.hpp"

namespace gen_hazards {
namespace {

using test_support::WriteEnd;

/// Far above the milliseconds a run takes, and above the FIFO's wait for a reader.
constexpr double kDeadline_s = 30.0;
const std::vector<std::string> kField = {"--seed=5",
                                         "--polygon=-150,-75:-150,-400:400,-400:400,-75",
                                         "--objects=8,benign"};

WriteEnd write_to(const std::string& path) {
  std::vector<std::string> args = kField;
  args.push_back("--output=" + path);
  const auto r = test_support::run_program(GEN_HAZARDS_PATH, args, kDeadline_s);
  return {r.exit_code, r.err};
}

void is_the_field(const std::string& bytes) {
  EXPECT_EQ(bytes, test_support::run_program(GEN_HAZARDS_PATH, kField, kDeadline_s).out);
}

class GenHazardsOutputTargets : public ::testing::Test {
 protected:
  test_support::ScratchDir dir_{"gen_hazards_output"};
};

TEST_F(GenHazardsOutputTargets, ANullDeviceStaysADevice) {
  test_support::check_null_device(dir_.path(), "null", write_to);
}

TEST_F(GenHazardsOutputTargets, AFullDeviceExitsOneNamingIt) {
  test_support::check_full_device(dir_.path(), "full", write_to);
}

TEST_F(GenHazardsOutputTargets, AFifoWithAReaderGetsTheField) {
  test_support::check_fifo_with_reader(dir_.path(), "fifo", write_to, is_the_field);
}

TEST_F(GenHazardsOutputTargets, AFifoWithoutAReaderExitsOneAfterTheWait) {
  test_support::check_fifo_without_reader(dir_.path(), "fifo", write_to);
}

TEST_F(GenHazardsOutputTargets, ASymlinkStaysALinkAndItsFileGetsTheField) {
  test_support::check_symlink(dir_.path(), "field.txt", write_to, is_the_field);
}

TEST_F(GenHazardsOutputTargets, ARegularFileIsReplacedByARename) {
  test_support::check_regular_file(dir_.path(), "field.txt", write_to, is_the_field);
}

TEST_F(GenHazardsOutputTargets, ADirectoryExitsOneNamingIt) {
  test_support::check_directory(dir_.path(), "folder", write_to);
}

}  // namespace
}  // namespace gen_hazards
