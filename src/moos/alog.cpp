#include "moos/alog.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "base/text.hpp"

namespace moos {

namespace {

// The column separators, space and tab (a test per byte, not a search through a set: replays
// read millions of lines).
bool is_blank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim_right_cr(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

void skip_blanks(std::string_view& rest) {
  std::size_t i = 0;
  while (i < rest.size() && is_blank(rest[i])) ++i;
  rest.remove_prefix(i);
}

// Splits off the next blank-separated token; returns an empty view at the end of the line.
std::string_view next_token(std::string_view& rest) {
  skip_blanks(rest);
  std::size_t end = 0;
  while (end < rest.size() && !is_blank(rest[end])) ++end;
  const std::string_view token = rest.substr(0, end);
  rest.remove_prefix(end);
  return token;
}

void pad_column(std::string& out, std::size_t written, std::size_t width) {
  out.append(written < width ? width - written : 0, ' ');
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

// Bytes a VARIABLE or SOURCE column cannot hold as they are (column_text).
bool needs_escape(char c) {
  const auto b = static_cast<unsigned char>(c);
  return b < 0x20 || b == 0x7F || c == '\\' || c == ' ';
}

// A VARIABLE or SOURCE column: one word, whatever a client sent, padded to `width`. Blanks
// would shift the columns and a newline would forge a record, so both are escaped.
void append_column(std::string& out, std::string_view text, std::size_t width) {
  const std::size_t at = out.size();
  if (text.empty()) {
    out.push_back('_');
  } else if (std::none_of(text.begin(), text.end(), needs_escape)) {
    out.append(text);  // the common case, without building the escaped copy
  } else {
    std::string escaped = base::escape_for_log(text);
    std::string::size_type blank = 0;
    while ((blank = escaped.find(' ', blank)) != std::string::npos) {
      escaped.replace(blank, 1, "\\x20");
    }
    out.append(escaped);
  }
  pad_column(out, out.size() - at, width);
}

}  // namespace

void append_alog_columns(std::string& out, double time_s, std::string_view variable,
                         std::string_view source) {
  const std::size_t at = out.size();
  base::append_fix(out, time_s, 3);  // printf's "%.3f" (base::fix)
  pad_column(out, out.size() - at, 10);
  append_column(out, variable, 20);
  append_column(out, source, 16);
}

void append_alog_value(std::string& out, std::string_view value) {
  const std::size_t value_at = out.size();
  out.append(value);
  // Two vectorised searches find the rare line break; the byte loop runs only then.
  if (!value.empty() && (std::memchr(value.data(), '\n', value.size()) != nullptr ||
                         std::memchr(value.data(), '\r', value.size()) != nullptr)) {
    std::replace_if(out.begin() + static_cast<std::ptrdiff_t>(value_at), out.end(),
                    [](char c) { return c == '\n' || c == '\r'; }, ' ');
  }
  out.push_back('\n');
}

void append_alog_line(std::string& out, const AlogEntryView& entry) {
  append_alog_columns(out, entry.time_s, entry.variable, entry.source);
  append_alog_value(out, entry.value);
}

std::string format_alog_line(const AlogEntry& entry) {
  std::string out;
  out.reserve(48 + entry.variable.size() + entry.value.size());
  append_alog_line(out, {entry.time_s, entry.variable, entry.source, entry.value});
  return out;
}

namespace {

// A TIME token that is a number, though perhaps not a finite one ("nan", "-inf", "1e400"): as
// strtod reads it, every byte used.
bool reads_as_double(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return end == token.data() + token.size() && !token.empty() &&
         (error == std::errc() || error == std::errc::result_out_of_range);
}

}  // namespace

std::string unusable_times_warning(std::size_t count) {
  if (count == 0) return {};
  return std::to_string(count) + (count == 1 ? " line" : " lines") +
         " with unusable times (not finite, or beyond 1e10 s) skipped";
}

AlogViewParse parse_alog_view(std::string_view line) {
  AlogViewParse result;
  std::string_view rest = trim_right_cr(line);
  skip_blanks(rest);
  if (rest.empty()) return result;
  if (rest.substr(0, 2) == "%%") {
    result.kind = AlogLineKind::kHeader;
    return result;
  }
  const std::string_view time = next_token(rest);
  const std::string_view variable = next_token(rest);
  const std::string_view source = next_token(rest);
  skip_blanks(rest);
  const std::string_view value = rest;
  const auto t = base::parse_number(time);
  if (!t || std::fabs(*t) > kMaxAlogTimeS) {
    const bool number = reads_as_double(time);
    result.kind = number ? AlogLineKind::kUnusableTime : AlogLineKind::kMalformed;
    result.error = "time '" + base::log_excerpt(time) +
                   (number ? "' is not finite or beyond 1e10 s" : "' is not a finite number");
    return result;
  }
  if (variable.empty() || source.empty()) {
    result.kind = AlogLineKind::kMalformed;
    result.error = "expected TIME VARIABLE SOURCE VALUE";
    return result;
  }
  result.kind = AlogLineKind::kEntry;
  result.entry = AlogEntryView{*t, variable, source, value};
  return result;
}

AlogParse parse_alog_line(std::string_view line) {
  AlogViewParse view = parse_alog_view(line);
  AlogParse result;
  result.kind = view.kind;
  result.error = std::move(view.error);
  const AlogEntryView& e = view.entry;
  if (view.kind == AlogLineKind::kEntry) {
    result.entry = AlogEntry{e.time_s, std::string(e.variable), std::string(e.source),
                             std::string(e.value)};
  }
  return result;
}

std::optional<double> alog_logstart(std::string_view header_line) {
  std::string_view rest = trim_right_cr(header_line);
  if (next_token(rest) != "%%") return std::nullopt;
  if (next_token(rest) != "LOGSTART") return std::nullopt;
  return base::parse_number(next_token(rest));
}

}  // namespace moos
