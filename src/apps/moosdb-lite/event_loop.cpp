// Socket event loop of moosdb-lite. See event_loop.hpp.
//
// One poll() round: accept new connections, read from readable ones (each read goes to
// the Hub at once and its actions are applied before the next read, so a connection the
// Hub closes is never read again), run the Hub's timers with the time poll() returned,
// write what is pending (topped up from the per-source queues in turns), enforce the output
// limits and the memory budget, pause or resume reading by the output each connection has
// queued, and close what is finished. Poll wakes at least every kPollInterval_ms so timeouts
// and the DB-variable timer run without traffic.

#include "event_loop.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "base/output_file.hpp"
#include "moos/clock.hpp"

namespace moosdb_lite {

namespace {

/// Longest sleep in poll(): the granularity of timeouts and the DB-variable timer.
constexpr int kPollInterval_ms = 50;
/// Listen backlog of the reference DB (protocol.md 1.1).
constexpr int kListenBacklog = 50;
/// One recv() call; and the most read from one connection in one round (fairness).
constexpr std::size_t kReadChunkBytes = 64 * 1024;
constexpr std::size_t kReadBudgetBytes = 1024 * 1024;
/// New connections accepted per round (the rest wait for the next round).
constexpr int kMaxAcceptsPerRound = 64;

std::string errno_text() { return std::strerror(errno); }
std::string errno_text(int error) { return std::strerror(error); }

/// A descriptor kept in reserve for accept-and-close when the process runs out of them.
int open_reserve_descriptor() { return ::open("/dev/null", O_RDONLY | O_CLOEXEC); }

bool out_of_descriptors(int error) {
  return error == EMFILE || error == ENFILE || error == ENOBUFS || error == ENOMEM;
}

std::string peer_name(const sockaddr_in& addr) {
  char host[INET_ADDRSTRLEN] = "?";
  inet_ntop(AF_INET, &addr.sin_addr, host, sizeof host);
  return std::string(host) + ":" + std::to_string(ntohs(addr.sin_port));
}

/// The bound port, one line, by the rule of every user-named output (base/output_file.hpp): a
/// script waiting for the file never reads half a number, and a device or FIFO stays one.
bool write_port_file(const std::string& path, int port, std::string* error) {
  const auto written = base::write_output_file(path, std::to_string(port) + "\n");
  if (!written) *error = "--port-file: " + written.error;
  return static_cast<bool>(written);
}

}  // namespace

EventLoop::EventLoop(EventLoopConfig config, Hub& hub, LogSink log)
    : config_(std::move(config)), hub_(hub), log_(std::move(log)) {}

EventLoop::~EventLoop() {
  for (auto& [id, socket] : sockets_) ::close(socket.fd);
  if (listen_fd_ >= 0) ::close(listen_fd_);
  if (reserve_fd_ >= 0) ::close(reserve_fd_);
}

bool EventLoop::listen(std::string* error) {
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(config_.port));
  if (inet_pton(AF_INET, config_.bind_address.c_str(), &addr.sin_addr) != 1) {
    *error = "not an IPv4 address: " + config_.bind_address;
    return false;
  }
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) {
    *error = "socket: " + errno_text();
    return false;
  }
  const int on = 1;
  setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  if (::bind(listen_fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    *error = "cannot bind " + config_.bind_address + ":" + std::to_string(config_.port) + ": " +
             errno_text();
    return false;
  }
  if (::listen(listen_fd_, kListenBacklog) != 0) {
    *error = "listen: " + errno_text();
    return false;
  }
  socklen_t length = sizeof addr;
  getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &length);
  bound_port_ = ntohs(addr.sin_port);
  if (config_.port_file && !write_port_file(*config_.port_file, bound_port_, error)) return false;
  reserve_fd_ = open_reserve_descriptor();
  return true;
}

void EventLoop::run(int wake_fd, const volatile std::sig_atomic_t& stop_requested,
                    const std::function<void()>& after_round) {
  std::vector<pollfd> fds;
  std::vector<ConnectionId> ids;
  while (stop_requested == 0) {
    fds.clear();
    ids.clear();
    const double before_poll = moos::system_clock().unix_now_s();
    // While the listener rests (no descriptors), poll a harmless -1 in its place.
    fds.push_back(pollfd{before_poll < listen_paused_until_s_ ? -1 : listen_fd_, POLLIN, 0});
    fds.push_back(pollfd{wake_fd, POLLIN, 0});
    for (const auto& [id, socket] : sockets_) {
      short events = 0;
      if (!socket.closing && !socket.reading_paused) events |= POLLIN;
      if (socket.pending() > 0 && !socket.broken) events |= POLLOUT;
      fds.push_back(pollfd{socket.fd, events, 0});
      ids.push_back(id);
    }
    if (::poll(fds.data(), fds.size(), kPollInterval_ms) < 0 && errno != EINTR) {
      log_("poll failed: " + errno_text());
      return;
    }
    // The last time the server looked at the sockets: whatever a client sent before this
    // is read in this round, so silence is judged at this time, however long the round.
    const double looked = moos::system_clock().unix_now_s();
    double now = looked;
    if (fds[1].revents != 0) {
      char drain[64];
      while (::read(wake_fd, drain, sizeof drain) > 0) {
      }
    }
    if (fds[0].revents & POLLIN) accept_new(now);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (fds[i + 2].revents & (POLLIN | POLLHUP | POLLERR)) read_from(ids[i], now);
    }
    hub_.tick(looked);
    now = moos::system_clock().unix_now_s();
    apply_actions(now);
    for (auto& [id, socket] : sockets_) {
      if (socket.pending() > 0 && !socket.broken) write_to(id, now);
    }
    apply_actions(now);
    enforce_output_limits(now);
    enforce_memory_budget(now);
    apply_back_pressure(now);
    reap_closed(now);
    if (after_round) after_round();
  }
}

