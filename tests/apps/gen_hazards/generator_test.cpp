// The generator (docs/gen_hazards.md; docs/differences.md D30; the hazard-line validation
// table; docs/gen_hazards.md): properties over many seeds, the formulas, the fallbacks.

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "generator.hpp"
#include "hazard/hazard_field.hpp"
#include "hazard/messages/hazard_line.hpp"
#include "options.hpp"

namespace gen_hazards {
namespace {

const std::string kManualBox = "--polygon=-150,-75:-150,-400:400,-400:400,-75";  // manual 2.3
/// Property tests run this many seeds per scenario.
constexpr std::uint64_t kPropertySeeds = 200;
/// Draws for each distribution test (team rules: 100,000+ trials).
constexpr std::uint64_t kDistributionDraws = 100'000;
/// Tolerance of a rate check, in binomial standard deviations (team rules).
constexpr double kSigmas = 5.0;
/// The documented rounding (docs/gen_hazards.md, "How a field is drawn"): each coordinate moves at
/// most this much.
constexpr double kRoundingLimit_m = 0.5;

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

GeneratorConfig config_of(const std::vector<std::string>& args, std::uint64_t seed) {
  CommandLine cli = parse_command_line(args);
  EXPECT_TRUE(cli.errors.empty()) << joined(cli.errors);
  cli.config.seed = seed;
  return cli.config;
}

std::vector<GeneratedObject> objects_of(const GeneratorConfig& config,
                                        const GeneratorLimits& limits = {}) {
  auto result = generate_objects(config, limits);
  if (!result) {
    ADD_FAILURE() << result.error;
    return {};
  }
  return std::move(*result.value);
}

std::string error_of(const GeneratorConfig& config, const GeneratorLimits& limits = {}) {
  return generate_objects(config, limits).error;
}

// Expects `count` within kSigmas binomial standard deviations of n * p.
void expect_binomial(std::uint64_t count, std::uint64_t n, double p, const std::string& what) {
  const double expected = static_cast<double>(n) * p;
  const double sigma = std::sqrt(static_cast<double>(n) * p * (1.0 - p));
  EXPECT_LE(std::abs(static_cast<double>(count) - expected), kSigmas * sigma)
      << what << ": " << count << " of " << n << ", expected " << expected << " (p " << p << ")";
}

// Everything a generated object must satisfy, whatever the seed (D30, docs/gen_hazards.md, the
// validation table).
void check_object(const GeneratedObject& g, const GeneratorConfig& config, const std::string& ctx) {
  bool inside = false;
  for (const auto& region : config.regions) inside = inside || region.polygon.contains(g.drawn_m);
  EXPECT_TRUE(inside) << ctx << ": drawn point outside every region";
  EXPECT_EQ(g.object.x_m, std::round(g.drawn_m.x)) << ctx;
  EXPECT_EQ(g.object.y_m, std::round(g.drawn_m.y)) << ctx;
  EXPECT_LE(std::abs(g.object.x_m - g.drawn_m.x), kRoundingLimit_m) << ctx;
  EXPECT_LE(std::abs(g.object.y_m - g.drawn_m.y), kRoundingLimit_m) << ctx;
  EXPECT_EQ(g.object.type, config.sets[g.set_index].type) << ctx;
  EXPECT_EQ(g.object.resemblance.has_value(), config.resemblance_exp.has_value()) << ctx;
  EXPECT_EQ(g.object.has_aspect_triple(), config.aspect.has_value()) << ctx;
  // The line the generator prints loads in the sensor with no warning and the same values.
  const std::string line = hazard::format_hazard_line(g.object);
  const hazard::HazardLineParse parsed = hazard::parse_hazard_line(line);
  ASSERT_TRUE(parsed.object.has_value()) << ctx << ": " << line << ": " << parsed.error;
  EXPECT_TRUE(parsed.warnings.empty()) << ctx << ": " << line << ": " << joined(parsed.warnings);
  EXPECT_EQ(parsed.object->x_m, g.object.x_m) << line;
  EXPECT_EQ(parsed.object->y_m, g.object.y_m) << line;
  EXPECT_EQ(parsed.object->label, g.object.label) << line;
  EXPECT_EQ(parsed.object->type, g.object.type) << line;
}

void check_field(const std::vector<std::string>& args, const std::string& name) {
  for (std::uint64_t seed = 0; seed < kPropertySeeds; ++seed) {
    const GeneratorConfig config = config_of(args, seed);
    const std::string ctx = name + " seed " + std::to_string(seed);
    const auto objects = objects_of(config);
    // Exact counts per set, sets in argument order.
    std::vector<std::uint64_t> per_set(config.sets.size(), 0);
    std::size_t previous_set = 0;
    std::set<std::string> labels;
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const auto& g = objects[i];
      ASSERT_LT(g.set_index, config.sets.size());
      EXPECT_GE(g.set_index, previous_set) << ctx;
      previous_set = g.set_index;
      ++per_set[g.set_index];
      // Labels: unique integers below the bound in force when issued.
      EXPECT_TRUE(labels.insert(g.object.label).second) << ctx << ": label " << g.object.label;
      EXPECT_LT(std::stoull(g.object.label), label_bound(i)) << ctx;
      EXPECT_EQ(std::to_string(std::stoull(g.object.label)), g.object.label) << ctx;
      check_object(g, config, ctx + " object " + std::to_string(i));
    }
    for (std::size_t s = 0; s < config.sets.size(); ++s) {
      EXPECT_EQ(per_set[s], config.sets[s].count) << ctx << " set " << s;
    }
    if (::testing::Test::HasFailure()) return;  // one seed's report is enough
  }
}

TEST(GenHazardsGenerator, ManualFieldPropertiesHoldForManySeeds_D30) {
  check_field({kManualBox, "--objects=5,hazard", "--objects=10,benign"}, "manual box");
}

TEST(GenHazardsGenerator, RotatedRegionWithResemblanceAndAspectPropertiesHold) {
  check_field({"--polygon=0,-300:300,0:0,300:-300,0", "--objects=40,benign", "--objects=30,hazard",
               "--exp=3", "--aspect_base=300", "--aspect_range=120", "--aspect_min_base=20",
               "--aspect_min_range=50", "--aspect_max_range=60"},
              "diamond with aspect");
}

TEST(GenHazardsGenerator, SeveralRegionsPropertiesHold) {
  check_field({"--polygon=0,0:100,0:100,100:0,100", "--polygon=50,0:150,0:150,100:50,100",
               "--polygon=pts={5000,5000:5010,5000:5005,5010}", "--objects=120,benign",
               "--objects=7,hazard", "--aspect_max_base=40"},
              "three regions");
}

TEST(GenHazardsGenerator, ObjectsAreUniformOverOverlappingRegions) {
  // A = [0,100]x[0,100], B = [50,150]x[0,100]: the union is three equal thirds (A only,
  // overlap, B only). Without the 1/k acceptance the overlap would get half the objects.
  const auto objects = objects_of(config_of(
      {"--polygon=0,0:100,0:100,100:0,100", "--polygon=50,0:150,0:150,100:50,100",
       "--objects=" + std::to_string(kDistributionDraws) + ",benign"},
      11));
  std::uint64_t a_only = 0, overlap = 0;
  for (const auto& g : objects) {
    if (g.drawn_m.x < 50.0) ++a_only;
    if (g.drawn_m.x >= 50.0 && g.drawn_m.x <= 100.0) ++overlap;
  }
  expect_binomial(a_only, kDistributionDraws, 1.0 / 3.0, "A only");
  expect_binomial(overlap, kDistributionDraws, 1.0 / 3.0, "overlap");
}

TEST(GenHazardsGenerator, ObjectsSplitBetweenDisjointRegionsByArea) {
  // 10 x 10 near the origin and 20 x 10 ten kilometres away: a third of the objects in the first.
  const auto objects = objects_of(config_of(
      {"--polygon=0,0:10,0:10,10:0,10", "--polygon=10000,0:10020,0:10020,10:10000,10",
       "--objects=" + std::to_string(kDistributionDraws) + ",hazard"},
      12));
  std::uint64_t near = 0;
  for (const auto& g : objects) near += g.drawn_m.x <= 10.0 ? 1 : 0;
  expect_binomial(near, kDistributionDraws, 1.0 / 3.0, "near region");
}

TEST(GenHazardsGenerator, PositionsAreUniformInsideOneRegion) {
  // Left half of the manual's box (x < 125) holds half the area.
  const auto objects = objects_of(
      config_of({kManualBox, "--objects=" + std::to_string(kDistributionDraws) + ",hazard"}, 13));
  std::uint64_t left = 0;
  for (const auto& g : objects) left += g.drawn_m.x < 125.0 ? 1 : 0;
  expect_binomial(left, kDistributionDraws, 0.5, "left half");
}

// P(hr <= t) for hr = q^e, q = k/1000, k uniform in [0, 999]: P(k <= 1000 t^(1/e)) (manual 6.3).
double resemblance_cdf(double t, double exp) {
  const double limit = 1000.0 * std::pow(t, 1.0 / exp);
  // Thresholds are chosen away from grid steps k >= 1, so rounding in pow cannot flip one
  // (k = 0 gives hr = 0, below every threshold).
  if (std::round(limit) >= 1.0) {
    EXPECT_GT(std::abs(limit - std::round(limit)), 1e-6) << "t " << t << " exp " << exp;
  }
  return std::min(1.0, (std::floor(limit) + 1.0) / 1000.0);
}

TEST(GenHazardsGenerator, ResemblanceFollowsPowerOfUniformGridStep_Manual6_3) {
  const std::vector<double> thresholds = {0.0015, 0.0505, 0.2501, 0.5001, 0.9001, 0.9905, 0.9995};
  for (const double exp : {0.01, 1.0, 4.0, 10.0}) {
    std::ostringstream exp_text;
    exp_text << exp;
    const auto objects = objects_of(config_of(
        {kManualBox, "--objects=" + std::to_string(kDistributionDraws) + ",benign",
         "--exp=" + exp_text.str()},
        static_cast<std::uint64_t>(exp * 100)));
    ASSERT_EQ(objects.size(), kDistributionDraws);
    for (const double t : thresholds) {
      std::uint64_t at_most = 0;
      for (const auto& g : objects) at_most += *g.object.resemblance <= t ? 1 : 0;
      expect_binomial(at_most, kDistributionDraws, resemblance_cdf(t, exp),
                      "exp " + exp_text.str() + " t " + std::to_string(t));
    }
  }
}

TEST(GenHazardsGenerator, ResemblanceIsThePowerOfTheStep_Manual6_3) {
  EXPECT_EQ(resemblance(0, 1.0), 0.0);
  EXPECT_EQ(resemblance(500, 1.0), 0.5);
  EXPECT_EQ(resemblance(500, 2.0), 0.25);
  EXPECT_DOUBLE_EQ(resemblance(999, 10.0), std::pow(0.999, 10.0));
  EXPECT_NEAR(resemblance(1, 0.01), 0.933254, 1e-6);  // 0.001^0.01
}

TEST(GenHazardsGenerator, ResemblanceIsWrittenForBenignObjectsOnly_Spec4_4) {
  const auto text = build_hazard_file(
      "// h", config_of({kManualBox, "--objects=3,hazard", "--objects=3,benign", "--exp=1"}, 5));
  ASSERT_TRUE(text) << text.error;
  std::istringstream lines(*text.value);
  std::string line;
  int hazards = 0, benign = 0;
  while (std::getline(lines, line)) {
    if (line.find("type=hazard") != std::string::npos) {
      ++hazards;
      EXPECT_EQ(line.find(",hr="), std::string::npos) << line;
    } else if (line.find("type=benign") != std::string::npos) {
      ++benign;
      EXPECT_NE(line.find(",hr="), std::string::npos) << line;
    }
  }
  EXPECT_EQ(hazards, 3);
  EXPECT_EQ(benign, 3);
}

TEST(GenHazardsGenerator, LabelBoundGrowsTenfoldWithLabelsIssued_Spec12_3) {
  EXPECT_EQ(label_bound(0), 100u);
  EXPECT_EQ(label_bound(99), 100u);
  EXPECT_EQ(label_bound(100), 1000u);
  EXPECT_EQ(label_bound(999), 1000u);
  EXPECT_EQ(label_bound(1000), 10000u);
  EXPECT_EQ(label_bound(99999), 100000u);
  // The original stopped at 100000 (and then wrote label_error); we keep growing.
  EXPECT_EQ(label_bound(100000), 1000000u);
  EXPECT_GT(label_bound(18446744073709551615ull), 0u);  // no overflow, no endless loop
}

TEST(GenHazardsGenerator, HundredObjectsUseEveryLabelBelowHundredOnce) {
  // The bound stays 100 until 100 labels are issued, so the last labels are drawn from an
  // almost full pool: uniqueness must still hold (the original could write label_error).
  std::set<std::string> expected;
  for (int i = 0; i < 100; ++i) expected.insert(std::to_string(i));
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    std::set<std::string> labels;
    for (const auto& g : objects_of(config_of({kManualBox, "--objects=60,hazard", "--objects=40,benign"}, seed)))
      labels.insert(g.object.label);
    EXPECT_EQ(labels, expected) << "seed " << seed;
  }
}

