#pragma once
// Replay: the watched postings of an .alog as Mail, and the JSON that drives the page from them
// (GET /replay.json, and the self-contained HTML file of --export).
//
// Contract
// - The log is read with libmoos's line parser (moos/alog.hpp). Times become MOOS times:
//   LOGSTART + the line's time (the header's LOGSTART; 0 without one).
// - Only watched variables are kept (watch_matches). A VALUE that is a number (base grammar)
//   becomes a double, as the log does not record the type.
// - Bounds, each an error naming the file (and line): the file at most max_file_bytes, at most
//   max_lines lines, at most max_mail kept postings. Malformed lines are skipped and counted;
//   lines with unusable times (moos::AlogLineKind::kUnusableTime) and lines over max_line_bytes
//   are skipped with one warning each kind, with its count (ReplayLog::warnings). The file is
//   read a line at a time (base::LineStream): a line is never held beyond max_line_bytes.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "view_mail.hpp"

namespace web_viewer {

struct ReplayLimits {
  std::uintmax_t max_file_bytes = std::uintmax_t(2) << 30;  ///< 2 GiB
  std::size_t max_lines = 50'000'000;
  std::size_t max_mail = 5'000'000;
  std::size_t max_line_bytes = std::size_t(1) << 20;  ///< 1 MiB
};

struct ReplayLog {
  double logstart_s = 0.0;
  std::vector<Mail> mail;      ///< in file order
  std::size_t lines = 0;
  std::size_t malformed = 0;
  std::size_t unusable_times = 0;
  std::vector<std::string> warnings;  ///< one per kind of skipped line, naming the file
};

/// True when `var` is one of the watched variables (entries may use * and ?).
bool watch_matches(const std::vector<std::string>& watch, const std::string& var);

std::optional<ReplayLog> read_replay_log(const std::string& path, const std::vector<std::string>& watch,
                                         const ReplayLimits& limits, std::string* error);

/// {"hello": <hello>, "mail": [<mail>, ...]}
std::string replay_json(const Hello& hello, const std::vector<Mail>& mail);

}  // namespace web_viewer
