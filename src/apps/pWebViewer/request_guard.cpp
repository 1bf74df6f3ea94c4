#include "request_guard.hpp"

#include <arpa/inet.h>

#include <cstdio>
#include <random>

#include "base/text.hpp"

namespace web_viewer {

namespace {

constexpr int kDefaultHttpPort = 80;

struct HostPort {
  std::string name;  ///< lower case; an IPv6 address keeps its brackets
  int port = kDefaultHttpPort;
};

/// `name[:port]` or `[v6][:port]`; nullopt when malformed.
std::optional<HostPort> split_host(std::string_view host) {
  HostPort out;
  std::string_view rest;
  if (!host.empty() && host.front() == '[') {
    const auto close = host.find(']');
    if (close == std::string_view::npos) return std::nullopt;
    out.name = base::to_lower(host.substr(0, close + 1));
    rest = host.substr(close + 1);
  } else {
    const auto colon = host.find(':');
    out.name = base::to_lower(host.substr(0, colon));
    if (colon != std::string_view::npos) rest = host.substr(colon);
  }
  if (out.name.empty()) return std::nullopt;
  if (rest.empty()) return out;
  if (rest.front() != ':') return std::nullopt;
  const std::string_view digits = rest.substr(1);
  if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string_view::npos)
    return std::nullopt;
  const auto port = base::parse_integer(digits, 1, 65535);
  if (!port) return std::nullopt;
  out.port = static_cast<int>(*port);
  return out;
}

bool is_ipv4(const std::string& text) {
  in_addr address{};
  return ::inet_pton(AF_INET, text.c_str(), &address) == 1;
}

bool is_bracketed_ipv6(std::string_view text) {
  if (text.size() < 3 || text.front() != '[' || text.back() != ']') return false;
  in6_addr address{};
  return ::inet_pton(AF_INET6, std::string(text.substr(1, text.size() - 2)).c_str(), &address) == 1;
}

bool is_ip_literal(const std::string& name) { return is_ipv4(name) || is_bracketed_ipv6(name); }

bool is_wildcard(std::string_view address) {
  return address == "0.0.0.0" || address == "::" || address == "[::]";
}

bool host_allowed(const GuardConfig& config, const std::string& name) {
  if (name == "localhost" || name == "127.0.0.1" || name == "[::1]") return true;
  if (name == host_form(config.bind_address)) return true;
  if (is_wildcard(config.bind_address) && is_ip_literal(name)) return true;
  for (const std::string& allowed : config.allowed_hosts)
    if (name == allowed) return true;
  return false;
}

bool changes_state(const std::string& method) {
  return method != "GET" && method != "HEAD" && method != "OPTIONS";
}

/// Compares in a time that does not depend on where the texts differ.
bool same_secret(std::string_view a, std::string_view b) {
  unsigned char diff = a.size() == b.size() ? 0 : 1;
  for (std::size_t i = 0; i < a.size(); ++i)
    diff |= static_cast<unsigned char>(a[i] ^ (i < b.size() ? b[i] : 0));
  return diff == 0;
}

std::optional<Refusal> check_origin(const GuardConfig& config, const RequestFacts& request) {
  if (request.origin && !base::iequals(*request.origin, "http://" + *request.host))
    return Refusal{403, "refused: a request from another origin\n"};
  if (request.sec_fetch_site && *request.sec_fetch_site != "same-origin" &&
      *request.sec_fetch_site != "none")
    return Refusal{403, "refused: a request from another site\n"};
  if (!request.token || !same_secret(*request.token, config.token))
    return Refusal{403, "refused: no valid token (open the URL pWebViewer printed at start-up)\n"};
  return std::nullopt;
}

}  // namespace

std::optional<Refusal> check_request(const GuardConfig& config, const RequestFacts& request) {
  const auto host = request.host_headers == 1 && request.host ? split_host(*request.host) : std::nullopt;
  if (!host || host->port != config.port || !host_allowed(config, host->name))
    return Refusal{421, "refused: this server is not known by that Host name (see allowed_hosts)\n"};
  if (changes_state(request.method)) return check_origin(config, request);
  return std::nullopt;
}

bool is_host_name(std::string_view name) {
  if (is_bracketed_ipv6(name)) return true;
  if (name.empty() || name.size() > 253 || name.front() == '.' || name.front() == '-') return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '.' || c == '-';
    if (!ok) return false;
  }
  return true;
}

std::string new_token() {
  std::random_device source;
  std::string out;
  for (int i = 0; i < 4; ++i) {  // 4 x 32 bits
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(source()));
    out += hex;
  }
  return out;
}

std::string host_form(const std::string& address) {
  if (address.find(':') != std::string::npos && address.front() != '[') return "[" + address + "]";
  return base::to_lower(address);
}

std::string server_url(const std::string& bind_address, int port) {
  return "http://" + host_form(bind_address) + ":" + std::to_string(port) + "/";
}

}  // namespace web_viewer
