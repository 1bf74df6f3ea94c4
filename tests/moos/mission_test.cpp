// Mission reader: docs/protocol.md section 6.1-6.3 plus the nsplug habits of
// include/moos/mission.hpp.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "moos/mission.hpp"
#include "scratch_files.hpp"

namespace moos {
namespace {

namespace fs = std::filesystem;

MissionFile parse(std::string_view text, std::vector<MissionError>* errors,
                  MissionOptions options = {}) {
  return MissionFile::parse(text, "test.moos", options, errors);
}

bool has_error(const std::vector<MissionError>& errors, const std::string& file, int line,
               const std::string& fragment) {
  for (const auto& e : errors)
    if (e.file == file && e.line == line && e.message.find(fragment) != std::string::npos) return true;
  return false;
}

std::string dump(const std::vector<MissionError>& errors) {
  std::string out;
  for (const auto& e : errors) out += e.to_string() + "\n";
  return out;
}

/// Writes `content` to `name` in `dir` (folders made as needed); returns its path.
std::string write_in(const test_support::ScratchDir& dir, const std::string& name,
                     const std::string& content) {
  test_support::write_file(dir / name, content);
  return (dir / name).string();
}

// ---- globals (protocol.md 6.2) ------------------------------------------------------------------

TEST(MissionGlobals, FirstOccurrenceWinsCaseInsensitiveWithBlanksRemoved_6_2) {
  std::vector<MissionError> errors;
  const auto m = parse("Community = alpha beta\nServerPort = 9001\nSERVERPORT = 9002\n"
                       "MOOS TimeWarp = 2\n",
                       &errors);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m.global("community"), "alphabeta");
  EXPECT_EQ(m.global("ServerPort"), "9001");
  EXPECT_EQ(m.global_double("serverport"), 9001.0);
  EXPECT_EQ(m.global("MOOSTimeWarp"), "2");  // blanks inside the key are removed too
  EXPECT_FALSE(m.global("LatOrigin").has_value());
}

TEST(MissionGlobals, LookupScansInsideProcessConfigBlocks_6_2) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA\n{\n  LatOrigin = 43.8\n}\nLatOrigin = 1\n", &errors);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m.global_double("LatOrigin"), 43.8);
}

TEST(MissionGlobals, GlobalDoubleRejectsWhatIsNotANumber_6_2) {
  std::vector<MissionError> errors;
  const auto m = parse("A = 12abc\nB = 0x10\nC = nan\nD = 1e999\nE = -2.5e1\nF =\n", &errors);
  EXPECT_FALSE(m.global_double("A").has_value());
  EXPECT_FALSE(m.global_double("B").has_value());
  EXPECT_FALSE(m.global_double("C").has_value());
  EXPECT_FALSE(m.global_double("D").has_value());
  EXPECT_EQ(m.global_double("E"), -25.0);
  EXPECT_EQ(m.global("F"), "");
  EXPECT_FALSE(m.global_double("F").has_value());
}

TEST(MissionGlobals, GlobalLineNamesItsPlace) {
  std::vector<MissionError> errors;
  const auto m = parse("\n\nMOOSTimeWarp = 1 0\n", &errors);
  const ConfigLine* line = m.global_line("moostimewarp");
  ASSERT_NE(line, nullptr);
  EXPECT_EQ(line->file, "test.moos");
  EXPECT_EQ(line->line, 3);
  EXPECT_EQ(line->value, "1 0");
  EXPECT_EQ(m.global("moostimewarp"), "10");
}

// ---- blocks (protocol.md 6.3) -------------------------------------------------------------------

