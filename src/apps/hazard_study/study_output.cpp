// hazard_study's outputs. Contract in study_output.hpp.

#include "study_output.hpp"

#include <cmath>
#include <cstdio>

#include "base/text.hpp"

namespace hazard_study {

namespace {

void append_json_string(std::string& out, const std::string& text) {
  out += '"';
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  out += '"';
}

void append_number(std::string& out, const char* key, std::optional<double> value) {
  out += ",\"";
  out += key;
  out += "\":";
  out += value && std::isfinite(*value) ? base::format_shortest(*value) : "null";
}

struct Stats {
  double mean = 0.0, sd = 0.0, half_width = 0.0;
};

Stats stats_of(const std::vector<double>& xs) {
  Stats s;
  if (xs.empty()) return s;
  double sum = 0.0;
  for (double x : xs) sum += x;
  s.mean = sum / static_cast<double>(xs.size());
  if (xs.size() < 2) return s;
  double squares = 0.0;
  for (double x : xs) squares += (x - s.mean) * (x - s.mean);
  s.sd = std::sqrt(squares / static_cast<double>(xs.size() - 1));
  s.half_width = t_quantile_975(xs.size() - 1) * s.sd / std::sqrt(static_cast<double>(xs.size()));
  return s;
}

}  // namespace

std::string json_line(const MissionResult& r) {
  std::string out = "{\"setting\":";
  append_json_string(out, r.setting);
  if (r.field_seed) out += ",\"field_seed\":" + std::to_string(*r.field_seed);
  out += ",\"seed\":" + std::to_string(r.seed) + ",\"end\":";
  append_json_string(out, r.end);
  append_number(out, "score", r.score);
  const auto field = [&](auto member) -> std::optional<double> {
    if (!r.eval) return std::nullopt;
    return static_cast<double>((*r.eval).*member);
  };
  append_number(out, "found", field(&mission::HazardsetEval::correct_hazards));
  append_number(out, "missed", field(&mission::HazardsetEval::missed_hazards));
  append_number(out, "false_alarms", field(&mission::HazardsetEval::false_alarms));
  append_number(out, "time_used", field(&mission::HazardsetEval::total_time_s));
  append_number(out, "detections", static_cast<double>(r.detections));
  append_number(out, "classifications", static_cast<double>(r.classifications));
  append_number(out, "sim_s", r.sim_s);
  out += "}\n";
  return out;
}

double t_quantile_975(std::size_t df) {
  static const double kSmall[] = {12.706, 4.303, 3.182, 2.776, 2.571,
                                  2.447,  2.365, 2.306, 2.262, 2.228};
  if (df == 0) return std::nan("");
  if (df <= 10) return kSmall[df - 1];
  // Cornish-Fisher expansion around the normal quantile: within 1e-3 for df > 10.
  const double z = 1.959963984540054, n = static_cast<double>(df);
  const double z3 = z * z * z, z5 = z3 * z * z;
  return z + (z3 + z) / (4 * n) + (5 * z5 + 16 * z3 + 3 * z) / (96 * n * n);
}

/// A label as one table cell: tabs and other control characters become blanks.
std::string cell(std::string text) {
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  return text;
}

std::string summary_table(const std::vector<SettingScores>& settings) {
  std::string out = "setting\tmissions\tscored\tmean\tsd\tci95_low\tci95_high\tmax_time\n";
  for (const SettingScores& s : settings) {
    const Stats st = stats_of(s.scores);
    const bool some = !s.scores.empty();
    const bool interval = s.scores.size() >= 2;
    out += cell(s.setting) + "\t" + std::to_string(s.missions) + "\t" + std::to_string(s.scores.size()) +
           "\t" + (some ? base::fix(st.mean, 2) : "-") + "\t" +
           (interval ? base::fix(st.sd, 2) : "-") + "\t" +
           (interval ? base::fix(st.mean - st.half_width, 2) : "-") + "\t" +
           (interval ? base::fix(st.mean + st.half_width, 2) : "-") + "\t" +
           std::to_string(s.max_time) + "\n";
  }
  return out;
}

}  // namespace hazard_study
