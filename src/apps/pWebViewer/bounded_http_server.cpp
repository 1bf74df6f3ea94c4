#include "bounded_http_server.hpp"

#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <utility>

#include "bounded_stream.hpp"

namespace web_viewer {
namespace {

/// Set on the listening thread while it hands over a connection that must be refused
/// (WaitBoundedQueue::enqueue); process_and_close_socket reads it.
thread_local bool t_refuse_connection = false;

constexpr char kBusyReply[] =
    "HTTP/1.1 503 Service Unavailable\r\nContent-Length: 0\r\nConnection: close\r\n\r\n";

/// Polling step of the wait for a keep-alive connection's next request: how soon a stopping
/// server lets the connection go (httplib polls as often).
constexpr int kIdleSlice_ms = 10;

int to_milliseconds(time_t sec, time_t usec) { return static_cast<int>(sec * 1000 + usec / 1000); }

void shut_and_close(socket_t sock) {
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
}

/// httplib's thread pool with a bound on the connections waiting for a thread. httplib hands
/// the queue one opaque job per accepted connection; a job over the bound runs at once on the
/// listening thread with t_refuse_connection set, so that the connection is answered 503 and
/// closed instead of being kept.
class WaitBoundedQueue final : public httplib::TaskQueue {
 public:
  WaitBoundedQueue(std::size_t threads, std::size_t max_waiting)
      : max_waiting_(max_waiting), pool_(threads) {}

  void enqueue(std::function<void()> job) override {
    if (waiting_.load() >= max_waiting_) {
      t_refuse_connection = true;
      job();
      t_refuse_connection = false;
      return;
    }
    ++waiting_;
    pool_.enqueue([this, job = std::move(job)] {
      --waiting_;
      job();
    });
  }
  void shutdown() override { pool_.shutdown(); }

 private:
  std::atomic<std::size_t> waiting_{0};  // declared before the pool, whose jobs count it
  std::size_t max_waiting_;
  httplib::ThreadPool pool_;
};

}  // namespace

BoundedHttpServer::BoundedHttpServer(std::size_t body_limit)
    : body_read_limit_(body_limit + kBodyFramingBytes) {
  set_payload_max_length(body_limit);
}

void BoundedHttpServer::set_pool_threads(std::size_t threads) {
  new_task_queue = [threads] { return new WaitBoundedQueue(threads, kMaxWaitingConnections); };
}

bool BoundedHttpServer::process_and_close_socket(socket_t sock) {
  if (t_refuse_connection) {
    // Best effort and never blocking: the listening thread must go on accepting.
    (void)::send(sock, kBusyReply, sizeof kBusyReply - 1, MSG_NOSIGNAL | MSG_DONTWAIT);
    shut_and_close(sock);
    return false;
  }
  const bool served = serve_connection(sock);
  shut_and_close(sock);
  return served;
}

bool BoundedHttpServer::serve_connection(socket_t sock) {
  BoundedStream stream(sock, to_milliseconds(read_timeout_sec_, read_timeout_usec_),
                       to_milliseconds(write_timeout_sec_, write_timeout_usec_),
                       kMaxRequestHeadBytes, body_read_limit_);
  // httplib calls this once the head is parsed, before it reads a body.
  const std::function<void(httplib::Request&)> head_parsed = [&stream](httplib::Request&) {
    stream.end_head();
  };
  bool served = false;
  for (std::size_t left = keep_alive_max_count_; left > 0 && next_request_arrives(stream);
       --left) {
    stream.begin_request();
    bool client_closes = false;
    served = process_request(stream, left == 1, client_closes, head_parsed);
    // A request cut at a bound left unread bytes: what follows is no request.
    if (!served || client_closes || stream.exhausted()) break;
  }
  return served;
}

bool BoundedHttpServer::next_request_arrives(const BoundedStream& stream) const {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(keep_alive_timeout_sec_);
  while (svr_sock_ != INVALID_SOCKET) {
    if (stream.wait_readable(kIdleSlice_ms)) return true;
    if (std::chrono::steady_clock::now() >= end) return false;
  }
  return false;
}

}  // namespace web_viewer
