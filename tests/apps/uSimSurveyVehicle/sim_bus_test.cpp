// uSimSurveyVehicle's app class on the in-process bus with a manual clock: deployment, node
// reports (fields, rate, LAT/LON through GeographicLib), the lawnmower route, new routes from
// SURVEY_ROUTE_<V>, done flags, configuration warnings, and that the app flies exactly the
// library's vehicle (it is a thin adapter).
#include <gtest/gtest.h>

#include <cmath>

#include "SimSurveyVehicle.hpp"
#include "SimSurveyVehicle_Info.hpp"
#include "app_on_bus.hpp"
#include "hazard/messages/node_report.hpp"
#include "mission/geodesy.hpp"
#include "mission/vehicle_config.hpp"

namespace usim_survey_vehicle {
namespace {

using mission_test::any_contains;
using mission_test::Bus;
using mission_test::example_block;
using mission_test::mission_text;

// The origin of mission_text's default globals (LatOrigin, LongOrigin).
constexpr double kLat = 43.8253;
constexpr double kLon = -70.3304;
constexpr const char* kAlias = "uSimSurveyVehicle_archie";

const std::string kRegion = "pts={0,0:100,0:100,-60:0,-60}";

class SimOnBus : public ::testing::Test {
 protected:
  /// Starts the app on a mission with the kLat/kLon origin, or without globals.
  bool start(const std::string& block, bool with_origin = true) {
    app.emplace();
    return bus.start(*app, kAlias,
                     with_origin ? mission_text(kAlias, block) : mission_text(kAlias, block, ""));
  }
  std::vector<hazard::NodeReport> reports() const {
    std::vector<hazard::NodeReport> out;
    for (const std::string& v : bus.values_of("NODE_REPORT", kAlias)) {
      auto r = hazard::parse_node_report(v);
      EXPECT_TRUE(r) << v << ": " << r.error;
      if (r) out.push_back(*r.value);
    }
    return out;
  }
  Bus bus;
  std::optional<SimSurveyVehicle> app;
};

const std::string kArchie =
    "  vname = archie\n  start_x = -20\n  start_y = 10\n  start_heading = 180\n"
    "  region = " + kRegion + "\n  swath_width = 25\n";

// ---- deployment ----------------------------------------------------------------------------

TEST_F(SimOnBus, WaitsAtTheStartPoseUntilDeployed) {
  ASSERT_TRUE(start(kArchie));
  app->run_for(10.0);
  const auto before = reports();
  ASSERT_FALSE(before.empty());
  for (const auto& r : before) {
    EXPECT_EQ(r.name, "archie");
    EXPECT_DOUBLE_EQ(r.x_m, -20.0);
    EXPECT_DOUBLE_EQ(r.y_m, 10.0);
    EXPECT_DOUBLE_EQ(r.speed_mps, 0.0);
    EXPECT_DOUBLE_EQ(r.heading_deg, 180.0);
  }
  EXPECT_FALSE(app->deployed());
  bus.post("DEPLOY_ALL", "true");
  app->run_for(10.0);
  const auto after = reports();
  EXPECT_TRUE(app->deployed());
  EXPECT_DOUBLE_EQ(after.back().speed_mps, 1.5);
  EXPECT_NE(after.back().x_m, -20.0);
}

TEST_F(SimOnBus, DeployForThisVehicleOnlyAndPlainDeployBothWork) {
  ASSERT_TRUE(start(kArchie));
  bus.post("DEPLOY_BETTY", "true");  // another vehicle's
  bus.post("DEPLOY_ALL", "false");   // false: nothing to start
  app->run_for(2.0);
  EXPECT_FALSE(app->deployed());
  bus.post("DEPLOY_ARCHIE", "true");
  app->run_for(1.0);
  EXPECT_TRUE(app->deployed());

  SimSurveyVehicle other;
  Bus bus2;
  ASSERT_TRUE(bus2.start(other, kAlias, mission_text(kAlias, kArchie)));
  bus2.post("DEPLOY", "true");  // a vehicle community fed by uFldShoreBroker
  other.run_for(1.0);
  EXPECT_TRUE(other.deployed());
}

TEST_F(SimOnBus, DeployTrueInTheBlockStartsAtOnce) {
  ASSERT_TRUE(start(kArchie + "  deploy = true\n"));
  app->run_for(5.0);
  EXPECT_TRUE(app->deployed());
  EXPECT_DOUBLE_EQ(reports().back().speed_mps, 1.5);
}

TEST_F(SimOnBus, DeployWithAWordThatIsNotBooleanIsARunWarning) {
  ASSERT_TRUE(start(kArchie));
  bus.post("DEPLOY_ALL", "soon");
  app->run_for(1.0);
  EXPECT_FALSE(app->deployed());
  EXPECT_TRUE(any_contains(mission_test::run_warning_texts(app->appcast()), "DEPLOY_ALL='soon'"));
}

// ---- node reports --------------------------------------------------------------------------

TEST_F(SimOnBus, NodeReportCarriesNameXYSpeedHeadingLatLonTimeAndType) {
  ASSERT_TRUE(start(kArchie + "  vehicle_type = kayak\n  deploy = true\n"));
  app->run_for(20.0);
  const auto all = bus.bus.postings_of("NODE_REPORT");
  ASSERT_FALSE(all.empty());
  const std::string text = all.back().sval;
  for (const char* key : {"NAME=archie,", ",X=", ",Y=", ",SPD=", ",HDG=", ",LAT=", ",LON=", ",TIME=",
                          ",TYPE=kayak"})
    EXPECT_NE(text.find(key), std::string::npos) << key << " in " << text;
  const auto r = *hazard::parse_node_report(text).value;
  // LAT/LON: GeographicLib's LocalCartesian around the origin (mission/geodesy.hpp); the
  // message keeps 8 decimals of a degree (about 1 mm).
  const mission::GeoPoint geo = mission::LocalGeodesy({kLat, kLon}).to_geo({r.x_m, r.y_m});
  EXPECT_NEAR(*r.lat_deg, geo.lat_deg, 1e-7);
  EXPECT_NEAR(*r.lon_deg, geo.lon_deg, 1e-7);
  EXPECT_NEAR(*r.time_s, all.back().time, 1e-3);
}

TEST_F(SimOnBus, WithoutAnOriginTheReportHasNoLatLon) {
  ASSERT_TRUE(start(kArchie, false));
  app->run_for(1.0);
  const auto r = reports().back();
  EXPECT_FALSE(r.lat_deg.has_value());
  EXPECT_FALSE(r.lon_deg.has_value());
}

// hazard_study without a log: its readers read X and Y, so the origin's LAT/LON are left out.
TEST_F(SimOnBus, WithReportLatLonOffTheReportHasNoLatLonDespiteAnOrigin) {
  app.emplace();
  app->report_lat_lon(false);
  ASSERT_TRUE(bus.start(*app, kAlias, mission_text(kAlias, kArchie)));
  app->run_for(1.0);
  const auto r = reports().back();
  EXPECT_FALSE(r.lat_deg.has_value());
  EXPECT_FALSE(r.lon_deg.has_value());
  EXPECT_TRUE(r.time_s.has_value());
}

TEST_F(SimOnBus, NodeReportVariableIsConfigurable) {
  ASSERT_TRUE(start(kArchie + "  node_report_var = NODE_REPORT_LOCAL\n"));
  app->run_for(2.0);
  EXPECT_TRUE(bus.values_of("NODE_REPORT", kAlias).empty());
  EXPECT_FALSE(bus.values_of("NODE_REPORT_LOCAL", kAlias).empty());
}

TEST_F(SimOnBus, ReportsComeEveryReportInterval) {
  // AppTick 4 with report_interval 0.5: every second iteration, 2 per second.
  ASSERT_TRUE(start(kArchie + "  AppTick = 4\n  report_interval = 0.5\n"));
  app->run_for(10.0);
  const auto posts = bus.bus.postings_of("NODE_REPORT");
  ASSERT_GE(posts.size(), 19u);
  EXPECT_LE(posts.size(), 21u);
  for (std::size_t i = 1; i < posts.size(); ++i)
    EXPECT_NEAR(posts[i].time - posts[i - 1].time, 0.5, 1e-6);
}

TEST_F(SimOnBus, ReportIntervalShorterThanAnIterationIsAConfigWarning) {
  ASSERT_TRUE(start(kArchie + "  AppTick = 4\n  report_interval = 0.1\n"));
  EXPECT_TRUE(any_contains(app->appcast().config_warnings(), "shorter than an iteration"));
}

// ---- routes and done flags ---------------------------------------------------------------

TEST_F(SimOnBus, FliesTheLibrarysLawnmowerAndMatchesTheLibraryVehicle_ThinAdapter) {
  ASSERT_TRUE(start(kArchie + "  deploy = true\n"));
  mission::SurveyVehicleConfig config;
  for (const auto& l : std::vector<std::pair<std::string, std::string>>{
           {"start_x", "-20"}, {"start_y", "10"}, {"region", kRegion}, {"swath_width", "25"}})
    ASSERT_EQ(mission::apply_survey_vehicle_param(config, l.first, l.second).error, "");
  const auto route = *mission::plan_route(config).value;
  ASSERT_EQ(app->vehicle()->waypoints(), route);

  // The library's vehicle, started at the same time and pose, flown at the report times.
  mission::SurveyVehicle twin(mission::VehicleParams{},
                              mission::Pose{{-20, 10}, 180.0, 0.0, app->start_time()});
  twin.set_waypoints(route);
  app->run_for(60.0);
  const auto posts = bus.bus.postings_of("NODE_REPORT");
  ASSERT_GT(posts.size(), 200u);
  for (const auto& m : posts) {
    const auto r = *hazard::parse_node_report(m.sval).value;
    const mission::Pose p = twin.advance_to(*r.time_s);
    EXPECT_NEAR(r.x_m, p.position_m.x, 0.006);  // FMT(.,2)
    EXPECT_NEAR(r.y_m, p.position_m.y, 0.006);
    EXPECT_NEAR(r.heading_deg, p.heading_deg, 0.006);
  }
}

TEST_F(SimOnBus, DoneFlagsArePostedOnceWhenTheRouteIsFinished) {
  ASSERT_TRUE(start("  vname = archie\n  deploy = true\n  waypoints = pts={0,15:0,30}\n"
                    "  done_flag = HAZARDSET_REQUEST_ARCHIE = true\n  done_flag = SURVEY_LEGS=2\n"));
  app->run_for(5.0);
  EXPECT_TRUE(bus.bus.postings_of("HAZARDSET_REQUEST_ARCHIE").empty());
  app->run_for(60.0);  // 30 m at 1.5 m/s
  ASSERT_TRUE(app->vehicle()->done());
  const auto request = bus.bus.postings_of("HAZARDSET_REQUEST_ARCHIE");
  ASSERT_EQ(request.size(), 1u);
  EXPECT_EQ(request[0].sval, "true");
  const auto legs = bus.bus.postings_of("SURVEY_LEGS");
  ASSERT_EQ(legs.size(), 1u);
  EXPECT_TRUE(legs[0].is_double());  // a number is posted as a double
  EXPECT_DOUBLE_EQ(legs[0].dval, 2.0);
  app->run_for(30.0);
  EXPECT_EQ(bus.bus.postings_of("HAZARDSET_REQUEST_ARCHIE").size(), 1u);
}

TEST_F(SimOnBus, WithoutARouteTheVehicleWaitsForSurveyRouteAndPostsNoDoneFlag) {
  // Jake's betty: no region, no waypoints; deployed, but idle until a reacquisition route.
  ASSERT_TRUE(start("  vname = betty\n  deploy = true\n  done_flag = HAZARDSET_REQUEST_BETTY=true\n"));
  app->run_for(30.0);
  EXPECT_TRUE(bus.bus.postings_of("HAZARDSET_REQUEST_BETTY").empty());
  EXPECT_DOUBLE_EQ(reports().back().speed_mps, 0.0);
  EXPECT_NE(app->terminal_report().find("waiting for SURVEY_ROUTE_BETTY"), std::string::npos);

  bus.post("SURVEY_ROUTE_BETTY", "pts={0,20:0,40}");
  app->run_for(60.0);
  EXPECT_TRUE(app->vehicle()->done());
  EXPECT_EQ(bus.bus.postings_of("HAZARDSET_REQUEST_BETTY").size(), 1u);
  // A second route re-arms the flag.
  bus.post("SURVEY_ROUTE_BETTY", "pts={0,0}");
  app->run_for(60.0);
  EXPECT_EQ(bus.bus.postings_of("HAZARDSET_REQUEST_BETTY").size(), 2u);
}

TEST_F(SimOnBus, RouteBeforeDeploymentIsFlownOnceDeployed) {
  ASSERT_TRUE(start("  vname = betty\n"));
  bus.post("SURVEY_ROUTE_BETTY", "0,30");
  app->run_for(5.0);
  EXPECT_DOUBLE_EQ(reports().back().speed_mps, 0.0);
  bus.post("DEPLOY_ALL", "true");
  app->run_for(5.0);
  EXPECT_DOUBLE_EQ(reports().back().speed_mps, 1.5);
}

TEST_F(SimOnBus, MalformedOrForeignRoutesChangeNothing) {
  ASSERT_TRUE(start("  vname = betty\n  deploy = true\n"));
  bus.post("SURVEY_ROUTE_BETTY", "pts={1,2:oops}");
  bus.post("SURVEY_ROUTE_ARCHIE", "pts={0,30}");  // another vehicle's, not subscribed
  app->run_for(5.0);
  EXPECT_TRUE(app->vehicle()->waypoints().empty());
  EXPECT_TRUE(any_contains(mission_test::run_warning_texts(app->appcast()), "SURVEY_ROUTE_BETTY ignored"));
}

// ---- configuration -----------------------------------------------------------------------

TEST_F(SimOnBus, BadValuesAreConfigWarningsNamingFileLineAndValue) {
  ASSERT_TRUE(start("  vname = archie\n  speed = fast\n  deploy = maybe\n  colour = red\n"
                    "  done_flag = NOEQUALS\n"));
  const auto& w = app->appcast().config_warnings();
  const std::string file = (bus.dir / "m.moos").string();
  const int first = mission_test::first_block_line();
  EXPECT_TRUE(any_contains(w, file + ":" + std::to_string(first + 1) + ": parameter speed='fast'"));
  EXPECT_TRUE(any_contains(w, file + ":" + std::to_string(first + 2) + ": parameter deploy='maybe'"));
  EXPECT_TRUE(any_contains(w, file + ":" + std::to_string(first + 3) + ": unknown parameter 'colour'"));
  EXPECT_TRUE(any_contains(w, "done_flag='NOEQUALS'"));
}

TEST_F(SimOnBus, VehicleNameDefaultsToTheCommunity) {
  ASSERT_TRUE(start(""));
  EXPECT_EQ(app->vname(), "jake");
}

TEST_F(SimOnBus, UnplannableRegionIsAConfigWarningAndNoRoute) {
  ASSERT_TRUE(start("  vname = archie\n  region = " + kRegion + "\n  overlap = 0.5\n"
                    "  swath_width = 25\n  deploy = true\n  lane_extension = 0\n"));
  EXPECT_TRUE(app->appcast().config_warnings().empty());  // a valid plan
  SimSurveyVehicle bad;
  Bus bus2;
  // Not a convex polygon: rejected when the line is read.
  ASSERT_TRUE(bus2.start(bad, kAlias, mission_text(kAlias, "  region = 0,0:10,10\n")));
  EXPECT_TRUE(any_contains(bad.appcast().config_warnings(), "parameter region"));
}

TEST(SimInfo, ExampleBlockLoadsWithoutWarnings_Practice5) {
  // --example is built from the parameter tables: as a block it must be accepted as it is.
  const auto block = example_block(example_text());
  ASSERT_TRUE(block);
  SimSurveyVehicle app;
  Bus bus;
  ASSERT_TRUE(bus.start(app, kAppName, mission_text(kAppName, *block)));
  EXPECT_TRUE(app.appcast().config_warnings().empty())
      << ::testing::PrintToString(app.appcast().config_warnings());
  EXPECT_EQ(app.vname(), "archie");
  bus.post("DEPLOY_ALL", "true");
  app.run_for(1.0);
  EXPECT_FALSE(app.vehicle()->waypoints().empty());  // the example's region gives a lawnmower
}

TEST(SimInfo, InterfaceNamesEveryVariableTheAppUses) {
  const std::string text = interface_text();
  for (const char* v : {"DEPLOY_ALL", "SURVEY_ROUTE_<V>", "NODE_REPORT", "APPCAST_REQ",
                        "USIMSURVEYVEHICLE_STATUS"})
    EXPECT_NE(text.find(v), std::string::npos) << v;
  EXPECT_NE(help_text().find("Usage: uSimSurveyVehicle file.moos"), std::string::npos);
  EXPECT_EQ(version_text().rfind("uSimSurveyVehicle ", 0), 0u);
}

}  // namespace
}  // namespace usim_survey_vehicle
