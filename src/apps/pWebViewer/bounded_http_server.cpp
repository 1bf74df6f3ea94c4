#include "bounded_http_server.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/error.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http/error.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/beast/http/string_body.hpp>
#include <boost/beast/http/write.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "base/text.hpp"

namespace web_viewer {

namespace net = boost::asio;
namespace beast = boost::beast;
namespace http = boost::beast::http;
using tcp = net::ip::tcp;
using error_code = boost::system::error_code;
using Clock = std::chrono::steady_clock;

std::size_t HttpRequest::count(std::string_view name) const {
  return static_cast<std::size_t>(std::count_if(
      headers.begin(), headers.end(), [&](const auto& h) { return base::iequals(h.first, name); }));
}

std::optional<std::string> HttpRequest::header(std::string_view name) const {
  for (const auto& [key, value] : headers)
    if (base::iequals(key, name)) return value;
  return std::nullopt;
}

namespace {

constexpr char kBusyReply[] =
    "HTTP/1.1 503 Service Unavailable\r\nContent-Length: 0\r\nConnection: close\r\n\r\n";
/// Bytes the read buffer may hold beyond the head's bound, so that Beast sees a head pass it
/// (header_limit) rather than a full buffer.
constexpr std::size_t kReadSlack = 4096;
/// The most one read takes from the socket, bytes.
constexpr std::size_t kReadBlock = 16 * 1024;
/// How long the accepting thread pauses after a failed accept (out of descriptors, say).
constexpr auto kAcceptRetry = std::chrono::milliseconds(10);
/// How long a refused request's remaining bytes are read and dropped before the close.
constexpr int kDrain_ms = 500;

Clock::time_point after_ms(int ms) { return Clock::now() + std::chrono::milliseconds(ms); }

/// Answers 503 and closes, never blocking (on the accepting thread, which must go on).
void refuse(tcp::socket& socket) {
  error_code ignored;
  socket.non_blocking(true, ignored);
  socket.write_some(net::buffer(kBusyReply, sizeof kBusyReply - 1), ignored);
  socket.shutdown(tcp::socket::shutdown_both, ignored);
  socket.close(ignored);
}

/// The status for a request that could not be read whole; 0: close without an answer.
int status_for(const error_code& ec, bool in_request_line) {
  if (ec == http::error::header_limit || ec == http::error::buffer_overflow) return in_request_line ? 414 : 431;
  if (ec == http::error::body_limit) return 413;
  if (ec == beast::error::timeout) return 408;
  if (ec == http::error::end_of_stream || ec == net::error::eof || ec == net::error::connection_reset ||
      ec == net::error::operation_aborted || ec == net::error::broken_pipe)
    return 0;
  return 400;
}

/// One connection, served on the calling thread: every socket operation runs on `context`
/// (this thread's) until it completes or its deadline passes.
class Connection {
 public:
  using RequestParser = http::request_parser<http::string_body>;

  /// `buffer`: the serving thread's, emptied here (kept across connections, so that a flood of
  /// connections allocates none).
  Connection(net::io_context& context, tcp::socket& socket, beast::flat_buffer& buffer,
             const std::atomic<bool>& stopping, const BoundedHttpServer::Handler& handler,
             std::size_t body_limit)
      : context_(context),
        socket_(socket),
        stopping_(stopping),
        handler_(handler),
        body_limit_(body_limit),
        buffer_(buffer) {
    buffer_.clear();
  }

  void serve() {
    for (std::size_t n = 1; n <= BoundedHttpServer::kMaxRequestsPerConnection && request_starts(); ++n) {
      RequestParser parser;
      const int refused = read_request(parser);
      if (refused != 0) {
        if (refused > 0 && write_refusal(refused)) drain();
        return;
      }
      const bool more = parser.keep_alive() && n < BoundedHttpServer::kMaxRequestsPerConnection;
      if (!answer(parser.get(), more)) return;
    }
  }

 private:
  /// Starts an operation with `start(done)` and runs it until `done(ec)` or `deadline` (then
  /// beast::error::timeout, the socket left open for an answer) or the server stops.
  template <class Start>
  error_code run(Start&& start, Clock::time_point deadline) {
    context_.restart();
    if (stopping_) return net::error::operation_aborted;
    error_code result = net::error::operation_aborted;
    bool done = false;
    bool timed_out = false;
    net::steady_timer timer(context_, deadline);
    timer.async_wait([&](error_code ec) {
      if (ec || done) return;
      timed_out = true;
      socket_.cancel(ec);
    });
    start([&](error_code ec) {
      done = true;
      result = ec;
      timer.cancel();
    });
    context_.run();
    if (!done) {  // stop(): end the operation; its handler must run before `done` goes away
      error_code ignored;
      socket_.close(ignored);
      timer.cancel();
      context_.restart();
      context_.run();
    }
    if (timed_out && result == net::error::operation_aborted) return beast::error::timeout;
    return result;
  }

