#include "scenario/reference_scenario.hpp"

#include <algorithm>
#include <cmath>

#include "hazard/dice.hpp"
#include "hazard/driver.hpp"
#include "hazard/messages/classify_request.hpp"
#include "hazard/messages/config_request.hpp"
#include "hazard/messages/node_report.hpp"
#include "hazard/messages/sensor_request.hpp"
#include "base/text.hpp"

namespace hazard {

namespace {

constexpr double kSpeed_mps = 1.5;
constexpr double kLegStart_m = -40.0;  // legs run from here to kLegEnd_m, turning where no
constexpr double kLegEnd_m = 240.0;    // swath (even 2 x 25 m wide) can reach an object
constexpr double kSensorRequestPeriod_s = 10.0;
constexpr double kClassifyInterval_s = 5.0;

struct Waypoint {
  double x, y;
};

// Mail for one vehicle driving the waypoints at kSpeed_mps from `start_s`; returns the end time.
double drive(const std::string& name, const std::vector<Waypoint>& path, double start_s,
             double hz, std::vector<TimedMail>& mail) {
  double t = start_s;
  const double dt = 1.0 / hz;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double dx = path[i + 1].x - path[i].x, dy = path[i + 1].y - path[i].y;
    const double length = std::hypot(dx, dy);
    const double heading = base::norm360(std::atan2(dx, dy) * 180.0 / 3.14159265358979323846);
    const int steps = static_cast<int>(std::ceil(length / (kSpeed_mps * dt)));
    for (int k = 0; k < steps; ++k) {
      const double f = static_cast<double>(k) / steps;
      NodeReport r;
      r.name = name;
      r.x_m = path[i].x + f * dx;
      r.y_m = path[i].y + f * dy;
      r.speed_mps = kSpeed_mps;
      r.heading_deg = heading;
      mail.push_back({t, "NODE_REPORT", format_node_report(r)});
      t += length / kSpeed_mps / steps;
    }
  }
  return t;
}

std::vector<Waypoint> lawnmower(const std::vector<double>& legs_y) {
  std::vector<Waypoint> path;
  for (std::size_t i = 0; i < legs_y.size(); ++i) {
    const bool east = i % 2 == 0;
    path.push_back({east ? kLegStart_m : kLegEnd_m, legs_y[i]});
    path.push_back({east ? kLegEnd_m : kLegStart_m, legs_y[i]});
  }
  return path;
}

}  // namespace

Scenario reference_survey(double node_report_hz) {
  Scenario s;
  auto add = [&](const std::string& key, const std::string& value) {
    s.config.push_back({key, value, "scenario.moos", static_cast<int>(s.config.size()) + 1});
  };
  add("sensor_config", "width=25, exp=4, pclass=0.85");
  add("sensor_config", "width=50, exp=2, pclass=0.60");
  add("sensor_config", "width=10, exp=6, pclass=0.93");
  add("swath_length", "10");
  add("min_classify_interval", base::fmt(kClassifyInterval_s));
  add("random_seed", "2024");
  add("show_pfa", "true");
  add("show_detections", "60");
  std::vector<std::string> labels;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 10; ++j) {
      const int n = i * 10 + j;
      std::string line = "x=" + base::fmt(5 + 10 * i) + ",y=" + base::fmt(5 + 10 * j) + ",label=r" +
                         std::to_string(n) + ",type=" + (n % 3 == 0 ? "hazard" : "benign");
      if (n % 4 == 1) line += ",hr=0.5";
      if (n % 5 == 2) line += ",aspect=" + base::fmt((n * 37) % 180) + ",aspect_min=10,aspect_max=40";
      add("hazard", line);
      labels.push_back("r" + std::to_string(n));
    }
  }

  std::vector<TimedMail>& mail = s.mail;
  mail.push_back({0.0, "UHZ_CONFIG_REQUEST", format_config_request({"archie", 10.0, 0.9})});
  mail.push_back({0.0, "UHZ_CONFIG_REQUEST", format_config_request({"betty", 25.0, 0.8})});
  const double archie_end = drive("archie", lawnmower({10, 30, 50, 70, 90}), 0.5,
                                  node_report_hz, mail);
  const double betty_end = drive("betty", lawnmower({25, 75}), 0.5, node_report_hz, mail);
  const double survey_end = std::max(archie_end, betty_end);
  for (double t = 0.0; t <= survey_end; t += kSensorRequestPeriod_s) {
    for (const char* v : {"archie", "betty"}) {
      mail.push_back({t, "UHZ_SENSOR_REQUEST", format_sensor_request({v})});
    }
  }
  // Classification requests after the survey: every label; a few with priorities or top.
  const double ask_s = std::ceil(survey_end) + 1.0;
  for (const char* v : {"archie", "betty"}) {
    for (std::size_t i = 0; i < labels.size(); ++i) {
      ClassifyRequest r{v, labels[i], std::nullopt, ClassifyAction::kNormal};
      if (i % 7 == 3) r.priority = 80;
      if (i % 50 == 9) r.action = ClassifyAction::kTop;
      mail.push_back({ask_s, "UHZ_CLASSIFY_REQUEST", format_classify_request(r)});
    }
  }
  std::stable_sort(mail.begin(), mail.end(),
                   [](const TimedMail& a, const TimedMail& b) { return a.time_s < b.time_s; });
  s.end_time_s = ask_s + kClassifyInterval_s * (static_cast<double>(labels.size()) + 2);
  return s;
}

void play_mail(Driver& driver, const std::vector<TimedMail>& mail, double tick_hz, double end_s,
               const std::function<void(const Outputs&)>& on_mail,
               const std::function<void(const Outputs&)>& on_step) {
  std::size_t next = 0;
  for (long k = 0; static_cast<double>(k) / tick_hz <= end_s; ++k) {
    const double now_s = static_cast<double>(k) / tick_hz;
    for (; next < mail.size() && mail[next].time_s <= now_s; ++next) {
      const TimedMail& m = mail[next];
      const TimedOutputs out = driver.deliver(Mail{m.variable, m.value, m.time_s});
      if (on_mail) on_mail(out.outputs);
    }
    const TimedOutputs out = driver.step(now_s);
    if (on_step) on_step(out.outputs);
  }
}

std::string grid_field_text(int objects, double spacing_m) {
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(objects))));
  const double half_m = side * spacing_m / 2.0;
  std::string out;
  out.reserve(static_cast<std::size_t>(objects) * 48);
  for (int n = 0; n < objects; ++n) {
    // Deterministic jitter of up to a third of the spacing, from the label's hash.
    const std::uint64_t h = mix64(static_cast<std::uint64_t>(n));
    const double jx = (static_cast<double>(h % 1000) / 1000.0 - 0.5) * spacing_m / 1.5;
    const double jy = (static_cast<double>((h >> 20) % 1000) / 1000.0 - 0.5) * spacing_m / 1.5;
    const double x = (n % side) * spacing_m - half_m + jx;
    const double y = static_cast<double>(n / side) * spacing_m - half_m + jy;
    out += "hazard = x=" + base::fmt(x, 2) + ",y=" + base::fmt(y, 2) + ",label=g" + std::to_string(n) +
           ",type=" + (n % 3 == 0 ? "hazard" : "benign") + "\n";
  }
  return out;
}

}  // namespace hazard
