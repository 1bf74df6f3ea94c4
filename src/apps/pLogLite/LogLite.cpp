#include "LogLite.hpp"

#include <ctime>
#include <filesystem>
#include <iostream>

#include "base/text.hpp"
#include "moos/alog.hpp"
#include "moos/wildcard.hpp"

namespace plog_lite {

moos::AppTraits logger_traits() { return mission_app::mission_traits(kAppName, kDefaultAppTick_hz); }

std::optional<LogRequest> parse_log_request(std::string_view text) {
  LogRequest r;
  const auto at = text.find('@');
  r.variable = std::string(base::trim(text.substr(0, at)));
  if (r.variable.empty() || r.variable.find_first_of(" \t,") != std::string::npos) return std::nullopt;
  if (at != std::string_view::npos) {
    const auto interval = base::parse_number(base::trim(text.substr(at + 1)));
    if (!interval || *interval < 0.0) return std::nullopt;
    r.interval_s = *interval;
  }
  return r;
}

std::string file_time_stamp(double unix_s) {
  const std::time_t t = static_cast<std::time_t>(unix_s);
  std::tm local{};
  ::localtime_r(&t, &local);
  char text[64];
  std::strftime(text, sizeof text, "_%Y_%m_%d_____%H_%M_%S", &local);
  return text;
}

LogLite::LogLite(std::shared_ptr<LogOutcome> outcome)
    : mission_app::MissionApp(logger_traits()), outcome_(std::move(outcome)) {}

LogLite::~LogLite() { close(); }

void LogLite::close() {
  if (!log_) return;
  closing_ = true;
  std::string problem;
  log_->close(problem);
  if (!problem.empty()) std::cerr << kAppName << ": the log is not whole: " << problem << std::endl;
  if (outcome_) *outcome_ = LogOutcome{log_->records_written(), log_->records_lost(), problem};
  log_.reset();
}

void LogLite::log_notice(const std::string& text) {
  if (!closing_) report_run_warning("log " + text);
  std::cerr << kAppName << ": log " << text << std::endl;
}

std::string LogLite::open_log() {
  moos::AlogFileOptions options;
  options.notice = [this](const std::string& text) { log_notice(text); };
  std::string problem;
  log_ = moos::AlogFile::open(file_path_, start_time(), std::move(options), problem);
  return problem;
}

std::string LogLite::apply(const moos::ConfigLine& line) {
  const std::string key = base::to_lower(line.key);
  const std::string& value = line.value;
  auto boolean = [&](bool& field) { return mission_app::bool_param(key, value, field); };
  if (key == "path") {
    if (value.empty()) return "parameter path is empty";
    path_ = value;
  } else if (key == "file") {
    if (value.empty() || value.find('/') != std::string::npos)
      return "parameter file='" + value + "' is not a file name";
    file_ = value;
  } else if (key == "file_timestamp" || key == "filetimestamp") {
    return boolean(file_timestamp_);
  } else if (key == "wildcard_logging" || key == "wildcardlogging") {
    return boolean(wildcard_logging_);
  } else if (key == "async_log" || key == "asynclog") {
    bool async = true;
    std::string problem = boolean(async);
    if (problem.empty() && !async) problem = "async_log = false (synchronous logs) is not supported";
    return problem;
  } else if (key == "log") {
    auto request = parse_log_request(value);
    if (!request) return "parameter log='" + value + "' is not VAR @ interval";
    requests_.push_back(*request);
  } else if (key == "wildcard_omit_pattern" || key == "wildcardomitpattern") {
    for (std::string_view p : base::split_trimmed(value, ','))
      if (!p.empty()) omit_patterns_.emplace_back(p);
  } else {
    return "unknown parameter '" + line.key + "'";
  }
  return std::string();
}

bool LogLite::on_start_up() {
  apply_config_lines([&](const moos::ConfigLine& line) { return apply(line); });
  if (!wildcard_logging_ && requests_.empty())
    report_config_warning("nothing to log: set wildcard_logging = true or add log = VAR lines");

  const std::string name = file_ + (file_timestamp_ ? file_time_stamp(start_time() / comms().time_warp()) : "");
  const std::filesystem::path folder(path_);
  std::error_code ignored;
  std::filesystem::create_directories(folder, ignored);
  file_path_ = (folder / (name + ".alog")).string();
  if (const std::string problem = open_log(); !problem.empty()) {
    report_config_warning("the log file: " + problem);
    return false;
  }

  if (wildcard_logging_) register_wildcard("*", "*");
  for (const LogRequest& r : requests_) register_variable(r.variable, r.interval_s);
  return true;
}

bool LogLite::omitted(const std::string& variable) const {
  for (const std::string& p : omit_patterns_)
    if (moos::wildcard_match(p, variable)) return true;
  return false;
}

void LogLite::on_new_mail(const std::vector<moos::Message>& mail) {
  if (!log_) return;
  for (const moos::Message& m : mail)
    if (!omitted(m.key)) log_->add(m, cycle_time());
}

void LogLite::on_iterate() {
  if (log_) log_->pump();
}

std::string LogLite::build_report() {
  std::string out;
  out += "File:     " + file_path_ + "\n";
  if (log_) {
    out += "Records:  " + std::to_string(log_->records_written()) + " written, " +
           std::to_string(log_->records_lost()) + " lost";
    if (log_->times_clamped() > 0)
      out += ", " + std::to_string(log_->times_clamped()) + " times clamped";
    if (log_->reopened() > 0)
      out += ", file created again " + std::to_string(log_->reopened()) + "x";
    out += "\n";
  }
  out += std::string("Logging:  ") + (wildcard_logging_ ? "every variable" : "listed variables") +
         ", " + std::to_string(requests_.size()) + " log lines, " +
         std::to_string(omit_patterns_.size()) + " omit patterns\n";
  return out;
}

}  // namespace plog_lite
