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
/// The value of header `name` (case-insensitive) in a reply's head, "" when absent.
std::string header_of(const std::string& reply, const std::string& name);
/// The data of the whole chunks of a chunked body (what has arrived of it so far; it stops at
/// the first line that is not a chunk size).
std::string dechunked(const std::string& body);

/// A reply, its body decoded when chunked.
struct Reply {
  int status = 0;  ///< 0: no answer
  std::string head;
  std::string body;
  std::string header(const std::string& name) const { return header_of(head, name); }
};
/// `method target` with Host 127.0.0.1:`port`, `headers` (whole lines) and Connection: close.
Reply request(int port, const std::string& method, const std::string& target,
              const std::string& headers = "", double timeout_s = 5.0);

/// GET /events on a connection of its own; read() takes what has arrived.
class EventStream {
 public:
  explicit EventStream(int port);
  ~EventStream();
  EventStream(const EventStream&) = delete;
  EventStream& operator=(const EventStream&) = delete;
  /// Reads for up to `wait_s`; false once the server closed the stream.
  bool read(double wait_s);
  /// The events' text so far (the body, its chunks decoded).
  std::string text() const { return dechunked(body_of(raw_)); }

 private:
  int fd_;
  std::string raw_;
};
/// GET /events until its text holds `until` or `timeout_s` passes.
std::string read_events(int port, const std::string& until, double timeout_s = 10.0);

}  // namespace web_viewer::raw_http
