// uFldHazardSensor's options for a study (HazardSensorOptions::readers and
// post_iteration_timing): with kReportCounts and no iteration timing the sensor posts no
// VIEW_* text and no _ITER_GAP/_ITER_LEN; by default it posts both. The Jake mission's block.
#include <gtest/gtest.h>

#include <string>

#include "HazardSensor.hpp"
#include "mission_plan.hpp"
#include "moos/bus.hpp"
#include "moos/clock.hpp"

namespace hazard_study {
namespace {

struct Counts {
  std::size_t markers = 0;
  std::size_t iteration_timing = 0;
};

Counts run_sensor(ufld_hazard_sensor::HazardSensorOptions options) {
  auto parsed = parse_args({std::string(HAZARD_SOURCE_DIR) + "/missions/jake/jake.moos"});
  std::string error;
  const auto plan = load_plan(*parsed.options, error);
  EXPECT_TRUE(plan) << error;
  moos::ManualClock clock;
  moos::InProcessBus bus(clock, moos::InProcessBus::Options{"jake", 1.0});
  ufld_hazard_sensor::HazardSensor sensor(std::move(options));
  auto comms = bus.connect("uFldHazardSensor");
  const Process process{"uFldHazardSensor", "uFldHazardSensor"};
  EXPECT_TRUE(sensor.start(*comms, process_settings(*plan, process, sensor.traits(),
                                                    parsed.options->settings[0], 1)));
  sensor.run_for(2.0);
  return Counts{bus.postings_of("VIEW_MARKER").size(),
                bus.postings_of("UFLDHAZARDSENSOR_ITER_GAP").size() +
                    bus.postings_of("UFLDHAZARDSENSOR_ITER_LEN").size()};
}

TEST(StudySensorOptions, ByDefaultTheSensorPostsItsVisualsAndIterationTiming) {
  const Counts c = run_sensor({});
  EXPECT_GT(c.markers, 0u);
  EXPECT_GT(c.iteration_timing, 0u);
}

TEST(StudySensorOptions, AStudysSensorPostsNoVisualsAndNoIterationTiming) {
  ufld_hazard_sensor::HazardSensorOptions options;
  options.readers = hazard::PostingReaders::kReportCounts;
  options.post_iteration_timing = false;
  const Counts c = run_sensor(std::move(options));
  EXPECT_EQ(c.markers, 0u);
  EXPECT_EQ(c.iteration_timing, 0u);
}

}  // namespace
}  // namespace hazard_study
