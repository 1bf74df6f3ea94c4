#include "http_server.hpp"

#include <httplib.h>

#include <chrono>
#include <optional>

#include "base/text.hpp"
#include "bounded_http_server.hpp"
#include "request_guard.hpp"
#include "web_files.hpp"

namespace web_viewer {

HttpServer::HttpServer(EventHub& hub, std::function<bool(int)> press)
    : hub_(hub),
      press_(std::move(press)),
      token_(new_token()),
      server_(std::make_unique<BoundedHttpServer>(kMaxRequestBodyBytes)) {}

HttpServer::~HttpServer() { stop(); }

void HttpServer::add_routes() {
  server_->Get("/events", [this](const httplib::Request&, httplib::Response& res) {
    auto client = hub_.subscribe();
    if (!client) {
      res.status = 503;
      res.set_content("too many viewers connected\n", "text/plain");
      return;
    }
    res.set_header("Cache-Control", "no-cache");
    res.set_header("X-Accel-Buffering", "no");
    res.set_chunked_content_provider(
        "text/event-stream",
        [client](std::size_t, httplib::DataSink& sink) {
          const auto events = client->take(kKeepAlive_s);
          if (!events) {
            sink.done();
            return false;
          }
          std::string text;
          if (events->empty()) text = ": keep-alive\n\n";
          for (const std::string& e : *events) text += "data: " + e + "\n\n";
          return sink.write(text.data(), text.size());
        },
        [this, client](bool) { hub_.unsubscribe(client); });
  });
  server_->Get("/replay.json", [this](const httplib::Request&, httplib::Response& res) {
    if (replay_json_.empty()) {
      res.status = 404;
      return;
    }
    res.set_content(replay_json_, "application/json");
  });
  server_->Post(R"(/button/(\d+))", [this](const httplib::Request& req, httplib::Response& res) {
    const auto n = base::parse_integer(req.matches[1].str(), 1, 1000);
    res.status = n && press_(static_cast<int>(*n)) ? 204 : 404;
  });
  server_->Get(R"(/(.*))", [](const httplib::Request& req, httplib::Response& res) {
    std::string path = req.matches[1].str();
    if (path.empty()) path = "index.html";
    const WebFile* file = find_web_file(path);
    if (!file) {
      res.status = 404;
      res.set_content("not found\n", "text/plain");
      return;
    }
    res.set_content(std::string(file->bytes), std::string(content_type(path)).c_str());
  });
}

namespace {

std::optional<std::string> header(const httplib::Request& req, const char* name) {
  if (!req.has_header(name)) return std::nullopt;
  return req.get_header_value(name);
}

}  // namespace

void HttpServer::add_guard(const HttpOptions& options) {
  GuardConfig config{options.bind_address, port_, options.allowed_hosts, token_};
  server_->set_pre_routing_handler([this, config](const httplib::Request& req, httplib::Response& res) {
    // On every answer: no other site may frame the page and lay it under its own clicks.
    res.set_header("X-Frame-Options", "DENY");
    res.set_header("Content-Security-Policy", "frame-ancestors 'none'");
    RequestFacts facts;
    facts.method = req.method;
    facts.host_headers = req.get_header_value_count("Host");
    facts.host = header(req, "Host");
    facts.origin = header(req, "Origin");
    facts.sec_fetch_site = header(req, "Sec-Fetch-Site");
    facts.token = header(req, kTokenHeader);
    const auto refusal = check_request(config, facts);
    if (!refusal) return httplib::Server::HandlerResponse::Unhandled;
    ++(refusal->status == 421 ? refused_hosts_ : refused_posts_);
    res.status = refusal->status;
    res.set_content(refusal->text, "text/plain");
    return httplib::Server::HandlerResponse::Handled;
  });
}

bool HttpServer::start(const HttpOptions& options, std::string* error) {
  const std::size_t threads = options.max_clients + kSpareThreads;
  server_->set_pool_threads(threads);
  server_->set_write_timeout(kWriteTimeout_s, 0);
  // An idle keep-alive connection holds a pool thread: let it go soon, so that a page's parallel
  // file requests never keep another page waiting for long.
  server_->set_keep_alive_timeout(kKeepAliveIdle_s);
  // SO_REUSEADDR only: httplib's default also sets SO_REUSEPORT, which would let a second
  // viewer share the port silently instead of failing with "address in use".
  server_->set_socket_options([](auto sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });
  add_routes();
  port_ = options.port == 0 ? server_->bind_to_any_port(options.bind_address)
                            : (server_->bind_to_port(options.bind_address, options.port) ? options.port : -1);
  if (port_ <= 0) {
    *error = "cannot listen on " + options.bind_address + ":" + std::to_string(options.port);
    return false;
  }
  add_guard(options);  // it needs the bound port
  thread_ = std::thread([this] { server_->listen_after_bind(); });
  // httplib's stop() does nothing before the loop runs: wait for it, so that a stop right after
  // start() (a short test, a start-up that fails later) cannot leave the thread listening.
  for (int i = 0; i < kStartWaitSteps && !server_->is_running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return true;
}

void HttpServer::stop() {
  hub_.close_all();
  if (server_) server_->stop();
  if (thread_.joinable()) thread_.join();
}

}  // namespace web_viewer
