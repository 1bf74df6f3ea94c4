// The field's visuals in bounded batches: a big field's markers arrive over several
// iterations, none above kFieldVisualsPerIteration objects, in load order, the same every run;
// PMV_CONNECT and Driver::restart_field_visuals start them again from the first object.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hazard/driver.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::quiet_block;
using testing::setup_from;
using testing::values_of;

constexpr int kObjects = 100000;

// A field of `objects` on a 10 m lattice; every tenth object has an aspect (two postings).
std::string lattice_field(int objects) {
  std::string text = "show_hazards = true\n";
  for (int i = 0; i < objects; ++i) {
    text += "hazard = x=" + std::to_string((i % 300) * 10) +
            ",y=" + std::to_string((i / 300) * 10) + ",label=o" + std::to_string(i) + (i % 2 ? ",type=hazard" : ",type=benign") +
            (i % 10 == 0 ? ",aspect=30,aspect_min=10,aspect_max=20" : "") + "\n";
  }
  return text;
}

// The label of a VIEW_MARKER value ("...,label=L,...").
std::string marker_label(const std::string& value) {
  const auto at = value.find("label=");
  return value.substr(at + 6, value.find(',', at) - at - 6);
}

struct Batches {
  std::vector<std::string> labels;  ///< every marker's label, in arrival order
  std::vector<std::size_t> markers_per_call;
  std::vector<std::string> values;  ///< every visual posting, in order
};

void collect(const Outputs& out, Batches& b) {
  const std::vector<std::string> markers = values_of(out, "VIEW_MARKER");
  b.markers_per_call.push_back(markers.size());
  for (const std::string& m : markers) b.labels.push_back(marker_label(m));
  for (const Posting& p : out.postings)
    if (p.variable == "VIEW_MARKER" || p.variable == "VIEW_SEGLIST") b.values.push_back(p.value);
}

Batches run_start_up(Driver& d, int iterations) {
  Batches b;
  collect(d.start(0.0).outputs, b);
  for (int i = 1; i <= iterations; ++i) collect(d.step(i * 0.25).outputs, b);
  return b;
}

Driver big_field_driver() {
  return Driver(setup_from(quiet_block(lattice_field(kObjects))),
                SeedChoice{1, SeedSource::kCommandLine});
}

TEST(FieldVisuals, ABigFieldsMarkersArriveInBoundedBatchesInLoadOrder) {
  Driver d = big_field_driver();
  const std::size_t calls = kObjects / kFieldVisualsPerIteration;  // start() + calls - 1 steps
  const Batches b = run_start_up(d, static_cast<int>(calls) + 3);
  ASSERT_EQ(b.labels.size(), static_cast<std::size_t>(kObjects));
  for (int i = 0; i < kObjects; ++i) ASSERT_EQ(b.labels[i], "o" + std::to_string(i));
  for (std::size_t n : b.markers_per_call) EXPECT_LE(n, kFieldVisualsPerIteration);
  EXPECT_EQ(b.markers_per_call.front(), kFieldVisualsPerIteration);  // the first batch at once
  EXPECT_GE(b.markers_per_call.size(), calls);
  EXPECT_EQ(b.markers_per_call[calls], 0u);  // all posted after `calls` calls
  EXPECT_EQ(d.engine().field_visuals_pending(), 0u);
  EXPECT_EQ(b.values.size(), static_cast<std::size_t>(kObjects + kObjects / 10));  // + axes
}

TEST(FieldVisuals, TheBatchesAreTheSameEveryRun) {
  Driver first = big_field_driver();
  Driver second = big_field_driver();
  EXPECT_EQ(run_start_up(first, 60).values, run_start_up(second, 60).values);
}

TEST(FieldVisuals, RestartPostsTheFieldAgainFromTheFirstObject) {
  Driver d = big_field_driver();
  const Batches first = run_start_up(d, 3);  // halfway through: a restart starts over
  Batches again;
  collect(d.restart_field_visuals(1.0).outputs, again);
  for (int i = 2; i < 60; ++i) collect(d.step(i).outputs, again);
  ASSERT_EQ(again.labels.size(), static_cast<std::size_t>(kObjects));
  EXPECT_EQ(again.labels.front(), "o0");
  EXPECT_EQ(std::vector<std::string>(again.values.begin(), again.values.begin() + 100),
            std::vector<std::string>(first.values.begin(), first.values.begin() + 100));
  Batches viewer;
  collect(d.deliver(Mail{"PMV_CONNECT", "pMarineViewer", 70.0}).outputs, viewer);
  EXPECT_EQ(viewer.labels.size(), kFieldVisualsPerIteration);
  EXPECT_EQ(d.engine().field_visuals_pending(), kObjects - kFieldVisualsPerIteration);
}

TEST(FieldVisuals, NothingWithoutShowHazards) {
  Driver d(setup_from(quiet_block("hazard = x=0,y=0,label=a,type=hazard\n")),
           SeedChoice{1, SeedSource::kCommandLine});
  d.start(0.0);
  EXPECT_TRUE(d.restart_field_visuals(1.0).outputs.postings.empty());
  EXPECT_EQ(d.engine().field_visuals_pending(), 0u);
}

}  // namespace
}  // namespace hazard
