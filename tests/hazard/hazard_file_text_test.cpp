// Hazard file text from outside: control bytes in a label are refused naming file and
// line, a UTF-8 byte-order mark at the start is accepted, and echoed text is escaped.
#include <gtest/gtest.h>

#include <string>

#include "hazard/hazard_field.hpp"
#include "hazard/ranges.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::quiet_block;
using testing::setup_from;

TEST(HazardFileText, ControlBytesInALabelRejectTheLineNamingFileAndLine) {
  const std::string text = std::string("hazard = x=1,y=2,label=ok,type=hazard\n") +
                           "hazard = x=3,y=4,label=a" + std::string(1, '\0') + "b,type=hazard\n" +
                           "hazard = x=5,y=6,label=line\x1b[2Jfeed,type=benign\n";
  const EngineSetup s = setup_from("hazard_file = f.txt\n", {{"f.txt", text}});
  EXPECT_EQ(s.field.size(), 1u);
  EXPECT_TRUE(contains(s.config_warnings,
                       "f.txt:2: field 'label' value 'a\\x00b' contains a control byte; line "
                       "rejected"));
  EXPECT_TRUE(contains(s.config_warnings, "f.txt:3: field 'label' value 'line\\x1B[2Jfeed'"));
  ASSERT_EQ(s.hazard_files.size(), 1u);
  EXPECT_EQ(s.hazard_files[0].counts.rejected_lines, 2);
  for (const std::string& w : s.config_warnings) {
    EXPECT_EQ(w.find('\0'), std::string::npos);
    EXPECT_EQ(w.find('\x1b'), std::string::npos);
  }
}

// A physically meaningful range for object positions (ranges.hpp): 9e307 is refused at the line,
// so the field's extent stays finite; the bound itself loads.
TEST(HazardFileText, PositionsBeyondTheBoundRejectTheLine) {
  HazardField field;
  std::vector<std::string> warnings;
  load_hazard_file_text("hazard = x=9e307,y=0,label=a,type=hazard\n"
                        "hazard = x=-9e307,y=0,label=b,type=hazard\n"
                        "hazard = x=1,y=-100000000,label=c,type=hazard\n",
                        "f", field, warnings);
  EXPECT_EQ(field.size(), 1u);
  EXPECT_TRUE(contains(warnings, "f:1: position (9e+307, 0) is beyond"));
  EXPECT_TRUE(contains(warnings, "beyond 100000000 m from the origin (kMaxObjectCoordinate_m); "
                                 "line rejected"));
}

TEST(HazardFileText, AByteOrderMarkAtTheStartIsAccepted) {
  const std::string text = "\xEF\xBB\xBFhazard = x=1,y=2,label=first,type=hazard\n"
                           "hazard = x=3,y=4,label=second,type=benign\n";
  const EngineSetup s = setup_from(
      "hazard_file = f.txt\nsensor_config = width=25,exp=4,pclass=0.8\n", {{"f.txt", text}});
  EXPECT_EQ(s.field.size(), 2u);
  EXPECT_TRUE(s.field.find("first").has_value());
  EXPECT_TRUE(s.config_warnings.empty()) << s.config_warnings.front();
}

TEST(HazardFileText, AByteOrderMarkElsewhereIsStillAnUnrecognisedLine) {
  HazardField field;
  std::vector<std::string> warnings;
  load_hazard_file_text("hazard = x=1,y=2,label=a,type=hazard\n\xEF\xBB\xBFhazard = x=1\n", "f",
                        field, warnings);
  EXPECT_EQ(field.size(), 1u);
  EXPECT_TRUE(contains(warnings, "f:2: unrecognised line"));
}

TEST(HazardFileText, UnrecognisedLinesAreEscapedInWarnings) {
  HazardField field;
  std::vector<std::string> warnings;
  load_hazard_file_text(std::string("junk\rforged: hazard ok\x01\n"), "f", field, warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("'junk\\x0Dforged: hazard ok\\x01'"), std::string::npos)
      << warnings[0];
}