TEST(MissionBlocks, ParametersInFileOrderWithDuplicatesAndPlaces_6_3) {
  std::vector<MissionError> errors;
  const auto m = parse("ServerPort = 9000\n"
                       "ProcessConfig = uFldHazardSensor\n"
                       "{\n"
                       "  AppTick   = 4\n"
                       "  sensor_config = width=25, exp=4, pclass=0.8\n"
                       "  AppTick = 2\n"
                       "  empty_value =\n"
                       "}\n",
                       &errors);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  const ProcessBlock* b = m.block("ufldhazardsensor");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->app_name, "uFldHazardSensor");
  EXPECT_EQ(b->line, 2);
  ASSERT_EQ(b->lines.size(), 4u);
  EXPECT_EQ(b->lines[0].key, "AppTick");
  EXPECT_EQ(b->lines[0].value, "4");
  EXPECT_EQ(b->lines[0].line, 4);
  EXPECT_EQ(b->lines[1].key, "sensor_config");
  EXPECT_EQ(b->lines[1].value, "width=25, exp=4, pclass=0.8");  // interior blanks kept
  EXPECT_EQ(b->lines[2].value, "2");
  EXPECT_EQ(b->lines[2].line, 6);
  EXPECT_EQ(b->lines[3].key, "empty_value");
  EXPECT_EQ(b->lines[3].value, "");
  EXPECT_EQ(b->lines[3].file, "test.moos");
}

TEST(MissionBlocks, MissingBlockIsNull) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA\n{\n}\n", &errors);
  EXPECT_NE(m.block("pA"), nullptr);
  EXPECT_EQ(m.block("pB"), nullptr);
  EXPECT_EQ(m.blocks().size(), 1u);
}

TEST(MissionBlocks, FirstOfTwoSameNameBlocksWinsAndTheSecondIsReported_6_3) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA\n{\n x = 1\n}\nProcessConfig = PA\n{\n x = 2\n}\n",
                       &errors);
  ASSERT_NE(m.block("pa"), nullptr);
  EXPECT_EQ(m.block("pa")->lines.at(0).value, "1");
  EXPECT_TRUE(has_error(errors, "test.moos", 5, "never read")) << dump(errors);
  EXPECT_EQ(errors.at(0).block, "PA");
}

TEST(MissionErrors, AProblemConcernsTheAppOfItsBlockAnyCaseOrEveryAppOutsideBlocks) {
  const MissionError in_block{"m.moos", 3, "bad", "pA"};
  EXPECT_TRUE(in_block.concerns("pA"));
  EXPECT_TRUE(in_block.concerns("PA"));
  EXPECT_FALSE(in_block.concerns("pB"));
  EXPECT_FALSE(in_block.concerns("pA_2"));
  const MissionError outside{"m.moos", 1, "bad", ""};
  EXPECT_TRUE(outside.concerns("pA"));
  EXPECT_TRUE(outside.concerns("anything"));
}

TEST(MissionBlocks, HeaderMatchedAfterRemovingBlanksAnyCase_6_3) {
  std::vector<MissionError> errors;
  const auto m = parse("  processconfig=pA\n\n  // comment between\n   {  \n a = 1\n   }\n", &errors);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  ASSERT_NE(m.block("pA"), nullptr);
  EXPECT_EQ(m.block("pA")->lines.size(), 1u);
}

TEST(MissionBlocks, BraceOnTheHeaderLineIsNotABlockAndIsReported_6_3) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA {\n  AppTick = 4\n}\n", &errors);
  EXPECT_EQ(m.block("pA"), nullptr);
  EXPECT_TRUE(has_error(errors, "test.moos", 1, "'{' must be on the line after")) << dump(errors);
  // As in libMOOS the lines stay visible to global lookups.
  EXPECT_EQ(m.global("AppTick"), "4");
}

TEST(MissionBlocks, HeaderNotFollowedByBraceIsReported_6_3) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA\nAppTick = 4\n{\n}\n", &errors);
  EXPECT_EQ(m.block("pA"), nullptr);
  EXPECT_TRUE(has_error(errors, "test.moos", 1, "next line must start with '{'")) << dump(errors);
  EXPECT_EQ(m.global("AppTick"), "4");
}

TEST(MissionBlocks, UnclosedBlockIsReportedAndKeepsItsLines) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA\n{\n a = 1\n b = 2\n", &errors);
  ASSERT_NE(m.block("pA"), nullptr);
  EXPECT_EQ(m.block("pA")->lines.size(), 2u);
  EXPECT_TRUE(has_error(errors, "test.moos", 1, "no closing '}'")) << dump(errors);
}

