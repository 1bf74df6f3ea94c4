// pLogLite's .alog where `<path>/<file>.alog` is not a plain new file (base/output_file.hpp,
// kInPlace), the app class on the in-process bus: a device stays a device, a FIFO's reader gets
// the log, a link stays a link, a full device or a folder fails the start-up naming it.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "LogLite.hpp"
#include "app_on_bus.hpp"
#include "output_targets.hpp"

namespace plog_lite {
namespace {

using test_support::WriteEnd;

/// Starts pLogLite on a bus of its own, logging to `path` (which must end in ".alog"), posts
/// one message and ends the app: 0, or 1 with the configuration or run warnings.
WriteEnd log_to(const std::string& path) {
  const std::filesystem::path where(path);
  mission_test::Bus bus;
  LogLite app;
  const std::string block = "  path = " + where.parent_path().string() + "\n  file = " +
                            where.stem().string() +
                            "\n  file_timestamp = false\n  wildcard_logging = true\n";
  if (!bus.start(app, kAppName, mission_test::mission_text(kAppName, block))) {
    std::string warnings;
    for (const auto& w : app.appcast().config_warnings()) warnings += w + "\n";
    return {1, warnings};
  }
  bus.post("SPEED", 1.5);
  app.run_for(0.5);
  std::string warnings;
  for (const auto& [w, count] : app.appcast().run_warnings()) warnings += w + "\n";
  return {warnings.empty() ? 0 : 1, warnings};
}

void is_a_log(const std::string& bytes) {
  EXPECT_EQ(bytes.rfind("%% LOG FILE:", 0), 0u) << bytes.substr(0, 200);
  EXPECT_NE(bytes.find("%% LOGSTART"), std::string::npos);
}

class LoggerOutputs : public ::testing::Test {
 protected:
  test_support::ScratchDir dir_{"ploglite_outputs"};
};

TEST_F(LoggerOutputs, ANullDeviceStaysADevice) {
  test_support::check_null_device(dir_.path(), "null.alog", log_to);
}

TEST_F(LoggerOutputs, AFullDeviceFailsTheStartUpNamingIt) {
  test_support::check_full_device(dir_.path(), "full.alog", log_to);
}

TEST_F(LoggerOutputs, AFifoWithAReaderGetsTheLog) {
  test_support::check_fifo_with_reader(dir_.path(), "fifo.alog", log_to, is_a_log);
}

TEST_F(LoggerOutputs, AFifoWithoutAReaderFailsTheStartUpAfterTheWait) {
  test_support::check_fifo_without_reader(dir_.path(), "fifo.alog", log_to);
}

TEST_F(LoggerOutputs, ASymlinkStaysALinkAndItsFileGetsTheLog) {
  test_support::check_symlink(dir_.path(), "run.alog", log_to, is_a_log);
}

TEST_F(LoggerOutputs, ARegularFileIsTruncatedAndWrittenInPlace) {
  test_support::check_regular_file(dir_.path(), "run.alog", log_to, is_a_log,
                                   test_support::Regular::kInPlace);
}

TEST_F(LoggerOutputs, ADirectoryFailsTheStartUpNamingIt) {
  test_support::check_directory(dir_.path(), "folder.alog", log_to);
}

}  // namespace
}  // namespace plog_lite
