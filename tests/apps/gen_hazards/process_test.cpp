// The gen_hazards binary: golden outputs (D30), reproducibility from the header, --output,
// properties of real output files, and bad input (docs/gen_hazards.md, D31): an error naming the
// argument on standard error, a non-zero exit, nothing on standard output, no file, no hang.

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "hazard/hazard_field.hpp"
#include "hazard/messages/hazard_line.hpp"
#include "base/text.hpp"
#include "mission/polygon.hpp"
#include "options.hpp"
#include "scratch_files.hpp"

namespace gen_hazards {
namespace {

using test_support::read_file;
using test_support::RunResult;
using test_support::ScratchDir;

/// Bad input must be rejected at once (issue: "every case finishes within a second"); a hang
/// shows as a kill at this deadline.
constexpr double kBadInputDeadline_s = 1.0;
/// Ordinary runs: far above the few milliseconds they take, only to bound a broken build.
constexpr double kRunDeadline_s = 30.0;
/// Seeds of the property test on real output files.
constexpr std::uint64_t kFileSeeds = 25;
/// The documented rounding (docs/gen_hazards.md, "How a field is drawn"): each coordinate moves at
/// most this much.
constexpr double kRoundingLimit_m = 0.5;

const std::string kManualBox = "--polygon=-150,-75:-150,-400:400,-400:400,-75";

RunResult run(const std::vector<std::string>& args, double deadline_s = kRunDeadline_s) {
  return test_support::run_program(GEN_HAZARDS_PATH, args, deadline_s);
}

std::string golden(const std::string& name) {
  return read_file(std::string(GEN_HAZARDS_GOLDEN_DIR) + "/" + name);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string word; in >> word;) out.push_back(word);
  return out;
}

void expect_golden(const std::vector<std::string>& args, const std::string& file) {
  const RunResult r = run(args);
  EXPECT_EQ(r.exit_code, kExitOk) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string expected = golden(file);
  ASSERT_FALSE(expected.empty()) << "golden file " << file << " is missing";
  EXPECT_EQ(r.out, expected) << "actual output:\n" << r.out;
}

TEST(GenHazardsProcess, ManualFieldWithSeed7MatchesGolden_D30) {
  expect_golden({"--seed=7", kManualBox, "--objects=5,hazard", "--objects=10,benign"},
                "manual_seed7.txt");
}

TEST(GenHazardsProcess, ResemblanceAndAspectFieldWithSeed7MatchesGolden) {
  expect_golden({"--seed=7", kManualBox, "--objects=4,hazard", "--objects=6,benign", "--exp=2",
                 "--aspect_base=45", "--aspect_range=90", "--aspect_min_base=10",
                 "--aspect_min_range=30", "--aspect_max_range=40"},
                "exp_aspect_seed7.txt");
}

TEST(GenHazardsProcess, HelpMatchesGolden) {
  expect_golden({"--help"}, "help.txt");
  EXPECT_EQ(run({"-h"}).out, golden("help.txt"));
  // Help wins over a bad argument next to it.
  const RunResult r = run({"--bogus", "-help"});
  EXPECT_EQ(r.exit_code, kExitOk);
  EXPECT_EQ(r.out, golden("help.txt"));
}

TEST(GenHazardsProcess, VersionMatchesGolden) {
  expect_golden({"--version"}, "version.txt");
  EXPECT_EQ(run({"-v"}).out, golden("version.txt"));
  EXPECT_EQ(run({"-version"}).out, golden("version.txt"));
}

TEST(GenHazardsProcess, HeaderWithoutSeedRegeneratesTheSameFile_D30) {
  const RunResult first = run({kManualBox, "--objects=3,hazard", "--objects=4,benign", "--exp=2"});
  ASSERT_EQ(first.exit_code, kExitOk) << first.err;
  const std::string header = lines_of(first.out).at(0);
  std::vector<std::string> words = words_of(header);
  ASSERT_GE(words.size(), 3u);
  EXPECT_EQ(words[0], "//");
  EXPECT_EQ(words[1], "gen_hazards");
  const std::string seed = words.back();
  ASSERT_EQ(seed.rfind("--seed=", 0), 0u) << header;
  EXPECT_TRUE(base::parse_unsigned(seed.substr(7)).has_value()) << header;

  const std::vector<std::string> again(words.begin() + 2, words.end());
  const RunResult second = run(again);
  EXPECT_EQ(second.exit_code, kExitOk);
  EXPECT_EQ(second.out, first.out);
}

TEST(GenHazardsProcess, RunsWithoutSeedUseDifferentSeeds) {
  const RunResult a = run({kManualBox, "--objects=5,hazard"});
  const RunResult b = run({kManualBox, "--objects=5,hazard"});
  EXPECT_NE(lines_of(a.out).at(0), lines_of(b.out).at(0));
}

TEST(GenHazardsProcess, OutputFileHoldsExactlyWhatStdoutWouldShow) {
  ScratchDir dir;
  const std::string path = (dir / "field.txt").string();
  const std::vector<std::string> args = {"--seed=5", kManualBox, "--objects=8,benign"};
  const RunResult to_stdout = run(args);
  std::vector<std::string> with_file = args;
  with_file.push_back("--output=" + path);
  const RunResult to_file = run(with_file);
  EXPECT_EQ(to_file.exit_code, kExitOk) << to_file.err;
  EXPECT_EQ(to_file.out, "");
  EXPECT_EQ(read_file(path), to_stdout.out);  // --output is not in the header either
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"field.txt"});
}

