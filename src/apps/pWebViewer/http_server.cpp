#include "http_server.hpp"

#include "base/text.hpp"
#include "web_files.hpp"

namespace web_viewer {
namespace {

HttpResponse plain(int status, std::string text) {
  HttpResponse res;
  res.status = status;
  res.content_type = "text/plain";
  res.body = std::move(text);
  return res;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

/// The target's path without its query, %XX escapes decoded (a malformed one kept as is).
std::string path_of(std::string_view target) {
  target = target.substr(0, target.find('?'));
  std::string out;
  out.reserve(target.size());
  for (std::size_t i = 0; i < target.size(); ++i) {
    const int high = target[i] == '%' && i + 2 < target.size() ? hex_digit(target[i + 1]) : -1;
    const int low = high >= 0 ? hex_digit(target[i + 2]) : -1;
    if (low >= 0) {
      out += static_cast<char>(high * 16 + low);
      i += 2;
    } else {
      out += target[i];
    }
  }
  return out;
}

}  // namespace

HttpServer::HttpServer(EventHub& hub, std::function<bool(int)> press)
    : hub_(hub),
      press_(std::move(press)),
      token_(new_token()),
      server_(std::make_unique<BoundedHttpServer>([this](const HttpRequest& r) { return answer(r); },
                                                  kMaxRequestBodyBytes)) {}

HttpServer::~HttpServer() { stop(); }

HttpResponse HttpServer::answer(const HttpRequest& request) {
  RequestFacts facts;
  facts.method = request.method;
  facts.host_headers = request.count("Host");
  facts.host = request.header("Host");
  facts.origin = request.header("Origin");
  facts.sec_fetch_site = request.header("Sec-Fetch-Site");
  facts.token = request.header(kTokenHeader);
  HttpResponse res;
  if (const auto refusal = check_request(guard_, facts)) {
    ++(refusal->status == 421 ? refused_hosts_ : refused_posts_);
    res = plain(refusal->status, refusal->text);
  } else {
    res = route(request);
  }
  // On every answer: no other site may frame the page and lay it under its own clicks.
  res.headers.emplace_back("X-Frame-Options", "DENY");
  res.headers.emplace_back("Content-Security-Policy", "frame-ancestors 'none'");
  return res;
}

HttpResponse HttpServer::route(const HttpRequest& request) {
  const std::string path = path_of(request.target);
  if (request.method == "POST") {
    const std::string prefix = "/button/";
    return base::starts_with(path, prefix) ? button(path.substr(prefix.size())) : plain(404, "not found\n");
  }
  if (request.method != "GET" && request.method != "HEAD") {
    HttpResponse res = plain(405, "method not allowed\n");
    res.headers.emplace_back("Allow", "GET, HEAD, POST");
    return res;
  }
  if (path == "/events") return event_stream();
  if (path == "/replay.json") return replay();
  return file(path);
}

HttpResponse HttpServer::event_stream() {
  auto client = hub_.subscribe();
  if (!client) return plain(503, "too many viewers connected\n");
  HttpResponse res;
  res.content_type = "text/event-stream";
  res.headers = {{"Cache-Control", "no-cache"}, {"X-Accel-Buffering", "no"}};
  res.next = [client]() -> std::optional<std::string> {
    const auto events = client->take(kKeepAlive_s);
    if (!events) return std::nullopt;
    std::string text;
    if (events->empty()) text = ": keep-alive\n\n";
    for (const std::string& e : *events) text += "data: " + e + "\n\n";
    return text;
  };
  res.on_end = [this, client](bool fell_behind) { hub_.unsubscribe(client, fell_behind); };
  return res;
}

HttpResponse HttpServer::replay() {
  if (replay_json_.empty()) return plain(404, "no replay\n");
  HttpResponse res;
  res.content_type = "application/json";
  res.body = replay_json_;
  return res;
}

HttpResponse HttpServer::file(const std::string& path) const {
  const std::string name = path == "/" ? "index.html" : path.substr(path.empty() ? 0 : 1);
  const WebFile* found = base::starts_with(path, "/") ? find_web_file(name) : nullptr;
  if (!found) return plain(404, "not found\n");
  HttpResponse res;
  res.content_type = std::string(content_type(name));
  res.body = std::string(found->bytes);
  return res;
}

HttpResponse HttpServer::button(const std::string& number) {
  const bool digits = !number.empty() && number.find_first_not_of("0123456789") == std::string::npos;
  const auto n = digits ? base::parse_integer(number, 1, 1000) : std::nullopt;
  HttpResponse res;
  res.status = n && press_(static_cast<int>(*n)) ? 204 : 404;
  return res;
}

bool HttpServer::start(const HttpOptions& options, std::string* error) {
  if (!server_->listen(options.bind_address, options.port, error)) return false;
  port_ = server_->port();
  guard_ = GuardConfig{options.bind_address, port_, options.allowed_hosts, token_};
  server_->run(options.max_clients + kSpareThreads);
  return true;
}

void HttpServer::stop() {
  hub_.close_all();
  if (server_) server_->stop();
}

}  // namespace web_viewer
