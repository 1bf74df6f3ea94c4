// Hazard files and the field (differences.md "Hazard lines"; docs/hazard-file.md) and the spatial
// grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "base/warning_budget.hpp"
#include "hazard/hazard_field.hpp"
#include "hazard/swath.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {


TEST(HazardFile, ManualFileLoadsAndSkipsHeaderRegionSourceAndBlanks) {
  const std::string text =
      "// gen_hazards --polygon=-150,-75:-150,-400:400,-400:400,-75 --objects=5,hazard\n"
      "source = jake survey\n"
      "region = pts={-150,-75:-150,-400:400,-400:400,-75}\n"
      "\n"
      "hazard = x=-52,y=-290,label=75,type=hazard\n"
      "hazard = x=41,y=-108,label=53,type=hazard   // comment after a line\n"
      "hazard = x=-41,y=-246,label=82,type=benign,hr=0.73\r\n";
  HazardField field;
  std::vector<std::string> warnings;
  const auto counts = load_hazard_file_text(text, "hazards.txt", field, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings[0];
  EXPECT_EQ(counts.hazards, 2);
  EXPECT_EQ(counts.benign, 1);
  EXPECT_EQ(field.size(), 3u);
  EXPECT_EQ(field.hazard_count(), 2);
  EXPECT_EQ(field.benign_count(), 1);
  ASSERT_TRUE(field.find("82"));
  EXPECT_EQ(field.object(*field.find("82")).resemblance, 0.73);
  EXPECT_EQ(field.object(*field.find("53")).type, ObjectType::kHazard);  // comment stripped
}

TEST(HazardFile, DuplicateLabelKeepsFirstAndNamesLine_T8) {
  const std::string text =
      "hazard = x=1,y=1,label=12,type=hazard\n"
      "hazard = x=2,y=2,label=12,type=benign\n";
  HazardField field;
  std::vector<std::string> warnings;
  load_hazard_file_text(text, "h.txt", field, warnings);
  ASSERT_EQ(field.size(), 1u);
  EXPECT_EQ(field.object(0).x_m, 1);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].substr(0, 8), "h.txt:2:");
  EXPECT_NE(warnings[0].find("duplicate label '12'"), std::string::npos);
}

// A file of many bad lines keeps the first kMaxWarningsPerKind warnings, in file order, then one
// line counting the rest; the good lines among them still load.
TEST(HazardFile, WarningsOfOneFileStopAtTheBoundAndTheRestAreCounted) {
  std::string text;
  for (int i = 0; i < 500; ++i) text += "bogus line " + std::to_string(i) + "\n";
  text += "hazard = x=0,y=0,label=a,type=hazard\n";
  HazardField field;
  std::vector<std::string> warnings{"an earlier file's warning"};
  load_hazard_file_text(text, "h.txt", field, warnings);
  EXPECT_EQ(field.size(), 1u);
  ASSERT_EQ(warnings.size(), 1 + base::kMaxWarningsPerKind + 1);
  EXPECT_EQ(warnings[1].substr(0, 8), "h.txt:1:");
  EXPECT_EQ(warnings[base::kMaxWarningsPerKind].substr(0, 10), "h.txt:100:");
  EXPECT_EQ(warnings.back(), "h.txt: ... and 400 more warnings");
}

// The bad-input file: each bad line warns with file and line; every good line loads.
TEST(HazardFile, BadLinesWarnWithFileAndLineAndGoodLinesLoad) {
  const std::string text =
      "hazard = x=0,y=0,label=a,type=hazard\n"                         // 1 good
      "hazard = x=1,y=1,label=a,type=benign\n"                         // 2 duplicate
      "hazard = x=2,y=2,type=benign\n"                                 // 3 missing label
      "hazard = x=three,y=3,label=c,type=benign\n"                     // 4 non-number
      "hazard = x=4,y=4,label=d,type=benign,hr=2\n"                    // 5 hr out of range
      "hazard = x=5,y=5,label=e,type=benign,aspect=400\n"              // 6 aspect out of range
      "hazard = x=6,y=6,label=f,type=benign,colour=red\n"              // 7 unknown key (loads)
      "hazard = x=7,y=7,label=g,type=benign\n"                         // 8 good
      "hazzard = x=8,y=8,label=h,type=benign\n";                       // 9 unrecognised line
  HazardField field;
  std::vector<std::string> warnings;
  const auto counts = load_hazard_file_text(text, "bad.txt", field, warnings);
  EXPECT_EQ(field.size(), 3u);  // a, f, g
  EXPECT_TRUE(field.find("a") && field.find("f") && field.find("g"));
  EXPECT_EQ(counts.rejected_lines, 5);
  ASSERT_EQ(warnings.size(), 7u);
  EXPECT_NE(warnings[0].find("bad.txt:2: duplicate label 'a'"), std::string::npos);
  EXPECT_NE(warnings[1].find("bad.txt:3: missing field 'label'"), std::string::npos);
  EXPECT_NE(warnings[2].find("bad.txt:4: field 'x' value 'three' is not a number"),
            std::string::npos);
  EXPECT_NE(warnings[3].find("bad.txt:5: field 'hr' value '2' is outside [0, 1]"),
            std::string::npos);
  EXPECT_NE(warnings[4].find("bad.txt:6: field 'aspect' value '400' is outside [0, 360)"),
            std::string::npos);
  EXPECT_NE(warnings[5].find("bad.txt:7: unknown key 'colour' (value 'red') ignored"),
            std::string::npos);
  EXPECT_NE(warnings[6].find("bad.txt:9: unrecognised line"), std::string::npos);
  for (int i = 1; i <= 4; ++i) EXPECT_NE(warnings[i].find("line rejected"), std::string::npos);
}