TEST(GenHazardsProcess, UnwritableOutputExitsOneNamingTheFile) {
  ScratchDir dir;
  const std::string path = (dir / "missing_folder/field.txt").string();
  const RunResult r = run({"--seed=5", kManualBox, "--objects=8,benign", "--output=" + path});
  EXPECT_EQ(r.exit_code, kExitCannotWrite);
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(dir.entries().empty());
}

// Some polygon contains a point within 0.5 m of (x, y) in each coordinate (the rounding above).
bool within_rounding_of_a_region(double x, double y,
                                 const std::vector<mission::ConvexPolygon>& regions) {
  for (const auto& region : regions) {
    const auto band = mission::clip_to_band(region.vertices(), {1.0, 0.0}, x - kRoundingLimit_m,
                                            x + kRoundingLimit_m);
    if (band.empty()) continue;
    if (!mission::clip_to_band(band, {0.0, 1.0}, y - kRoundingLimit_m, y + kRoundingLimit_m).empty())
      return true;
  }
  return false;
}

TEST(GenHazardsProcess, GeneratedFilesLoadCleanlyAndKeepObjectsInTheirRegions) {
  const std::vector<std::string> polygons = {"--polygon=0,-60:60,0:0,60:-60,0",
                                             "--polygon=pts={40,0:140,0:140,50}"};
  for (std::uint64_t seed = 1; seed <= kFileSeeds; ++seed) {
    const RunResult r = run({polygons[0], polygons[1], "--objects=30,hazard", "--objects=90,benign",
                             "--exp=0.5", "--aspect_min_range=60", "--aspect_max_range=60",
                             "--seed=" + std::to_string(seed)});
    ASSERT_EQ(r.exit_code, kExitOk) << r.err;
    const auto lines = lines_of(r.out);
    ASSERT_EQ(lines.size(), 1u + 2u + 120u);
    // One region line per polygon, in order (D30); they are the regions we check against.
    std::vector<mission::ConvexPolygon> regions;
    for (std::size_t i = 1; i <= 2; ++i) {
      ASSERT_EQ(lines[i].rfind("region = pts={", 0), 0u) << lines[i];
      auto parsed = mission::ConvexPolygon::parse(lines[i].substr(9));
      ASSERT_TRUE(parsed) << lines[i] << ": " << parsed.error;
      regions.push_back(*parsed.value);
    }
    std::set<std::string> labels;
    int hazards = 0;
    for (std::size_t i = 3; i < lines.size(); ++i) {
      ASSERT_EQ(lines[i].rfind("hazard = ", 0), 0u) << lines[i];
      const auto parsed = hazard::parse_hazard_line(lines[i].substr(9));
      ASSERT_TRUE(parsed.object) << lines[i] << ": " << parsed.error;
      EXPECT_TRUE(parsed.warnings.empty()) << lines[i];
      const auto& o = *parsed.object;
      EXPECT_TRUE(within_rounding_of_a_region(o.x_m, o.y_m, regions)) << "seed " << seed << ": " << lines[i];
      EXPECT_TRUE(labels.insert(o.label).second) << "seed " << seed << ": " << lines[i];
      EXPECT_EQ(o.is_hazard(), i < 3 + 30) << lines[i];  // sets in argument order
      hazards += o.is_hazard() ? 1 : 0;
    }
    EXPECT_EQ(hazards, 30);
    hazard::HazardField field;
    std::vector<std::string> warnings;
    const auto counts = hazard::load_hazard_file_text(r.out, "generated", field, warnings);
    EXPECT_TRUE(warnings.empty()) << "seed " << seed << ": " << warnings.front();
    EXPECT_EQ(counts.hazards, 30);
    EXPECT_EQ(counts.benign, 90);
    if (HasFailure()) return;
  }
}

