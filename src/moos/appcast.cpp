// AppCast model, string and terminal frame. Follows docs/protocol.md 7.2 (the core-moos AppCast
// layout, byte for byte) and docs/uFldHazardSensor.md; contract in include/moos/appcast.hpp.

#include "moos/appcast.hpp"

#include <algorithm>

#include "base/text.hpp"

namespace moos {

namespace {
constexpr std::string_view kOuterSeparator = "!@#";
constexpr std::string_view kInnerSeparator = "!@";
/// Width of the terminal header line and its '=' rules (docs/uFldHazardSensor.md).
constexpr std::size_t kHeaderWidth = 62;
/// Width of the '=' rules around the events list (core-moos terminal layout).
constexpr std::size_t kEventsRuleWidth = 67;
constexpr int kEventTimeDecimals = 2;
/// "[" and "]: " around the time, and room for its digits.
constexpr std::size_t kEventPrefixBytes = 24;

template <typename Container>
std::string join_inner(const Container& items) {
  std::string out;
  bool first = true;
  for (const auto& s : items) {
    if (!first) out += kInnerSeparator;
    first = false;
    out += s;
  }
  return out;
}
}  // namespace

void AppCast::set_max_events(std::size_t max_events) {
  max_events_ = std::min(max_events, kMaxEventsLimit);
  while (events_.size() > max_events_) events_.pop_front();
}

void AppCast::add_event(const std::string& text, double seconds_since_start) {
  // A full list's oldest line lends its buffer to the new one: a busy sensor reports an event
  // for every detection and every classify request.
  std::string line;
  if (!events_.empty() && events_.size() >= max_events_) {
    line = std::move(events_.front());
    events_.pop_front();
    line.clear();
  }
  line.reserve(text.size() + kEventPrefixBytes);
  line += '[';
  base::append_fix(line, seconds_since_start, kEventTimeDecimals);
  line += "]: ";
  line += text;
  events_.push_back(std::move(line));
  while (events_.size() > max_events_) events_.pop_front();
}

void AppCast::add_config_warning(const std::string& text) {
  if (config_warnings_.size() >= kMaxConfigWarnings) {
    ++config_warnings_dropped_;
    return;
  }
  config_warnings_.push_back(text);
}

void AppCast::add_run_warning(const std::string& text) {
  // A full table sends every further report, even of a listed text, to the "other" line
  // (core-moos AppCast behaviour).
  if (run_warnings_.size() < max_run_warnings_)
    ++run_warnings_[text];
  else
    ++run_warnings_[std::string(kOtherRunWarnings)];
  ++run_warning_count_;
}

bool AppCast::retract_run_warning(const std::string& text) {
  auto it = run_warnings_.find(text);
  if (it == run_warnings_.end()) return false;
  run_warning_count_ -= std::min(run_warning_count_, it->second);
  run_warnings_.erase(it);
  return true;
}

std::string AppCast::appcast_string() const {
  const std::string iter = std::to_string(iteration_);
  std::string out;
  auto item = [&](std::string_view text) {
    out += text;
    out += kOuterSeparator;
  };
  item("proc=" + proc_);
  item("iter=" + iter);
  if (!node_.empty()) item("node=" + node_);
  item("iter=" + iter);

  // Each body line followed by the inner separator; a final '\n' adds no empty line.
  std::string messages = "messages=";
  std::size_t pos = 0;
  while (pos < messages_.size()) {
    const auto nl = messages_.find('\n', pos);
    const std::size_t end = nl == std::string::npos ? messages_.size() : nl;
    messages.append(messages_, pos, end - pos);
    messages += kInnerSeparator;
    pos = end + 1;
  }
  item(messages);

  item(config_warnings_.empty() ? std::string() : "config_warnings=" + join_inner(config_warnings_));
  item("events_total=" + std::to_string(events_.size()));
  item(events_.empty() ? std::string() : "events=" + join_inner(events_));

  item("run_warning_total=" + std::to_string(run_warning_count_));
  if (!run_warnings_.empty()) {
    out += "run_warnings=";
    bool first = true;
    for (const auto& [warning, count] : run_warnings_) {
      if (!first) out += kInnerSeparator;
      first = false;
      out += std::to_string(count) + ":" + warning;
    }
  }
  return out;
}

std::string AppCast::terminal_report() const {
  const std::string rule(kHeaderWidth, '=');
  const std::string title = proc_ + " " + node_;
  const std::string warnings =
      std::to_string(config_warnings_.size()) + "/" + std::to_string(run_warning_count_);
  const std::string iter = "(" + std::to_string(iteration_) + ")";
  const std::size_t used = title.size() + warnings.size() + iter.size();
  const std::string pad(used < kHeaderWidth ? kHeaderWidth - used : 0, ' ');

  std::string out = rule + "\n" + title + pad + warnings + iter + "\n" + rule + "\n";
  if (!config_warnings_.empty()) {
    const std::string n = std::to_string(config_warnings_.size());
    out += "Configuration Warnings: " + n + "\n";
    for (std::size_t j = 0; j < config_warnings_.size(); ++j)
      out += " [" + std::to_string(j + 1) + " of " + n + "]: " + config_warnings_[j] + "\n";
    out += "\n";
  }
  if (run_warning_count_ > 0) {
    out += "Runtime Warnings: " + std::to_string(run_warning_count_) + "\n";
    for (const auto& [warning, count] : run_warnings_)
      out += " [" + std::to_string(count) + "]: " + warning + "\n";
    out += "\n";
  }
  out += messages_ + "\n";
  if (!events_.empty()) {
    const std::string events_rule(kEventsRuleWidth, '=');
    out += events_rule + "\nMost Recent Events (" + std::to_string(events_.size()) + "):\n" +
           events_rule + "\n";
    for (auto it = events_.rbegin(); it != events_.rend(); ++it) out += *it + "\n";
  }
  return out;
}

std::optional<AppCastRequest> parse_appcast_request(std::string_view request, std::string_view node,
                                                    std::string_view app) {
  AppCastRequest out;
  std::string duration;
  for (std::string_view item : base::split(request, ',')) {
    const auto eq = item.find('=');
    const std::string param = base::to_upper(base::trim(item.substr(0, eq)));
    const std::string value(eq == std::string_view::npos ? std::string_view() : base::trim(item.substr(eq + 1)));
    if (param == "NODE") {
      if (value != node && value != "all") return std::nullopt;
    } else if (param == "APP") {
      if (value != app && value != "all") return std::nullopt;
    } else if (param == "DURATION") {
      duration = value;
    } else if (param == "THRESH") {
      out.thresh = value;
    } else if (param == "KEY") {
      out.key = value;
    }
  }
  if (out.key.empty()) return std::nullopt;
  // libMOOS reads the duration with atof: text that is not a number counts as 0.
  const double d = base::parse_number(duration).value_or(0.0);
  out.duration_s = std::clamp(d, 0.0, kMaxAppCastRequestDuration_s);
  return out;
}

}  // namespace moos
