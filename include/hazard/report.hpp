#pragma once
// The app body of the terminal/AppCast report (docs/uFldHazardSensor.md, D32), plus the seed in use
// and the active effects in its header block. Pure: ReportData is a snapshot of engine state, and
// format_report turns it into text. The AppCast frame (title, warnings, events) is the app's.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hazard/config.hpp"
#include "hazard/engine.hpp"
#include "hazard/vehicle_state.hpp"

namespace hazard {

struct ReportVehicleRow {
  std::string name;
  SensorSetting setting;
  VehicleCounters counters;
};

struct ReportData {
  std::vector<HazardFileStatus> hazard_files;
  int hazards = 0;
  int benign = 0;
  SeedChoice seed;
  std::vector<std::string> effects;
  std::vector<SensorOption> options;  ///< in width order
  std::optional<double> start_time_s;
  std::vector<ReportVehicleRow> vehicles;  ///< vehicles with a setting, in name order
  BoundDrops drops;  ///< shown in the header block only when a bound was reached
};

ReportData collect_report_data(const Engine& engine);
std::string format_report(const ReportData& data);

/// Left-justified columns separated by two blanks, the header rows underlined with dashes,
/// trailing blanks removed (the original's table style).
std::string format_table(const std::vector<std::vector<std::string>>& header_rows,
                         const std::vector<std::vector<std::string>>& rows);

}  // namespace hazard
