// The command line of gen_hazards (docs/gen_hazards.md; docs/differences.md D30, D31).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "options.hpp"

namespace gen_hazards {
namespace {

const std::string kBox = "--polygon=-150,-75:-150,-400:400,-400:400,-75";

CommandLine parse(const std::vector<std::string>& args) { return parse_command_line(args); }

// The one error of a command line that must fail because of `bad`, which it must quote.
void expect_single_error_naming(const std::vector<std::string>& args, const std::string& bad) {
  const CommandLine cli = parse(args);
  ASSERT_EQ(cli.errors.size(), 1u) << bad;
  EXPECT_NE(cli.errors[0].find("'" + bad + "'"), std::string::npos) << cli.errors[0];
}

TEST(GenHazardsOptions, PolygonIsRepeatableAndKeepsArgumentOrder_Spec12_1) {
  const CommandLine cli =
      parse({"--polygon=0,0:10,0:10,10", "--polygon=pts={20,20:30,20:30,30:20,30}"});
  ASSERT_TRUE(cli.errors.empty());
  ASSERT_EQ(cli.config.regions.size(), 2u);
  EXPECT_EQ(cli.config.regions[0].polygon.vertices().size(), 3u);
  EXPECT_EQ(cli.config.regions[1].polygon.vertices().size(), 4u);
  EXPECT_EQ(cli.config.regions[1].argument, "--polygon=pts={20,20:30,20:30,30:20,30}");
}

TEST(GenHazardsOptions, BadPolygonsAreErrorsNamingTheArgument_Spec12_4) {
  expect_single_error_naming({"--polygon=0,0:10,0:2,2:0,10"}, "--polygon=0,0:10,0:2,2:0,10");
  expect_single_error_naming({"--polygon=0,0:10,10:20,20"}, "--polygon=0,0:10,10:20,20");
  expect_single_error_naming({"--polygon=0,0:10,10"}, "--polygon=0,0:10,10");
  expect_single_error_naming({"--polygon=0,0:x,1:2,2"}, "--polygon=0,0:x,1:2,2");
  // A rejected polygon does not also produce "objects need a polygon".
  expect_single_error_naming({"--polygon=0,0:10,10", "--objects=1,hazard"},
                             "--polygon=0,0:10,10");
}

// Objects beyond the sensor's coordinate bound would be refused by every reader.
TEST(GenHazardsOptions, APolygonBeyondTheObjectBoundIsAnErrorNamingIt_Hardening) {
  expect_single_error_naming({"--polygon=0,0:1e300,0:1e300,1e300"},
                             "--polygon=0,0:1e300,0:1e300,1e300");
  const CommandLine far = parse({"--polygon=0,0:2e8,0:2e8,2e8"});
  ASSERT_EQ(far.errors.size(), 1u);
  EXPECT_NE(far.errors[0].find("reaches 2e+08 m from the origin, beyond the 1e+08 m"),
            std::string::npos)
      << far.errors[0];
  EXPECT_TRUE(parse({"--polygon=-1e8,-1e8:1e8,-1e8:1e8,1e8"}).errors.empty());
}

TEST(GenHazardsOptions, ObjectsTakeAWholeCountAndHazardOrBenignInAnyCase) {
  const CommandLine cli =
      parse({kBox, "--objects=5,hazard", "--objects= 10 , Benign", "--objects=0,HAZARD"});
  ASSERT_TRUE(cli.errors.empty());
  ASSERT_EQ(cli.config.sets.size(), 3u);
  EXPECT_EQ(cli.config.sets[0].count, 5u);
  EXPECT_EQ(cli.config.sets[0].type, hazard::ObjectType::kHazard);
  EXPECT_EQ(cli.config.sets[1].count, 10u);
  EXPECT_EQ(cli.config.sets[1].type, hazard::ObjectType::kBenign);
  EXPECT_EQ(cli.config.sets[2].count, 0u);
  EXPECT_EQ(cli.config.sets[2].type, hazard::ObjectType::kHazard);
}

TEST(GenHazardsOptions, ObjectsCountThatIsNotAWholeNumberIsAnError_N15) {
  // The original truncated with atoi ("5.7" -> 5) and turned negatives into 0.
  for (const std::string bad : {"--objects=abc,hazard", "--objects=5.5,hazard", "--objects=-1,hazard",
                                "--objects=,hazard", "--objects=1e2,benign"}) {
    expect_single_error_naming({kBox, bad}, bad);
  }
}

TEST(GenHazardsOptions, ObjectsTypeOtherThanHazardOrBenignIsAnError) {
  // The sensor rejects any other type (differences.md "Validation"); the original wrote it.
  for (const std::string bad : {"--objects=5,inert", "--objects=5,", "--objects=5", "--objects=5,hazard,x"}) {
    expect_single_error_naming({kBox, bad}, bad);
  }
}

TEST(GenHazardsOptions, ObjectsWithoutAnyPolygonIsAnError_Spec12_4) {
  expect_single_error_naming({"--objects=5,hazard", "--objects=2,benign"}, "--objects=5,hazard");
  EXPECT_TRUE(parse({}).errors.empty());  // no objects, no polygon: just the header
}

TEST(GenHazardsOptions, MoreThanTheTotalObjectLimitIsAnError) {
  const std::string all = "--objects=" + std::to_string(kMaxTotalObjects) + ",hazard";
  EXPECT_TRUE(parse({kBox, all}).errors.empty());
  expect_single_error_naming({kBox, all, "--objects=1,benign"}, "--objects=1,benign");
  expect_single_error_naming({kBox, "--objects=18446744073709551615,benign"},
                             "--objects=18446744073709551615,benign");
}

TEST(GenHazardsOptions, ExpMustLieInTheManualsRangeInclusive_D31) {
  EXPECT_EQ(parse({"--exp=0.01"}).config.resemblance_exp, 0.01);
  EXPECT_EQ(parse({"--exp=10"}).config.resemblance_exp, 10.0);
  EXPECT_FALSE(parse({}).config.resemblance_exp.has_value());
  for (const std::string bad : {"--exp=0.0099", "--exp=10.01", "--exp=0", "--exp=-1", "--exp=abc",
                                "--exp=", "--exp=inf", "--exp=nan"}) {
    expect_single_error_naming({bad}, bad);
    EXPECT_FALSE(parse({bad}).config.resemblance_exp.has_value()) << bad;
  }
}

TEST(GenHazardsOptions, AnyAspectOptionEnablesAspectWithTheOriginalsDefaults_Spec12_1) {
  EXPECT_FALSE(parse({kBox}).config.aspect.has_value());
  const CommandLine cli = parse({"--aspect_min_range=5"});
  ASSERT_TRUE(cli.config.aspect.has_value());
  EXPECT_EQ(cli.config.aspect->base_deg, 0.0);
  EXPECT_EQ(cli.config.aspect->range_deg, 360.0);
  EXPECT_EQ(cli.config.aspect->min_base_deg, 15.0);
  EXPECT_EQ(cli.config.aspect->min_range_deg, 5.0);
  EXPECT_FALSE(cli.config.aspect->max_base_deg.has_value());
  EXPECT_EQ(cli.config.aspect->max_range_deg, 0.0);
}

TEST(GenHazardsOptions, AspectOptionsAcceptTheirRangeBoundsAndRejectBeyond_Spec12_1) {
  const CommandLine ok = parse({"--aspect_base=-725.5", "--aspect_range=360", "--aspect_min_base=0",
                                "--aspect_min_range=90", "--aspect_max_base=90",
                                "--aspect_max_range=0"});
  ASSERT_TRUE(ok.errors.empty());
  EXPECT_EQ(ok.config.aspect->base_deg, -725.5);
  EXPECT_EQ(ok.config.aspect->range_deg, 360.0);
  EXPECT_EQ(ok.config.aspect->min_range_deg, 90.0);
  EXPECT_EQ(ok.config.aspect->max_base_deg, 90.0);
  for (const std::string bad :
       {"--aspect_range=-0.1", "--aspect_range=360.1", "--aspect_min_base=-1", "--aspect_min_base=91",
        "--aspect_min_range=90.5", "--aspect_max_base=-0.5", "--aspect_max_range=100",
        "--aspect_base=north", "--aspect_base=1e999"}) {
    expect_single_error_naming({bad}, bad);
  }
}

TEST(GenHazardsOptions, RepeatedScalarOptionTakesTheLastValue) {
  const CommandLine cli = parse({"--exp=2", "--exp=3", "--seed=1", "--seed=2"});
  ASSERT_TRUE(cli.errors.empty());
  EXPECT_EQ(cli.config.resemblance_exp, 3.0);
  EXPECT_EQ(cli.seed, 2u);
}

TEST(GenHazardsOptions, SeedIsAnyUnsigned64BitNumber) {
  EXPECT_EQ(parse({"--seed=0"}).seed, 0u);
  EXPECT_EQ(parse({"--seed=18446744073709551615"}).seed, 18446744073709551615ull);
  EXPECT_FALSE(parse({}).seed.has_value());
  for (const std::string bad : {"--seed=-1", "--seed=1.5", "--seed=18446744073709551616", "--seed=x"}) {
    expect_single_error_naming({bad}, bad);
  }
}

TEST(GenHazardsOptions, OutputNeedsAFileName) {
  EXPECT_EQ(parse({"--output=out/field.txt"}).output_path, "out/field.txt");
  expect_single_error_naming({"--output="}, "--output=");
}

TEST(GenHazardsOptions, UnknownOptionOrMissingValueIsAnError_Spec12_1) {
  expect_single_error_naming({"--bogus"}, "--bogus");
  expect_single_error_naming({"--polygonx=0,0:1,0:1,1"}, "--polygonx=0,0:1,0:1,1");
  expect_single_error_naming({"polygon=0,0:1,0:1,1"}, "polygon=0,0:1,0:1,1");
  expect_single_error_naming({"--exp"}, "--exp");
  expect_single_error_naming({"--objects"}, "--objects");
  expect_single_error_naming({"--EXP=2"}, "--EXP=2");  // names are case-sensitive (original)
}

TEST(GenHazardsOptions, EveryBadArgumentIsReportedNotJustTheFirst) {
  const CommandLine cli = parse({"--bogus", kBox, "--exp=20", "--objects=x,hazard"});
  EXPECT_EQ(cli.errors.size(), 3u);
}

TEST(GenHazardsOptions, HelpAndVersionAliases_Spec12_1) {
  for (const std::string flag : {"-h", "--help", "-help"}) EXPECT_TRUE(parse({flag}).help) << flag;
  for (const std::string flag : {"-v", "--version", "-version"})
    EXPECT_TRUE(parse({flag}).version) << flag;
  // Help wins even next to a bad argument (main prints it and exits 0).
  EXPECT_TRUE(parse({"--bogus", "--help"}).help);
}

TEST(GenHazardsOptions, RecordedArgumentsKeepOrderAndLeaveOutSeedAndOutput_D30) {
  const CommandLine cli = parse({kBox, "--seed=7", "--objects=5,hazard", "--output=f.txt",
                                 "--objects=10,benign", "--exp=2"});
  ASSERT_TRUE(cli.errors.empty());
  EXPECT_EQ(cli.recorded_args,
            (std::vector<std::string>{kBox, "--objects=5,hazard", "--objects=10,benign", "--exp=2"}));
}

TEST(GenHazardsOptions, HeaderNamesTheProgramAndEndsWithTheSeed_D30) {
  EXPECT_EQ(header_line({kBox, "--objects=5,hazard"}, 7),
            "// gen_hazards " + kBox + " --objects=5,hazard --seed=7");
  EXPECT_EQ(header_line({}, 18446744073709551615ull), "// gen_hazards --seed=18446744073709551615");
}

TEST(GenHazardsOptions, HeaderQuotesArgumentsAShellWouldSplitOrExpand) {
  // Braces with commas would be brace-expanded by bash; blanks would split the word.
  EXPECT_EQ(header_line({"--polygon=pts={0,0:10,0:10,10}"}, 1),
            "// gen_hazards '--polygon=pts={0,0:10,0:10,10}' --seed=1");
  EXPECT_EQ(header_line({"--polygon=0,0 : 10,0 : 10,10"}, 1),
            "// gen_hazards '--polygon=0,0 : 10,0 : 10,10' --seed=1");
  EXPECT_EQ(header_line({"it's"}, 1), "// gen_hazards 'it'\\''s' --seed=1");
}

}  // namespace
}  // namespace gen_hazards
