// Numerically delicate geometry (differences.md D1, D2, "Containment"):
// swath widths 0, 1e-9 and 1e6; objects exactly on edges and corners at headings 0, 90, 45 and
// 137.5 under the one inclusive rule (swath.hpp); coordinates at UTM scale (6e5, 4.8e6) and at
// 1e7, where containment and report text must match the same scene at the origin to 1 mm.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "hazard/swath.hpp"
#include "scenario.hpp"

namespace hazard {
namespace {

using testing::contains;
using testing::Driver;
using testing::quiet_block;
using testing::values_of;

constexpr double kMicrometre = 1e-6;

// ---- widths ----------------------------------------------------------------------------------------

TEST(NumericsGeometry, WidthZeroIsRejectedAtConfigurationWithAWarning_N1) {
  Driver d("sensor_config = width=0, exp=4, pclass=0.8\n");
  EXPECT_TRUE(d.engine.config().options.empty());
  EXPECT_TRUE(contains(d.all.config_warnings, "value 'width=0, exp=4, pclass=0.8'"));
}

TEST(NumericsGeometry, WidthOneNanometreHoldsOnlyTheTrackLine) {
  for (double heading : {0.0, 90.0, 37.0}) {
    const Swath s({10, 20}, heading, 1e-9, 10);
    const SinCos sc = sin_cos_deg(heading);
    const glm::dvec2 stb{sc.cos, -sc.sin}, fwd{sc.sin, sc.cos};
    EXPECT_TRUE(s.contains({10, 20})) << heading;
    EXPECT_TRUE(s.contains(glm::dvec2{10, 20} + fwd * 4.0)) << heading;
    EXPECT_FALSE(s.contains(glm::dvec2{10, 20} + stb * kMicrometre)) << heading;
  }
  Driver d(quiet_block("sensor_config = width=1e-9, exp=1, pclass=1\n"
                       "hazard = x=0,y=3,label=on,type=hazard\n"
                       "hazard = x=0.01,y=0,label=off,type=hazard\n"));
  d.sense_at_origin("v", "1e-9", "1");
  EXPECT_EQ(values_of(d.all, "UHZ_DETECTION_REPORT"),
            std::vector<std::string>{"vname=v,x=0,y=3,label=on"});
}

TEST(NumericsGeometry, WidthOneMillionMetresHoldsEverythingWithinAndNothingBeyond) {
  const Swath s({0, 0}, 45, 1e6, 10);
  const SinCos sc = sin_cos_deg(45);
  const glm::dvec2 stb{sc.cos, -sc.sin};
  EXPECT_TRUE(s.contains(stb * 999999.0));
  EXPECT_TRUE(s.contains(stb * -999999.999));
  EXPECT_FALSE(s.contains(stb * 1000000.001));
  Driver d(quiet_block("sensor_config = width=1e6, exp=1, pclass=1\n"
                       "hazard = x=999999,y=0,label=in,type=hazard\n"
                       "hazard = x=-1000000,y=4,label=edge,type=hazard\n"
                       "hazard = x=1000000.01,y=0,label=out,type=hazard\n"));
  d.sense_at_origin("v", "1e6", "1");
  EXPECT_EQ(d.vehicle("v").counters.hazard_chances, 2);
  EXPECT_EQ(d.vehicle("v").inside.size(), 2u);
}

// ---- edges and corners: one inclusive rule, with and without rotation (D1, D2) -------------------

// Points on the swath's boundary as a user computes them: centre + a W starboard + b L/2 ahead,
// a, b in [-1, 1] with one of them +-1 (edges) or both (corners).
std::vector<glm::dvec2> boundary_points(const glm::dvec2& c, double heading, double w, double l) {
  const SinCos sc = sin_cos_deg(heading);
  const glm::dvec2 fwd{sc.sin, sc.cos}, stb{sc.cos, -sc.sin};
  std::vector<glm::dvec2> out;
  for (double a : {-1.0, -0.5, 0.0, 0.37, 1.0}) {
    for (double b : {-1.0, 1.0}) {
      out.push_back(c + stb * (w * b) + fwd * (l / 2 * a));  // a point on a side edge
      out.push_back(c + stb * (w * a) + fwd * (l / 2 * b));  // a point on a front/rear edge
    }
  }
  return out;
}

TEST(NumericsGeometry, PointsOnEdgesAndCornersAreInsideAtEveryHeadingAndScale_D1_D2) {
  for (const glm::dvec2 c : {glm::dvec2{0, 0}, glm::dvec2{123.4, -567.8},
                             glm::dvec2{6e5, 4.8e6}, glm::dvec2{1e7, -1e7}}) {
    for (double heading : {0.0, 90.0, 45.0, 137.5, 180.0, 270.0, 313.1}) {
      for (const auto& [w, l] : std::vector<std::pair<double, double>>{{25, 5}, {10, 10},
                                                                      {0.5, 1}, {1e3, 1}}) {
        const Swath s(c, heading, w, l);
        for (const glm::dvec2& p : boundary_points(c, heading, w, l)) {
          EXPECT_TRUE(s.contains(p)) << "centre " << c.x << "," << c.y << " heading " << heading
                                     << " point " << p.x << "," << p.y;
        }
        for (const glm::dvec2& corner : s.corners()) {
          EXPECT_TRUE(s.contains(corner)) << heading;  // the posted polygon's own vertices
        }
      }
    }
  }
}

TEST(NumericsGeometry, PointsOneMicrometreOutsideAreOutsideAtEveryHeadingAndScale_D1_D2) {
  for (const glm::dvec2 c : {glm::dvec2{0, 0}, glm::dvec2{6e5, 4.8e6}, glm::dvec2{1e7, 1e7}}) {
    for (double heading : {0.0, 90.0, 45.0, 137.5}) {
      const double w = 25, l = 5;
      const Swath s(c, heading, w, l);
      const SinCos sc = sin_cos_deg(heading);
      const glm::dvec2 fwd{sc.sin, sc.cos}, stb{sc.cos, -sc.sin};
      for (double side : {-1.0, 1.0}) {
        EXPECT_FALSE(s.contains(c + stb * (side * (w + kMicrometre)))) << heading;
        EXPECT_FALSE(s.contains(c + fwd * (side * (l / 2 + kMicrometre)))) << heading;
        EXPECT_FALSE(s.contains(c + stb * (side * (w + kMicrometre)) + fwd * (l / 2))) << heading;
        EXPECT_TRUE(s.contains(c + stb * (side * (w - kMicrometre)))) << heading;
      }
    }
  }
}

TEST(NumericsGeometry, TheRoundingAllowanceIsFourUnitsInTheLastPlace) {
  EXPECT_LT(Swath({0, 0}, 45, 25, 5).tolerance_m(), 1e-13);
  EXPECT_LT(Swath({1e7, 1e7}, 45, 25, 5).tolerance_m(), 2e-8);  // far below 1 mm
  EXPECT_GT(Swath({1e7, 1e7}, 45, 25, 5).tolerance_m(), 1e-9);  // above the coordinates' ulp
}

TEST(NumericsGeometry, AxisAlignedEdgesNeedNoAllowance) {
  // Headings 0 and 90 use exact sines: a point a single ulp beyond an edge is outside.
  const Swath s({0, 0}, 0, 25, 5);
  EXPECT_TRUE(s.contains({25, 2.5}));
  EXPECT_FALSE(s.contains({std::nextafter(25.0 + s.tolerance_m(), 30.0), 0}));
  const Swath east({100, 200}, 90, 10, 4);
  EXPECT_TRUE(east.contains({102, 190}));  // front-starboard corner
  EXPECT_TRUE(east.contains({98, 210}));   // rear-port corner
}

// ---- coordinates at UTM scale and at 1e7 --------------------------------------------------------------

struct SceneRun {
  std::vector<std::string> decisions;  // label pass outcome
  std::vector<std::string> reports;    // UHZ_DETECTION_REPORT values
};

// A vehicle mows a field whose objects sit at centimetre positions, some exactly on the swath's
// axis-aligned edges and corners; everything shifted by `shift` (exact decimal offsets).
SceneRun run_scene(glm::dvec2 shift, const std::string& extra) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> cm(-4000, 4000);
  std::string block = quiet_block("sensor_config = width=20, exp=2, pclass=0.9\n" + extra);
  std::vector<glm::dvec2> offsets;
  for (int i = 0; i < 300; ++i) offsets.emplace_back(cm(rng) / 100.0, cm(rng) / 100.0);
  // On the side edges of the swaths at x = -10 and x = 10 (W 20): x = -30, 10, -10, 30; the
  // poses' y are multiples of 2.5 (L 10), so these also sit on front and rear edges (corners).
  for (double y : {-35.0, -5.0, 15.0, 25.0}) {
    for (double x : {-30.0, -10.0, 10.0, 30.0}) offsets.emplace_back(x, y);
  }
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    block += "hazard = x=" + base::fmt(shift.x + offsets[i].x, 2) + ",y=" +
             base::fmt(shift.y + offsets[i].y, 2) + ",label=o" + std::to_string(i) + ",type=" +
             (i % 2 ? "hazard" : "benign") + "\n";
  }
  Driver d(block);
  SceneRun run;
  d.driver.set_decision_observer([&](const Decision& dec) {
    run.decisions.push_back(std::string(dec.label) + " " + std::to_string(dec.pass) + " " +
                            (dec.outcome ? "1" : "0"));
  });
  d.mail("UHZ_CONFIG_REQUEST", "vname=v,width=20,pd=0.7");
  d.sensor_on("v");
  int k = 0;
  for (double x : {-10.0, 10.0}) {
    for (double y = -40.0; y <= 40.0; y += 2.5) {
      d.pose("v", shift.x + x, shift.y + (x < 0 ? y : -y), x < 0 ? 0 : 180);
      d.tick_at(++k);
    }
  }
  run.reports = values_of(d.all, "UHZ_DETECTION_REPORT");
  return run;
}

