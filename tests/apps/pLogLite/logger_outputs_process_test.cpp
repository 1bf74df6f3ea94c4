// pLogLite, the binary, logging to a device named `<file>.alog` (base/output_file.hpp): the
// sink stays a device, and a full device fails the start-up naming it with a non-zero exit.
#include <gtest/gtest.h>

#include <string>

#include "child_process.hpp"
#include "moosdb_server.hpp"
#include "output_targets.hpp"
#include "scratch_files.hpp"

namespace plog_lite {
namespace {

using test_support::Child;
using test_support::MoosdbServer;
using test_support::WriteEnd;

/// A start-up that fails exits at once; one that succeeds is stopped after this long.
constexpr double kRunFor_s = 2.0;

class LoggerOutputsProcess : public ::testing::Test {
 protected:
  /// pLogLite against the server, logging to `path` (ending in ".alog").
  WriteEnd log_to(const std::string& path) {
    const std::filesystem::path where(path);
    test_support::write_file(dir_ / "m.moos",
                             "ServerHost = localhost\nServerPort = " + std::to_string(server_.port()) +
                                 "\nCommunity = logtest\n\nProcessConfig = pLogLite\n{\n  path = " +
                                 where.parent_path().string() + "\n  file = " + where.stem().string() +
                                 "\n  file_timestamp = false\n  wildcard_logging = true\n}\n");
    auto logger = Child::spawn(PLOGLITE_PATH, {(dir_ / "m.moos").string()});
    if (!logger) return {std::nullopt, "cannot start pLogLite"};
    auto code = logger->wait(kRunFor_s);
    if (logger->running()) code = logger->stop();
    return {code, logger->stderr_text()};
  }
  test_support::WriteTo writer() {
    return [this](const std::string& path) { return log_to(path); };
  }

  test_support::ScratchDir dir_{"ploglite_outputs"};
  MoosdbServer server_{MOOSDB_LITE_PATH, {"--moos_community=logtest"}};
};

TEST_F(LoggerOutputsProcess, ANullDeviceStaysADevice) {
  ASSERT_TRUE(server_.ok());
  test_support::check_null_device(dir_.path(), "null.alog", writer());
}

TEST_F(LoggerOutputsProcess, AFullDeviceExitsNonZeroNamingIt) {
  ASSERT_TRUE(server_.ok());
  test_support::check_full_device(dir_.path(), "full.alog", writer());
}

}  // namespace
}  // namespace plog_lite