TEST(MissionBlocks, NewHeaderInsideAnOpenBlockClosesItWithAnError) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA\n{\n a = 1\nProcessConfig = pB\n{\n b = 2\n}\n", &errors);
  ASSERT_NE(m.block("pA"), nullptr);
  ASSERT_NE(m.block("pB"), nullptr);
  EXPECT_EQ(m.block("pB")->lines.at(0).key, "b");
  EXPECT_TRUE(has_error(errors, "test.moos", 1, "before the next ProcessConfig")) << dump(errors);
}

TEST(MissionBlocks, LineWithoutEqualsIsReportedWithFileLineAndBlock) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA\n{\n  just words\n a = 1\n}\n", &errors);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].line, 3);
  EXPECT_EQ(errors[0].block, "pA");
  EXPECT_EQ(errors[0].to_string(), "test.moos:3: line has no '=' and is ignored: just words");
  EXPECT_EQ(m.block("pA")->lines.size(), 1u);
}

// ---- comments, quoting, line ends (protocol.md 6.1) ---------------------------------------------

TEST(MissionText, CommentsWholeLineAndTrailing_6_1) {
  std::vector<MissionError> errors;
  const auto m = parse("// a comment = not a global\n  // indented comment\n"
                       "ProcessConfig = pA // trailing\n{\n x = 1 // one\n //y = 2\n}\n",
                       &errors);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_FALSE(m.global("a comment").has_value());
  ASSERT_NE(m.block("pA"), nullptr);
  ASSERT_EQ(m.block("pA")->lines.size(), 1u);
  EXPECT_EQ(m.block("pA")->lines[0].value, "1");
}

TEST(MissionText, FirstQuotePairIsRemovedAndProtectsSlashes_6_1) {
  std::vector<MissionError> errors;
  const auto m = parse("ProcessConfig = pA\n{\n path = \"/a//b\" // comment\n"
                       " label = \"x y\" and \"z\"\n url = a // \"b//c\"\n}\n",
                       &errors);
  const auto& lines = m.block("pA")->lines;
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].value, "/a//b");
  EXPECT_EQ(lines[1].value, "x y and \"z\"");  // only the first pair goes
  EXPECT_EQ(lines[2].value, "a");              // the comment starts before the quotes
}

TEST(MissionText, CrLfLineEndsAndByteOrderMarkAreAccepted) {
  std::vector<MissionError> errors;
  const auto m = parse("\xEF\xBB\xBF" "Community = alpha\r\nProcessConfig = pA\r\n{\r\n x = 1 \r\n}\r\n",
                       &errors);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m.global("Community"), "alpha");
  ASSERT_NE(m.block("pA"), nullptr);
  EXPECT_EQ(m.block("pA")->lines.at(0).value, "1");
  EXPECT_EQ(m.block("pA")->lines.at(0).line, 4);
}

// ---- ${NAME} and define: (protocol.md 6.1) ------------------------------------------------------

TEST(MissionDefines, DefineValuesSubstituteEverywhereLaterDuplicateWins_6_1) {
  std::vector<MissionError> errors;
  const auto m = parse("Community = ${VNAME}\n"
                       "define: VNAME = al pha\n"
                       "define: PORT = 9001\n"
                       "define: PORT = 9002\n"
                       "ServerPort = ${PORT}\n"
                       "ProcessConfig = p${VNAME}\n{\n x = ${VNAME}_${PORT}\n}\n",
                       &errors);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m.global("Community"), "alpha");  // blanks removed from define values
  EXPECT_EQ(m.global("ServerPort"), "9002");
  ASSERT_NE(m.block("palpha"), nullptr);
  EXPECT_EQ(m.block("palpha")->lines.at(0).value, "alpha_9002");
  EXPECT_FALSE(m.global("define:VNAME").has_value());  // a define line is not a global
}