  /// Whether a request's first byte arrives (or is buffered) within the idle time.
  bool request_starts() {
    if (buffer_.size() > 0) return true;
    const error_code ec = run(
        [&](auto done) {
          socket_.async_wait(tcp::socket::wait_read, [done](error_code e) mutable { done(e); });
        },
        after_ms(BoundedHttpServer::kKeepAliveIdle_ms));
    return !ec;
  }

  /// Reads one request whole into `parser`: 0, or the status to refuse it with (-1: none).
  /// The socket is read here and the bytes put into Beast's parser, so that the read timeout
  /// holds for each read, not for Beast's read of a whole head. Beast 1.74's header_limit
  /// does not count the header lines its first put() already parsed and took (up to one read),
  /// so the head's bytes are counted here as well.
  int read_request(RequestParser& parser) {
    parser.header_limit(static_cast<std::uint32_t>(BoundedHttpServer::kMaxRequestHeadBytes));
    parser.body_limit(body_limit_);
    const auto deadline = after_ms(BoundedHttpServer::kRequestDeadline_ms);
    std::size_t head_bytes = 0;  // parsed bytes of the head
    while (!parser.is_done()) {
      error_code ec;
      const bool in_head = !parser.is_header_done();
      const std::size_t used = buffer_.size() > 0 ? parser.put(buffer_.data(), ec) : 0;
      buffer_.consume(used);
      if (in_head) head_bytes += used;
      if (ec && ec != http::error::need_more) return refusal(ec, head_bytes);
      const std::size_t unparsed_head = parser.is_header_done() ? 0 : buffer_.size();
      if (head_bytes + unparsed_head > BoundedHttpServer::kMaxRequestHeadBytes)
        return refusal(http::error::header_limit, head_bytes);
      if (parser.is_done()) break;
      if (used > 0) continue;  // a part parsed: the next may be whole already
      ec = receive(std::min(deadline, after_ms(BoundedHttpServer::kReadTimeout_ms)));
      if (ec) return refusal(ec, head_bytes);
    }
    return parser.get().target().size() > BoundedHttpServer::kMaxTargetBytes ? 414 : 0;
  }

  /// Appends what arrives by `deadline` to the buffer (buffer_overflow when it is full).
  error_code receive(Clock::time_point deadline) {
    const std::size_t room = std::min(buffer_.max_size() - buffer_.size(), kReadBlock);
    if (room == 0) return http::error::buffer_overflow;
    std::size_t got = 0;
    const auto space = buffer_.prepare(room);
    const error_code ec = run(
        [&](auto done) {
          socket_.async_read_some(space, [done, &got](error_code e, std::size_t n) mutable {
            got = n;
            done(e);
          });
        },
        deadline);
    buffer_.commit(got);
    return ec;
  }

  /// `head_bytes`: 0 while the request line is unparsed (Beast takes it whole).
  static int refusal(const error_code& ec, std::size_t head_bytes) {
    const int status = status_for(ec, head_bytes == 0);
    return status == 0 ? -1 : status;
  }

  static HttpRequest to_request(const http::request<http::string_body>& message) {
    HttpRequest request;
    request.method = std::string(message.method_string());
    request.target = std::string(message.target());
    for (const auto& field : message)
      request.headers.emplace_back(std::string(field.name_string()), std::string(field.value()));
    request.body = message.body();
    return request;
  }

  bool answer(const http::request<http::string_body>& message, bool keep_alive) {
    HttpResponse response = handler_(to_request(message));
    if (response.next) return write_stream(response);
    const bool head_only = message.method() == http::verb::head;
    const bool more = keep_alive && response.status < 400;
    return write_response(std::move(response), head_only, more) && more;
  }

  bool write_refusal(int status) {
    HttpResponse response;
    response.status = status;
    response.content_type = "text/plain";
    response.body = std::string(http::obsolete_reason(static_cast<http::status>(status))) + "\n";
    return write_response(std::move(response), false, false);
  }

  /// After a refusal: stops sending and reads (a bounded amount, for a bounded time) what the
  /// client is still sending, so that closing with unread bytes does not reset the connection
  /// before the client reads the answer.
  void drain() {
    error_code ignored;
    socket_.shutdown(tcp::socket::shutdown_send, ignored);
    const auto deadline = after_ms(kDrain_ms);
    std::array<char, 4096> scratch;
    for (std::size_t drained = 0; drained < BoundedHttpServer::kMaxRequestHeadBytes;) {
      std::size_t got = 0;
      const error_code ec = run(
          [&](auto done) {
            socket_.async_read_some(net::buffer(scratch), [done, &got](error_code e, std::size_t n) mutable {
              got = n;
              done(e);
            });
          },
          deadline);
      if (ec) return;
      drained += got;
    }
  }

