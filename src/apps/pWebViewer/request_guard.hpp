#pragma once
// Which requests pWebViewer answers at all (docs/viewer.md, "Trust model"). Checked before any
// route runs, so a refused request learns nothing of the mission and changes nothing.
//
// Contract
// - Host: exactly one Host header, `name[:port]`, whose port (80 when absent) is the server's
//   and whose name is `localhost`, `127.0.0.1`, `[::1]`, the bound address (an IPv6 one in
//   brackets) or a name of `allowed_hosts`, compared case-insensitively. When the server is bound
//   to every address (0.0.0.0 or ::), any IP address literal is accepted too: an address cannot
//   be rebound the way a DNS name can. Anything else: 421. This stops DNS rebinding.
// - A request that may change state (every method but GET, HEAD and OPTIONS) also needs:
//   no Origin header or one equal to `http://<its Host>`; no Sec-Fetch-Site header or one of
//   `same-origin` and `none`; and an X-Viewer-Token header equal to the run's token. Anything
//   else: 403. A cross-site form cannot set a header, so it can never carry the token.
// - new_token(): 128 random bits (std::random_device) as 32 lowercase hex digits.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace web_viewer {

/// The header a state-changing request carries the run's token in.
inline constexpr const char* kTokenHeader = "X-Viewer-Token";

struct GuardConfig {
  std::string bind_address;
  int port = 0;
  std::vector<std::string> allowed_hosts;  ///< extra names (lower case), `allowed_hosts`
  std::string token;
};

/// The headers of a request that the guard reads; nullopt for an absent header.
struct RequestFacts {
  std::string method;
  std::size_t host_headers = 0;  ///< how many Host headers the request has
  std::optional<std::string> host;
  std::optional<std::string> origin;
  std::optional<std::string> sec_fetch_site;
  std::optional<std::string> token;
};

struct Refusal {
  int status = 0;
  std::string text;  ///< a short plain-text reason, for the response body
};

/// nullopt when the request may go on to its route.
std::optional<Refusal> check_request(const GuardConfig& config, const RequestFacts& request);

/// Whether `name` may appear in `allowed_hosts`: a DNS name or an IP literal ([v6] bracketed).
bool is_host_name(std::string_view name);

std::string new_token();

/// The bound address as a Host header and a URL write it: an IPv6 literal in brackets
/// ("::1" -> "[::1]"), a name in lower case.
std::string host_form(const std::string& address);
/// "http://HOST:PORT/" of a server bound to `bind_address` (host_form).
std::string server_url(const std::string& bind_address, int port);

}  // namespace web_viewer