// The exact decimal text of shift + offset, from the report text at the origin (2 decimals).
std::string shifted_text(const std::string& origin_text, double shift) {
  const long long cents = std::llround(*base::parse_number(origin_text) * 100) +
                          std::llround(shift * 100);
  std::string out = cents < 0 ? "-" : "";
  const long long a = std::llabs(cents);
  out += std::to_string(a / 100);
  if (a % 100) {
    std::string frac = std::to_string(a % 100);
    if (frac.size() < 2) frac = "0" + frac;
    if (frac.back() == '0') frac.pop_back();
    out += "." + frac;
  }
  return out;
}

std::string field_of(const std::string& report, const std::string& key) {
  const auto at = report.find("," + key + "=") + key.size() + 2;
  return report.substr(at, report.find(',', at) - at);
}

TEST(NumericsGeometry, UtmScaleAndTenMegametreScenesMatchTheSceneAtTheOrigin) {
  for (const std::string mode : {"", "swath_sweep = true\n", "swath_substeps = 3\n"}) {
    const SceneRun origin = run_scene({0, 0}, mode);
    ASSERT_GT(origin.reports.size(), 30u) << mode;
    for (const glm::dvec2 shift : {glm::dvec2{6e5, 4.8e6}, glm::dvec2{1e7, 1e7},
                                   glm::dvec2{-1e7, 4.8e6}}) {
      const SceneRun far = run_scene(shift, mode);
      EXPECT_EQ(far.decisions, origin.decisions) << mode << " shift " << shift.x;
      ASSERT_EQ(far.reports.size(), origin.reports.size());
      for (std::size_t i = 0; i < far.reports.size(); ++i) {
        // The report text is the exact decimal position: no binary noise at 1e7 (1 mm and better).
        EXPECT_EQ(field_of(far.reports[i], "x"), shifted_text(field_of(origin.reports[i], "x"), shift.x));
        EXPECT_EQ(field_of(far.reports[i], "y"), shifted_text(field_of(origin.reports[i], "y"), shift.y));
      }
    }
  }
}

TEST(NumericsGeometry, SwathPolygonTextAtUtmScaleIsTheOriginsShifted_N10) {
  Driver d(quiet_block("show_swath = true\nhazard = x=0,y=0,label=a,type=hazard\n"));
  d.sensor_on("v");
  d.pose("v", 600000.2, 4800000.7, 90);
  d.tick();
  const std::string polygon = values_of(d.all, "VIEW_POLYGON").at(0);
  EXPECT_EQ(polygon.substr(0, polygon.find("},") + 2),
            "pts={600005.2,4799975.7:599995.2,4799975.7:599995.2,4800025.7:600005.2,4800025.7},");
}

}  // namespace
}  // namespace hazard
