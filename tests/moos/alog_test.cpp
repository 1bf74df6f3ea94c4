#include <gtest/gtest.h>

#include "moos/alog.hpp"

namespace moos {
namespace {

TEST(Alog, LineRoundTripsWithBlanksInValue) {
  const AlogEntry e{12.25, "UHZ_HAZARD_REPORT", "uFldHazardSensor", "vname=archie, x=1 ,y=2"};
  const std::string line = format_alog_line(e);
  EXPECT_EQ(line.back(), '\n');
  EXPECT_EQ(line.substr(0, 11), "12.250     ");
  const AlogParse p = parse_alog_line(line.substr(0, line.size() - 1));
  ASSERT_EQ(p.kind, AlogLineKind::kEntry);
  EXPECT_DOUBLE_EQ(p.entry.time_s, 12.25);
  EXPECT_EQ(p.entry.variable, e.variable);
  EXPECT_EQ(p.entry.source, e.source);
  EXPECT_EQ(p.entry.value, e.value);
}

TEST(Alog, NewlinesInValueNeverSplitAPosting) {
  const std::string line = format_alog_line({1, "X", "src", "a\nb\r\nc"});
  EXPECT_EQ(line, std::string("1.000      X                    src              a b  c\n"));
}

TEST(Alog, HeaderAndBlankLinesAreClassified) {
  const std::string header = alog_header("run.alog", 1700000000.5);
  EXPECT_EQ(parse_alog_line("%% LOGSTART 5").kind, AlogLineKind::kHeader);
  EXPECT_EQ(parse_alog_line("   ").kind, AlogLineKind::kBlank);
  EXPECT_EQ(parse_alog_line("").kind, AlogLineKind::kBlank);
  ASSERT_TRUE(alog_logstart("%% LOGSTART           1700000000.500"));
  EXPECT_DOUBLE_EQ(*alog_logstart("%% LOGSTART           1700000000.500"), 1700000000.5);
  EXPECT_FALSE(alog_logstart("%% LOG FILE: x"));
  EXPECT_NE(header.find("%% LOGSTART           1700000000.500\n"), std::string::npos);
}

TEST(Alog, EmptyValueIsAllowed) {
  const AlogParse p = parse_alog_line("3.5 PMV_CONNECT pMarineViewer");
  ASSERT_EQ(p.kind, AlogLineKind::kEntry);
  EXPECT_EQ(p.entry.value, "");
}

TEST(Alog, MalformedLinesSayWhy) {
  AlogParse p = parse_alog_line("abc NODE_REPORT src NAME=x");
  EXPECT_EQ(p.kind, AlogLineKind::kMalformed);
  EXPECT_NE(p.error.find("'abc'"), std::string::npos);
  EXPECT_EQ(parse_alog_line("1.0 X").kind, AlogLineKind::kMalformed);
  EXPECT_EQ(parse_alog_line("1e5x X src v").kind, AlogLineKind::kMalformed);
}

// A time that is a number no clock wrote is its own kind: readers skip it and count it, under
// one warning, instead of replaying until 1e300 s.
TEST(Alog, NonFiniteAndAbsurdTimesAreUnusable) {
  for (const char* time : {"nan", "NaN", "-inf", "+inf", "infinity", "1e300", "-1e300", "1e999",
                           "1.5e10"}) {
    const AlogParse p = parse_alog_line(std::string(time) + " X src v");
    EXPECT_EQ(p.kind, AlogLineKind::kUnusableTime) << time;
    EXPECT_NE(p.error.find("is not finite or beyond 1e10 s"), std::string::npos) << p.error;
  }
  EXPECT_EQ(parse_alog_line("1700000000.5 X src v").kind, AlogLineKind::kEntry);  // epoch time
  EXPECT_EQ(parse_alog_line("-1e10 X src v").kind, AlogLineKind::kEntry);
  EXPECT_EQ(unusable_times_warning(0), "");
  EXPECT_EQ(unusable_times_warning(1),
            "1 line with unusable times (not finite, or beyond 1e10 s) skipped");
  EXPECT_EQ(unusable_times_warning(3),
            "3 lines with unusable times (not finite, or beyond 1e10 s) skipped");
}

// A writer marks the lines it dropped with a "%%" comment line: readers pass over it.
TEST(Alog, GapMarkerCommentsAreHeaderLines) {
  EXPECT_EQ(parse_alog_line("%% 120 lines dropped (queue full)").kind, AlogLineKind::kHeader);
  EXPECT_EQ(parse_alog_line("  %%gap 12.5 X src").kind, AlogLineKind::kHeader);
  EXPECT_FALSE(alog_logstart("%% 120 lines dropped"));
}

// The warning quotes the bad time for a terminal or a log: escaped and cut, never raw.
TEST(Alog, ABadTimeIsQuotedEscapedAndCut) {
  AlogParse p = parse_alog_line("1\x1b[2J NODE_REPORT src NAME=x");
  ASSERT_EQ(p.kind, AlogLineKind::kMalformed);
  EXPECT_EQ(p.error, "time '1\\x1B[2J' is not a finite number");
  p = parse_alog_line(std::string(5000, '9') + "x X src v");
  ASSERT_EQ(p.kind, AlogLineKind::kMalformed);
  EXPECT_LT(p.error.size(), 400u) << p.error;
  EXPECT_NE(p.error.find("(5001 bytes)"), std::string::npos) << p.error;
}

TEST(AlogLine, NamesFromClientsCannotForgeRecords_Hardening) {
  const AlogEntry forged{1.0, "X\n  2.000 UHZ_CLASSIFY_REQUEST", "evil client", "v"};
  const std::string line = format_alog_line(forged);
  EXPECT_EQ(line.find('\n'), line.size() - 1) << line;  // one posting, one line
  const AlogParse back = parse_alog_line(line.substr(0, line.size() - 1));
  ASSERT_EQ(back.kind, AlogLineKind::kEntry);
  EXPECT_EQ(back.entry.variable, "X\\x0A\\x20\\x202.000\\x20UHZ_CLASSIFY_REQUEST");
  EXPECT_EQ(back.entry.source, "evil\\x20client");
  EXPECT_EQ(back.entry.value, "v");
}

}  // namespace
}  // namespace moos
