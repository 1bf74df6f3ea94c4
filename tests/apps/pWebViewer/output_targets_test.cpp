// pWebViewer --export=LOG --output=FILE where FILE is not a plain new file
// (base/output_file.hpp): a device stays a device, a FIFO's reader gets the page, a link stays a
// link, a full device or a folder is an error naming it with exit 1.
#include <gtest/gtest.h>

#include <string>

#include "child_process.hpp"
#include "output_targets.hpp"
#include "scratch_files.hpp"

namespace web_viewer {
namespace {

using test_support::WriteEnd;

/// Far above the time an export takes, and above the FIFO's wait for a reader.
constexpr double kDeadline_s = 30.0;

class WebViewerOutputTargets : public ::testing::Test {
 protected:
  void SetUp() override {
    test_support::write_file(dir_ / "run.alog",
                             "%% LOG FILE: run.alog\n%% LOGSTART 1700000000\n%%%%%%%%\n"
                             "1.000 NODE_REPORT uSimSurveyVehicle NAME=archie,X=-180,Y=-40,HDG=180\n");
    std::filesystem::create_directories(dir_ / "out");
  }
  test_support::WriteTo writer() const {
    const std::string log = (dir_ / "run.alog").string();
    return [log](const std::string& path) {
      const auto r = test_support::run_program(
          PWEBVIEWER_PATH, {"--export=" + log, "--output=" + path}, kDeadline_s);
      return WriteEnd{r.exit_code, r.err};
    };
  }
  static void is_the_page(const std::string& bytes) {
    EXPECT_EQ(bytes.rfind("<!DOCTYPE html>", 0), 0u) << bytes.substr(0, 100);
    EXPECT_NE(bytes.find("NAME=archie,X=-180,Y=-40,HDG=180"), std::string::npos);
    EXPECT_NE(bytes.find("</html>"), std::string::npos);
  }
  std::filesystem::path out() const { return dir_ / "out"; }

  test_support::ScratchDir dir_{"pwv_output"};
};

TEST_F(WebViewerOutputTargets, ANullDeviceStaysADevice) {
  test_support::check_null_device(out(), "null", writer());
}

TEST_F(WebViewerOutputTargets, AFullDeviceExitsOneNamingIt) {
  test_support::check_full_device(out(), "full", writer());
}

TEST_F(WebViewerOutputTargets, AFifoWithAReaderGetsThePage) {
  test_support::check_fifo_with_reader(out(), "fifo", writer(), is_the_page);
}

TEST_F(WebViewerOutputTargets, AFifoWithoutAReaderExitsOneAfterTheWait) {
  test_support::check_fifo_without_reader(out(), "fifo", writer());
}

TEST_F(WebViewerOutputTargets, ASymlinkStaysALinkAndItsFileGetsThePage) {
  test_support::check_symlink(out(), "view.html", writer(), is_the_page);
}

TEST_F(WebViewerOutputTargets, ARegularFileIsReplacedByARename) {
  test_support::check_regular_file(out(), "view.html", writer(), is_the_page);
}

TEST_F(WebViewerOutputTargets, ADirectoryExitsOneNamingIt) {
  test_support::check_directory(out(), "folder", writer());
}

}  // namespace
}  // namespace web_viewer
