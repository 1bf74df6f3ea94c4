// Fuzz target: what pWebViewer reads of a request before any route (request_guard.hpp) and how
// it writes a MOOS string into the page's JSON (view_mail.hpp). The input's lines are the
// method, Host, Origin, Sec-Fetch-Site and token headers (an empty line: header absent); the
// whole input is also written as a JSON string. Checked: a state-changing request passes only
// with the run's token, and the JSON text is one line of valid UTF-8.

#include <cstdlib>

#include "fuzz_input.hpp"
#include "request_guard.hpp"
#include "view_mail.hpp"

namespace {

std::optional<std::string> header(const std::vector<std::string_view>& lines, std::size_t i) {
  if (i >= lines.size() || lines[i].empty()) return std::nullopt;
  return std::string(lines[i]);
}

/// Whether `text` is well-formed UTF-8 (no overlongs, no surrogates, at most U+10FFFF).
bool valid_utf8(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    const std::size_t length = b < 0x80           ? 1
                               : (b >> 5) == 0x6  ? 2
                               : (b >> 4) == 0xE  ? 3
                               : (b >> 3) == 0x1E ? 4
                                                  : 0;
    if (length == 0 || i + length > text.size()) return false;
    std::uint32_t code = length == 1 ? b : b & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) {
      const auto c = static_cast<unsigned char>(text[i + k]);
      if ((c >> 6) != 0x2) return false;
      code = (code << 6) | (c & 0x3F);
    }
    const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
      return false;
    }
    i += length;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = fuzz::as_text(data, size);
  const std::vector<std::string_view> lines = fuzz::lines_of(text);

  web_viewer::GuardConfig config;
  config.bind_address = "127.0.0.1";
  config.port = 8080;
  config.allowed_hosts = {"viewer.example"};
  config.token = "0123456789abcdef0123456789abcdef";
  web_viewer::RequestFacts request;
  request.method = lines.empty() ? "GET" : std::string(lines[0]);
  request.host = header(lines, 1);
  request.host_headers = request.host ? 1 : 0;
  request.origin = header(lines, 2);
  request.sec_fetch_site = header(lines, 3);
  request.token = header(lines, 4);
  const bool passes = !web_viewer::check_request(config, request);
  const bool reads_only =
      request.method == "GET" || request.method == "HEAD" || request.method == "OPTIONS";
  if (passes && !reads_only && request.token != config.token) std::abort();
  if (passes && !request.host) std::abort();
  (void)web_viewer::is_host_name(text);

  const std::string json = web_viewer::json_string(text);
  if (!valid_utf8(json) || json.find('\n') != std::string::npos) std::abort();
  return 0;
}
