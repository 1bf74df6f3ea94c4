// The sending half of TcpClient (contract in tcp_client.hpp): posted messages wait in the outbox
// and leave as one packet per send slot, a TIMING at its head when one is due (protocol.md 4.3).
// The comms thread sends, or the app's own thread when it releases a batch and the slot is open.

#include <sys/socket.h>

#include <algorithm>
#include <cerrno>

#include "base/text.hpp"
#include "moos/tcp_client.hpp"

namespace moos {

namespace {
constexpr double kMsPerSecond = 1000.0;
}  // namespace

bool TcpClient::transmit(Message&& msg) {
  bool first_of_batch = false;
  std::string refusal;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (state_ == ConnectionState::kClosed || state_ == ConnectionState::kPoisoned) return false;
    const bool connected = state_ == ConnectionState::kConnected;
    // Registrations wait for no connection: the replay sends the remembered ones (comms.hpp).
    if (!connected && msg.type != msg_type::kNotify) return false;
    const std::size_t size = msg.encoded_size();
    refusal = outbox_bound_.refusal(size);
    if (refusal.empty()) {
      msg.id = next_id_++;  // every posted message consumes an id (protocol.md 2.5)
      first_of_batch = connected && outbox_.empty() && !holding_sends_;
      outbox_bound_.add(size);
      outbox_.push_back(std::move(msg));
    }
  }
  if (!refusal.empty()) {
    count_posting_dropped("NOTIFY " + base::excerpt(msg.key) + " refused: " + refusal);
    return false;
  }
  // Only the first message of a batch wakes the comms thread: it takes the whole outbox, and it
  // never sleeps past its next send slot while the outbox holds anything (serve()). While sends
  // are held, release_sends() sends them, or wakes it.
  if (first_of_batch) wake();
  return true;
}

void TcpClient::hold_sends() {
  std::lock_guard<std::mutex> lock(mutex_);
  holding_sends_ = true;
}

void TcpClient::release_sends() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    holding_sends_ = false;
    if (outbox_.empty()) return;
  }
  if (!send_for_app()) wake();
}

bool TcpClient::send_for_app() {
  const std::unique_lock<std::mutex> io = lock_io_for_app();
  if (!io.owns_lock()) return false;
  const double now = steady_now_s();
  if (!start_packet_if_due(now)) return false;
  last_app_send_ = now;
  write_pending();  // a failure is handed to the comms thread
  return write_buffer_.empty();  // the rest of a partial write is the comms thread's
}

std::unique_lock<std::mutex> TcpClient::lock_io_for_app() {
  std::unique_lock<std::mutex> io(io_mutex_, std::try_to_lock);
  // Connected first: app_io_failure_ is the lock's only while connected.
  if (io.owns_lock() && (!is_connected() || !app_io_failure_.empty())) io.unlock();
  return io;
}

Message TcpClient::timing_message() const {
  Message m;  // id -1, source "" (protocol.md 2.6, vector I)
  m.type = msg_type::kTiming;
  m.data_type = data_type::kDouble;
  m.key = kTimingKey;
  m.time = local_time();
  m.dval = 0.0;
  return m;
}

bool TcpClient::start_packet_if_due(double now) {
  if (!write_buffer_.empty() || now < next_send_allowed_) return false;
  const bool timing_due = !last_timing_sent_ || now - *last_timing_sent_ >= kTimingInterval_real_s;
  // TIMING first (protocol.md 4.3 step 2); stamped before mutex_ is taken, as the clock may be
  // the caller's code.
  std::optional<Message> timing;
  if (timing_due) timing = timing_message();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    // Held messages wait for the release, unless a TIMING goes out anyway.
    if (!timing_due && (outbox_.empty() || holding_sends_)) return false;
    take_batch(timing ? timing->encoded_size() : 0);
    ++packets_sent_;
    ++packets_in_flight_;
  }
  if (timing_due) {
    last_timing_sent_ = now;
    awaiting_timing_echo_ = true;
  }
  write_packet(write_buffer_, timing ? &*timing : nullptr, batch_.data(),
               batch_.data() + batch_.size());
  write_offset_ = 0;
  batch_.clear();
  release_if_large(batch_);
  return true;
}

void TcpClient::take_batch(std::size_t lead_bytes) {
  batch_.clear();
  // As many as fit in a packet the server surely accepts (codec.hpp); the rest go next. The
  // whole outbox, as usual, trades places with the (empty) batch.
  std::size_t bytes = kPacketHeaderSize + lead_bytes;
  std::size_t taken = 0;
  for (; taken < outbox_.size(); ++taken) {
    const std::size_t size = outbox_[taken].encoded_size();
    if (bytes + size > kDefaultMaxPacketBytes && (lead_bytes > 0 || taken > 0)) break;
    bytes += size;
    outbox_bound_.remove(size);
  }
  if (taken == outbox_.size()) {
    batch_.swap(outbox_);
    return;
  }
  batch_.reserve(taken);
  for (std::size_t i = 0; i < taken; ++i) batch_.push_back(std::move(outbox_[i]));
  outbox_.erase(outbox_.begin(), outbox_.begin() + static_cast<std::ptrdiff_t>(taken));
}

bool TcpClient::write_pending() {
  while (write_offset_ < write_buffer_.size()) {
    const ssize_t n = ::send(socket_, write_buffer_.data() + write_offset_,
                             write_buffer_.size() - write_offset_, MSG_NOSIGNAL);
    if (n > 0) {
      write_offset_ += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return true;
    fail_io(errno_text("send"));
    return false;
  }
  if (!write_buffer_.empty()) {
    write_buffer_.clear();
    write_offset_ = 0;
    // Pause after each send (protocol.md 4.3 step 4): the server's requested delay or the warp
    // delay.
    const double warp_delay_s = options_.time_warp > 1
                                    ? options_.time_warp * options_.tw_delay_factor_ms / kMsPerSecond
                                    : 0.0;
    next_send_allowed_ = steady_now_s() + std::max(server_delay_s_.load(), warp_delay_s);
    std::lock_guard<std::mutex> lock(mutex_);
    if (packets_in_flight_ > 0) --packets_in_flight_;
    changed_.notify_all();
  }
  return true;
}

}  // namespace moos
