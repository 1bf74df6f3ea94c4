#pragma once
// An httplib::Server whose memory stays bounded whatever a client sends.
//
// Why: cpp-httplib 0.11 keeps every request header line with no count limit (a client sending
// 8 kB header lines for 8 s took pWebViewer from 9 MB to 775 MB), reads a chunked or
// length-less request body whole, and queues every accepted connection. Debian ships it
// compiled, so its CPPHTTPLIB_* limits cannot be changed. This class serves each accepted
// socket through a stream of its own (bounded_stream.hpp) instead of httplib's, which
// httplib allows: process_and_close_socket is a virtual member and process_request is
// protected.
//
// Contract
// - A request's head (request line and header lines) may be at most kMaxRequestHeadBytes; what
//   follows is not read. httplib then answers 400 (or 414 for an overlong target) and the
//   connection is closed. The head is kept by httplib, so this bounds its memory per connection.
// - After the head, at most body_limit + kBodyFramingBytes bytes of body are read; httplib
//   answers 413 to a Content-Length over body_limit (set_payload_max_length) and 400 to a
//   chunked or length-less body cut at the bound; the connection is then closed.
// - A request (head and body) must arrive whole within kRequestDeadline_ms of its first byte,
//   however slowly it trickles; past it httplib answers 400 and the connection is closed.
// - A request whose body was announced but not read (a route refused it first) closes the
//   connection after its answer, so that the body is never read as a request.
// - Reads wait at most the server's read timeout, writes its write timeout (httplib's
//   defaults, or set_read_timeout / set_write_timeout); an idle keep-alive connection is closed
//   after its keep-alive timeout, or at once when the server stops; at most
//   keep_alive_max_count requests per connection, as httplib does. Responses, the event
//   stream's chunks among them, are written through the same stream.
// - Connections: set_pool_threads(n) serves at most n at once; at most kMaxWaitingConnections
//   more wait for a thread; beyond that a new connection gets 503 and is closed at once, so
//   queued connections cannot grow without bound either. At most kMaxConnectionsPerAddress
//   connections of one client address are served at once: a further one gets 503 and is closed
//   as soon as a thread takes it, so a few slow clients cannot hold every thread.

#include <httplib.h>

#include <cstddef>
#include <map>
#include <mutex>
#include <string>

namespace web_viewer {

class BoundedStream;

class BoundedHttpServer : public httplib::Server {
 public:
  /// Request line and headers, bytes: 8 header lines of httplib's 8 KiB maximum. A browser's
  /// request head is under 2 KiB.
  static constexpr std::size_t kMaxRequestHeadBytes = 64 * 1024;
  /// Chunk-size lines and trailers a chunked body may add to its data, bytes.
  static constexpr std::size_t kBodyFramingBytes = 1024;
  /// Accepted connections waiting for a free thread beyond which new ones are refused.
  static constexpr std::size_t kMaxWaitingConnections = 64;
  /// Connections of one client address served at once (a browser opens at most 6 per server).
  static constexpr std::size_t kMaxConnectionsPerAddress = 8;
  /// How long a request's head and body may take to arrive, from its first byte.
  static constexpr int kRequestDeadline_ms = 10000;

  /// `body_limit`: the largest request body accepted, bytes (413 above it).
  explicit BoundedHttpServer(std::size_t body_limit);

  /// Serve from a pool of `threads` threads (before listening).
  void set_pool_threads(std::size_t threads);

 private:
  bool process_and_close_socket(socket_t sock) override;
  /// Serves the requests of one connection; false when the last one failed.
  bool serve_connection(socket_t sock);
  /// Whether the next request of a keep-alive connection starts in time (false when the
  /// server stops).
  bool next_request_arrives(const BoundedStream& stream) const;
  /// Counts a connection of `address`; false (counting nothing) when it has its share already.
  bool take_address_slot(const std::string& address);
  void release_address_slot(const std::string& address);

  std::size_t body_read_limit_;
  std::mutex addresses_mutex_;
  std::map<std::string, std::size_t> connections_of_address_;
};

}  // namespace web_viewer
