// Asynchronous MOOS client over TCP. Follows docs/protocol.md sections 1.4-1.9,
// 4.1, 4.3, 4.4 and the advice of 4.6; deliberate deviations are listed in tcp_client.hpp.
//
// Structure: one comms thread owns the socket (non-blocking) and runs
//   connect -> handshake -> serve (poll on socket + self-pipe) -> drop -> wait 1 MOOS s -> ...
// Public calls touch the shared state under `mutex_` and write one byte into the self-pipe to
// wake the thread; fetch() and release_sends() may also do the socket's I/O themselves under
// `io_mutex_` (try-locked, see tcp_client.hpp). No user code runs while either lock is held.
// Lock order: io_mutex_, then mutex_ (this client), then the Comms base's book lock.
// The sending half is in tcp_client_send.cpp, the receiving half in tcp_client_receive.cpp.

#include "moos/tcp_client.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <utility>

#include "moos/limits.hpp"
#include "base/descriptors.hpp"
#include "base/text.hpp"

namespace moos {

namespace {

/// The hostname token of WELCOME's source aux (protocol.md 1.6).
constexpr std::string_view kHostnameToken = "hostname";
constexpr double kMsPerSecond = 1000.0;
/// A longest poll wait, so a missed wake-up can never stall the thread for long.
constexpr double kMaxPollWait_real_s = 1.0;

int poll_timeout_ms(double seconds) {
  if (seconds <= 0) return 0;
  return static_cast<int>(std::ceil(std::min(seconds, kMaxPollWait_real_s) * kMsPerSecond));
}

bool set_nonblocking(int fd) {
  const int flags = fcntl(fd, F_GETFL, 0);
  return flags >= 0 && fcntl(fd, F_SETFL, flags | O_NONBLOCK) == 0;
}

/// Empties the (non-blocking) self-pipe: one wake-up covers every byte written so far.
void drain_wake_pipe(int fd) {
  char buf[64];
  while (::read(fd, buf, sizeof buf) > 0) {
  }
}

std::string own_hostname(const std::string& configured) {
  if (!configured.empty()) return configured;
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return {};
  return buf;
}

/// The value of `token` in a comma-separated key=value list, key compared case-insensitively.
std::string token_value(std::string_view list, std::string_view token) {
  for (std::string_view item : base::split(list, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string_view::npos) continue;
    if (base::iequals(base::trim(item.substr(0, eq)), token))
      return std::string(base::trim(item.substr(eq + 1)));
  }
  return {};
}

std::optional<in_addr> resolve_ipv4(const std::string& host, std::string* error) {
  in_addr addr{};
  if (base::iequals(host, "localhost")) {
    addr.s_addr = htonl(INADDR_LOOPBACK);
    return addr;
  }
  if (inet_pton(AF_INET, host.c_str(), &addr) == 1) return addr;
  addrinfo hints{};
  hints.ai_family = AF_INET;  // libMOOS is IPv4 only (protocol.md 1.1)
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* result = nullptr;
  const int rc = getaddrinfo(host.c_str(), nullptr, &hints, &result);
  if (rc != 0 || !result) {
    *error = "cannot resolve host " + host + ": " + gai_strerror(rc);
    return std::nullopt;
  }
  addr = reinterpret_cast<sockaddr_in*>(result->ai_addr)->sin_addr;
  freeaddrinfo(result);
  return addr;
}

}  // namespace

double TcpClient::steady_now_s() {
  using namespace std::chrono;
  return duration_cast<duration<double>>(steady_clock::now().time_since_epoch()).count();
}

std::string TcpClient::errno_text(const char* what) {
  return std::string(what) + ": " + std::strerror(errno);
}

bool TcpClient::on_comms_thread() const { return std::this_thread::get_id() == comms_thread_id_.load(); }

TcpClient::TcpClient(TcpClientOptions options)
    : Comms(options.name),
      options_(std::move(options)),
      clock_(options_.clock ? *options_.clock : system_clock()),
      reader_(options_.max_packet_bytes) {
  outbox_bound_.max_messages = options_.max_outbox_messages;
  outbox_bound_.max_bytes = options_.max_outbox_bytes;
}

TcpClient::~TcpClient() { close(); }

bool TcpClient::start() {
  std::string problem;
  if (options_.name.empty()) problem = "the client name is empty";
  else if (options_.port < 1 || options_.port > kMaxPort) problem = "port " + std::to_string(options_.port) + " is outside 1..65535";
  else if (!is_valid_time_warp(options_.time_warp))
    problem = "time warp " + base::format_g(options_.time_warp) + " is outside (0, 400]";
  else if (options_.max_inbox_messages < 1 || options_.max_inbox_bytes < 1)
    problem = "the inbox bounds must be at least 1";
  else if (options_.max_outbox_messages < 1 || options_.max_outbox_bytes < 1)
    problem = "the outbox bounds must be at least 1";
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (problem.empty() && state_ != ConnectionState::kNotStarted) problem = "already started";
    if (!problem.empty()) {
      last_error_ = problem;
      return false;
    }
    int fds[2];
    if (!base::open_internal_pipe(fds)) {
      last_error_ = errno_text("pipe");
      return false;
    }
    wake_read_ = fds[0];
    wake_write_ = fds[1];
    state_ = ConnectionState::kConnecting;
  }
  thread_ = std::thread([this] { run(); });
  return true;
}