TEST(GenHazardsGenerator, LabelFallbackTakesTheSmallestFreeLabel) {
  GeneratorLimits no_draws;
  no_draws.max_label_draws = 0;  // every label comes from the fallback
  const auto objects = objects_of(config_of({kManualBox, "--objects=150,benign"}, 3), no_draws);
  ASSERT_EQ(objects.size(), 150u);
  for (std::size_t i = 0; i < objects.size(); ++i) EXPECT_EQ(objects[i].object.label, std::to_string(i));

  GeneratorLimits one_draw;
  one_draw.max_label_draws = 1;  // collisions fall back at once
  std::set<std::string> labels;
  for (const auto& g : objects_of(config_of({kManualBox, "--objects=1000,benign"}, 3), one_draw))
    EXPECT_TRUE(labels.insert(g.object.label).second) << g.object.label;
  EXPECT_EQ(labels.size(), 1000u);
}

TEST(GenHazardsGenerator, SameSeedGivesTheSameFieldAndOtherSeedsDiffer) {
  const std::vector<std::string> args = {kManualBox, "--objects=20,benign", "--exp=2",
                                         "--aspect_min_range=20"};
  const auto a = *build_hazard_file("// h", config_of(args, 99)).value;
  const auto b = *build_hazard_file("// h", config_of(args, 99)).value;
  const auto c = *build_hazard_file("// h", config_of(args, 100)).value;
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(GenHazardsGenerator, ResemblanceAndAspectOptionsMoveNoObject) {
  // Each purpose has its own random stream (generator.hpp contract).
  const auto plain = objects_of(config_of({kManualBox, "--objects=30,benign"}, 8));
  const auto rich = objects_of(config_of(
      {kManualBox, "--objects=30,benign", "--exp=4", "--aspect_range=90"}, 8));
  ASSERT_EQ(plain.size(), rich.size());
  for (std::size_t i = 0; i < plain.size(); ++i) {
    EXPECT_EQ(plain[i].drawn_m, rich[i].drawn_m);
    EXPECT_EQ(plain[i].object.label, rich[i].object.label);
  }
}

TEST(GenHazardsGenerator, AspectDefaultsGiveWindowFifteenFifteen_Spec12_3) {
  for (const auto& g : objects_of(config_of({kManualBox, "--objects=50,benign", "--aspect_base=0"}, 4))) {
    EXPECT_GE(*g.object.aspect_deg, 0.0);
    EXPECT_LT(*g.object.aspect_deg, 360.0);
    EXPECT_EQ(*g.object.aspect_min_deg, 15.0);
    EXPECT_EQ(*g.object.aspect_max_deg, 15.0);
  }
}

TEST(GenHazardsGenerator, AspectIsDrawnFromBasePlusRangeModulo360InTenths) {
  const auto objects = objects_of(config_of(
      {kManualBox, "--objects=500,benign", "--aspect_base=350", "--aspect_range=20"}, 6));
  bool wrapped = false;
  for (const auto& g : objects) {
    const double a = *g.object.aspect_deg;
    EXPECT_TRUE(a >= 350.0 || a <= 10.0) << a;
    EXPECT_EQ(a, std::round(a * 10.0) / 10.0) << a;
    wrapped = wrapped || a < 10.0;
  }
  EXPECT_TRUE(wrapped);  // about half the draws pass 360
}

TEST(GenHazardsGenerator, AspectThatRoundsTo360BecomesZero_N16) {
  // The original dropped the aspect when snapping made it 360.0.
  for (const auto& g : objects_of(config_of(
           {kManualBox, "--objects=20,hazard", "--aspect_base=359.99", "--aspect_range=0"}, 2))) {
    ASSERT_TRUE(g.object.aspect_deg.has_value());
    EXPECT_EQ(*g.object.aspect_deg, 0.0);
  }
}

TEST(GenHazardsGenerator, AspectMaxBaseRaisesAspectMaxButNeverBelowAspectMin) {
  for (const auto& g : objects_of(config_of({kManualBox, "--objects=20,hazard", "--aspect_max_base=40"}, 2))) {
    EXPECT_EQ(*g.object.aspect_min_deg, 15.0);
    EXPECT_EQ(*g.object.aspect_max_deg, 40.0);
  }
  for (const auto& g : objects_of(config_of(
           {kManualBox, "--objects=20,hazard", "--aspect_min_base=30", "--aspect_max_base=10"}, 2))) {
    EXPECT_EQ(*g.object.aspect_min_deg, 30.0);
    EXPECT_EQ(*g.object.aspect_max_deg, 30.0);
  }
}

TEST(GenHazardsGenerator, AspectMaxWithoutItsBaseAddsItsRangeToAspectMin_Spec12_3) {
  // The original's rule, kept when --aspect_max_base is not given: max in [min, min + range].
  for (const auto& g : objects_of(config_of(
           {kManualBox, "--objects=200,hazard", "--aspect_min_base=5", "--aspect_min_range=20",
            "--aspect_max_range=10"},
           2))) {
    const double lo = *g.object.aspect_min_deg, hi = *g.object.aspect_max_deg;
    EXPECT_GE(lo, 5.0);
    EXPECT_LE(lo, 25.0);
    EXPECT_GE(hi, lo);
    EXPECT_LE(hi, lo + 10.0 + 1e-9);
  }
}

TEST(GenHazardsGenerator, AspectWindowsOverNinetyAreResolvedNotPrinted) {
  // min in [40, 90], max in [min, 90]: most draws break min + max <= 90; every written triple
  // must still load (the original printed `Illegal aspect range` into the file instead).
  const auto objects = objects_of(config_of(
      {kManualBox, "--objects=300,benign", "--aspect_min_base=40", "--aspect_min_range=50",
       "--aspect_max_range=90"},
      21));
  for (const auto& g : objects) {
    const double lo = *g.object.aspect_min_deg, hi = *g.object.aspect_max_deg;
    EXPECT_LE(lo, hi);
    EXPECT_LE(lo + hi, 90.0);
    EXPECT_GE(lo, 0.0);
  }
}

TEST(GenHazardsGenerator, ResolveAspectWindowLowersBothByHalfTheExcess) {
  using W = AspectWindowTenths;
  auto same = [](W a, W b) { return a.min_tenths == b.min_tenths && a.max_tenths == b.max_tenths; };
  EXPECT_TRUE(same(resolve_aspect_window({150, 150}), {150, 150}));
  EXPECT_TRUE(same(resolve_aspect_window({300, 600}), {300, 600}));  // sum exactly 90 deg
  EXPECT_TRUE(same(resolve_aspect_window({600, 700}), {400, 500}));
  EXPECT_TRUE(same(resolve_aspect_window({100, 801}), {100, 800}));  // odd tenth off max
  EXPECT_TRUE(same(resolve_aspect_window({451, 452}), {450, 450}));
  EXPECT_TRUE(same(resolve_aspect_window({900, 900}), {450, 450}));
  // Every valid input (0 <= min <= max <= 900) gives a window the sensor accepts.
  for (int lo = 0; lo <= 900; ++lo) {
    for (int hi = lo; hi <= 900; ++hi) {
      const W r = resolve_aspect_window({lo, hi});
      ASSERT_GE(r.min_tenths, 0);
      ASSERT_LE(r.min_tenths, r.max_tenths) << lo << " " << hi;
      ASSERT_LE(r.min_tenths + r.max_tenths, 900) << lo << " " << hi;
      ASSERT_LE(std::abs((r.max_tenths - r.min_tenths) - (hi - lo)), 1) << lo << " " << hi;
    }
  }
}

TEST(GenHazardsGenerator, ThinPolygonIsRejectedNamingIt_Spec12_4) {
  const std::string thin = "--polygon=0,0:1000,1000.01:0,0.01";
  const std::string message = error_of(config_of({thin, "--objects=1,hazard"}, 1));
  EXPECT_NE(message.find("'" + thin + "'"), std::string::npos) << message;
  EXPECT_NE(message.find("too thin"), std::string::npos) << message;
  // Without objects to place the region is only written, not sampled.
  EXPECT_EQ(error_of(config_of({thin, "--objects=0,hazard"}, 1)), "");
}

TEST(GenHazardsGenerator, PlacementGivesUpAfterItsAttemptLimit) {
  GeneratorLimits none;
  none.max_attempts = 0;
  const std::string tri = "--polygon=0,0:100,0:0,100";
  std::string message = error_of(config_of({tri, "--objects=3,benign"}, 1), none);
  EXPECT_NE(message.find("'" + tri + "'"), std::string::npos) << message;
  EXPECT_NE(message.find("'--objects=3,benign'"), std::string::npos) << message;

  GeneratorLimits one;
  one.max_attempts = 1;  // a triangle fills half its box: 100 objects cannot all succeed
  message = error_of(config_of({tri, "--objects=100,benign"}, 1), one);
  EXPECT_NE(message.find("could not place object"), std::string::npos) << message;
}

TEST(GenHazardsGenerator, FileHasHeaderOneRegionLinePerPolygonThenObjects_D30) {
  const auto text = build_hazard_file(
      "// gen_hazards x --seed=3",
      config_of({"--polygon=0,0:100,0:100,100", "--polygon=pts={12.34,0:20,0:20,7.96}",
                 "--objects=2,hazard", "--objects=1,benign"},
                3));
  ASSERT_TRUE(text) << text.error;
  std::istringstream in(*text.value);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "// gen_hazards x --seed=3");
  EXPECT_EQ(lines[1], "region = pts={0,0:100,0:100,100}");
  EXPECT_EQ(lines[2], "region = pts={12.3,0:20,0:20,8}");  // FMT(.,1)
  for (std::size_t i = 3; i < 6; ++i) EXPECT_EQ(lines[i].rfind("hazard = x=", 0), 0u) << lines[i];
  EXPECT_NE(lines[3].find("type=hazard"), std::string::npos);
  EXPECT_NE(lines[5].find("type=benign"), std::string::npos);

  // The whole file loads in the sensor with no warning.
  hazard::HazardField field;
  std::vector<std::string> warnings;
  const auto counts = hazard::load_hazard_file_text(*text.value, "f", field, warnings);
  EXPECT_TRUE(warnings.empty()) << joined(warnings);
  EXPECT_EQ(counts.hazards, 2);
  EXPECT_EQ(counts.benign, 1);
}

TEST(GenHazardsGenerator, NoObjectsGivesHeaderAndRegionsOnly_Spec12_4) {
  const auto text = build_hazard_file("// h", config_of({kManualBox}, 1));
  ASSERT_TRUE(text) << text.error;
  EXPECT_EQ(*text.value, "// h\nregion = pts={-150,-75:-150,-400:400,-400:400,-75}\n");
  EXPECT_EQ(*build_hazard_file("// h", config_of({}, 1)).value, "// h\n");
}

}  // namespace
}  // namespace gen_hazards