  /// Writes what `serializer` holds, each slice within the write timeout.
  template <class Serializer>
  bool write_message(Serializer& serializer, bool header_only) {
    while (!(header_only ? serializer.is_header_done() : serializer.is_done())) {
      const error_code ec = run(
          [&](auto done) {
            auto handler = [done](error_code e, std::size_t) mutable { done(e); };
            if (header_only)
              http::async_write_header(socket_, serializer, std::move(handler));
            else
              http::async_write_some(socket_, serializer, std::move(handler));
          },
          after_ms(BoundedHttpServer::kWriteTimeout_ms));
      if (ec) return false;
    }
    return true;
  }

  error_code write_text(const std::string& text) {
    return run(
        [&](auto done) {
          net::async_write(socket_, net::buffer(text), [done](error_code e, std::size_t) mutable { done(e); });
        },
        after_ms(BoundedHttpServer::kWriteTimeout_ms));
  }

  template <class Message>
  static void set_fields(Message& message, const HttpResponse& response) {
    if (!response.content_type.empty()) message.set(http::field::content_type, response.content_type);
    for (const auto& [name, value] : response.headers) message.set(name, value);
  }

  /// Whether the response was written whole.
  bool write_response(HttpResponse response, bool head_only, bool keep_alive) {
    http::response<http::string_body> message{static_cast<http::status>(response.status), 11};
    set_fields(message, response);
    message.body() = std::move(response.body);
    message.keep_alive(keep_alive);
    message.prepare_payload();
    http::response_serializer<http::string_body> serializer(message);
    return write_message(serializer, head_only);
  }

  /// Sends the response's texts chunked (framed here: Beast's chunk encoder costs more to
  /// compile than the three lines it saves).
  bool write_stream(HttpResponse& response) {
    struct AtEnd {
      std::function<void(bool)>& on_end;
      error_code failed;
      ~AtEnd() {
        if (on_end) on_end(failed == beast::error::timeout);
      }
    } at_end{response.on_end, {}};
    http::response<http::string_body> message{static_cast<http::status>(response.status), 11};
    set_fields(message, response);
    message.keep_alive(false);
    message.chunked(true);
    http::response_serializer<http::string_body> serializer(message);
    if (!write_message(serializer, true)) return false;
    char size[20];
    while (const auto text = response.next()) {
      if (text->empty()) continue;  // an empty chunk would end the body
      std::snprintf(size, sizeof size, "%zx\r\n", text->size());
      at_end.failed = write_text(size + *text + "\r\n");
      if (at_end.failed) return false;
    }
    write_text("0\r\n\r\n");
    return false;
  }

  net::io_context& context_;
  tcp::socket& socket_;
  const std::atomic<bool>& stopping_;
  const BoundedHttpServer::Handler& handler_;
  std::size_t body_limit_;
  beast::flat_buffer& buffer_;  // bytes read and not yet parsed; bounded (work())
};

struct Admitted {
  tcp::socket::native_handle_type handle;
  tcp protocol;
  std::string address;
};

}  // namespace

struct BoundedHttpServer::Impl {
  Impl(Handler h, std::size_t limit) : handler(std::move(h)), body_limit(limit) {}

  void accept_next();
  void admit(tcp::socket socket);
  void work();
  /// The next admitted connection; nullopt when the server stops.
  std::optional<Admitted> take();
  void serve(net::io_context& context, beast::flat_buffer& buffer, const Admitted& admitted);
  void release(const std::string& address);

