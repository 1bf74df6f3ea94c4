// MOOSDB rule: the fan-out of a NOTIFY (docs/protocol.md 5.3), mail, replies and their order
// (2.6, 5.6).
// Contract in include/moos/database.hpp.

#include <utility>

#include "moos/codec.hpp"
#include "moos/database.hpp"

namespace moos {

namespace mt = msg_type;
namespace dt = data_type;

void Database::fan_out(Variable& var, Message&& msg, double now) {
  // Steps 5-6: every subscriber whose interval expired, the publisher included; throttled
  // updates are dropped, not delayed. A subscription that never delivered is due. Each due
  // subscriber but the last gets a copy; the last one gets the message itself (a mail sink
  // takes it apart instead of copying it).
  const std::size_t size = msg.encoded_size();  // one size for every reader
  Client* previous = nullptr;
  for (auto& [subscriber, sub] : var.subscribers) {
    // Only a throttled subscription looks at its last delivery (an interval changes only with
    // a new subscription, which has never delivered).
    if (sub.interval_s > 0.0) {
      if (sub.last_delivery_moos_s && now - *sub.last_delivery_moos_s < sub.interval_s) continue;
      sub.last_delivery_moos_s = now;
    }
    if (previous) queue_fan_out_mail(*previous, msg, size, false);
    previous = sub.client;
  }
  if (previous) queue_fan_out_mail(*previous, msg, size, true);
}

Message Database::snapshot(const Variable& var) const {
  // protocol.md 2.6 "NOTIFY S->C snapshot on REGISTER"; an unwritten variable (the `ALL` answer)
  // shows the wire's unset fields.
  Message m;
  m.id = kUnsetId;
  m.type = mt::kNotify;
  m.data_type = var.data_type;
  m.key = var.name;
  m.dval2 = kUnsetDouble;
  if (var.value) {
    m.source = var.value->writer;
    m.source_aux = var.value->writer_aux;
    m.community = var.value->community;
    m.time = var.value->time_moos_s;
    m.dval = var.value->dval;
    m.sval = var.value->sval;
  }
  return m;
}

bool Database::admit_mail(Client& client, std::size_t size) {
  if (client.overflowed) return false;
  if (client.sink && client.sink_call != calls_) {  // the first mail of this call
    client.sink_call = calls_;
    client.pending_bytes = 0;
  }
  if (client.pending_bytes + size > config_.max_pending_bytes) {
    overflow(client);
    return false;
  }
  client.pending_bytes += size;
  if (client.async && !client.sink && !client.queued_for_flush) list_for_flush(client);
  return true;
}

void Database::list_for_flush(Client& client) {
  client.queued_for_flush = true;
  async_with_mail_.push_back(&client);
}

void Database::overflow(Client& client) {
  client.overflowed = true;
  drops_.push_back(DropRequest{
      client.id, "undelivered mail would exceed " + std::to_string(config_.max_pending_bytes) +
                     " bytes (the client does not collect its mail)"});
}

void Database::queue_mail(ClientId id, Message&& msg) {
  queue_fan_out_mail(clients_.at(id), msg, msg.encoded_size(), true);
}

void Database::queue_fan_out_mail(Client& client, Message& msg, std::size_t size, bool take) {
  if (!admit_mail(client, size)) return;
  if (client.sink) {  // delivered now: no packet per message
    if (take) {
      client.sink->take_mail(msg);
    } else {
      client.sink->copy_mail(msg);
    }
  } else if (take) {
    client.pending.push_back(std::move(msg));
  } else {
    client.pending.push_back(msg);
  }
}

void Database::take_pending(Client& client, std::vector<Message>& reply) {
  if (client.async) {  // the connection layer cuts it into packets (moosdb-lite's hub.hpp)
    for (auto& mail : client.pending) reply.push_back(std::move(mail));
    client.pending.clear();
    client.pending_bytes = 0;
    return;
  }
  // A synchronous client gets one packet per packet it sends (5.6): what would not fit in one
  // it accepts waits for its next reply, in order.
  std::size_t bytes = kPacketHeaderSize;
  for (const Message& m : reply) bytes += m.encoded_size();
  std::size_t taken = 0;
  for (; taken < client.pending.size(); ++taken) {
    const std::size_t size = client.pending[taken].encoded_size();
    if (bytes + size > config_.max_reply_bytes && taken > 0) break;  // one always goes
    bytes += size;
    client.pending_bytes -= size;
    reply.push_back(std::move(client.pending[taken]));
  }
  client.pending.erase(client.pending.begin(),
                       client.pending.begin() + static_cast<std::ptrdiff_t>(taken));
}

void Database::send_listed_mail() {
  for (Client* client : async_with_mail_) {
    client->queued_for_flush = false;
    client->pending_bytes = 0;  // the bound is per call
    if (client->pending.empty()) continue;
    send_packet(client->id, std::move(client->pending));
    client->pending.clear();
  }
  async_with_mail_.clear();
}

void Database::send_packet(ClientId to, std::vector<Message> messages) {
  output_.push_back(OutPacket{to, std::move(messages)});
}

Message Database::null_reply(double now) const {
  // protocol.md 2.6 "NULL S->C": dval carries the server's local warped time, time is -1.
  Message m;
  m.id = kUnsetId;
  m.type = mt::kNull;
  m.data_type = dt::kDouble;
  m.dval = now;
  return m;
}

std::vector<OutPacket> Database::take_output() {
  std::vector<OutPacket> out;
  out.swap(output_);
  return out;
}

void Database::take_output(std::vector<OutPacket>& out) {
  out.clear();
  out.swap(output_);
}

std::vector<DropRequest> Database::take_drop_requests() {
  std::vector<DropRequest> out;
  out.swap(drops_);
  return out;
}

}  // namespace moos
