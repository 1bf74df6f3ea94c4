// moosdb-lite's user-named outputs, --log=FILE and --port-file=FILE, where FILE is not a plain
// new file (base/output_file.hpp): a device stays a device, a FIFO's reader gets the log or the
// port, a link stays a link, a full device or a folder stops the start with an error naming it.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "output_targets.hpp"
#include "scratch_files.hpp"

namespace moosdb_lite {
namespace {

using test_support::Child;
using test_support::WriteEnd;

/// Start-up on a loaded machine, plus the FIFO's wait for a reader.
constexpr double kStartDeadline_s = 30.0;
constexpr double kStopTimeout_s = 5.0;

/// Starts moosdb-lite with `args` on a free port; once it listens, stops it (SIGTERM). Its exit
/// code and standard error, whether it stopped at start-up or when asked.
WriteEnd run_server(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"--moos_port=0"};
  all.insert(all.end(), args.begin(), args.end());
  auto child = Child::spawn(MOOSDB_LITE_PATH, all);
  if (!child) return {std::nullopt, "cannot start moosdb-lite"};
  const double deadline = test_support::steady_now_s() + kStartDeadline_s;
  while (test_support::steady_now_s() < deadline) {
    const auto code = child->wait(0.02);
    if (!child->running()) return {code, child->stderr_text()};
    if (child->stderr_text().find("listening on") != std::string::npos) break;
  }
  const auto code = child->stop(kStopTimeout_s);
  return {code, child->stderr_text()};
}

WriteEnd log_to(const std::string& path) { return run_server({"--log=" + path}); }

WriteEnd port_to(const std::string& path) { return run_server({"--port-file=" + path}); }

void is_a_log(const std::string& bytes) {
  EXPECT_EQ(bytes.rfind("%% LOG FILE:", 0), 0u) << bytes.substr(0, 200);
  EXPECT_NE(bytes.find("%% LOGSTART"), std::string::npos) << bytes.substr(0, 200);
}

void is_a_port(const std::string& bytes) {
  EXPECT_TRUE(std::regex_match(bytes, std::regex("[1-9][0-9]*\n"))) << "'" << bytes << "'";
}

class MoosdbLiteOutputs : public ::testing::Test {
 protected:
  test_support::ScratchDir dir_{"moosdb_outputs"};
};

TEST_F(MoosdbLiteOutputs, ANullDeviceStaysADevice) {
  test_support::check_null_device(dir_.path(), "log_null", log_to);
  test_support::check_null_device(dir_.path(), "port_null", port_to);
}

TEST_F(MoosdbLiteOutputs, AFullDeviceStopsTheStartNamingIt) {
  test_support::check_full_device(dir_.path(), "log_full", log_to);
  test_support::check_full_device(dir_.path(), "port_full", port_to);
}

TEST_F(MoosdbLiteOutputs, AFifoWithAReaderGetsTheLogOrThePort) {
  test_support::check_fifo_with_reader(dir_.path(), "log_fifo", log_to, is_a_log);
  test_support::check_fifo_with_reader(dir_.path(), "port_fifo", port_to, is_a_port);
}

TEST_F(MoosdbLiteOutputs, AFifoWithoutAReaderStopsTheStartAfterTheWait) {
  test_support::check_fifo_without_reader(dir_.path(), "log_fifo", log_to);
  test_support::check_fifo_without_reader(dir_.path(), "port_fifo", port_to);
}

TEST_F(MoosdbLiteOutputs, ASymlinkStaysALinkAndItsFileGetsTheLogOrThePort) {
  test_support::check_symlink(dir_.path(), "run.alog", log_to, is_a_log);
  test_support::check_symlink(dir_.path(), "db.port", port_to, is_a_port);
}

TEST_F(MoosdbLiteOutputs, ARegularFileIsALogInPlaceOrAPortReplacedByARename) {
  test_support::check_regular_file(dir_.path(), "run.alog", log_to, is_a_log,
                                   test_support::Regular::kInPlace);
  test_support::check_regular_file(dir_.path(), "db.port", port_to, is_a_port);
}

TEST_F(MoosdbLiteOutputs, ADirectoryStopsTheStartNamingIt) {
  test_support::check_directory(dir_.path(), "log_folder", log_to);
  test_support::check_directory(dir_.path(), "port_folder", port_to);
}

}  // namespace
}  // namespace moosdb_lite
