// The receiving half of TcpClient (contract in tcp_client.hpp): a decoded packet from the
// server goes to the bounded inbox; a TIMING echo at its head refines the skew
// (protocol.md 4.3, 4.4).
// The comms thread reads, or fetch() on the app's own thread; the inbox is shared under `mutex_`.

#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <utility>

#include "moos/tcp_client.hpp"

namespace moos {

namespace {

/// What a message costs the inbox, in bytes: its strings plus a fixed part for the rest.
std::size_t inbox_cost(const Message& msg) {
  constexpr std::size_t kFixedPart = sizeof(Message);
  return kFixedPart + msg.key.size() + msg.sval.size() + msg.source.size() +
         msg.source_aux.size() + msg.community.size();
}

/// Skew filter weight of the previous value (protocol.md 4.4).
constexpr double kSkewMemory = 0.9;

}  // namespace

void TcpClient::fetch_into(std::vector<Message>& mail) {
  read_for_app();
  std::lock_guard<std::mutex> lock(mutex_);
  inbox_.hand_over(mail);
  inbox_bytes_ = 0;
}

void TcpClient::read_for_app() {
  // Without a promise the comms thread reads everything as it arrives: nothing is left here.
  if (steady_now_s() >= app_reads_until_.load()) return;
  std::unique_lock<std::mutex> io = lock_io_for_app();
  // The comms thread is busy with the socket, or more than one read's worth is waiting: it reads
  // the rest in its next round and announces it (comms.hpp), so no mail waits for a later fetch.
  bool hand_back = !io.owns_lock();
  if (!hand_back) {
    hand_back = read_available() && input_left_;  // a failure is handed to the comms thread
    new_mail_ = false;  // the caller is fetching it now: nothing to announce
    io.unlock();
  }
  if (hand_back) {
    comms_reads_once_ = true;
    wake();
  }
}

bool TcpClient::read_available() {
  bool peer_closed = false;
  input_left_ = true;  // until a read comes back short: the socket may hold more
  char buf[kReadChunkBytes];
  // Bounded so that a flooding server cannot starve our own sending.
  for (int chunk = 0; chunk < kMaxReadChunksPerWake; ++chunk) {
    const ssize_t n = ::recv(socket_, buf, sizeof buf, 0);
    if (n > 0) {
      reader_.feed(std::string_view(buf, static_cast<std::size_t>(n)));
      if (static_cast<std::size_t>(n) < sizeof buf) {  // drained: spare the EAGAIN call
        input_left_ = false;
        break;
      }
      continue;
    }
    if (n == 0) {
      peer_closed = true;  // process what arrived before the close first
      break;
    }
    if (errno == EAGAIN || errno == EWOULDBLOCK) {
      input_left_ = false;
      break;
    }
    if (errno == EINTR) continue;
    fail_io(errno_text("recv"));
    return false;
  }
  if (!process_buffered()) return false;
  if (peer_closed) {
    fail_io("the server closed the connection");
    return false;
  }
  return true;
}

bool TcpClient::read_and_announce(bool (TcpClient::*read)()) {
  bool ok = false;
  bool mail = false;
  {
    std::lock_guard<std::mutex> io(io_mutex_);
    ok = (this->*read)();
    mail = std::exchange(new_mail_, false);
  }
  if (mail) fire_on_mail();
  return ok;
}

bool TcpClient::process_buffered() {
  while (true) {
    DecodeError derr;
    const auto status = reader_.next(decoded_, &derr);
    if (status == PacketReader::Status::kNeedMore) return true;
    if (status == PacketReader::Status::kError) {
      fail_io("bad packet from the server: " + derr.reason + " (offset " +
              std::to_string(derr.offset) + ")");
      return false;
    }
    handle_packet(decoded_);
    release_if_large(decoded_);
  }
}

void TcpClient::handle_packet(std::vector<Message>& messages) {
  if (messages.empty()) return;
  auto begin = messages.begin();
  if (begin->type == msg_type::kTiming) {  // consumed by the comms layer (protocol.md 4.3)
    refine_skew(*begin);
    awaiting_timing_echo_ = false;
    ++begin;
  }
  const auto not_mail = [](const Message& m) {
    return m.type == msg_type::kNull || m.type == msg_type::kTiming;
  };
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = begin; it != messages.end(); ++it) {
    if (not_mail(*it)) continue;
    inbox_bytes_ += inbox_cost(*it);
    // The next packet is decoded into the storage of the kept message traded for this one:
    // steady mail allocates no strings.
    inbox_.push_trade(*it);
    new_mail_ = true;
  }
  enforce_inbox_bounds();
}

void TcpClient::enforce_inbox_bounds() {
  if (inbox_.size() <= options_.max_inbox_messages && inbox_bytes_ <= options_.max_inbox_bytes)
    return;
  const std::size_t keep_messages = std::max<std::size_t>(1, options_.max_inbox_messages / 4 * 3);
  const std::size_t keep_bytes = options_.max_inbox_bytes / 4 * 3;
  std::size_t drop = 0;
  while (drop < inbox_.size() &&
         (inbox_.size() - drop > keep_messages || inbox_bytes_ > keep_bytes)) {
    inbox_bytes_ -= inbox_cost(inbox_[drop]);
    ++drop;
  }
  inbox_.drop_oldest(drop);
  count_mail_dropped(drop);
}

void TcpClient::refine_skew(const Message& echo) {
  bool async = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    async = server_async_;
  }
  if (async) server_delay_s_ = std::max(0.0, echo.dval2);
  if (!time_correction_) return;
  // protocol.md 4.4: measured = Ts - (Tq + Tr) / 2; exponential filter unless the skew is
  // exactly 0.
  const double tq = echo.time;
  const double ts = echo.dval;
  const double tr = local_time();
  const double measured = ts - (tq + tr) / 2.0;
  const double current = skew_s_.load();
  skew_s_ = current == 0.0 ? measured : kSkewMemory * current + (1.0 - kSkewMemory) * measured;
}

}  // namespace moos