// Line ends from other systems: CR LF loads as LF does; a file with CR alone has one
// line, refused with its value named (never silently half-loaded).
TEST(HazardFileText, CrLfLineEndsLoadLikeLf) {
  HazardField field;
  std::vector<std::string> warnings;
  load_hazard_file_text("hazard = x=1,y=2,label=a,type=hazard\r\n"
                        "hazard = x=3,y=4,label=b,type=benign\r\n",
                        "f", field, warnings);
  EXPECT_EQ(field.size(), 2u);
  EXPECT_TRUE(field.find("a").has_value());
  EXPECT_TRUE(field.find("b").has_value());  // no '\r' left in the last field
  EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(HazardFileText, CrOnlyLineEndsAreOneLineRefusedNamingTheValue) {
  HazardField field;
  std::vector<std::string> warnings;
  const HazardFileCounts counts = load_hazard_file_text(
      "hazard = x=1,y=2,label=a,type=hazard\rhazard = x=3,y=4,label=b,type=benign\r", "f", field,
      warnings);
  EXPECT_EQ(field.size(), 0u);
  EXPECT_EQ(counts.rejected_lines, 1);
  EXPECT_TRUE(contains(warnings, "f:1: field 'type' value 'hazard\\x0Dhazard = x=3' is neither"));
}

// A label is posted in every report about its object: bounded (ranges.hpp, kMaxLabelBytes).
TEST(HazardFileText, ALabelOverTheBoundRejectsTheLine_Hardening) {
  HazardField field;
  std::vector<std::string> warnings;
  const std::string at_bound(kMaxLabelBytes, 'a');
  const std::string megabyte(1u << 20, 'b');
  load_hazard_file_text("hazard = x=1,y=2,label=" + at_bound + ",type=hazard\n" +
                            "hazard = x=1,y=2,label=" + megabyte + ",type=hazard\n",
                        "f", field, warnings);
  EXPECT_EQ(field.size(), 1u);
  EXPECT_TRUE(field.find(at_bound).has_value());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(contains(warnings, "f:2: field 'label' value 'bbbb"));
  EXPECT_TRUE(contains(warnings, "is longer than 256 bytes (kMaxLabelBytes); line rejected"));
  EXPECT_LT(warnings[0].size(), 400u) << "the label is cut in the warning";
}

TEST(HazardFileText, AMegabyteLineIsWarnedAsAShortExcerpt) {
  HazardField field;
  std::vector<std::string> warnings;
  load_hazard_file_text(std::string(1u << 20, 'z') + "\n", "f", field, warnings);
  EXPECT_EQ(field.size(), 0u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_TRUE(contains(warnings, "f:1: unrecognised line 'zzz"));
  EXPECT_TRUE(contains(warnings, "(1048576 bytes)"));
  EXPECT_LT(warnings[0].size(), 400u);
}

TEST(HazardFileText, AnEmptyHazardFileWarnsThatNothingCanBeDetected) {
  const EngineSetup s = setup_from(quiet_block("hazard_file = empty.txt\n"), {{"empty.txt", ""}});
  EXPECT_EQ(s.field.size(), 0u);
  ASSERT_EQ(s.hazard_files.size(), 1u);
  EXPECT_TRUE(s.hazard_files[0].read_ok);
  EXPECT_TRUE(contains(s.config_warnings, "no hazard field: no objects were loaded"));
}

TEST(HazardFileText, AMissingHazardFileIsAWarningNamingItAndThePlace) {
  const EngineSetup s = setup_from(quiet_block("hazard_file = gone.txt\n"));
  ASSERT_EQ(s.hazard_files.size(), 1u);
  EXPECT_FALSE(s.hazard_files[0].read_ok);
  EXPECT_TRUE(contains(s.config_warnings, "cannot read hazard file 'gone.txt'"));
  EXPECT_TRUE(contains(s.config_warnings, "no hazard field"));
}

}  // namespace
}  // namespace hazard
