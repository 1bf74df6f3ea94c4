#pragma once
// pWebViewer's HTTP/1.1 server: Boost.Beast's parser and Asio's sockets, with every bound set
// through their public interface, so that nothing a client sends can take more memory, threads
// or time than below. Asio and Beast stay inside bounded_http_server.cpp (they compile slowly);
// this header is plain C++.
//
// Contract
// - listen() binds `address`:`port` (0: a port the OS picks; SO_REUSEADDR, not SO_REUSEPORT, so
//   a second server on the port fails); false with `error` when it cannot. run(threads) then
//   accepts on a thread of its own and serves from `threads` threads, one connection each.
// - A request's head (request line and header lines) may be at most kMaxRequestHeadBytes
//   (Beast's header_limit): 431 beyond it, or 414 when the request line alone passes
//   kMaxTargetBytes or the target does. A body may be at most `body_limit` bytes (Beast's
//   body_limit), by Content-Length or chunked: 413. Other malformed requests: 400.
// - A request (head and body) must arrive whole within kRequestDeadline_ms of its first byte,
//   and no read waits more than kReadTimeout_ms: 408 past either.
// - After any of these answers the connection is closed, so that unread bytes are never taken
//   for a request.
// - A connection waits kKeepAliveIdle_ms at most for a request's first byte and serves at most
//   kMaxRequestsPerConnection requests; a response with a status of 400 or more ends it.
//   Each write waits at most kWriteTimeout_ms for the client to take a slice.
// - Connections: at most kMaxConnectionsPerAddress of one client address, waiting or served;
//   at most kMaxWaitingConnections waiting for a thread. Beyond either a new connection gets
//   503 and is closed on the accepting thread at once, never kept.
// - The handler runs on a serving thread, once per whole request. A response with `next` set
//   is an endless body (server-sent events): sent chunked, each text `next` returns as it comes,
//   until `next` returns nullopt, a write fails or the server stops; `on_end` runs after it,
//   told whether a write timed out (a client that stopped reading, not one that closed).
// - stop() ends every connection within a read or a write (and a stream within one `next`),
//   joins the threads and closes what waits; the destructor stops.
//
// Threads: the accepting thread owns the listening socket and hands each admitted connection
// to the waiting queue (mutex); each serving thread owns one io_context and the connection it
// took; stop() only sets a flag and calls io_context::stop(), which Asio makes thread-safe.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace web_viewer {

using HttpHeaders = std::vector<std::pair<std::string, std::string>>;

struct HttpRequest {
  std::string method;  ///< as sent, e.g. "GET"
  std::string target;  ///< as sent, e.g. "/index.html?token=..."
  HttpHeaders headers;
  std::string body;

  /// How many headers of `name` (case-insensitive) the request has.
  std::size_t count(std::string_view name) const;
  /// The first header of `name`; nullopt when absent.
  std::optional<std::string> header(std::string_view name) const;
};

struct HttpResponse {
  int status = 200;
  std::string content_type;  ///< none when empty
  HttpHeaders headers;
  std::string body;
  /// Set: the body is a stream of texts (see above); `body` is not sent.
  std::function<std::optional<std::string>()> next;
  /// After a stream: true when it ended because the client took nothing for kWriteTimeout_ms.
  std::function<void(bool write_timed_out)> on_end;
};

class BoundedHttpServer {
 public:
  using Handler = std::function<HttpResponse(const HttpRequest&)>;

  /// Request line and headers, bytes. A browser's request head is under 2 KiB.
  static constexpr std::size_t kMaxRequestHeadBytes = 64 * 1024;
  /// The longest request target, bytes (414 beyond it).
  static constexpr std::size_t kMaxTargetBytes = 8 * 1024;
  /// Accepted connections waiting for a free thread beyond which new ones are refused.
  static constexpr std::size_t kMaxWaitingConnections = 64;
  /// Connections of one client address at once (a browser opens at most 6 per server).
  static constexpr std::size_t kMaxConnectionsPerAddress = 8;
  /// How long a request's head and body may take to arrive, from its first byte.
  static constexpr int kRequestDeadline_ms = 10000;
  static constexpr int kReadTimeout_ms = 5000;
  static constexpr int kWriteTimeout_ms = 5000;
  /// An idle keep-alive connection holds a thread: let it go soon, so that a page's parallel
  /// file requests never keep another page waiting for long.
  static constexpr int kKeepAliveIdle_ms = 1000;
  static constexpr std::size_t kMaxRequestsPerConnection = 5;

  /// `body_limit`: the largest request body accepted, bytes (413 above it).
  BoundedHttpServer(Handler handler, std::size_t body_limit);
  ~BoundedHttpServer();
  BoundedHttpServer(const BoundedHttpServer&) = delete;
  BoundedHttpServer& operator=(const BoundedHttpServer&) = delete;

  bool listen(const std::string& address, int port, std::string* error);
  /// The bound port (after listen()).
  int port() const;
  void run(std::size_t threads);
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace web_viewer