void EventLoop::accept_new(double now) {
  for (int i = 0; i < kMaxAcceptsPerRound; ++i) {
    sockaddr_in addr{};
    socklen_t length = sizeof addr;
    const int fd = ::accept4(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &length,
                             SOCK_NONBLOCK | SOCK_CLOEXEC);
    if (fd < 0) {
      const int error = errno;
      if (out_of_descriptors(error)) {
        shed_connection(now, error);
      } else if (error != EAGAIN && error != EWOULDBLOCK && error != EINTR &&
                 error != ECONNABORTED) {
        log_("accept failed: " + errno_text(error));
      }
      return;
    }
    const int on = 1;
    setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
    const ConnectionId id = hub_.open(peer_name(addr), now);
    Socket socket;
    socket.fd = fd;
    socket.last_progress_real_s = now;
    sockets_.emplace(id, std::move(socket));
  }
}

void EventLoop::shed_connection(double now, int error) {
  ++shed_count_;
  bool shed = false;
  if (reserve_fd_ >= 0) {
    // The reserve makes room for exactly one accept: take the connection and close it, so
    // the client learns at once, and the listener stops reporting it (no spin).
    ::close(reserve_fd_);
    const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd >= 0) {
      ::close(fd);
      shed = true;
    }
    reserve_fd_ = open_reserve_descriptor();
  }
  // Without a reserve (or if another thread of the system took the slot), rest the listener.
  if (!shed || reserve_fd_ < 0) listen_paused_until_s_ = now + kAcceptBackoff_s;
  if (now - shed_logged_s_ >= kDescriptorLogInterval_s) {
    log_("warning: cannot accept connections (" + errno_text(error) + "): " +
         std::to_string(shed_count_ - shed_logged_count_) + " refused since the last warning, " +
         std::to_string(shed_count_) + " in total; clients connected: " +
         std::to_string(sockets_.size()));
    shed_logged_s_ = now;
    shed_logged_count_ = shed_count_;
  }
}

void EventLoop::read_from(ConnectionId id, double now) {
  read_chunks(id, now);
  // Whatever it sent has been processed now, however long that took.
  hub_.heard(id, moos::system_clock().unix_now_s());
}

