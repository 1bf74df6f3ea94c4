// The large hazard field end to end: missions/hazard_field_large/launch.sh at warp 400
// on moosdb-lite: 10,000 generated objects, four vehicles in parallel, the fleet's answer in
// deb's report. Checked: the field is the one gen_hazards promises for the seed, every process
// stopped and none is left, each vehicle was graded, deb's report carries the hand-overs of the
// three others (it covers the whole field), and the CPU each process used is recorded.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "mission_run.hpp"

namespace mission_test {
namespace {

TEST(LargeMission, FourVehiclesSearchTenThousandObjectsAndDebReportsForTheFleet) {
  const fs::path run_dir = fresh_run_dir("large");
  const test_support::RunResult launched = test_support::run_program(
      LARGE_LAUNCH, {"--warp=400", "--bin-dir=" + std::string(APPS_DIR),
                     "--run-dir=" + run_dir.string(), "--quiet", "--no-picture"},
      280.0);
  ASSERT_EQ(launched.exit_code, 0) << launched.out << launched.err;
  const auto processes = read_pids(run_dir);
  EXPECT_EQ(processes.size(), 1u + 1u + 10u + 1u);  // launcher, moosdb-lite, 10 apps, watcher
  EXPECT_FALSE(any_alive(processes, run_dir.string()));

  // The field: gen_hazards's header names the seed, and 2,000 + 8,000 objects.
  const std::string field = read_file(run_dir / "hazards.txt");
  EXPECT_EQ(field.rfind("// gen_hazards --polygon=0,0:3000,0:3000,-3000:0,-3000 --objects=2000,hazard "
                        "--objects=8000,benign --seed=2026", 0), 0u);
  const auto truth = read_truth(run_dir / "hazards.txt");
  ASSERT_EQ(truth.size(), 10000u);

  std::map<std::string, std::map<std::string, std::string>> evals;
  std::set<std::string> handovers_to_deb;
  for (const auto& e : read_alog(run_dir / "hazard_field_large.alog").entries) {
    if (e.variable == "HAZARDSET_EVAL") evals[fields(e.value)["vname"]] = fields(e.value);
    if (e.variable == "HAZARD_HANDOVER_DEB") handovers_to_deb.insert(e.source);
  }
  for (const char* v : {"abe", "ben", "cal", "deb"}) ASSERT_EQ(evals.count(v), 1u) << v;
  EXPECT_EQ(handovers_to_deb, (std::set<std::string>{"pHazardMgr_abe", "pHazardMgr_ben", "pHazardMgr_cal"}));
  // A strip covers a quarter of the field: each vehicle alone misses about three quarters of
  // the hazards; deb's report, with the three hand-overs, misses few.
  const double deb_missed = std::stod(evals["deb"]["missed_hazards"]);
  for (const char* v : {"abe", "ben", "cal"})
    EXPECT_GT(std::stod(evals[v]["missed_hazards"]), 1000.0) << v;
  EXPECT_LT(deb_missed, 400.0);
  EXPECT_GT(std::stod(evals["deb"]["total_objects"]), 5000.0);

  const std::string summary = read_file(run_dir / "summary.json");
  for (const char* p : {"uFldHazardSensor", "pHazardMgr_deb", "uSimSurveyVehicle_abe", "moosdb-lite"})
    EXPECT_NE(summary.find("\"name\": \"" + std::string(p) + "\""), std::string::npos) << p;
  EXPECT_TRUE(std::regex_search(launched.out, std::regex("CPU seconds \\(user\\+system\\): [0-9.]+ in all")));
}

}  // namespace
}  // namespace mission_test