TEST(MissionDefines, UnknownBraceNameBecomesTheBareNameWithAnError_6_1) {
  std::vector<MissionError> errors;
  MissionOptions options;
  options.use_environment = false;
  const auto m = parse("\nCommunity = ${NOPE}\n", &errors, options);
  EXPECT_EQ(m.global("Community"), "NOPE");
  EXPECT_TRUE(has_error(errors, "test.moos", 2, "${NOPE}")) << dump(errors);
}

// Defines that name themselves or each other: one pass, so no loop and no growth; the
// inner name stays as written.
TEST(MissionDefines, SelfAndMutualReferencesAreNotExpandedAgain_Hardening) {
  std::vector<MissionError> errors;
  MissionOptions options;
  options.use_environment = false;
  std::string chain = "define: D0 = xx\n";
  for (int i = 1; i <= 40; ++i)  // each doubles the one before: 2^41 bytes if expanded again
    chain += "define: D" + std::to_string(i) + " = ${D" + std::to_string(i - 1) + "}${D" +
             std::to_string(i - 1) + "}\n";
  const auto m = parse("define: A = ${A}\ndefine: B = ${C}\ndefine: C = ${B}\n" + chain +
                           "Community = ${A}\nServerHost = ${B}\nServerPort = ${D40}\n",
                       &errors, options);
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m.global("Community"), "${A}");
  EXPECT_EQ(m.global("ServerHost"), "${C}");
  EXPECT_EQ(m.global("ServerPort"), "${D39}${D39}");
}

TEST(MissionDefines, AnUnterminatedBraceIsReportedAndKeptAsWritten) {
  std::vector<MissionError> errors;
  const auto m = parse("define: A = 1\nCommunity = x${A\n", &errors);
  EXPECT_EQ(m.global("Community"), "x${A");
  EXPECT_TRUE(has_error(errors, "test.moos", 2, "unterminated ${")) << dump(errors);
}

TEST(MissionDefines, BraceNameFallsBackToTheEnvironment_6_1) {
  ::setenv("MOOS_MISSION_TEST_ENV", "fromenv", 1);
  std::vector<MissionError> errors;
  const auto m = parse("Community = ${MOOS_MISSION_TEST_ENV}\n", &errors);
  ::unsetenv("MOOS_MISSION_TEST_ENV");
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m.global("Community"), "fromenv");
}

// ---- nsplug $(NAME) ---------------------------------------------------------------------------

TEST(MissionSubstitution, ParenNamesComeFromSubstitutionsThenEnvironment) {
  ::setenv("MOOS_MISSION_TEST_PORT", "9100", 1);
  MissionOptions options;
  options.substitutions["VNAME"] = "archie";
  std::vector<MissionError> errors;
  const auto m = parse("Community = $(VNAME)\nServerPort = $(MOOS_MISSION_TEST_PORT)\n", &errors,
                       options);
  ::unsetenv("MOOS_MISSION_TEST_PORT");
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m.global("Community"), "archie");
  EXPECT_EQ(m.global("ServerPort"), "9100");
}

TEST(MissionSubstitution, SubstitutionsBeatTheEnvironment) {
  ::setenv("MOOS_MISSION_TEST_BOTH", "env", 1);
  MissionOptions options;
  options.substitutions["MOOS_MISSION_TEST_BOTH"] = "cli";
  std::vector<MissionError> errors;
  const auto m = parse("X = $(MOOS_MISSION_TEST_BOTH)\n", &errors, options);
  ::unsetenv("MOOS_MISSION_TEST_BOTH");
  EXPECT_EQ(m.global("X"), "cli");
}

TEST(MissionSubstitution, MissingParenNameIsAnErrorNamingItsFileAndLine) {
  MissionOptions options;
  options.use_environment = false;
  std::vector<MissionError> errors;
  const auto m = parse("\n\nProcessConfig = pA\n{\n speed = $(SPEED) // $(IN_COMMENT)\n}\n", &errors,
                       options);
  ASSERT_EQ(errors.size(), 1u) << dump(errors);
  EXPECT_EQ(errors[0].file, "test.moos");
  EXPECT_EQ(errors[0].line, 5);
  EXPECT_NE(errors[0].message.find("$(SPEED)"), std::string::npos);
  EXPECT_EQ(m.block("pA")->lines.at(0).value, "$(SPEED)");  // kept as written
}