void TcpClient::close() {
  stopping_ = true;
  wake();
  if (thread_.joinable()) thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  if (wake_read_ >= 0) ::close(wake_read_);
  if (wake_write_ >= 0) ::close(wake_write_);
  wake_read_ = wake_write_ = -1;
  if (state_ != ConnectionState::kNotStarted) state_ = ConnectionState::kClosed;
  changed_.notify_all();
}

// ---- public state ---------------------------------------------------------------------------

bool TcpClient::wait_until_connected(double timeout_real_s) const {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, std::chrono::duration<double>(timeout_real_s), [&] {
    return state_ == ConnectionState::kConnected || state_ == ConnectionState::kPoisoned ||
           state_ == ConnectionState::kClosed || state_ == ConnectionState::kNotStarted;
  });
  return state_ == ConnectionState::kConnected;
}

bool TcpClient::flush(double timeout_real_s) {
  std::unique_lock<std::mutex> lock(mutex_);
  const std::uint64_t connection = connections_;
  const bool done = changed_.wait_for(lock, std::chrono::duration<double>(timeout_real_s), [&] {
    return state_ != ConnectionState::kConnected || connections_ != connection ||
           (outbox_.empty() && packets_in_flight_ == 0);
  });
  return done && state_ == ConnectionState::kConnected && connections_ == connection &&
         outbox_.empty() && packets_in_flight_ == 0;
}

ConnectionState TcpClient::state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_;
}

std::string TcpClient::last_error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_error_;
}

std::string TcpClient::server_hostname() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return server_hostname_;
}

bool TcpClient::server_is_asynchronous() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return server_async_;
}

std::uint64_t TcpClient::packets_sent() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return packets_sent_;
}

bool TcpClient::is_connected() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_ == ConnectionState::kConnected;
}

std::uint64_t TcpClient::connection_count() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return connections_;
}

std::string TcpClient::community() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return community_;
}

void TcpClient::expect_fetch_within(double real_s) {
  if (!(real_s > 0)) {
    // The comms thread reads again; wake it if it had left reading to fetch().
    if (app_reads_until_.exchange(0.0) > steady_now_s()) wake();
    return;
  }
  const double now = steady_now_s();
  // A first promise wakes the comms thread, which may be polling for input, to stop doing so; a
  // promise renewed in time (every cycle of a cycling app) costs nothing.
  if (app_reads_until_.exchange(now + real_s + kAppReadGrace_real_s) <= now) wake();
}

// ---- comms thread ---------------------------------------------------------------------------

void TcpClient::wake() {
  // Written under the lock that close() takes to close the pipe, so the byte never lands in a
  // closed (or reused) descriptor. The pipe is non-blocking: the lock is held for one write.
  std::lock_guard<std::mutex> lock(mutex_);
  if (wake_write_ < 0) return;
  const char byte = 1;
  // A full pipe already guarantees a wake-up; the result can be ignored.
  [[maybe_unused]] const auto n = ::write(wake_write_, &byte, 1);
}

void TcpClient::wait_for_wake(double timeout_real_s) {
  const double deadline = steady_now_s() + timeout_real_s;
  while (!stopping_) {
    const double left = deadline - steady_now_s();
    if (left <= 0) return;
    pollfd p{wake_read_, POLLIN, 0};
    if (::poll(&p, 1, poll_timeout_ms(left)) > 0) drain_wake_pipe(wake_read_);
  }
}

void TcpClient::set_error(const std::string& error) {
  std::lock_guard<std::mutex> lock(mutex_);
  last_error_ = error;
}

double TcpClient::retry_delay_real_s() const { return 1.0 / options_.time_warp; }  // 1 MOOS s

void TcpClient::run() {
  comms_thread_id_ = std::this_thread::get_id();
  while (!stopping_) {
    if (connect_socket() && handshake()) {
      fire_on_connect();
      serve();
      std::lock_guard<std::mutex> io(io_mutex_);
      drop_connection("");
    } else if (socket_ >= 0) {
      std::lock_guard<std::mutex> io(io_mutex_);
      ::close(socket_);
      socket_ = -1;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (state_ == ConnectionState::kPoisoned) break;
    }
    wait_for_wake(retry_delay_real_s());
  }
  std::lock_guard<std::mutex> io(io_mutex_);
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
}

