#include "viewer_config.hpp"

#include "base/text.hpp"
#include "mission_app.hpp"
#include "request_guard.hpp"

namespace web_viewer {

namespace {

/// A whole number in [min, max] into `field`: "" when set, else the problem.
template <typename T>
std::string whole(const std::string& key, const std::string& value, long long min, long long max, T& field) {
  const auto n = base::parse_integer(value, min, max);
  if (!n) return key + "='" + base::excerpt(value) + "' is not a whole number in [" +
                 std::to_string(min) + ", " + std::to_string(max) + "]";
  field = static_cast<T>(*n);
  return std::string();
}

bool is_variable_name(std::string_view v) {
  return !v.empty() && v.find_first_of(" \t,=#") == std::string_view::npos;
}

// What the block says about the watch list, applied at the end (watch_defaults may come last).
struct WatchLines {
  bool defaults = true;
  std::vector<std::string> listed;
};

std::string apply_watch(const std::string& value, WatchLines& watch) {
  for (std::string_view v : base::split_trimmed(value, ',')) {
    if (v.empty()) continue;
    if (!is_variable_name(v)) return "watch: '" + base::excerpt(v) + "' is not a variable name";
    if (watch_contains(watch.listed, v)) continue;
    if (watch.listed.size() >= kMaxWatch)
      return "watch: more than " + std::to_string(kMaxWatch) + " variables";
    watch.listed.emplace_back(v);
  }
  return std::string();
}

std::string apply_allowed_hosts(const std::string& value, std::vector<std::string>& hosts) {
  for (std::string_view v : base::split_trimmed(value, ',')) {
    if (v.empty()) continue;
    if (!is_host_name(v)) return "allowed_hosts: '" + base::excerpt(v) + "' is not a host name";
    const std::string name = base::to_lower(v);
    if (watch_contains(hosts, name)) continue;
    if (hosts.size() >= kMaxAllowedHosts)
      return "allowed_hosts: more than " + std::to_string(kMaxAllowedHosts) + " names";
    hosts.push_back(name);
  }
  return std::string();
}

std::string apply(const moos::ConfigLine& line, ViewerConfig& config, WatchLines& watch) {
  const std::string key = base::to_lower(line.key);
  const std::string& value = line.value;
  RetentionLimits& keep = config.limits.retention;
  if (key == "http_port") return whole(key, value, 0, 65535, config.http.port);
  if (key == "http_bind") {
    if (value.empty() || value.find_first_of(" \t/") != std::string::npos)
      return "http_bind='" + base::excerpt(value) + "' is not an address";
    config.http.bind_address = value;
    return std::string();
  }
  if (key == "allowed_hosts") return apply_allowed_hosts(value, config.http.allowed_hosts);
  if (key == "watch") return apply_watch(value, watch);
  if (key == "watch_defaults") return mission_app::bool_param(key, value, watch.defaults);
  if (key == "appcast_request") return mission_app::bool_param(key, value, config.appcast_request);
  if (const auto index = button_index(key)) {
    std::string problem;
    auto button = parse_button(*index, value, &problem);
    if (!button) return key + ": " + problem;
    for (Button& b : config.buttons)
      if (b.index == *index) {
        b = std::move(*button);
        return std::string();
      }
    config.buttons.push_back(std::move(*button));
    return std::string();
  }
  if (key == "trail_length") return whole(key, value, 1, 100000, keep.trail_length);
  if (key == "max_vehicles") return whole(key, value, 1, 10000, keep.max_vehicles);
  if (key == "max_labels") return whole(key, value, 1, 1000000, keep.max_labels);
  if (key == "unlabelled_ring") return whole(key, value, 0, 1000000, keep.unlabelled_ring);
  if (key == "max_appcasts") return whole(key, value, 1, 100000, keep.max_appcasts);
  if (key == "max_value_bytes") return whole(key, value, 64, 16 << 20, keep.max_value_bytes);
  if (key == "max_clients") return whole(key, value, 1, 64, config.limits.max_clients);
  if (key == "max_queued") return whole(key, value, 100, 10000000, config.limits.max_queued);
  return "unknown parameter '" + base::excerpt(line.key) + "'";
}

}  // namespace

bool watch_contains(const std::vector<std::string>& watch, std::string_view var) {
  for (const std::string& w : watch)
    if (w == var) return true;
  return false;
}

const std::vector<std::string>& default_watch() {
  static const std::vector<std::string> kDefault = {
      "NODE_REPORT", "VIEW_MARKER", "VIEW_POLYGON",      "VIEW_CIRCLE",    "VIEW_SEGLIST",
      "VIEW_POINT",  "APPCAST",     "UHZ_MISSION_SCORE", "HAZARD_SEARCH_SCORE", "HAZARDSET_EVAL"};
  return kDefault;
}

Hello configured_hello(const ViewerConfig& config) {
  Hello h;
  for (const Button& b : config.buttons) h.buttons.push_back({b.index, b.label});
  h.trail_length = config.limits.retention.trail_length;
  h.unlabelled_ring = config.limits.retention.unlabelled_ring;
  return h;
}

ViewerConfig read_viewer_config(const std::vector<moos::ConfigLine>& lines,
                                std::vector<std::string>* warnings) {
  ViewerConfig config;
  WatchLines watch;
  for (const moos::ConfigLine& line : lines) {
    const std::string problem = apply(line, config, watch);
    if (!problem.empty()) warnings->push_back(mission_app::at_line(line, problem));
  }
  if (!watch.defaults) config.watch.clear();
  for (const std::string& w : watch.listed)
    if (!watch_contains(config.watch, w)) config.watch.push_back(w);
  return config;
}

}  // namespace web_viewer
