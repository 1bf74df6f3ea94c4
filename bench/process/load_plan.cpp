#include "load_plan.hpp"

#include <algorithm>
#include <cmath>

#include "base/text.hpp"

namespace bench {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerRad = 180.0 / kPi;

/// MOOS heading of the direction (dx, dy): 0 north, 90 east.
double heading_of(double dx_m, double dy_m) {
  return base::norm360(std::atan2(dx_m, dy_m) * kDegPerRad);
}

}  // namespace

std::vector<Strip> split_field(double side_m, int vehicles) {
  std::vector<Strip> strips;
  const int n = std::max(vehicles, 1);
  const double width = side_m / n;
  for (int i = 0; i < n; ++i) strips.push_back({i * width, (i + 1) * width, 0.0, side_m});
  return strips;
}

Lawnmower::Lawnmower(const Strip& strip, double lane_spacing_m) {
  const double width = strip.x_max_m - strip.x_min_m;
  const double spacing = std::max(lane_spacing_m, 1e-3);
  const int lanes = std::max(1, static_cast<int>(std::floor(width / spacing)));
  const double first_x = lanes == 1 && width < spacing ? strip.x_min_m + width / 2
                                                       : strip.x_min_m + spacing / 2;
  for (int lane = 0; lane < lanes; ++lane) {
    const double x = first_x + lane * spacing;
    const bool north = lane % 2 == 0;
    waypoints_.push_back({x, north ? strip.y_min_m : strip.y_max_m, 0});
    waypoints_.push_back({x, north ? strip.y_max_m : strip.y_min_m, 0});
  }
  cumulative_m_.push_back(0);
  for (std::size_t i = 1; i < waypoints_.size(); ++i) {
    const double dx = waypoints_[i].x_m - waypoints_[i - 1].x_m;
    const double dy = waypoints_[i].y_m - waypoints_[i - 1].y_m;
    cumulative_m_.push_back(cumulative_m_.back() + std::hypot(dx, dy));
  }
}

Pose Lawnmower::at(double distance_m) const {
  const double total = length_m();
  if (total <= 0) return waypoints_.front();
  // Out and back: the second half of each period runs the track in reverse.
  const double phase = std::fmod(std::max(distance_m, 0.0), 2 * total);
  const bool back = phase > total;
  const double s = back ? 2 * total - phase : phase;
  const auto upper = std::upper_bound(cumulative_m_.begin(), cumulative_m_.end(), s);
  const std::size_t leg_end = std::min<std::size_t>(
      std::max<std::ptrdiff_t>(upper - cumulative_m_.begin(), 1), waypoints_.size() - 1);
  const Pose& a = waypoints_[leg_end - 1];
  const Pose& b = waypoints_[leg_end];
  const double leg = cumulative_m_[leg_end] - cumulative_m_[leg_end - 1];
  const double t = leg > 0 ? (s - cumulative_m_[leg_end - 1]) / leg : 0;
  const double dx = b.x_m - a.x_m;
  const double dy = b.y_m - a.y_m;
  Pose pose{a.x_m + t * dx, a.y_m + t * dy, 0};
  pose.heading_deg = back ? heading_of(-dx, -dy) : heading_of(dx, dy);
  return pose;
}

bool in_swath(const Pose& pose, double x_m, double y_m, double half_width_m,
              double half_length_m) {
  const double h = pose.heading_deg / kDegPerRad;
  const double dx = x_m - pose.x_m;
  const double dy = y_m - pose.y_m;
  const double along = dx * std::sin(h) + dy * std::cos(h);
  const double across = dx * std::cos(h) - dy * std::sin(h);
  return std::abs(along) <= half_length_m && std::abs(across) <= half_width_m;
}

std::optional<double> detection_delay(const std::deque<SentReport>& history, double received_s,
                                      double x_m, double y_m, double half_width_m,
                                      double half_length_m) {
  auto inside = [&](auto it) { return in_swath(it->pose, x_m, y_m, half_width_m, half_length_m); };
  auto it = std::upper_bound(history.begin(), history.end(), received_s,
                             [](double t, const SentReport& s) { return t < s.real_s; });
  while (it != history.begin() && !inside(std::prev(it))) --it;
  if (it == history.begin()) return std::nullopt;
  while (it != history.begin() && inside(std::prev(it))) --it;
  return received_s - it->real_s;
}

std::string node_report(std::string_view name, const Pose& pose, double speed_mps, double time_s) {
  std::string text = "NAME=";
  text += name;
  text += ",X=" + base::fix(pose.x_m, 2) + ",Y=" + base::fix(pose.y_m, 2) +
          ",SPD=" + base::fmt(speed_mps, 2) + ",HDG=" + base::fix(pose.heading_deg, 2) +
          ",TYPE=kayak,TIME=" + base::fix(time_s, 2) + ",LENGTH=4";
  return text;
}

std::string value_of(std::string_view text, std::string_view key) {
  for (const auto& kv : base::split_key_values(text)) {
    if (kv.key == key) return std::string(kv.value);
  }
  return {};
}

std::optional<long long> appcast_iteration(std::string_view appcast) {
  // Items are separated by "!@#"; the first iter= item is the counter (it appears twice).
  constexpr std::string_view kSeparator = "!@#";
  constexpr std::string_view kKey = "iter=";
  std::size_t start = 0;
  while (start <= appcast.size()) {
    const auto end = appcast.find(kSeparator, start);
    const auto item = appcast.substr(start, end == std::string_view::npos ? end : end - start);
    if (base::starts_with(item, kKey))
      return base::parse_integer(item.substr(kKey.size()), 0, (1LL << 62));
    if (end == std::string_view::npos) break;
    start = end + kSeparator.size();
  }
  return std::nullopt;
}

std::string mission_text(const MissionSpec& spec) {
  std::string text;
  text += "// Written by process_bench: one uFldHazardSensor under load.\n";
  text += "ServerHost = localhost\n";
  text += "ServerPort = " + std::to_string(spec.port) + "\n";
  text += "Community = " + spec.community + "\n";
  text += "MOOSTimeWarp = " + base::format_g(spec.time_warp) + "\n\n";
  text += "ProcessConfig = uFldHazardSensor\n{\n";
  text += "  AppTick = " + base::format_g(spec.app_tick_hz) + "\n";
  text += "  CommsTick = " + base::format_g(spec.app_tick_hz) + "\n";
  if (spec.idle_app_tick_hz)
    text += "  IdleAppTick = " + base::format_g(*spec.idle_app_tick_hz) + "\n";
  text += "  hazard_file = " + spec.hazard_file + "\n";
  text += "  sensor_config = width=25, exp=4, pclass=0.85\n";
  text += "  sensor_config = width=50, exp=2, pclass=0.60\n";
  text += "  sensor_config = width=10, exp=6, pclass=0.93\n";
  text += "  swath_length = " + base::format_g(spec.swath_length_m) + "\n";
  text += "  show_hazards = " + std::string(spec.show_hazards ? "true" : "false") + "\n";
  text += "  seed_random = false\n";
  text += "}\n";
  return text;
}

}  // namespace bench
