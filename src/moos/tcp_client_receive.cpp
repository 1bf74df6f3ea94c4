// The receiving half of TcpClient (contract in tcp_client.hpp): a decoded packet from the
// server goes to the bounded inbox; a TIMING echo at its head refines the skew (spec 4.3, 4.4).
// Runs on the comms thread; the inbox is shared with fetch() under `mutex_`.

#include <algorithm>

#include "moos/tcp_client.hpp"

namespace moos {

namespace {

/// What a message costs the inbox, in bytes: its strings plus a fixed part for the rest.
std::size_t inbox_cost(const Message& msg) {
  constexpr std::size_t kFixedPart = sizeof(Message);
  return kFixedPart + msg.key.size() + msg.sval.size() + msg.source.size() +
         msg.source_aux.size() + msg.community.size();
}

/// Skew filter weight of the previous value (spec 4.4).
constexpr double kSkewMemory = 0.9;

}  // namespace

void TcpClient::handle_packet(std::vector<Message> messages) {
  if (messages.empty()) return;
  auto begin = messages.begin();
  if (begin->type == msg_type::kTiming) {  // consumed by the comms layer (spec 4.3)
    refine_skew(*begin);
    ++begin;
  }
  bool added = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = begin; it != messages.end(); ++it) {
      if (it->type == msg_type::kNull || it->type == msg_type::kTiming) continue;
      inbox_bytes_ += inbox_cost(*it);
      inbox_.push_back(std::move(*it));
      added = true;
    }
    enforce_inbox_bounds();
  }
  if (added) fire_on_mail();
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
  inbox_.erase(inbox_.begin(), inbox_.begin() + static_cast<std::ptrdiff_t>(drop));
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
  // Spec 4.4: measured = Ts - (Tq + Tr) / 2; exponential filter unless the skew is exactly 0.
  const double tq = echo.time;
  const double ts = echo.dval;
  const double tr = local_time();
  const double measured = ts - (tq + tr) / 2.0;
  const double current = skew_s_.load();
  skew_s_ = current == 0.0 ? measured : kSkewMemory * current + (1.0 - kSkewMemory) * measured;
}

}  // namespace moos