bool TcpClient::connect_socket() {
  std::string error;
  const auto addr = resolve_ipv4(options_.host, &error);
  if (!addr) {
    set_error(error);
    return false;
  }
  socket_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (socket_ < 0) {
    set_error(errno_text("socket"));
    return false;
  }
  const int one = 1;
  setsockopt(socket_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);  // protocol.md 1.1
  set_nonblocking(socket_);
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(options_.port));
  sa.sin_addr = *addr;
  const std::string where = options_.host + ":" + std::to_string(options_.port);
  if (::connect(socket_, reinterpret_cast<sockaddr*>(&sa), sizeof sa) == 0) return true;
  if (errno != EINPROGRESS) {
    set_error(errno_text(("connect to " + where).c_str()));
    return false;
  }
  pollfd p[2] = {{socket_, POLLOUT, 0}, {wake_read_, POLLIN, 0}};
  const double deadline = steady_now_s() + options_.connect_timeout_real_s;
  while (!stopping_) {
    const double left = deadline - steady_now_s();
    if (left <= 0) {
      set_error("connect to " + where + ": timed out");
      return false;
    }
    if (::poll(p, 2, poll_timeout_ms(left)) > 0 && (p[0].revents != 0)) break;
  }
  if (stopping_) return false;
  int so_error = 0;
  socklen_t len = sizeof so_error;
  getsockopt(socket_, SOL_SOCKET, SO_ERROR, &so_error, &len);
  if (so_error != 0) {
    set_error("connect to " + where + ": " + std::strerror(so_error));
    return false;
  }
  return true;
}

bool TcpClient::handshake() {
  if (options_.skew_policy != SkewPolicy::kNever) skew_s_ = 0.0;  // protocol.md 1.8
  Message ident;
  ident.type = msg_type::kData;
  ident.data_type = data_type::kString;
  ident.key = kAsynchronousKey;
  ident.sval = name();
  ident.time = local_time();  // skew is 0 here, so this is the MOOS time libMOOS sends
  write_buffer_ = protocol_banner() + encode_packet({ident});
  write_offset_ = 0;
  reader_ = PacketReader(options_.max_packet_bytes);

  const double deadline = steady_now_s() + options_.handshake_timeout_real_s;
  std::vector<Message> reply;
  bool have_reply = false;
  while (!stopping_ && !have_reply) {
    if (!write_pending()) return false;
    const double left = deadline - steady_now_s();
    if (left <= 0) {
      set_error("handshake: no reply from the server within " +
                base::format_g(options_.handshake_timeout_real_s) + " s");
      return false;
    }
    pollfd p[2] = {{socket_, static_cast<short>(POLLIN | (write_buffer_.empty() ? 0 : POLLOUT)), 0},
                   {wake_read_, POLLIN, 0}};
    ::poll(p, 2, poll_timeout_ms(left));
    if (p[0].revents & (POLLIN | POLLERR | POLLHUP)) {
      char buf[kReadChunkBytes];
      const ssize_t n = ::recv(socket_, buf, sizeof buf, 0);
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        set_error("handshake: the server closed the connection");
        return false;
      }
      if (n > 0) reader_.feed(std::string_view(buf, static_cast<std::size_t>(n)));
      DecodeError derr;
      const auto status = reader_.next(reply, &derr);
      if (status == PacketReader::Status::kError) {
        set_error("handshake: " + derr.reason);
        return false;
      }
      have_reply = status == PacketReader::Status::kPacket;
    }
  }
  if (stopping_) return false;
  if (reply.empty()) {
    set_error("handshake: the server's reply holds no message");
    return false;
  }
  const Message& first = reply.front();  // libMOOS reads only the first message (protocol.md 1.7)
  if (first.type == msg_type::kPoison) {
    std::lock_guard<std::mutex> lock(mutex_);
    last_error_ = "refused by the server: " + first.sval;
    state_ = ConnectionState::kPoisoned;
    changed_.notify_all();
    return false;
  }

  const std::string db_host = token_value(first.source_aux, kHostnameToken);
  switch (options_.skew_policy) {
    case SkewPolicy::kNever: time_correction_ = false; break;
    case SkewPolicy::kAlways: time_correction_ = true; break;
    case SkewPolicy::kLibMoos:
      time_correction_ = first.source_aux.empty() || db_host != own_hostname(options_.own_hostname);
      break;
  }
  if (time_correction_) skew_s_ = first.dval;
  server_delay_s_ = 0.0;
  last_timing_sent_.reset();
  last_app_send_.reset();
  awaiting_timing_echo_ = false;
  next_send_allowed_ = 0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    community_ = first.community;
    server_async_ = base::iequals(first.sval, kAsynchronousKey);
    server_hostname_ = db_host;
    state_ = ConnectionState::kConnected;
    ++connections_;
    // The server forgot our subscriptions: they go first (protocol.md 1.9, 4.6), then the
    // postings kept while disconnected.
    std::vector<Message> replay = replay_messages();
    for (auto& m : replay) {
      m.id = next_id_++;
      outbox_bound_.add(m.encoded_size());
    }
    outbox_.insert(outbox_.begin(), replay.begin(), replay.end());
    changed_.notify_all();
  }
  return true;
}