TEST(MissionSubstitution, ValuesAreNotScannedAgain) {
  MissionOptions options;
  options.substitutions["A"] = "$(B)";
  options.substitutions["B"] = "no";
  std::vector<MissionError> errors;
  const auto m = parse("X = $(A)\n", &errors, options);
  EXPECT_EQ(m.global("X"), "$(B)");
}

TEST(MissionSubstitution, UnterminatedParenIsReported) {
  std::vector<MissionError> errors;
  const auto m = parse("X = $(A\n", &errors);
  EXPECT_TRUE(has_error(errors, "test.moos", 1, "unterminated $(")) << dump(errors);
  EXPECT_EQ(m.global("X"), "$(A");
}

// ---- #include ---------------------------------------------------------------------------------

TEST(MissionInclude, IncludedLinesNameTheirOwnFileAndLine) {
  const test_support::ScratchDir dir;
  write_in(dir, "plugs/common.plug", "// header\nServerPort = $(PORT)\nProcessConfig = pB\n{\n y = 2\n}\n");
  const std::string top = write_in(dir, "m.moos", "Community = alpha\n#include plugs/common.plug\n"
                                              "ProcessConfig = pA\n{\n x = 1\n}\n");
  MissionOptions options;
  options.substitutions["PORT"] = "9300";
  std::vector<MissionError> errors;
  const auto m = MissionFile::load(top, options, &errors);
  ASSERT_TRUE(m.has_value());
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m->global("ServerPort"), "9300");
  const ConfigLine* port = m->global_line("ServerPort");
  ASSERT_NE(port, nullptr);
  EXPECT_EQ(port->line, 2);
  EXPECT_EQ(fs::path(port->file).filename(), "common.plug");
  ASSERT_NE(m->block("pB"), nullptr);
  EXPECT_EQ(m->block("pB")->lines.at(0).line, 5);
  ASSERT_NE(m->block("pA"), nullptr);
  EXPECT_EQ(m->block("pA")->lines.at(0).line, 5);
  EXPECT_EQ(m->block("pA")->lines.at(0).file, top);
}

TEST(MissionInclude, QuotedAndAngleBracketPathsAndIncludesOfIncludes) {
  const test_support::ScratchDir dir;
  write_in(dir, "a.plug", "#include <sub/b.plug>\n");
  write_in(dir, "sub/b.plug", "#include c.plug\n");  // relative to sub/
  write_in(dir, "sub/c.plug", "Deep = yes\n");
  const std::string top = write_in(dir, "m.moos", "#include \"a.plug\"\n");
  std::vector<MissionError> errors;
  const auto m = MissionFile::load(top, {}, &errors);
  ASSERT_TRUE(m.has_value());
  EXPECT_TRUE(errors.empty()) << dump(errors);
  EXPECT_EQ(m->global("Deep"), "yes");
}

TEST(MissionInclude, ErrorsInsideAnIncludedFileNameThatFile) {
  const test_support::ScratchDir dir;
  write_in(dir, "bad.plug", "\nX = $(UNDEFINED_IN_PLUG)\n");
  const std::string top = write_in(dir, "m.moos", "#include bad.plug\n");
  MissionOptions options;
  options.use_environment = false;
  std::vector<MissionError> errors;
  const auto m = MissionFile::load(top, options, &errors);
  ASSERT_EQ(errors.size(), 1u) << dump(errors);
  EXPECT_EQ(fs::path(errors[0].file).filename(), "bad.plug");
  EXPECT_EQ(errors[0].line, 2);
}

