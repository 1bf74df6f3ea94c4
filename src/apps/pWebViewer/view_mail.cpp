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

std::string json_string(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
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
