// The validation scene of bench/validation/pass_scene: where the objects are, the lanes, the
// passes each object gets and the result file.
#include "pass_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

namespace {

TEST(PassScene, PlacesEveryKindEquallyInEveryGroup) {
  const auto objects = validation::make_scene({});
  std::map<std::string, int> count;
  std::set<std::string> labels;
  for (const auto& o : objects) {
    ++count[o.group + "," + o.kind];
    labels.insert(o.label);
  }
  EXPECT_EQ(labels.size(), objects.size());
  for (const char* kind : {"H", "B", "B0", "Bh"}) {
    EXPECT_EQ(count[std::string("inside,") + kind], 200) << kind;
    EXPECT_EQ(count[std::string("outside,") + kind], 100) << kind;
  }
  for (const char* group : {"edge_3", "edge_7", "edge_12"}) {
    EXPECT_EQ(count[std::string(group) + ",H"], 6) << group;
  }
}

TEST(PassScene, KeepsInsideRowsWellWithinAndOutsideRowsWellBeyondTheSwathWidth) {
  for (const auto& o : validation::make_scene({})) {
    if (o.group == "inside") {
      EXPECT_LE(std::fabs(o.y_m), 17) << o.label;
    }
    if (o.group == "outside") {
      EXPECT_GE(std::fabs(o.y_m), 33) << o.label;
    }
  }
}

TEST(PassScene, PutsEdgeObjectsTheirDistanceBeyondTheLaneEnds) {
  const validation::SceneSpec spec;  // columns at 0..396, lane ends at -40 and 436
  for (const auto& o : validation::make_scene(spec)) {
    if (o.group != "edge_7") continue;
    EXPECT_TRUE(o.x_m == -47 || o.x_m == 443) << o.x_m;
  }
}

TEST(PassScene, DrivesEastThenWestTurningOnTheSpot) {
  const validation::SceneSpec spec;
  EXPECT_DOUBLE_EQ(validation::lane_length_m(spec), 476);
  auto p = validation::pose_at(spec, 0);
  EXPECT_DOUBLE_EQ(p.x_m, -40);
  EXPECT_DOUBLE_EQ(p.heading_deg, 90);
  EXPECT_EQ(p.lane, 0);
  p = validation::pose_at(spec, 476 + 10);
  EXPECT_DOUBLE_EQ(p.x_m, 426);
  EXPECT_DOUBLE_EQ(p.heading_deg, 270);
  EXPECT_EQ(p.lane, 1);
  EXPECT_DOUBLE_EQ(p.y_m, 0);
}

TEST(PassScene, CountsTheVisitsOfEachLaneEndWithTheStart) {
  validation::SceneObject west{"a", "H", "edge_3", -43, 0};
  validation::SceneObject east{"b", "H", "edge_3", 439, 0};
  validation::SceneObject row{"c", "B", "inside", 8, 2};
  EXPECT_EQ(validation::passes_by(west, 4), 3);  // start, end of lanes 1 and 3
  EXPECT_EQ(validation::passes_by(east, 4), 2);  // end of lanes 0 and 2
  EXPECT_EQ(validation::passes_by(east, 5), 3);
  EXPECT_EQ(validation::passes_by(row, 4), 4);
}

TEST(PassScene, WritesTheHazardFileWithTheResemblances) {
  const std::vector<validation::SceneObject> objects = {{"o1", "H", "inside", 0, -17},
                                                        {"o2", "B0", "inside", 4, -17},
                                                        {"o3", "Bh", "inside", 8, 2.5}};
  const auto text = validation::hazard_file_text(objects, 0.5);
  EXPECT_NE(text.find("hazard = x=0,y=-17,label=o1,type=hazard\n"), std::string::npos);
  EXPECT_NE(text.find("hazard = x=4,y=-17,label=o2,type=benign,hr=0\n"), std::string::npos);
  EXPECT_NE(text.find("hazard = x=8,y=2.5,label=o3,type=benign,hr=0.5\n"), std::string::npos);
}

TEST(PassScene, WritesTalliesAfterTheHeader) {
  validation::Tallies tallies;
  tallies["inside,H"] = {200, 800, 640, 640, 640, 512};
  const auto text = validation::tallies_csv({{"seed", "1"}}, tallies);
  EXPECT_EQ(text,
            "# seed=1\n"
            "group,kind,objects,passes,detections,classify_requests,answers,correct\n"
            "inside,H,200,800,640,640,640,512\n");
}

}  // namespace
