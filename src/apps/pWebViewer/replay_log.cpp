#include "replay_log.hpp"

#include <filesystem>

#include "base/line_stream.hpp"
#include "base/text.hpp"
#include "moos/alog.hpp"
#include "moos/wildcard.hpp"

namespace web_viewer {

bool watch_matches(const std::vector<std::string>& watch, const std::string& var) {
  for (const std::string& w : watch)
    if (w == var || moos::wildcard_match(w, var)) return true;
  return false;
}

namespace {

void add_skip_warnings(const std::string& path, const base::LineStream& in,
                       const ReplayLimits& limits, ReplayLog& log) {
  if (log.unusable_times > 0) {
    log.warnings.push_back(path + ": " + moos::unusable_times_warning(log.unusable_times));
  }
  if (in.long_lines() > 0) {
    log.warnings.push_back(path + ": " +
                           base::long_lines_warning(in.long_lines(), limits.max_line_bytes));
  }
  if (!in.error().empty()) log.warnings.push_back(path + ": " + in.error());
}

}  // namespace

std::optional<ReplayLog> read_replay_log(const std::string& path, const std::vector<std::string>& watch,
                                         const ReplayLimits& limits, std::string* error) {
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  base::Result<base::LineStream> opened = base::LineStream::open(path, limits.max_line_bytes);
  if (ec || !opened) {
    *error = path + ": cannot read the log";
    return std::nullopt;
  }
  if (bytes > limits.max_file_bytes) {
    *error = path + ": the log has " + std::to_string(bytes) + " bytes, more than the limit of " +
             std::to_string(limits.max_file_bytes);
    return std::nullopt;
  }
  base::LineStream& in = *opened.value;
  ReplayLog log;
  for (std::optional<std::string_view> line; (line = in.next());) {
    log.lines = in.line_number();
    if (log.lines > limits.max_lines) {
      *error = path + ":" + std::to_string(log.lines) + ": more than " +
               std::to_string(limits.max_lines) + " lines";
      return std::nullopt;
    }
    const moos::AlogParse parsed = moos::parse_alog_line(*line);
    if (parsed.kind == moos::AlogLineKind::kHeader) {
      if (const auto start = moos::alog_logstart(*line)) log.logstart_s = *start;
      continue;
    }
    if (parsed.kind == moos::AlogLineKind::kMalformed) ++log.malformed;
    if (parsed.kind == moos::AlogLineKind::kUnusableTime) ++log.unusable_times;
    if (parsed.kind != moos::AlogLineKind::kEntry || !watch_matches(watch, parsed.entry.variable)) continue;
    if (log.mail.size() >= limits.max_mail) {
      *error = path + ":" + std::to_string(log.lines) + ": more than " +
               std::to_string(limits.max_mail) + " watched postings";
      return std::nullopt;
    }
    Mail m;
    m.var = parsed.entry.variable;
    m.src = parsed.entry.source;
    m.time_s = log.logstart_s + parsed.entry.time_s;
    if (const auto number = base::parse_number(parsed.entry.value)) {
      m.is_double = true;
      m.dval = *number;
    } else {
      m.sval = parsed.entry.value;
    }
    log.mail.push_back(std::move(m));
  }
  add_skip_warnings(path, in, limits, log);
  return log;
}

std::string replay_json(const Hello& hello, const std::vector<Mail>& mail) {
  std::string out = "{\"hello\":" + hello_json(hello) + ",\"mail\":[";
  bool first = true;
  for (const Mail& m : mail) {
    if (!first) out += ",\n";
    first = false;
    out += mail_json(m);
  }
  return out + "]}";
}

}  // namespace web_viewer