void TcpClient::drop_connection(const std::string& why) {
  app_io_failure_.clear();
  awaiting_timing_echo_ = false;
  {
    // State first, socket second: whoever sees the close also sees the reason.
    std::lock_guard<std::mutex> lock(mutex_);
    if (!why.empty()) last_error_ = why;
    forget_registrations_in_outbox();  // replayed at the next connection; postings stay
    packets_in_flight_ = 0;
    if (state_ == ConnectionState::kConnected) state_ = ConnectionState::kConnecting;
    changed_.notify_all();
  }
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
  write_buffer_.clear();
  write_offset_ = 0;
  reader_ = PacketReader(options_.max_packet_bytes);
}

void TcpClient::forget_registrations_in_outbox() {
  const auto registration = [](const Message& m) { return m.type != msg_type::kNotify; };
  for (const Message& m : outbox_)
    if (registration(m)) outbox_bound_.remove(m.encoded_size());
  outbox_.erase(std::remove_if(outbox_.begin(), outbox_.end(), registration), outbox_.end());
}

void TcpClient::fail_io(const std::string& why) {
  if (on_comms_thread()) {
    drop_connection(why);
    return;
  }
  if (app_io_failure_.empty()) app_io_failure_ = why;
  wake();
}

bool TcpClient::app_reads(double now) {
  if (now >= app_reads_until_.load()) return false;
  if (comms_reads_once_.exchange(false)) return false;  // handed back by fetch()
  // With the skew corrected, a TIMING echo is read the moment it arrives: that moment is the
  // measurement (protocol.md 4.4).
  const bool echo_due = time_correction_ && awaiting_timing_echo_ && last_timing_sent_ &&
                        now < *last_timing_sent_ + kTimingEchoWindow_real_s;
  return !echo_due;
}

TcpClient::PollPlan TcpClient::plan_poll(double now) {
  PollPlan plan;
  // The next TIMING is due then (at once if none was ever sent), or a little later when the
  // app's thread sends, as its next packet carries it.
  const bool app_sends = last_app_send_ && now - *last_app_send_ < kTimingInterval_real_s;
  const double slack_s = app_sends ? kAppTimingSlack_real_s : 0.0;
  plan.wait_real_s =
      last_timing_sent_ ? *last_timing_sent_ + kTimingInterval_real_s + slack_s - now : 0.0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!outbox_.empty() && !holding_sends_ && write_buffer_.empty())
      plan.wait_real_s = std::min(plan.wait_real_s, next_send_allowed_ - now);
  }
  if (!write_buffer_.empty()) plan.socket_events |= POLLOUT;
  if (app_reads(now)) {
    plan.wait_real_s = std::min(plan.wait_real_s, app_reads_until_.load() - now);
  } else {
    plan.socket_events |= POLLIN;
  }
  return plan;
}

void TcpClient::serve() {
  // Bytes that followed WELCOME in the same segment belong to normal traffic (protocol.md 5.1a).
  bool ok = read_and_announce(&TcpClient::process_buffered);
  while (ok && !stopping_) {
    pollfd p[2] = {{-1, 0, 0}, {wake_read_, POLLIN, 0}};
    double wait = 0;
    {
      std::lock_guard<std::mutex> io(io_mutex_);
      if (!app_io_failure_.empty()) {
        drop_connection(std::exchange(app_io_failure_, {}));
        return;
      }
      const double now = steady_now_s();
      start_packet_if_due(now);
      if (!write_pending()) return;
      const PollPlan plan = plan_poll(now);
      p[0] = {socket_, plan.socket_events, 0};
      wait = plan.wait_real_s;
    }
    // Sleep until something happens, or the next TIMING / send slot / read is due.
    if (::poll(p, 2, poll_timeout_ms(wait)) < 0 && errno != EINTR) {
      std::lock_guard<std::mutex> io(io_mutex_);
      drop_connection(errno_text("poll"));
      return;
    }
    if (p[1].revents & POLLIN) drain_wake_pipe(wake_read_);
    if (p[0].revents & (POLLIN | POLLERR | POLLHUP))
      ok = read_and_announce(&TcpClient::read_available);
  }
}

}  // namespace moos
