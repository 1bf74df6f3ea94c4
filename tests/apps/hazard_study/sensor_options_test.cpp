// uFldHazardSensor's options for a study (HazardSensorOptions::readers, post_iteration_timing,
// share_node_report_parses, and moos::AppSettings::post_status): with kReportCounts, no iteration
// timing and no status the sensor posts no VIEW_* text, no _ITER_GAP/_ITER_LEN and no _STATUS;
// by default (a live app) it posts all three and parses its node reports alone. The Jake
// mission's block.
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
  std::size_t status = 0;
};

Counts run_sensor(ufld_hazard_sensor::HazardSensorOptions options, bool post_status = true) {
  auto parsed = parse_args({std::string(HAZARD_SOURCE_DIR) + "/missions/jake/jake.moos"});
  std::string error;
  const auto plan = load_plan(*parsed.options, error);
  EXPECT_TRUE(plan) << error;
  moos::ManualClock clock;
  moos::InProcessBus bus(clock, moos::InProcessBus::Options{"jake", 1.0});
  ufld_hazard_sensor::HazardSensor sensor(std::move(options));
  auto comms = bus.connect("uFldHazardSensor");
  const Process process{"uFldHazardSensor", "uFldHazardSensor"};
  moos::AppSettings settings =
      process_settings(*plan, process, sensor.traits(), parsed.options->settings[0], 1);
  EXPECT_TRUE(settings.post_status);  // on unless the host turns it off
  settings.post_status = post_status;
  EXPECT_TRUE(sensor.start(*comms, std::move(settings)));
  sensor.run_for(2.0);
  return Counts{bus.postings_of("VIEW_MARKER").size(),
                bus.postings_of("UFLDHAZARDSENSOR_ITER_GAP").size() +
                    bus.postings_of("UFLDHAZARDSENSOR_ITER_LEN").size(),
                bus.postings_of("UFLDHAZARDSENSOR_STATUS").size()};
}

TEST(StudySensorOptions, ByDefaultTheSensorPostsItsVisualsAndIterationTiming) {
  const Counts c = run_sensor({});
  EXPECT_GT(c.markers, 0u);
  EXPECT_GT(c.iteration_timing, 0u);
  EXPECT_GT(c.status, 0u);
  EXPECT_FALSE(ufld_hazard_sensor::HazardSensorOptions{}.share_node_report_parses);
}

TEST(StudySensorOptions, AStudysSensorPostsNoVisualsAndNoIterationTiming) {
  ufld_hazard_sensor::HazardSensorOptions options;
  options.readers = hazard::PostingReaders::kReportCounts;
  options.post_iteration_timing = false;
  const Counts c = run_sensor(std::move(options), /*post_status=*/false);
  EXPECT_EQ(c.markers, 0u);
  EXPECT_EQ(c.iteration_timing, 0u);
  EXPECT_EQ(c.status, 0u);
}

}  // namespace
}  // namespace hazard_study
