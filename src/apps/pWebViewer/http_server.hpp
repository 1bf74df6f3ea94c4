#pragma once
// pWebViewer's HTTP side: the page's files, the server-sent event stream, the replay data and
// the buttons, served by BoundedHttpServer (Boost.Beast) from threads of its own
// (docs/viewer.md, "Protocol").
//
// Contract
// - start() binds `bind_address`:`port` (0: a port the OS picks) and serves from
//   max_clients + kSpareThreads threads, so that max_clients event streams never starve requests
//   for files (a browser fetches up to 6 at once). It returns false (with `error`) when the
//   address cannot be bound.
// - Memory, threads and time stay bounded whatever a client sends: bounded_http_server.hpp
//   (a head of at most 64 KiB, a body of at most kMaxRequestBodyBytes, 10 s for a request to
//   arrive, 8 connections per client address, 64 waiting for a thread).
// - Every request first passes request_guard.hpp's checks (the Host header; for a POST also
//   Origin, Sec-Fetch-Site and the run's token, token()), else 421 or 403 with a short text and
//   no route runs. Every answer forbids framing (X-Frame-Options, frame-ancestors), so no other
//   site can lay the page under its own clicks.
// - GET (or HEAD) / and /<file>: the embedded files (web_files.hpp), 404 for anything else;
//   the target's query is ignored and its %XX escapes decoded.
// - GET /events: text/event-stream; the hub's events, one `data:` line each; a comment line
//   every kKeepAlive_s when there is nothing to send. 503 when max_clients streams are open.
// - GET /replay.json: the replay data when one was set, else 404.
// - POST /button/<n>: 404 unless `press(n)` accepts n; 204 when it does. Other methods: 405.
// - stop() ends every stream and joins the threads; the destructor stops.

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bounded_http_server.hpp"
#include "event_hub.hpp"
#include "request_guard.hpp"

namespace web_viewer {

struct HttpOptions {
  std::string bind_address = "127.0.0.1";
  int port = 8080;
  std::size_t max_clients = 8;
  /// Host names accepted besides loopback and the bound address (lower case; request_guard.hpp).
  std::vector<std::string> allowed_hosts;
};

class HttpServer {
 public:
  static constexpr std::size_t kSpareThreads = 8;
  /// Seconds between an idle event stream's comment lines.
  static constexpr double kKeepAlive_s = 1.0;
  /// The largest request body accepted, bytes. Only a button press has a body, and it needs
  /// none.
  static constexpr std::size_t kMaxRequestBodyBytes = 4096;

  /// `press(n)` is called on a server thread; true when button n exists.
  HttpServer(EventHub& hub, std::function<bool(int)> press);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  /// The JSON served at /replay.json (set before start()).
  void set_replay_json(std::string json) { replay_json_ = std::move(json); }

  bool start(const HttpOptions& options, std::string* error);
  void stop();
  /// The bound port (after start()).
  int port() const { return port_; }
  /// The run's secret that every POST must carry (32 hex digits, new for each server).
  const std::string& token() const { return token_; }
  /// Requests refused for their Host name (421), and for their origin or token (403).
  std::uint64_t refused_hosts() const { return refused_hosts_; }
  std::uint64_t refused_posts() const { return refused_posts_; }

 private:
  /// The answer to `request` (on a server thread).
  HttpResponse answer(const HttpRequest& request);
  HttpResponse route(const HttpRequest& request);
  HttpResponse event_stream();
  HttpResponse replay();
  HttpResponse file(const std::string& path) const;
  HttpResponse button(const std::string& number);
  EventHub& hub_;
  std::function<bool(int)> press_;
  std::string replay_json_;
  const std::string token_;
  std::atomic<std::uint64_t> refused_hosts_{0};
  std::atomic<std::uint64_t> refused_posts_{0};
  GuardConfig guard_;  // written before the server's threads start, read-only after
  std::unique_ptr<BoundedHttpServer> server_;
  int port_ = 0;
};

}  // namespace web_viewer
