#pragma once
// Raw-socket HTTP for the viewer's hostile-input tests: no client library normalises a request
// first, and a client can pick its own loopback source address (127.0.0.2 is "another machine").
#include <string>

namespace web_viewer::raw_http {

/// A socket connected to 127.0.0.1:`port`, from `source` (an IPv4 loopback address) when given;
/// -1 on failure.
int connect_to(int port, const char* source = nullptr);
/// What the server sends on `fd` until it closes the connection or `timeout_s` passes (a reset
/// ends it too).
std::string read_reply(int fd, double timeout_s);
/// Sends `request` on a fresh connection and returns what the server answers until it closes
/// the connection or `timeout_s` passes.
std::string raw_exchange(int port, const std::string& request, double timeout_s = 5.0,
                         const char* source = nullptr);
/// The status line's code ("HTTP/1.1 404 Not Found" gives 404), or 0.
int status_of(const std::string& reply);
/// The body of a reply (after the blank line), "" when none.
std::string body_of(const std::string& reply);

}  // namespace web_viewer::raw_http
