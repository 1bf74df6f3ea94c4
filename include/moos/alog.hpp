#pragma once
// pLogger's asynchronous log (.alog): a few header lines starting with "%%", then one line per
// posting: TIME VARIABLE SOURCE VALUE, separated by blanks, where TIME is seconds since the
// LOGSTART header (3 decimals) and VALUE is the rest of the line (it may contain blanks).
//
// Contract: format_alog_line() output parses back to the same entry, except that VALUE loses
// leading blanks and a value cannot contain a newline (such a value is written with each
// newline replaced by a blank, so one posting is always one line).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "moos/message.hpp"

namespace moos {

struct AlogEntry {
  double time_s = 0.0;  ///< seconds since LOGSTART (or the input's own time base)
  std::string variable;
  std::string source;
  std::string value;
};

/// An entry whose text columns are views (into a parsed line, or the caller's strings): for
/// readers and writers of large logs (hazard_replay) that copy nothing per line.
struct AlogEntryView {
  double time_s = 0.0;
  std::string_view variable;
  std::string_view source;
  std::string_view value;
};

/// Header lines: "%% LOG FILE: <name>", "%% LOGSTART <epoch>", and a rule of '%'.
std::string alog_header(std::string_view log_name, double logstart_epoch_s);

/// The VALUE column for a message: the shortest text that reads back as the same double,
/// the string itself, `<binary:N:HEX>` for binary data, `<not set>` for an unwritten variable.
std::string alog_value(const Message& msg);
/// The entry pLogger would write for a message, with its time relative to `logstart_s`.
AlogEntry alog_entry(const Message& msg, double logstart_s);

/// One line, newline-terminated.
std::string format_alog_line(const AlogEntry& entry);
/// The same line appended to `out`.
void append_alog_line(std::string& out, const AlogEntryView& entry);
/// The line in two parts, for a writer of many lines with the same time, variable and source
/// (hazard_replay: a hundred swath polygons per iteration): the TIME, VARIABLE and SOURCE
/// columns, and then the VALUE column with the newline. Together they are append_alog_line.
void append_alog_columns(std::string& out, double time_s, std::string_view variable,
                         std::string_view source);
void append_alog_value(std::string& out, std::string_view value);

/// kHeader: a line whose first non-blank characters are "%%" (the header, and the gap markers a
/// writer leaves where it dropped lines). kUnusableTime: TIME reads as a number but is not finite
/// or lies beyond kMaxAlogTimeS (`nan`, `-inf`, `1e300`): no clock wrote it, and a reader that
/// replays it would run for ever; readers skip such lines and say how many in one warning.
enum class AlogLineKind { kEntry, kHeader, kBlank, kMalformed, kUnusableTime };

/// The largest TIME magnitude a reader accepts, in seconds: above any epoch time (2286) and any
/// time since a LOGSTART.
inline constexpr double kMaxAlogTimeS = 1e10;

struct AlogParse {
  AlogLineKind kind = AlogLineKind::kBlank;
  AlogEntry entry;        ///< valid when kind == kEntry
  std::string error;      ///< why the line is malformed (kMalformed, kUnusableTime)
};

struct AlogViewParse {
  AlogLineKind kind = AlogLineKind::kBlank;
  AlogEntryView entry;  ///< views into the line; valid when kind == kEntry
  std::string error;    ///< why the line is malformed (kMalformed, kUnusableTime)
};

/// Classifies and parses one line (without its newline; a trailing CR is ignored).
AlogParse parse_alog_line(std::string_view line);
/// The same, without copying the columns (the line must outlive the entry).
AlogViewParse parse_alog_view(std::string_view line);

/// The one warning for `count` lines of kind kUnusableTime ("N lines with unusable times (not
/// finite, or beyond 1e10 s) skipped"); empty when `count` is 0.
std::string unusable_times_warning(std::size_t count);

/// The LOGSTART value of a header line ("%% LOGSTART 1700000000.0"), if it is one.
std::optional<double> alog_logstart(std::string_view header_line);

}  // namespace moos