TEST(MissionInclude, CycleIsAnErrorAndParsingGoesOn) {
  const test_support::ScratchDir dir;
  write_in(dir, "a.plug", "A = 1\n#include b.plug\n");
  write_in(dir, "b.plug", "B = 2\n#include a.plug\n");
  const std::string top = write_in(dir, "m.moos", "#include a.plug\nTop = 3\n#include m.moos\n");
  std::vector<MissionError> errors;
  const auto m = MissionFile::load(top, {}, &errors);
  ASSERT_TRUE(m.has_value());
  ASSERT_EQ(errors.size(), 2u) << dump(errors);
  EXPECT_NE(errors[0].message.find("#include cycle"), std::string::npos);
  EXPECT_EQ(fs::path(errors[0].file).filename(), "b.plug");
  EXPECT_EQ(errors[0].line, 2);
  EXPECT_EQ(errors[1].line, 3);  // the top file including itself
  EXPECT_EQ(m->global("A"), "1");
  EXPECT_EQ(m->global("B"), "2");
  EXPECT_EQ(m->global("Top"), "3");
}

TEST(MissionInclude, MissingIncludedFileIsAnErrorAtTheIncludeLine) {
  const test_support::ScratchDir dir;
  const std::string top = write_in(dir, "m.moos", "\n#include nothere.plug\nX = 1\n");
  std::vector<MissionError> errors;
  const auto m = MissionFile::load(top, {}, &errors);
  ASSERT_TRUE(m.has_value());
  EXPECT_TRUE(has_error(errors, top, 2, "cannot read included file")) << dump(errors);
  EXPECT_EQ(m->global("X"), "1");
}

// A device, a directory or a FIFO as an included file: refused at once naming the kind, never
// read (a FIFO without a writer would block, /dev/zero would never end).
TEST(MissionInclude, ASpecialFileIsRefusedAtTheIncludeLine_Hardening) {
  const test_support::ScratchDir dir;
  const std::string fifo = (dir / "pipe").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string top = write_in(dir, "m.moos",
                                   "#include /dev/zero\n#include " + dir.path().string() +
                                       "\n#include " + fifo + "\nX = 1\n");
  std::vector<MissionError> errors;
  const auto m = MissionFile::load(top, {}, &errors);
  ASSERT_TRUE(m.has_value());
  EXPECT_TRUE(has_error(errors, top, 1, "/dev/zero: is a device, not a regular file"))
      << dump(errors);
  EXPECT_TRUE(has_error(errors, top, 2, "is a directory")) << dump(errors);
  EXPECT_TRUE(has_error(errors, top, 3, "is a FIFO, not a regular file")) << dump(errors);
  EXPECT_EQ(m->global("X"), "1");
}

// Each file includes the next twice, 30 deep: within the depth bound, but 2^30 files in all.
// The total bound ends it at once with one error, and what came before is kept.
TEST(MissionInclude, AnIncludeFanOutStopsAtTheTotalBound) {
  const test_support::ScratchDir dir;
  constexpr int kDepth = 30;
  for (int i = 0; i < kDepth; ++i) {
    write_in(dir, "f" + std::to_string(i) + ".plug",
             "#include f" + std::to_string(i + 1) + ".plug\n#include f" +
                 std::to_string(i + 1) + ".plug\n");
  }
  write_in(dir, "f" + std::to_string(kDepth) + ".plug", "Leaf = 1\n");
  const std::string top = write_in(dir, "m.moos", "Before = yes\n#include f0.plug\nAfter = yes\n");
  std::vector<MissionError> errors;
  const auto m = MissionFile::load(top, {}, &errors);
  ASSERT_TRUE(m.has_value());
  ASSERT_EQ(errors.size(), 1u) << dump(errors).substr(0, 2000);
  EXPECT_NE(errors[0].message.find("more than 10000 included files"), std::string::npos)
      << errors[0].message;
  EXPECT_EQ(m->global("Before"), "yes");
  EXPECT_EQ(m->global("Leaf"), "1");
  EXPECT_FALSE(m->global("After").has_value());  // the rest of the expansion is skipped
}