struct BadInput {
  std::string name;
  std::vector<std::string> args;
  std::string named;  ///< the argument the error must quote
};

std::vector<BadInput> bad_inputs() {
  const std::string box = "--polygon=0,0:100,0:100,100:0,100";
  return {
      {"UnknownOption", {box, "--objects=5,hazard", "--bogus=1"}, "--bogus=1"},
      {"PositionalArgument", {box, "hazards.txt"}, "hazards.txt"},
      {"NonConvexPolygon", {"--polygon=0,0:10,0:2,2:0,10", "--objects=5,hazard"}, "--polygon=0,0:10,0:2,2:0,10"},
      {"CollinearPolygon", {"--polygon=0,0:10,10:20,20", "--objects=5,hazard"}, "--polygon=0,0:10,10:20,20"},
      {"TwoPointPolygon", {"--polygon=0,0:10,10", "--objects=5,hazard"}, "--polygon=0,0:10,10"},
      {"CountNotANumber", {box, "--objects=five,hazard"}, "--objects=five,hazard"},
      {"CountNotWhole", {box, "--objects=2.9,hazard"}, "--objects=2.9,hazard"},
      {"UnknownType", {box, "--objects=5,inert"}, "--objects=5,inert"},
      {"NoPolygon", {"--objects=5,hazard"}, "--objects=5,hazard"},
      {"ThinPolygon", {"--polygon=0,0:1000,1000.01:0,0.01", "--objects=5,hazard"},
       "--polygon=0,0:1000,1000.01:0,0.01"},
      {"ExpTooSmall", {box, "--objects=5,benign", "--exp=0.001"}, "--exp=0.001"},
      {"ExpTooLarge", {box, "--objects=5,benign", "--exp=11"}, "--exp=11"},
      {"AspectRangeTooLarge", {box, "--objects=5,benign", "--aspect_range=361"}, "--aspect_range=361"},
      {"AspectMinBaseNegative", {box, "--objects=5,benign", "--aspect_min_base=-5"}, "--aspect_min_base=-5"},
      {"AspectMinRangeTooLarge", {box, "--objects=5,benign", "--aspect_min_range=95"}, "--aspect_min_range=95"},
      {"AspectMaxBaseTooLarge", {box, "--objects=5,benign", "--aspect_max_base=90.1"}, "--aspect_max_base=90.1"},
      {"AspectMaxRangeNotANumber", {box, "--objects=5,benign", "--aspect_max_range=wide"}, "--aspect_max_range=wide"},
      {"AspectBaseNotANumber", {box, "--objects=5,benign", "--aspect_base=north"}, "--aspect_base=north"},
      {"SeedNotANumber", {box, "--objects=5,benign", "--seed=abc"}, "--seed=abc"},
      {"TooManyObjects", {box, "--objects=1000001,benign"}, "--objects=1000001,benign"},
  };
}

// gtest prints the case by name instead of as raw bytes.
void PrintTo(const BadInput& bad, std::ostream* os) { *os << bad.name; }

class GenHazardsBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(GenHazardsBadInput, ErrorNamesTheArgumentAndNothingIsWritten_Spec12_4_D31) {
  const BadInput& bad = GetParam();
  const RunResult r = run(bad.args, kBadInputDeadline_s);
  EXPECT_FALSE(r.timed_out) << "still running after " << kBadInputDeadline_s << " s";
  EXPECT_EQ(r.exit_code, kExitBadInput) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err.rfind("gen_hazards: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("'" + bad.named + "'"), std::string::npos) << r.err;

  ScratchDir dir;
  std::vector<std::string> with_file = bad.args;
  with_file.push_back("--output=" + (dir / "field.txt").string());
  const RunResult f = run(with_file, kBadInputDeadline_s);
  EXPECT_FALSE(f.timed_out);
  EXPECT_EQ(f.exit_code, kExitBadInput);
  EXPECT_TRUE(dir.entries().empty()) << "a file was left behind";
}

INSTANTIATE_TEST_SUITE_P(Cases, GenHazardsBadInput, ::testing::ValuesIn(bad_inputs()),
                         [](const ::testing::TestParamInfo<BadInput>& param) { return param.param.name; });

TEST(GenHazardsProcess, BadOutputArgumentLeavesAnExistingFileAlone) {
  ScratchDir dir;
  const std::string path = (dir / "field.txt").string();
  { std::ofstream(path) << "previous field\n"; }
  const RunResult r = run({"--objects=5,hazard", "--output=" + path}, kBadInputDeadline_s);
  EXPECT_EQ(r.exit_code, kExitBadInput);
  EXPECT_EQ(read_file(path), "previous field\n");
}

}  // namespace
}  // namespace gen_hazards