TEST(HazardFile, EmptyTextIsAnEmptyField) {
  HazardField field;
  std::vector<std::string> warnings;
  const auto counts = load_hazard_file_text("", "empty.txt", field, warnings);
  EXPECT_EQ(field.size(), 0u);
  EXPECT_EQ(counts.hazards + counts.benign + counts.rejected_lines, 0);
  EXPECT_TRUE(warnings.empty());
}

TEST(HazardField, IdsAreLoadOrderAndLabelsHashStably) {
  HazardField field;
  HazardObject a;
  a.label = "zeta";
  HazardObject b;
  b.label = "alpha";
  ASSERT_TRUE(field.add(a));
  ASSERT_TRUE(field.add(b));
  EXPECT_FALSE(field.add(a));
  EXPECT_EQ(field.find("zeta"), 0u);
  EXPECT_EQ(field.find("alpha"), 1u);
  EXPECT_FALSE(field.find("beta"));
  EXPECT_NE(field.label_hash(0), field.label_hash(1));
}

// The grid must return every point inside a query box (and only points near it).
TEST(SpatialGrid, BoxQueriesMatchBruteForce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-500.0, 500.0);
  std::vector<glm::dvec2> points(5000);
  for (auto& p : points) p = {coord(rng), coord(rng)};
  points.push_back({2000.0, 2000.0});  // an outlier stretches the grid
  const SpatialGrid grid(points);
  for (int q = 0; q < 200; ++q) {
    const double x = coord(rng), y = coord(rng), w = coord(rng) / 10 + 60, h = coord(rng) / 10 + 60;
    const Box box{x - w, y - h, x + w, y + h};
    std::vector<std::uint32_t> got, want;
    grid.for_each_in_box(box, [&](std::uint32_t id, glm::dvec2 p) {
      EXPECT_EQ(p, points[id]);
      if (p.x >= box.min_x && p.x <= box.max_x && p.y >= box.min_y && p.y <= box.max_y) {
        got.push_back(id);
      }
    });
    for (std::uint32_t i = 0; i < points.size(); ++i) {
      const auto& p = points[i];
      if (p.x >= box.min_x && p.x <= box.max_x && p.y >= box.min_y && p.y <= box.max_y) {
        want.push_back(i);
      }
    }
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);
  }
}

TEST(SpatialGrid, QueryTouchesOnlyNearbyCells) {
  std::vector<glm::dvec2> points;
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) points.push_back({i * 10.0, j * 10.0});
  }
  const SpatialGrid grid(points);
  int visited = 0;
  grid.for_each_in_box(Box{495, 495, 515, 515}, [&](std::uint32_t, glm::dvec2) { ++visited; });
  EXPECT_LE(visited, 40);  // 4 points inside, a ring of cells around them, never the field
  EXPECT_GE(visited, 4);
  int outside = 0;
  grid.for_each_in_box(Box{5000, 5000, 6000, 6000}, [&](std::uint32_t, glm::dvec2) { ++outside; });
  EXPECT_EQ(outside, 0);
}

TEST(SpatialGrid, DegenerateFieldsWork) {
  const SpatialGrid one_point(std::vector<glm::dvec2>(3, glm::dvec2{5, 5}));
  int n = 0;
  one_point.for_each_in_box(Box{4, 4, 6, 6}, [&](std::uint32_t, glm::dvec2) { ++n; });
  EXPECT_EQ(n, 3);
  std::vector<glm::dvec2> line;
  for (int i = 0; i < 1000; ++i) line.push_back({i * 1.0, 0.0});
  const SpatialGrid thin(line);
  n = 0;
  thin.for_each_in_box(Box{10, -1, 12, 1}, [&](std::uint32_t, glm::dvec2 p) {
    if (p.x >= 10 && p.x <= 12) ++n;
  });
  EXPECT_EQ(n, 3);
  const SpatialGrid empty{std::vector<glm::dvec2>{}};
  empty.for_each_in_box(Box{0, 0, 1, 1}, [&](std::uint32_t, glm::dvec2) { ADD_FAILURE(); });
}

