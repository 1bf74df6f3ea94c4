#include "LogLite.hpp"

#include <ctime>
#include <filesystem>

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

LogLite::LogLite() : mission_app::MissionApp(logger_traits()) {}

LogLite::~LogLite() { close(); }

void LogLite::close() {
  std::string problem;
  if (out_ && !out_->commit(problem)) write_failed(problem);
  out_.reset();
}

void LogLite::write_failed(const std::string& problem) {
  if (write_failed_) return;
  write_failed_ = true;
  report_run_warning(problem);
}

std::string LogLite::open_log(const std::string& name) {
  std::string problem;
  out_ = base::OutputFile::open(file_path_, base::OutputMode::kInPlace, problem);
  const std::string header = moos::alog_header(name + ".alog", start_time());
  if (out_ && out_->write(header, problem) && out_->flush(problem)) return "";
  out_.reset();
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
  if (const std::string problem = open_log(name); !problem.empty()) {
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
  if (!out_) return;
  for (const moos::Message& m : mail) {
    if (omitted(m.key)) continue;
    const std::string line = moos::format_alog_line(moos::alog_entry(m, start_time()));
    std::string problem;
    if (!out_->write(line, problem)) write_failed(problem);
    ++lines_written_;
  }
}

void LogLite::on_iterate() {
  std::string problem;
  if (out_ && !write_failed_ && !out_->flush(problem)) write_failed(problem);
}

std::string LogLite::build_report() {
  std::string out;
  out += "File:     " + file_path_ + "\n";
  out += "Lines:    " + std::to_string(lines_written_) + "\n";
  out += std::string("Logging:  ") + (wildcard_logging_ ? "every variable" : "listed variables") +
         ", " + std::to_string(requests_.size()) + " log lines, " +
         std::to_string(omit_patterns_.size()) + " omit patterns\n";
  return out;
}

}  // namespace plog_lite
