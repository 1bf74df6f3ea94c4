#include "moos/alog.hpp"

#include <charconv>
#include <cstdio>
#include <system_error>

#include "base/text.hpp"

namespace moos {

namespace {

constexpr std::string_view kBlanks = " \t";

std::string_view trim_right_cr(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

// Splits off the next blank-separated token; returns an empty view at the end of the line.
std::string_view next_token(std::string_view& rest) {
  const auto start = rest.find_first_not_of(kBlanks);
  if (start == std::string_view::npos) {
    rest = {};
    return {};
  }
  rest.remove_prefix(start);
  const auto end = rest.find_first_of(kBlanks);
  const std::string_view token = rest.substr(0, end);
  rest.remove_prefix(end == std::string_view::npos ? rest.size() : end);
  return token;
}

void append_padded(std::string& out, std::string_view text, std::size_t width) {
  out.append(text);
  out.append(text.size() < width ? width - text.size() : 0, ' ');
  out.push_back(' ');
}

constexpr char kHexDigits[] = "0123456789abcdef";

}  // namespace

std::string alog_value(const Message& msg) {
  switch (msg.data_type) {
    case data_type::kDouble: {
      char text[64];
      const auto [end, error] = std::to_chars(text, text + sizeof text, msg.dval);
      return error == std::errc() ? std::string(text, end) : std::string("nan");
    }
    case data_type::kBinary: {
      std::string out = "<binary:" + std::to_string(msg.sval.size()) + ":";
      for (const unsigned char c : msg.sval) {
        out.push_back(kHexDigits[c >> 4]);
        out.push_back(kHexDigits[c & 0x0f]);
      }
      return out + ">";
    }
    case data_type::kNotSet:
      return "<not set>";
    default:
      return msg.sval;
  }
}

AlogEntry alog_entry(const Message& msg, double logstart_s) {
  return AlogEntry{msg.time - logstart_s, msg.key, msg.source, alog_value(msg)};
}

std::string alog_header(std::string_view log_name, double logstart_epoch_s) {
  char start[64];
  std::snprintf(start, sizeof start, "%.3f", logstart_epoch_s);
  std::string out;
  out += "%% LOG FILE:       ";
  out += log_name;
  out += "\n%% LOGSTART           ";
  out += start;
  out += "\n%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%\n";
  return out;
}

namespace {

// A VARIABLE or SOURCE column: one word, whatever a client sent. Blanks would shift the
// columns and a newline would forge a record, so both are escaped (issue 12).
std::string column_text(std::string_view text) {
  if (text.empty()) return "_";
  std::string out = base::escape_for_log(text);
  std::string::size_type blank = 0;
  while ((blank = out.find(' ', blank)) != std::string::npos) out.replace(blank, 1, "\\x20");
  return out;
}

}  // namespace

std::string format_alog_line(const AlogEntry& entry) {
  char time[64];
  std::snprintf(time, sizeof time, "%.3f", entry.time_s);
  std::string out;
  out.reserve(48 + entry.variable.size() + entry.value.size());
  append_padded(out, time, 10);
  append_padded(out, column_text(entry.variable), 20);
  append_padded(out, column_text(entry.source), 16);
  for (char c : entry.value) out.push_back(c == '\n' || c == '\r' ? ' ' : c);
  out.push_back('\n');
  return out;
}

AlogParse parse_alog_line(std::string_view line) {
  AlogParse result;
  line = trim_right_cr(line);
  if (line.find_first_not_of(kBlanks) == std::string_view::npos) return result;
  if (line.substr(line.find_first_not_of(kBlanks), 2) == "%%") {
    result.kind = AlogLineKind::kHeader;
    return result;
  }
  std::string_view rest = line;
  const std::string_view time = next_token(rest);
  const std::string_view variable = next_token(rest);
  const std::string_view source = next_token(rest);
  const auto value_start = rest.find_first_not_of(kBlanks);
  const std::string_view value =
      value_start == std::string_view::npos ? std::string_view{} : rest.substr(value_start);
  const auto t = base::parse_number(time);
  if (!t) {
    result.kind = AlogLineKind::kMalformed;
    result.error = "time '" + std::string(time) + "' is not a finite number";
    return result;
  }
  if (variable.empty() || source.empty()) {
    result.kind = AlogLineKind::kMalformed;
    result.error = "expected TIME VARIABLE SOURCE VALUE";
    return result;
  }
  result.kind = AlogLineKind::kEntry;
  result.entry = AlogEntry{*t, std::string(variable), std::string(source), std::string(value)};
  return result;
}

std::optional<double> alog_logstart(std::string_view header_line) {
  std::string_view rest = trim_right_cr(header_line);
  if (next_token(rest) != "%%") return std::nullopt;
  if (next_token(rest) != "LOGSTART") return std::nullopt;
  return base::parse_number(next_token(rest));
}

}  // namespace moos
