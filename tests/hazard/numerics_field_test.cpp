// A field of one million objects on one spot, and a vehicle inside all of them at once (design
// "Scale"; docs/performance.md). The spatial grid degenerates to one cell, every object is a
// candidate, each one is a sensor event with its own die, and the per-(vehicle, object) state holds
// a million
// entries; the outcomes still follow the rules (one pass per entry, rates within 5 sigma).
#include <gtest/gtest.h>

#include <cmath>

#include "hazard/dice.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::five_sigma;
using testing::setup_from;

constexpr int kObjects = 1'000'000;

TEST(NumericsField, AMillionObjectsOnOneSpotAreEachSensedOncePerPass) {
  EngineSetup setup = setup_from(testing::quiet_block());
  for (int i = 0; i < kObjects; ++i) {
    HazardObject o;
    o.x_m = 1234.5;
    o.y_m = -678.25;
    o.label = "o" + std::to_string(i);
    o.type = i % 3 == 0 ? ObjectType::kHazard : ObjectType::kBenign;
    ASSERT_TRUE(setup.field.add(std::move(o)));
  }
  hazard::Driver driver(std::move(setup), SeedChoice{7, SeedSource::kCommandLine});
  EXPECT_EQ(driver.engine().field().grid().cells_x() * driver.engine().field().grid().cells_y(), 1);
  driver.start(0);
  driver.deliver(Mail{"UHZ_CONFIG_REQUEST", "vname=v,width=25,pd=0.05", 0});
  driver.deliver(Mail{"UHZ_SENSOR_REQUEST", "vname=v", 0});
  auto at = [&](double x, double y, double now) {
    driver.deliver(Mail{"NODE_REPORT", testing::node_report("v", x, y), now});
    return driver.step(now).outputs;
  };
  const Outputs first = at(1234.5, -670, 1);  // the spot is 8.25 m behind: inside (L/2 = 5)? no
  EXPECT_EQ(driver.engine().vehicle(0).inside.size(), 0u);
  const Outputs in = at(1234.5, -675, 2);  // 3.25 m behind, on the track: inside all of them
  const VehicleState& v = driver.engine().vehicle(0);
  ASSERT_EQ(v.inside.size(), static_cast<std::size_t>(kObjects));
  EXPECT_EQ(v.counters.hazard_chances + v.counters.benign_chances, kObjects);
  // Hazards detect with pd = 0.05 (exactly 500 of the 10000 die values); benign objects with
  // pfa = 0.05^4 = 6.25e-6, which the die's resolution makes 1e-4.
  const double hazards = v.counters.hazard_chances;
  EXPECT_NEAR(v.counters.hazard_reports / hazards, 0.05, five_sigma(0.05, hazards));
  const double benign = v.counters.benign_chances;
  EXPECT_NEAR(v.counters.benign_reports / benign, 1e-4, five_sigma(1e-4, benign));
  std::size_t reports = 0;
  for (const Posting& p : in.postings) reports += p.variable == "UHZ_DETECTION_REPORT";
  EXPECT_EQ(reports, static_cast<std::size_t>(v.counters.detections));

  // Staying inside is no new event; leaving and coming back is pass 2 for every object.
  at(1234.5, -676, 3);
  EXPECT_EQ(v.counters.hazard_chances + v.counters.benign_chances, kObjects);
  at(1300, -675, 4);
  EXPECT_TRUE(v.inside.empty());
  std::uint32_t max_pass = 0, second_passes = 0;
  driver.set_decision_observer([&](const Decision& d) {
    max_pass = std::max(max_pass, d.pass);
    second_passes += d.pass == 2;
  });
  at(1234.5, -675, 5);
  EXPECT_EQ(second_passes, static_cast<std::uint32_t>(kObjects));
  EXPECT_EQ(max_pass, 2u);
  EXPECT_TRUE(driver.engine().invariant_violations().empty());
  (void)first;
}

}  // namespace
}  // namespace hazard
