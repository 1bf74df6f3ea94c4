#include "hazard/report.hpp"

#include <algorithm>

#include "hazard/engine.hpp"
#include "base/text.hpp"

namespace hazard {

namespace {

constexpr std::size_t kRuleWidth = 44;  // the original's '=' rule length
constexpr const char* kColumnGap = "  ";

std::string rule() { return std::string(kRuleWidth, '=') + "\n"; }

std::string section(const std::string& title) { return rule() + title + "\n" + rule(); }

std::string hazard_file_label(const std::vector<HazardFileStatus>& files) {
  if (files.empty()) return "None provided.";
  std::string out;
  for (const HazardFileStatus& f : files) {
    if (!out.empty()) out += ", ";
    const std::string path = base::escape_for_log(f.path);  // mission text: any byte but '\n'
    out += f.read_ok ? path : "Error reading: " + path;
  }
  return out;
}

// "3(12)": a count and the time of the latest one relative to the start ("-" if never).
std::string count_with_time(int count, std::optional<double> time_s,
                            std::optional<double> start_s) {
  const std::string when = time_s ? base::fix(*time_s - start_s.value_or(0.0), 0) : "-";
  return std::to_string(count) + "(" + when + ")";
}

std::string rate(int reports, int chances) {
  return chances > 0 ? base::fix(static_cast<double>(reports) / chances, 2) : "n/a";
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out.empty() ? "none" : out;
}

// "      Drops: vehicles 2, ..." when a bound of the engine was reached (engine.hpp), else
// nothing, so the report of a mission that never reaches one is unchanged.
std::string drops_line(const BoundDrops& d) {
  const std::pair<const char*, std::uint64_t> counts[] = {
      {"vehicles refused", d.vehicles},           {"vehicles forgotten", d.vehicles_forgotten},
      {"classify requests", d.classify_requests}, {"credits", d.credits},
      {"teleports", d.teleports}};
  std::string out;
  for (const auto& [name, count] : counts) {
    if (count == 0) continue;
    out += (out.empty() ? "" : ", ") + std::string(name) + " " + std::to_string(count);
  }
  return out.empty() ? "" : "      Drops: " + out + "\n";
}

}  // namespace

std::string format_table(const std::vector<std::vector<std::string>>& header_rows,
                         const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> widths;
  auto measure = [&](const std::vector<std::string>& row) {
    if (widths.size() < row.size()) widths.resize(row.size(), 0);
    for (std::size_t c = 0; c < row.size(); ++c) widths[c] = std::max(widths[c], row[c].size());
  };
  for (const auto& r : header_rows) measure(r);
  for (const auto& r : rows) measure(r);
  auto line = [&](const std::vector<std::string>& row) {
    std::string out;
    for (std::size_t c = 0; c < widths.size(); ++c) {
      const std::string cell = c < row.size() ? row[c] : "";
      out += cell + std::string(widths[c] - cell.size(), ' ');
      if (c + 1 < widths.size()) out += kColumnGap;
    }
    out.erase(out.find_last_not_of(' ') + 1);
    return out + "\n";
  };
  std::string out;
  for (const auto& r : header_rows) out += line(r);
  std::vector<std::string> dashes;
  for (std::size_t w : widths) dashes.emplace_back(w, '-');
  out += line(dashes);
  for (const auto& r : rows) out += line(r);
  return out;
}

ReportData collect_report_data(const Engine& engine) {
  ReportData d;
  d.hazard_files = engine.hazard_files();
  d.hazards = engine.field().hazard_count();
  d.benign = engine.field().benign_count();
  d.seed = engine.seed();
  for (std::string_view name : engine.effects().active_names()) d.effects.emplace_back(name);
  d.options = engine.config().options.by_width();
  d.start_time_s = engine.start_time_s();
  d.drops = engine.drops();
  for (VehicleId id : engine.vehicles_by_name()) {
    const VehicleState& v = engine.vehicle(id);
    if (v.setting) d.vehicles.push_back({v.name, *v.setting, v.counters});
  }
  return d;
}

std::string format_report(const ReportData& d) {
  std::string out = "Hazard File: (" + hazard_file_label(d.hazard_files) + ") \n";
  out += "     Hazard: " + std::to_string(d.hazards) + "\n";
  out += "     Benign: " + std::to_string(d.benign) + "\n";
  out += "       Seed: " + std::to_string(d.seed.seed) + " (" + seed_source_name(d.seed.source) +
         ")\n";
  out += "    Effects: " + join(d.effects) + "\n";
  out += drops_line(d.drops) + "\n";

  out += section("Sensor Configuration Options");
  std::vector<std::vector<std::string>> options;
  for (const SensorOption& o : d.options) {
    options.push_back({base::fix(o.width_m, 1), base::fix(o.exp, 1), base::fix(o.pclass, 3),
                       std::to_string(o.max_vehicles)});
  }
  out += format_table({{"Width", "Exp", "Classify", "Max"}}, options);
  out += "\n";

  out += section("Sensor Settings / Stats for known vehicles:");
  std::vector<std::vector<std::string>> settings, stats;
  for (const ReportVehicleRow& v : d.vehicles) {
    const VehicleCounters& c = v.counters;
    settings.push_back({v.name, base::fix(v.setting.width_m, 1), base::fix(v.setting.pd, 3),
                        base::fix(v.setting.pfa, 3), base::fix(v.setting.pclass, 3),
                        std::to_string(c.width_attempts),
                        count_with_time(c.width_resets, c.last_width_reset_s, d.start_time_s),
                        count_with_time(c.pd_resets, c.last_pd_reset_s, d.start_time_s)});
    stats.push_back({v.name, std::to_string(c.sensor_requests), std::to_string(c.detections),
                     rate(c.benign_reports, c.benign_chances),
                     rate(c.hazard_reports, c.hazard_chances),
                     std::to_string(c.classify_requests), std::to_string(c.answers)});
  }
  out += format_table({{"Vehicle", "Swath", "", "", "", "Try Swath", "Swath", "Pd"},
                       {"Name", "Width", "Pd", "Pfa", "Pclass", "Resets", "Resets", "Resets"}},
                      settings);
  out += "\n";
  out += format_table({{"Vehicle", "Sensor", "", "FA", "Det", "Classify", "Classify"},
                       {"Name", "Reqs", "Detections", "Rate", "Rate", "Requests", "Answers"}},
                      stats);
  return out;
}

}  // namespace hazard
