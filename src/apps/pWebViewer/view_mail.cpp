#include "view_mail.hpp"

#include <cmath>
#include <cstdio>

#include "base/text.hpp"

namespace web_viewer {

std::optional<Mail> from_message(const moos::Message& message) {
  if (!message.is_double() && !message.is_string()) return std::nullopt;
  Mail mail;
  mail.var = message.key;
  mail.src = message.source;
  mail.time_s = message.time;
  mail.is_double = message.is_double();
  mail.dval = message.dval;
  if (!mail.is_double) mail.sval = message.sval;
  return mail;
}

namespace {

bool is_continuation(std::string_view text, std::size_t i) {
  return i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80;
}

/// The length of the well-formed UTF-8 sequence (RFC 3629: no overlong form, no surrogate, at
/// most U+10FFFF) that starts at `pos`, a non-ASCII byte; 0 when none does.
std::size_t utf8_sequence_length(std::string_view text, std::size_t pos) {
  const auto lead = static_cast<unsigned char>(text[pos]);
  const auto second = pos + 1 < text.size() ? static_cast<unsigned char>(text[pos + 1]) : 0;
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;  // the second byte's range
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (second < low || second > high) return 0;
  for (std::size_t i = 2; i < length; ++i)
    if (!is_continuation(text, pos + i)) return 0;
  return length;
}

}  // namespace

std::string json_string(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) {
      // Valid UTF-8 is copied; a byte that is not part of it becomes the text \xNN.
      const std::size_t length = utf8_sequence_length(text, i);
      if (length == 0) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\\\x%02X", u);
        out += escaped;
      } else {
        out.append(text, i, length);
        i += length - 1;
      }
      continue;
    }
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        // Control characters, and the three characters that could end an inlined <script>.
        if (u < 0x20 || c == '<' || c == '>' || c == '&') {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", u);
          out += escaped;
        } else {
          out += c;
        }
    }
  }
  out += '"';
  return out;
}

std::string json_number(double value) {
  return std::isfinite(value) ? base::format_shortest(value) : std::string("null");
}

std::string mail_json(const Mail& mail) {
  return "{\"type\":\"mail\",\"var\":" + json_string(mail.var) +
         ",\"val\":" + (mail.is_double ? json_number(mail.dval) : json_string(mail.sval)) +
         ",\"src\":" + json_string(mail.src) + ",\"time\":" + json_number(mail.time_s) + "}";
}

std::string hello_json(const Hello& hello) {
  std::string buttons;
  for (const ButtonLabel& b : hello.buttons) {
    if (!buttons.empty()) buttons += ',';
    buttons += "{\"index\":" + std::to_string(b.index) + ",\"label\":" + json_string(b.label) + "}";
  }
  std::string out = "{\"type\":\"hello\",\"app\":\"pWebViewer\",\"community\":" +
                    json_string(hello.community) + ",\"time\":" + json_number(hello.time_s) +
                    ",\"warp\":" + json_number(hello.warp) + ",\"mode\":\"" +
                    (hello.replay ? "replay" : "live") + "\",\"buttons\":[" + buttons + "]" +
                    ",\"trail_length\":" + std::to_string(hello.trail_length) +
                    ",\"unlabelled_ring\":" + std::to_string(hello.unlabelled_ring);
  if (hello.lat_origin_deg && hello.lon_origin_deg)
    out += ",\"lat_origin\":" + json_number(*hello.lat_origin_deg) +
           ",\"lon_origin\":" + json_number(*hello.lon_origin_deg);
  return out + "}";
}

std::string clock_json(double time_s, double warp) {
  return "{\"type\":\"clock\",\"time\":" + json_number(time_s) + ",\"warp\":" + json_number(warp) + "}";
}

}  // namespace web_viewer