  const Handler handler;
  const std::size_t body_limit;
  net::io_context accept_context;
  tcp::acceptor acceptor{accept_context};
  net::steady_timer retry{accept_context};
  std::thread accept_thread;
  std::vector<std::thread> workers;
  std::atomic<bool> stopping{false};
  std::mutex mutex;  // guards what follows
  std::condition_variable wake;
  std::deque<Admitted> waiting;
  std::map<std::string, std::size_t> connections_of_address;
  std::set<net::io_context*> serving_contexts;
};

void BoundedHttpServer::Impl::accept_next() {
  acceptor.async_accept([this](error_code ec, tcp::socket socket) {
    if (ec == net::error::operation_aborted) return;
    if (!ec) {
      admit(std::move(socket));
      accept_next();
      return;
    }
    retry.expires_after(kAcceptRetry);
    retry.async_wait([this](error_code e) {
      if (!e) accept_next();
    });
  });
}

void BoundedHttpServer::Impl::admit(tcp::socket socket) {
  error_code ec;
  const tcp::endpoint peer = socket.remote_endpoint(ec);
  const std::string address = ec ? std::string() : peer.address().to_string();
  std::lock_guard<std::mutex> lock(mutex);
  std::size_t& count = connections_of_address[address];
  if (count >= kMaxConnectionsPerAddress || waiting.size() >= kMaxWaitingConnections) {
    if (count == 0) connections_of_address.erase(address);
    refuse(socket);
    return;
  }
  const tcp protocol = peer.protocol();
  const auto handle = socket.release(ec);
  if (ec) return;
  ++count;
  waiting.push_back({handle, protocol, address});
  wake.notify_one();
}

std::optional<Admitted> BoundedHttpServer::Impl::take() {
  std::unique_lock<std::mutex> lock(mutex);
  wake.wait(lock, [this] { return stopping || !waiting.empty(); });
  if (stopping) return std::nullopt;
  Admitted next = waiting.front();
  waiting.pop_front();
  return next;
}

void BoundedHttpServer::Impl::work() {
  net::io_context context;
  beast::flat_buffer buffer(kMaxRequestHeadBytes + kReadSlack);
  buffer.reserve(buffer.max_size());
  {
    std::lock_guard<std::mutex> lock(mutex);
    serving_contexts.insert(&context);
  }
  while (const auto admitted = take()) serve(context, buffer, *admitted);
  std::lock_guard<std::mutex> lock(mutex);
  serving_contexts.erase(&context);
}

void BoundedHttpServer::Impl::serve(net::io_context& context, beast::flat_buffer& buffer,
                                    const Admitted& admitted) {
  tcp::socket socket(context);
  error_code ec;
  socket.assign(admitted.protocol, admitted.handle, ec);
  if (!ec) {
    Connection(context, socket, buffer, stopping, handler, body_limit).serve();
    socket.shutdown(tcp::socket::shutdown_both, ec);
  }
  socket.close(ec);
  release(admitted.address);
}

void BoundedHttpServer::Impl::release(const std::string& address) {
  std::lock_guard<std::mutex> lock(mutex);
  const auto it = connections_of_address.find(address);
  if (it != connections_of_address.end() && --it->second == 0) connections_of_address.erase(it);
}

BoundedHttpServer::BoundedHttpServer(Handler handler, std::size_t body_limit)
    : impl_(std::make_unique<Impl>(std::move(handler), body_limit)) {}

BoundedHttpServer::~BoundedHttpServer() { stop(); }

bool BoundedHttpServer::listen(const std::string& address, int port, std::string* error) {
  error_code ec;
  tcp::resolver resolver(impl_->accept_context);
  const auto found = resolver.resolve(address, std::to_string(port), tcp::resolver::passive, ec);
  tcp::acceptor& acceptor = impl_->acceptor;
  if (!ec && found.empty()) ec = net::error::host_not_found;
  if (!ec) acceptor.open(found.begin()->endpoint().protocol(), ec);
  if (!ec) acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor.bind(found.begin()->endpoint(), ec);
  if (!ec) acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) {
    *error = "cannot listen on " + address + ":" + std::to_string(port) + " (" + ec.message() + ")";
    acceptor.close(ec);
    return false;
  }
  return true;
}

int BoundedHttpServer::port() const {
  error_code ec;
  const tcp::endpoint local = impl_->acceptor.local_endpoint(ec);
  return ec ? 0 : local.port();
}

void BoundedHttpServer::run(std::size_t threads) {
  Impl& impl = *impl_;
  for (std::size_t i = 0; i < threads; ++i) impl.workers.emplace_back([&impl] { impl.work(); });
  impl.accept_next();
  impl.accept_thread = std::thread([&impl] { impl.accept_context.run(); });
}

void BoundedHttpServer::stop() {
  Impl& impl = *impl_;
  impl.accept_context.stop();
  if (impl.accept_thread.joinable()) impl.accept_thread.join();
  {
    std::lock_guard<std::mutex> lock(impl.mutex);
    impl.stopping = true;
    for (net::io_context* context : impl.serving_contexts) context->stop();
  }
  impl.wake.notify_all();
  for (std::thread& worker : impl.workers) worker.join();
  impl.workers.clear();
  error_code ignored;
  impl.acceptor.close(ignored);
  std::lock_guard<std::mutex> lock(impl.mutex);
  for (const Admitted& admitted : impl.waiting) {
    tcp::socket socket(impl.accept_context);
    socket.assign(admitted.protocol, admitted.handle, ignored);
  }  // each socket closes as it goes out of scope
  impl.waiting.clear();
}

}  // namespace web_viewer
