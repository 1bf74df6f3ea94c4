// Connection state machine (protocol.md 5.1a). See hub.hpp for the contract.
//
// Each connection holds its state, the banner bytes seen so far and a PacketReader that
// reassembles packets from arbitrary segments. receive() first completes the banner, then
// feeds everything else to the reader and processes every complete packet in order: the
// first one is the identification, the rest go to the Database. Database output is turned
// into Send actions right after each Database call, so a POISON or a reply always precedes
// the Close that follows it, and mail to a connection that is already closed is dropped.
// Each Send names its source (the connection whose packet was being processed) for the
// transport's per-source queues, and mail to an asynchronous client is cut into packets of
// kFairPacketBytes, so one source's large packet is not one long turn.

#include "hub.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "base/text.hpp"

namespace moosdb_lite {

namespace {

/// How much of a rejected banner is quoted in the log.
constexpr std::size_t kQuotedBannerBytes = 32;

// Printable ASCII kept, everything else as \xNN, so a log line stays one readable line.
std::string quote_bytes(std::string_view bytes, std::size_t max_bytes) {
  std::string out = "\"";
  for (std::size_t i = 0; i < bytes.size() && i < max_bytes; ++i) {
    const auto c = static_cast<unsigned char>(bytes[i]);
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
      out.push_back(static_cast<char>(c));
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out + "\"";
}

}  // namespace

Hub::Hub(HubConfig config, double start_real_s, LogSink log,
         moos::Database::NotifyObserver observer)
    : config_(std::move(config)),
      log_(std::move(log)),
      db_(config_.database, start_real_s * config_.time_warp, log_, std::move(observer)),
      last_refresh_real_s_(start_real_s) {}

ConnectionId Hub::open(std::string peer, double now_real_s) {
  const ConnectionId id = next_id_++;
  auto [it, inserted] = connections_.emplace(id, Connection(config_.max_packet_bytes));
  it->second.peer = std::move(peer);
  it->second.state_since_real_s = now_real_s;
  return id;
}

void Hub::receive(ConnectionId id, std::string_view bytes, double now_real_s) {
  const auto it = connections_.find(id);
  if (it == connections_.end()) return;
  Connection& conn = it->second;
  // Liveness is judged by what the client sent: any byte counts, so a large packet that
  // takes many reads to arrive keeps its sender alive.
  if (!bytes.empty()) conn.last_input_real_s = now_real_s;
  if (conn.state == State::kBanner) {
    process_banner(id, conn, bytes, now_real_s);
    if (connections_.count(id) == 0 || conn.state == State::kBanner) return;
  }
  conn.reader.feed(bytes);
  process_packets(id, now_real_s);
}

void Hub::process_banner(ConnectionId id, Connection& conn, std::string_view& bytes,
                         double now) {
  const std::size_t wanted = moos::kBannerSize - conn.banner.size();
  const std::size_t taken = std::min(wanted, bytes.size());
  conn.banner.append(bytes.data(), taken);
  bytes.remove_prefix(taken);  // what follows belongs to the next state (5.1a)
  if (conn.banner.size() < moos::kBannerSize) return;
  if (!moos::banner_matches(conn.banner)) {
    close(id, "wrong protocol banner " + quote_bytes(conn.banner, kQuotedBannerBytes) +
                  "; closed without reply",
          now, Action::Kind::kClose);
    return;
  }
  conn.state = State::kIdent;
  conn.state_since_real_s = now;
}

void Hub::process_packets(ConnectionId id, double now) {
  for (;;) {
    const auto it = connections_.find(id);
    if (it == connections_.end()) return;
    Connection& conn = it->second;
    std::vector<moos::Message> packet;
    moos::DecodeError error;
    const auto status = conn.reader.next(packet, &error);
    if (status == moos::PacketReader::Status::kNeedMore) return;
    if (status == moos::PacketReader::Status::kError) {
      const std::string what = "bad packet (" + base::escape_for_log(error.reason) + " at byte " +
                               std::to_string(error.offset) + ")";
      if (conn.state == State::kIdent) {
        log_(describe(id) + ": " + what + " in the handshake");
        handle_identification(id, {}, now);  // answered with POISON, as the DB does
      } else {
        close(id, what + "; connection dropped", now, Action::Kind::kClose);
      }
      return;
    }
    if (conn.state == State::kIdent) {
      handle_identification(id, packet, now);
      continue;
    }
    source_ = id;
    db_.process_packet(id, std::move(packet), moos_time(now));
    collect_database_output(now);
    source_ = kServerSource;
  }
}

void Hub::handle_identification(ConnectionId id, const std::vector<moos::Message>& packet,
                                double now) {
  const std::optional<std::string> refusal = db_.handshake_refusal(packet);
  const bool accepted = db_.connect(id, packet, moos_time(now));
  if (!accepted) {
    // The POISON is already queued; tell why in the log, as the POISON does.
    const bool no_name = packet.empty() || packet.front().sval.empty();
    collect_database_output(now);
    close(id,
          no_name ? std::string("handshake refused: no client name")
                  : "handshake refused: " + base::escape_for_log(refusal.value_or("")),
          now, Action::Kind::kCloseAfterSend);
    return;
  }
  Connection& conn = connections_.at(id);
  conn.state = State::kActive;
  conn.state_since_real_s = now;
  conn.last_input_real_s = now;
  log_(describe(id) + ": connected (" +
       (db_.is_async(id) ? "asynchronous" : "synchronous") + ")");
  collect_database_output(now);
}

void Hub::end_of_stream(ConnectionId id, double now_real_s, std::string_view reason) {
  const auto it = connections_.find(id);
  if (it == connections_.end()) return;
  const Connection& conn = it->second;
  std::string why = reason.empty() ? std::string("closed by the peer") : std::string(reason);
  const std::size_t partial = conn.reader.buffered();
  switch (conn.state) {
    case State::kBanner:
      why += " after " + std::to_string(conn.banner.size()) + " of 32 banner bytes";
      break;
    case State::kIdent:
      why += " before identifying itself";
      break;
    case State::kActive:
      break;
  }
  if (partial > 0)
    why += "; " + std::to_string(partial) + " bytes of an incomplete packet discarded";
  // Half-closed peers may still read: write what is pending, then close.
  close(id, why, now_real_s, Action::Kind::kCloseAfterSend);
}

void Hub::drop(ConnectionId id, const std::string& reason, double now_real_s) {
  close(id, reason + "; connection dropped", now_real_s, Action::Kind::kClose);
}

void Hub::heard(ConnectionId id, double now_real_s) {
  const auto it = connections_.find(id);
  if (it != connections_.end())
    it->second.last_input_real_s = std::max(it->second.last_input_real_s, now_real_s);
}

void Hub::set_reading_paused(ConnectionId id, bool paused, double now_real_s) {
  const auto it = connections_.find(id);
  if (it == connections_.end() || it->second.reading_paused == paused) return;
  it->second.reading_paused = paused;
  // The client could not be heard while paused: its silence counts from the resumption.
  if (!paused) it->second.last_input_real_s = now_real_s;
}

std::size_t Hub::held_bytes(ConnectionId id) const {
  const auto it = connections_.find(id);
  if (it == connections_.end()) return 0;
  return it->second.reader.buffered() + db_.pending_bytes(id);
}

void Hub::tick(double now_real_s) {
  std::vector<std::pair<ConnectionId, std::string>> expired;
  for (const auto& [id, conn] : connections_) {
    const double in_state_s = now_real_s - conn.state_since_real_s;
    if (conn.state == State::kBanner && in_state_s > config_.banner_timeout_s) {
      expired.emplace_back(id, "no protocol banner within " +
                                   base::format_g(config_.banner_timeout_s) + " s");
    } else if (conn.state == State::kIdent && in_state_s > config_.handshake_timeout_s) {
      expired.emplace_back(id, "no identification packet within " +
                                   base::format_g(config_.handshake_timeout_s) + " s");
    } else if (conn.state == State::kActive && config_.client_timeout_s &&
               !conn.reading_paused &&
               now_real_s - conn.last_input_real_s > *config_.client_timeout_s) {
      expired.emplace_back(id, "nothing received for more than " +
                                   base::format_g(*config_.client_timeout_s) +
                                   " s (ClientTimeout)");
    }
  }
  for (const auto& [id, reason] : expired)
    close(id, reason + "; connection dropped", now_real_s, Action::Kind::kClose);

  if (now_real_s - last_refresh_real_s_ >= kDbVariableRefreshInterval_s) {
    last_refresh_real_s_ = now_real_s;
    db_.refresh_db_variables(moos_time(now_real_s));
    collect_database_output(now_real_s);
  }
}

void Hub::close(ConnectionId id, const std::string& reason, double now, Action::Kind kind) {
  const auto it = connections_.find(id);
  if (it == connections_.end()) return;
  log_(describe(id) + ": " + reason);
  const bool was_active = it->second.state == State::kActive;
  connections_.erase(it);
  actions_.push_back(Action{kind, id, {}});
  if (was_active) {
    // What a disconnect publishes (DB_CLIENTS, DB_EVENT) is the server's, whoever caused it.
    const ConnectionId caller = source_;
    source_ = kServerSource;
    db_.disconnect(id, moos_time(now));
    collect_database_output(now);
    source_ = caller;
  }
}

void Hub::collect_database_output(double now) {
  for (auto& packet : db_.take_output()) {
    if (connections_.count(packet.to) == 0) continue;
    queue_send(std::move(packet));
  }
  for (const auto& drop_request : db_.take_drop_requests())
    close(drop_request.id, drop_request.reason + "; connection dropped", now,
          Action::Kind::kClose);
}

void Hub::queue_send(moos::OutPacket packet) {
  const auto send = [&](const moos::Message* first, const moos::Message* last) {
    actions_.push_back(
        Action{Action::Kind::kSend, packet.to, moos::encode_packet(first, last), source_});
  };
  const std::vector<moos::Message>& messages = packet.messages;
  if (!db_.is_async(packet.to)) {
    send(messages.data(), messages.data() + messages.size());
    return;
  }
  // Slices in order: an echoed TIMING stays the first message of the first packet (5.6).
  std::size_t begin = 0;
  std::size_t bytes = 0;
  for (std::size_t i = 0; i < messages.size(); ++i) {
    const std::size_t size = messages[i].encoded_size();
    if (i > begin && bytes + size > kFairPacketBytes) {
      send(messages.data() + begin, messages.data() + i);
      begin = i;
      bytes = 0;
    }
    bytes += size;
  }
  if (begin < messages.size()) send(messages.data() + begin, messages.data() + messages.size());
}

std::vector<Action> Hub::take_actions() {
  std::vector<Action> out;
  out.swap(actions_);
  return out;
}

std::string Hub::describe(ConnectionId id) const {
  const auto it = connections_.find(id);
  if (it == connections_.end()) return "connection #" + std::to_string(id);
  if (const auto name = db_.client_name(id))
    return "client \"" + base::escape_for_log(*name) + "\" (" + it->second.peer + ")";
  return "connection #" + std::to_string(id) + " (" + it->second.peer + ")";
}

}  // namespace moosdb_lite