void EventLoop::read_chunks(ConnectionId id, double now) {
  static char buffer[kReadChunkBytes];
  std::size_t budget = kReadBudgetBytes;
  while (budget > 0) {
    const auto it = sockets_.find(id);
    if (it == sockets_.end() || it->second.closing) return;
    const ssize_t n = ::recv(it->second.fd, buffer, sizeof buffer, 0);
    if (n > 0) {
      hub_.receive(id, std::string_view(buffer, static_cast<std::size_t>(n)), now);
      apply_actions(now);
      budget -= std::min(budget, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
    // End of stream, or a socket error: every complete packet has been processed already.
    const std::string reason = n == 0 ? std::string() : "socket error: " + errno_text();
    hub_.end_of_stream(id, now, reason);
    apply_actions(now);
    return;
  }
}

void EventLoop::write_to(ConnectionId id, double now) {
  Socket& socket = sockets_.at(id);
  for (;;) {
    fill_buffer(socket);
    if (socket.in_buffer() == 0) break;
    const ssize_t n = ::send(socket.fd, socket.out.data() + socket.out_offset, socket.in_buffer(),
                             MSG_NOSIGNAL);
    if (n > 0) {
      socket.out_offset += static_cast<std::size_t>(n);
      socket.last_progress_real_s = now;
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) break;
    socket.broken = true;
    const std::string reason = "write failed: " + errno_text();
    socket.out.clear();
    socket.out_offset = 0;
    socket.queued.clear();
    socket.queued_bytes = 0;
    hub_.end_of_stream(id, now, reason);
    return;
  }
  // Compact once the written part dominates, so the buffer does not grow without bound.
  if (socket.out_offset == socket.out.size()) {
    socket.out.clear();
    socket.out_offset = 0;
  } else if (socket.out_offset > socket.out.size() / 2) {
    socket.out.erase(0, socket.out_offset);
    socket.out_offset = 0;
  }
}

void EventLoop::apply_actions(double now) {
  for (auto& action : hub_.take_actions()) {
    const auto it = sockets_.find(action.id);
    if (it == sockets_.end()) continue;
    Socket& socket = it->second;
    switch (action.kind) {
      case Action::Kind::kSend:
        if (socket.broken) break;
        if (socket.pending() == 0) socket.last_progress_real_s = now;
        enqueue(socket, action.source, std::move(action.bytes));
        break;
      case Action::Kind::kClose:
        close_socket(action.id);
        break;
      case Action::Kind::kCloseAfterSend:
        socket.closing = true;
        socket.close_deadline_real_s = now + kCloseGrace_s;
        break;
    }
  }
}

void EventLoop::enqueue(Socket& socket, ConnectionId source, std::string bytes) {
  if (socket.queued_bytes == 0 && socket.in_buffer() < kWriteBufferBytes) {
    // An empty buffer takes the packet's bytes as they are: no copy on the usual path.
    if (socket.out.empty()) socket.out = std::move(bytes);
    else socket.out += bytes;
    return;
  }
  socket.queued_bytes += bytes.size();
  socket.queued[source].push_back(std::move(bytes));
}

void EventLoop::fill_buffer(Socket& socket) {
  while (socket.queued_bytes > 0 && socket.in_buffer() < kWriteBufferBytes) {
    auto it = socket.queued.lower_bound(socket.next_source);
    if (it == socket.queued.end()) it = socket.queued.begin();
    std::deque<std::string>& packets = it->second;
    socket.queued_bytes -= packets.front().size();
    if (socket.in_buffer() == 0) {
      socket.out = std::move(packets.front());  // no copy when the buffer is drained
      socket.out_offset = 0;
    } else {
      socket.out += packets.front();
    }
    packets.pop_front();
    socket.next_source = it->first + 1;
    if (packets.empty()) socket.queued.erase(it);
  }
}

void EventLoop::enforce_output_limits(double now) {
  std::vector<std::pair<ConnectionId, std::string>> overloaded;
  for (const auto& [id, socket] : sockets_) {
    if (socket.closing || socket.broken) continue;
    if (socket.pending() > config_.max_output_bytes) {
      overloaded.emplace_back(id, std::to_string(socket.pending()) +
                                      " unsent bytes exceed the limit of " +
                                      std::to_string(config_.max_output_bytes) +
                                      " (the client does not read fast enough)");
    } else if (socket.pending() > 0 && now - socket.last_progress_real_s > kSendStall_s) {
      overloaded.emplace_back(id, "nothing could be written for " +
                                      std::to_string(static_cast<int>(kSendStall_s)) + " s");
    }
  }
  for (const auto& [id, reason] : overloaded) hub_.drop(id, reason, now);
  if (!overloaded.empty()) apply_actions(now);
}

void EventLoop::apply_back_pressure(double now) {
  // Under a small output limit, pause at half of it: the warning always comes before a drop.
  const std::size_t pause_at = std::min(kPauseReadingOutputBytes, config_.max_output_bytes / 2);
  for (auto& [id, socket] : sockets_) {
    if (socket.closing || socket.broken) continue;
    if (!socket.reading_paused && socket.pending() > pause_at) {
      socket.reading_paused = true;
      hub_.set_reading_paused(id, true, now);
      log_("warning: " + hub_.describe(id) + ": " + std::to_string(socket.pending()) +
           " bytes wait to be sent; its messages are delayed, reading from it paused until "
           "it takes them");
    } else if (socket.reading_paused && socket.pending() <= pause_at / 2) {
      socket.reading_paused = false;
      hub_.set_reading_paused(id, false, now);
    }
  }
}

void EventLoop::enforce_memory_budget(double now) {
  for (;;) {
    std::size_t total = 0;
    std::size_t largest = 0;
    ConnectionId largest_id = 0;
    for (const auto& [id, socket] : sockets_) {
      const std::size_t held = socket.pending() + hub_.held_bytes(id);
      total += held;
      if (held > largest) {
        largest = held;
        largest_id = id;
      }
    }
    if (total <= config_.memory_budget_bytes || largest == 0) return;
    ++budget_drops_;
    log_("warning: connections hold " + std::to_string(total) +
         " bytes (unsent output, incomplete packets, kept mail), over the memory budget of " +
         std::to_string(config_.memory_budget_bytes) + " bytes; dropping the largest (" +
         std::to_string(budget_drops_) + " dropped by the budget so far)");
    hub_.drop(largest_id,
              "holds " + std::to_string(largest) + " bytes, the most under the memory budget",
              now);
    // The Hub may not know it (a connection already closing): close it here regardless.
    apply_actions(now);
    close_socket(largest_id);
  }
}

void EventLoop::reap_closed(double now) {
  std::vector<ConnectionId> finished;
  for (const auto& [id, socket] : sockets_) {
    if (socket.closing &&
        (socket.pending() == 0 || socket.broken || now > socket.close_deadline_real_s))
      finished.push_back(id);
  }
  for (const ConnectionId id : finished) close_socket(id);
}

void EventLoop::close_socket(ConnectionId id) {
  const auto it = sockets_.find(id);
  if (it == sockets_.end()) return;
  ::close(it->second.fd);
  sockets_.erase(it);
}

}  // namespace moosdb_lite