TEST(MissionInclude, TheTotalLineAndByteBoundsNameTheLineWhereTheyWereReached) {
  const test_support::ScratchDir dir;
  write_in(dir, "ten.plug", "A = 1\nB = 2\nC = 3\nD = 4\nE = 5\nF = 6\nG = 7\nH = 8\nI = 9\nJ = 10\n");
  const std::string top = write_in(dir, "m.moos", "#include ten.plug\n#include ten.plug\nZ = 1\n");
  MissionOptions lines;
  lines.max_expanded_lines = 15;
  std::vector<MissionError> errors;
  auto m = MissionFile::load(top, lines, &errors);
  ASSERT_EQ(errors.size(), 1u) << dump(errors);
  EXPECT_NE(errors[0].message.find("more than 15 lines"), std::string::npos) << errors[0].message;
  EXPECT_EQ(fs::path(errors[0].file).filename(), "ten.plug");
  // The top file's first line, the included file's eleven (ten and the empty one after its last
  // newline), the top file's second line, then the included file's first three: 16 lines.
  EXPECT_EQ(errors[0].line, 3);
  EXPECT_FALSE(m->global("Z").has_value());

  MissionOptions bytes;
  bytes.max_expanded_bytes = 110;  // the top file (42 bytes) and one include (61) fit
  errors.clear();
  m = MissionFile::load(top, bytes, &errors);
  ASSERT_EQ(errors.size(), 1u) << dump(errors);
  EXPECT_NE(errors[0].message.find("more than 110 bytes"), std::string::npos) << errors[0].message;
  EXPECT_EQ(errors[0].line, 2);
}

TEST(MissionInclude, OtherNsplugDirectivesAreReportedUnsupported) {
  std::vector<MissionError> errors;
  const auto m = parse("#ifdef VNAME\nX = 1\n#endif\n# just a hash line = 2\n", &errors);
  ASSERT_EQ(errors.size(), 2u) << dump(errors);
  EXPECT_EQ(errors[0].line, 1);
  EXPECT_NE(errors[0].message.find("#ifdef"), std::string::npos);
  EXPECT_EQ(errors[1].line, 3);
  EXPECT_EQ(m.global("X"), "1");
  EXPECT_EQ(m.global("# just a hash line"), "2");  // not a directive: an ordinary line
}

// ---- files ------------------------------------------------------------------------------------

TEST(MissionFiles, UnreadableFileReturnsNulloptWithAnError) {
  std::vector<MissionError> errors;
  const auto m = MissionFile::load("/nonexistent/dir/x.moos", {}, &errors);
  EXPECT_FALSE(m.has_value());
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].to_string(), "/nonexistent/dir/x.moos: cannot read the mission file: "
            "cannot be opened: No such file or directory");
}

TEST(MissionFiles, ADirectoryAsMissionFileIsRefusedWithTheReason_Hardening) {
  std::vector<MissionError> errors;
  EXPECT_FALSE(MissionFile::load(fs::temp_directory_path().string(), {}, &errors).has_value());
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].message, "cannot read the mission file: is a directory");
}

TEST(MissionFiles, DirectoryIsTheFolderOfThePath) {
  std::vector<MissionError> errors;
  EXPECT_EQ(MissionFile::parse("", "missions/jake/jake.moos", {}, &errors).directory(),
            "missions/jake");
  EXPECT_EQ(MissionFile::parse("", "jake.moos", {}, &errors).directory(), ".");
}

TEST(MissionFiles, TheRepositoryMissionsParseWithoutErrors) {
  const fs::path root = fs::path(HAZARD_SOURCE_DIR) / "missions";
  if (!fs::exists(root)) GTEST_SKIP() << "no missions folder yet";
  int parsed = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".moos") continue;
    std::vector<MissionError> errors;
    const auto m = MissionFile::load(entry.path().string(), {}, &errors);
    ASSERT_TRUE(m.has_value()) << entry.path();
    for (const auto& e : errors)
      EXPECT_NE(e.message.find("is not defined"), std::string::npos) << e.to_string();
    ++parsed;
  }
  if (parsed == 0) GTEST_SKIP() << "no .moos files yet";
}

}  // namespace
}  // namespace moos