// A known crash: two finite positions whose distance exceeds the largest double (the field's extent
// overflowed to infinity, the cell counts became NaN and their cast to int aborted start-up).
TEST(SpatialGrid, FieldWiderThanTheLargestDoubleIsIndexed) {
  const std::vector<glm::dvec2> far{{9e307, 0}, {-9e307, 0}, {0, 9e307}, {0, -9e307}, {1, 1}};
  const SpatialGrid grid(far);
  EXPECT_GE(grid.cells_x(), 1);
  EXPECT_LE(grid.cells_x(), SpatialGrid::kMaxCellsPerAxis);
  EXPECT_GE(grid.cells_y(), 1);
  EXPECT_LE(grid.cells_y(), SpatialGrid::kMaxCellsPerAxis);
  EXPECT_TRUE(std::isfinite(grid.cell_size_m()));
  for (std::uint32_t id = 0; id < far.size(); ++id) {
    const glm::dvec2 p = far[id];
    int hits = 0;
    grid.for_each_in_box(Box{p.x - 1, p.y - 1, p.x + 1, p.y + 1},
                         [&](std::uint32_t found, glm::dvec2) { hits += found == id; });
    EXPECT_EQ(hits, 1) << "object " << id;
  }
}

// The crash (std::length_error at start-up): objects at x = +-9e307. Such positions are
// now refused at the line (kMaxObjectCoordinate_m), and the grid itself indexes a field wider
// than the largest double (SpatialGrid.FieldWiderThanTheLargestDoubleIsIndexed), so neither
// layer alone can crash.
TEST(HazardFile, ObjectsAtOppositeEndsOfTheDoubleRangeAreRefusedWithoutACrash_Hardening) {
  HazardField field;
  std::vector<std::string> warnings;
  load_hazard_file_text("hazard = x=9e307,y=0,label=a,type=hazard\n"
                        "hazard = x=-9e307,y=0,label=b,type=benign\n"
                        "hazard = x=10,y=0,label=c,type=hazard\n",
                        "far.txt", field, warnings);
  ASSERT_EQ(field.size(), 1u);
  EXPECT_EQ(warnings.size(), 2u);
  for (const std::string& w : warnings) EXPECT_NE(w.find("far.txt:"), std::string::npos) << w;
  field.build_index();
  int found = 0;
  field.grid().for_each_in_box(Box{-1e308, -1, 1e308, 1},
                               [&](std::uint32_t, glm::dvec2) { ++found; });
  EXPECT_EQ(found, 1);
}

}  // namespace
}  // namespace hazard

namespace hazard {
namespace {

// The compact tables give back every field of every object as it was added.
TEST(HazardField, TablesGiveBackEachObjectAsAdded) {
  HazardField field;
  std::vector<HazardObject> added(3);
  added[0].label = "plain";
  added[0].x_m = -3.5;
  added[1].label = "styled";
  added[1].type = ObjectType::kHazard;
  added[1].color = "a_colour_name_longer_than_fifteen";
  added[1].shape = "circle";
  added[1].marker_width_m = 4.0;
  added[1].source = "survey";
  added[2].label = "aspect";
  added[2].y_m = 7.25;
  added[2].resemblance = 0.0;
  added[2].aspect_deg = 30.0;
  added[2].aspect_min_deg = 10.0;
  for (const HazardObject& o : added) ASSERT_TRUE(field.add(o));
  field.build_index();
  for (ObjectId id = 0; id < field.size(); ++id) {
    const HazardObject o = field.object(id);
    const HazardObject& a = added[id];
    EXPECT_EQ(o.label, a.label);
    EXPECT_EQ(field.label(id), a.label);
    EXPECT_EQ(o.x_m, a.x_m);
    EXPECT_EQ(o.y_m, a.y_m);
    EXPECT_EQ(o.type, a.type);
    EXPECT_EQ(o.resemblance, a.resemblance);
    EXPECT_EQ(o.aspect_deg, a.aspect_deg);
    EXPECT_EQ(o.aspect_min_deg, a.aspect_min_deg);
    EXPECT_EQ(o.aspect_max_deg, a.aspect_max_deg);
    EXPECT_EQ(o.color, a.color);
    EXPECT_EQ(o.shape, a.shape);
    EXPECT_EQ(o.marker_width_m, a.marker_width_m);
    EXPECT_EQ(o.source, a.source);
    EXPECT_EQ(field.has_aspect_triple(id), a.has_aspect_triple());
    EXPECT_EQ(field.find(a.label), id);
  }
  EXPECT_EQ(field.hazard_count(), 1);
}

// The label lookup stays exact while it grows past many rehashes.
TEST(HazardField, LabelLookupSurvivesGrowth) {
  HazardField field;
  for (int i = 0; i < 50000; ++i) {
    HazardObject o;
    o.label = "n" + std::to_string(i);
    ASSERT_TRUE(field.add(o));
  }
  for (int i = 0; i < 50000; i += 97) EXPECT_EQ(field.find("n" + std::to_string(i)), ObjectId(i));
  EXPECT_FALSE(field.find("n50000"));
  HazardObject dup;
  dup.label = "n123";
  EXPECT_FALSE(field.add(dup));
  EXPECT_EQ(field.size(), 50000u);
  EXPECT_GT(field.memory_bytes(), 0u);
}

}  // namespace
}  // namespace hazard
