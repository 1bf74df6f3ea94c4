// The option table: parsing, width choice (D3, D20), the default (D4, T2), the summary (D21, T3).
#include <gtest/gtest.h>

#include "hazard/sensor_options.hpp"

namespace hazard {
namespace {

SensorOptions table_of(std::initializer_list<double> widths) {
  SensorOptions t;
  for (double w : widths) {
    SensorOption o;
    o.width_m = w;
    EXPECT_TRUE(t.add(o));
  }
  return t;
}

const auto kNoneFull = [](OptionIndex) { return false; };

TEST(SensorConfig, ParsesKeysInAnyOrderAndCase_D20) {
  const auto p = parse_sensor_config("EXP=4, pclass=0.80 ,width=25");
  ASSERT_TRUE(p.option) << p.error;
  EXPECT_EQ(p.option->width_m, 25);
  EXPECT_EQ(p.option->exp, 4);
  EXPECT_EQ(p.option->pclass, 0.8);
  EXPECT_EQ(p.option->max_vehicles, 0);
  EXPECT_EQ(p.option->as_written.pclass, "0.80");  // as written (D21)
  const auto q = parse_sensor_config("width=10, exp=6, class=0.93,max=1");
  ASSERT_TRUE(q.option) << q.error;
  EXPECT_EQ(q.option->pclass, 0.93);
  EXPECT_EQ(q.option->max_vehicles, 1);
}

TEST(SensorConfig, ValidationTable) {
  EXPECT_EQ(parse_sensor_config("exp=4,pclass=0.8").error, "missing field 'width'");
  EXPECT_EQ(parse_sensor_config("width=4,pclass=0.8").error, "missing field 'exp'");
  EXPECT_EQ(parse_sensor_config("width=4,exp=2").error, "missing field 'pclass'");
  EXPECT_NE(parse_sensor_config("width=0,exp=4,pclass=0.8").error.find("'width' value '0'"),
            std::string::npos);
  EXPECT_NE(parse_sensor_config("width=5,exp=0.5,pclass=0.8").error.find("'exp'"),
            std::string::npos);
  EXPECT_NE(parse_sensor_config("width=5,exp=2,pclass=0.4").error.find("[0.5, 1]"),
            std::string::npos);  // D27
  EXPECT_NE(parse_sensor_config("width=5,exp=2,pclass=1.01").error.find("'pclass'"),
            std::string::npos);
  EXPECT_NE(parse_sensor_config("width=5,exp=2,pclass=0.8,max=1.9").error.find("'max'"),
            std::string::npos);
  EXPECT_NE(parse_sensor_config("width=5,exp=2,pclass=0.8,max=-1").error.find("'max'"),
            std::string::npos);
  EXPECT_TRUE(parse_sensor_config("width=5,exp=1,pclass=0.5").option);
  const auto unknown = parse_sensor_config("width=5,exp=2,pclass=0.8,colour=red");
  EXPECT_TRUE(unknown.option);
  ASSERT_EQ(unknown.warnings.size(), 1u);
}

TEST(SensorOptionsTable, SortedByWidthAndDuplicatesRefused) {
  SensorOptions t = table_of({50, 10, 25});
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t.option(0).width_m, 10);
  EXPECT_EQ(t.option(2).width_m, 50);
  SensorOption dup;
  dup.width_m = 25.0000001;
  const base::Result<std::size_t> refused = t.add(dup);  // same width within 1e-6 m
  EXPECT_FALSE(refused);
  EXPECT_NE(refused.error.find("is already configured"), std::string::npos) << refused.error;
  EXPECT_EQ(t.size(), 3u);
}

TEST(SensorOptionsTable, DefaultWidthIsHighestNotAboveAverage_D4_T2) {
  EXPECT_EQ(table_of({5, 10, 25, 50}).default_width_m(), 25);       // average 27.5
  EXPECT_EQ(table_of({10, 25, 50}).default_width_m(), 25);          // average 30
  EXPECT_EQ(table_of({18, 30, 50, 65, 80}).default_width_m(), 30);  // average 49
  EXPECT_EQ(table_of({20}).default_width_m(), 20);
  EXPECT_EQ(table_of({10, 30}).default_width_m(), 10);              // average 20
}

TEST(SensorOptionsTable, RequestPicksExactElseNextLower_D3) {
  const SensorOptions t = table_of({18, 30, 50, 65, 80});
  auto width = [&](double req) { return t.option(*t.choose(req, kNoneFull)).width_m; };
  EXPECT_EQ(width(30), 30);
  EXPECT_EQ(width(32), 30);
  EXPECT_EQ(width(45), 30);  // next lower, not the closest (50)
  EXPECT_EQ(width(49.999), 30);
  EXPECT_EQ(width(5), 18);   // below the smallest: the smallest
  EXPECT_EQ(width(100), 80);
  EXPECT_EQ(width(30.0000005), 30);  // within 1e-6 m
}

TEST(SensorOptionsTable, FullWidthsAreSkipped_D20) {
  const SensorOptions t = table_of({10, 25, 50});
  auto width = [&](double req, std::initializer_list<OptionIndex> full) {
    const auto i = t.choose(req, [&](OptionIndex j) {
      return std::find(full.begin(), full.end(), j) != full.end();
    });
    return i ? t.option(*i).width_m : -1.0;
  };
  EXPECT_EQ(width(25, {1}), 10);     // requested full: next lower free
  EXPECT_EQ(width(10, {0}), 25);     // nothing lower: next higher free
  EXPECT_EQ(width(50, {1, 2}), 10);
  EXPECT_EQ(width(25, {0, 1, 2}), -1);  // every option full
}

}  // namespace
}  // namespace hazard
