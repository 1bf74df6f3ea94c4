#include "bounded_http_server.hpp"

#include <netdb.h>
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

/// Answers 503 and closes, best effort and never blocking (on the listening thread, it must go
/// on accepting).
void refuse(socket_t sock) {
  (void)::send(sock, kBusyReply, sizeof kBusyReply - 1, MSG_NOSIGNAL | MSG_DONTWAIT);
  shut_and_close(sock);
}

/// The numeric address of the peer of `sock` ("" when unknown).
std::string peer_address(socket_t sock) {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  char host[NI_MAXHOST] = "";
  if (::getpeername(sock, reinterpret_cast<sockaddr*>(&address), &length) != 0 ||
      ::getnameinfo(reinterpret_cast<const sockaddr*>(&address), length, host, sizeof host,
                    nullptr, 0, NI_NUMERICHOST) != 0)
    return std::string();
  return host;
}

/// Whether the request announced a body (that httplib would read before routing).
bool announces_body(const httplib::Request& req) {
  return req.has_header("Transfer-Encoding") ||
         (req.has_header("Content-Length") && req.get_header_value("Content-Length") != "0");
}

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
    refuse(sock);
    return false;
  }
  const std::string address = peer_address(sock);
  if (!take_address_slot(address)) {
    refuse(sock);
    return false;
  }
  const bool served = serve_connection(sock);
  shut_and_close(sock);
  release_address_slot(address);
  return served;
}

bool BoundedHttpServer::take_address_slot(const std::string& address) {
  std::lock_guard<std::mutex> lock(addresses_mutex_);
  std::size_t& count = connections_of_address_[address];
  if (count >= kMaxConnectionsPerAddress) return false;
  ++count;
  return true;
}

void BoundedHttpServer::release_address_slot(const std::string& address) {
  std::lock_guard<std::mutex> lock(addresses_mutex_);
  const auto it = connections_of_address_.find(address);
  if (it != connections_of_address_.end() && --it->second == 0) connections_of_address_.erase(it);
}

bool BoundedHttpServer::serve_connection(socket_t sock) {
  BoundedStream stream(sock, to_milliseconds(read_timeout_sec_, read_timeout_usec_),
                       to_milliseconds(write_timeout_sec_, write_timeout_usec_),
                       kMaxRequestHeadBytes, body_read_limit_, kRequestDeadline_ms);
  // httplib calls this once the head is parsed, before it reads a body.
  bool body_announced = false;
  const std::function<void(httplib::Request&)> head_parsed = [&](httplib::Request& req) {
    stream.end_head();
    body_announced = announces_body(req);
  };
  bool served = false;
  for (std::size_t left = keep_alive_max_count_; left > 0 && next_request_arrives(stream);
       --left) {
    stream.begin_request();
    body_announced = false;
    bool client_closes = false;
    served = process_request(stream, left == 1, client_closes, head_parsed);
    // A request cut at a bound, or refused before its body was read, left unread bytes: what
    // follows is no request.
    const bool body_unread = body_announced && stream.body_given() == 0;
    if (!served || client_closes || stream.exhausted() || body_unread) break;
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
