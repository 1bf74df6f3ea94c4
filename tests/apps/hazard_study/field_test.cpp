// hazard_study's fields: a generated field (--field, --field-seed, --field-seeds) is gen_hazards'
// own file for its seed, the same seed gives the same field and the same lines, two seeds two
// fields, and each line names its field seed; bad values are errors naming the option; and a
// field, from the file or generated, is loaded once for every mission that uses it, which
// changes no line.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "field.hpp"
#include "field_cache.hpp"
#include "generator.hpp"
#include "mission_plan.hpp"
#include "mission_run.hpp"
#include "study.hpp"
#include "study_args.hpp"
#include "study_output.hpp"

namespace hazard_study {
namespace {

const std::string kJake = std::string(HAZARD_SOURCE_DIR) + "/missions/jake/jake.moos";
// Jake's search region with its own numbers of objects.
const std::string kField =
    "--polygon=-150,-75:-150,-400:400,-400:400,-75 --objects=5,hazard --objects=10,benign";

std::string error_of(std::vector<std::string> args) {
  args.insert(args.begin(), "m.moos");
  const ParsedArgs p = parse_args(args);
  EXPECT_FALSE(p.options);
  return p.error;
}

std::string study(std::vector<std::string> args, int expected_status = 0) {
  args.insert(args.begin(), kJake);
  const ParsedArgs parsed = parse_args(args);
  EXPECT_TRUE(parsed.options) << parsed.error;
  if (!parsed.options) return {};
  std::ostringstream out, err;
  EXPECT_EQ(run(*parsed.options, out, err), expected_status) << err.str();
  return expected_status == 0 ? out.str() : err.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(StudyField, TheFieldOfASeedIsGenHazardsOwnFileForThatSeed) {
  const ParsedField parsed = parse_field(kField);
  ASSERT_TRUE(parsed.spec) << parsed.error;
  const FieldText a = generate_field(*parsed.spec, 7);
  ASSERT_TRUE(a.text) << a.error;
  EXPECT_EQ(a.text, generate_field(*parsed.spec, 7).text);
  EXPECT_NE(a.text, generate_field(*parsed.spec, 8).text);
  // What `gen_hazards <the --field words> --seed=7` writes.
  const gen_hazards::CommandLine cli = gen_hazards::parse_command_line(
      {"--polygon=-150,-75:-150,-400:400,-400:400,-75", "--objects=5,hazard", "--objects=10,benign"});
  gen_hazards::GeneratorConfig config = cli.config;
  config.seed = 7;
  const auto file = gen_hazards::build_hazard_file(gen_hazards::header_line(cli.recorded_args, 7), config);
  ASSERT_TRUE(file) << file.error;
  EXPECT_EQ(*a.text, *file.value);
  EXPECT_EQ(a.text->rfind("// gen_hazards --polygon=-150,-75:-150,-400:400,-400:400,-75 "
                          "--objects=5,hazard --objects=10,benign --seed=7\n", 0), 0u);
}

TEST(StudyField, LinesCarryTheFieldSeedAndTheSameFieldSeedGivesTheSameLines) {
  const std::string out = study({"--field=" + kField, "--field-seeds=4..5", "--seeds=1..2"});
  const auto lines = lines_of(out);
  ASSERT_EQ(lines.size(), 4u) << out;
  EXPECT_EQ(lines[0].rfind("{\"setting\":\"mission\",\"field_seed\":4,\"seed\":1,\"end\":\"graded\"", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("{\"setting\":\"mission\",\"field_seed\":4,\"seed\":2,", 0), 0u);
  EXPECT_EQ(lines[2].rfind("{\"setting\":\"mission\",\"field_seed\":5,\"seed\":1,", 0), 0u);
  // The same field seed alone gives the same lines; another field, other missions.
  EXPECT_EQ(study({"--field=" + kField, "--field-seed=5", "--seeds=1..2"}),
            lines[2] + "\n" + lines[3] + "\n");
  const auto tail = [](const std::string& line) { return line.substr(line.find(",\"end\"")); };
  EXPECT_NE(tail(lines[0]), tail(lines[2]));
  // The generated field replaces the mission's hazards.txt for the sensor and the grader.
  const std::string mission = study({"--seed=1"});
  EXPECT_NE(tail(mission), tail(lines[0]) + "\n");
}

TEST(StudyField, WithoutFieldOptionsTheLinesHaveNoFieldSeed) {
  const std::string out = study({"--seed=2", "--max-time=300"});
  EXPECT_EQ(out.find("field_seed"), std::string::npos) << out;
  EXPECT_EQ(out.rfind("{\"setting\":\"mission\",\"seed\":2,", 0), 0u) << out;
}

TEST(StudyField, BadFieldValuesAreErrorsNamingTheOption) {
  EXPECT_EQ(error_of({"--field="}).rfind("--field needs gen_hazards options", 0), 0u);
  EXPECT_EQ(error_of({"--field=--objects=5,hazrd --polygon=0,0:10,0:10,10"}),
            "--field: '--objects=5,hazrd': the type 'hazrd' is neither 'hazard' nor 'benign' "
            "(the only types uFldHazardSensor accepts)");
  EXPECT_EQ(error_of({"--field=--objects=5,hazard"}),
            "--field: '--objects=5,hazard': objects need at least one --polygon");
  EXPECT_EQ(error_of({"--field=--polygon=0,0:10,0:10,10"}).rfind(
                "--field: needs at least one --objects=N,TYPE", 0), 0u);
  EXPECT_EQ(error_of({"--field=--polygon=0,0:10,0:10,10 --objects=600000,hazard "
                      "--objects=400001,benign"}),
            "--field: '--objects=400001,benign': more than 1000000 objects in total");
  EXPECT_EQ(error_of({"--field=" + kField + " --seed=3"}),
            "--field: '--seed=3': the field's seed is --field-seed (or --field-seeds)");
  EXPECT_EQ(error_of({"--field=" + kField + " --output=f.txt"}).rfind("--field: '--output=f.txt': ", 0), 0u);
  EXPECT_EQ(error_of({"--field=" + kField + " --colour=red"}),
            "--field: '--colour=red': unknown option (see gen_hazards --help)");
  EXPECT_EQ(error_of({"--field=--help"}).rfind("--field: takes gen_hazards' field options", 0), 0u);
  EXPECT_EQ(error_of({"--field=" + std::string(kMaxFieldText + 1, 'x')}).rfind(
                "--field: needs gen_hazards options on one line", 0), 0u);
}

TEST(StudyField, AFieldTheGeneratorCannotPlaceIsExit2NamingField) {
  // A sliver of a region: gen_hazards refuses it before any draw.
  const std::string err =
      study({"--field=--polygon=0,0:10000,10000:10000,10001 --objects=1,hazard"}, 2);
  EXPECT_EQ(err.rfind("hazard_study: --field: '--polygon=0,0:10000,10000:10000,10001': ", 0), 0u)
      << err;
}

TEST(StudyField, BadFieldSeedsAreErrorsNamingTheOption) {
  const std::string field = "--field=" + kField;
  EXPECT_EQ(error_of({"--field-seed=3"}), "--field-seed and --field-seeds need --field (the field to generate)");
  EXPECT_EQ(error_of({"--field-seeds=1..2"}), "--field-seed and --field-seeds need --field (the field to generate)");
  EXPECT_EQ(error_of({field, "--field-seeds=5..4"}),
            "--field-seeds needs A..B, whole numbers with A <= B and at most 10000000 seeds: "
            "'--field-seeds=5..4'");
  EXPECT_EQ(error_of({field, "--field-seeds=x"}).rfind("--field-seeds needs A..B", 0), 0u);
  EXPECT_EQ(error_of({field, "--field-seed=-1"}).rfind("--field-seed needs a whole number", 0), 0u);
  EXPECT_EQ(error_of({field, "--field-seed=1", "--field-seeds=1..2"}),
            "--field-seed and --field-seeds exclude each other");
  // Missions per setting are bounded as --seeds alone bounds them.
  EXPECT_EQ(error_of({field, "--field-seeds=1..10000", "--seeds=1..1001"}),
            "--field-seeds and --seeds: 10000 x 1001 missions per setting, more than 10000000");
  EXPECT_EQ(error_of({field, "--set=uFldHazardMetric.hazard_file=h.txt"}),
            "--set 'uFldHazardMetric.hazard_file=h.txt': --field gives every block its "
            "hazard_file; give one or the other");
  EXPECT_EQ(error_of({field, "--field-seeds=1..2", "--seed=1", "--alog=x.alog"}),
            "--alog writes one mission: give --field-seed=N (not --field-seeds)");
}

TEST(StudyField, AFieldIsLoadedOncePerFieldAndTheCopiesChangeNoLine) {
  std::string error;
  const auto parsed = parse_args({kJake});
  ASSERT_TRUE(parsed.options);
  const auto plan = load_plan(*parsed.options, error);
  ASSERT_TRUE(plan) << error;
  const Setting& setting = parsed.options->settings[0];
  FieldCache fields;
  fields.start_field(std::nullopt);
  RunOptions cached;
  cached.fields = &fields;
  for (std::uint64_t seed = 1; seed <= 3; ++seed)
    EXPECT_EQ(json_line(run_mission(*plan, setting, seed, cached)),
              json_line(run_mission(*plan, setting, seed, RunOptions{})));
  EXPECT_EQ(fields.files_read(), 1u);  // hazards.txt, for the sensor and the grader
  EXPECT_EQ(fields.builds(), 2u);      // one engine, one grader, for three missions
  // A setting that changes the grader's block builds its own grader, from the same text.
  Setting strict{"strict", {*parse_assignment("uFldHazardMetric.penalty_false_alarm=25")}};
  run_mission(*plan, strict, 1, cached);
  EXPECT_EQ(fields.files_read(), 1u);
  EXPECT_EQ(fields.builds(), 3u);
  fields.start_field(std::nullopt);  // the next field starts afresh
  run_mission(*plan, setting, 1, cached);
  EXPECT_EQ(fields.files_read(), 1u);
  EXPECT_EQ(fields.builds(), 2u);
}

}  // namespace
}  // namespace hazard_study
