// MOOSDB rules: handshake, disconnect and the packet loop (docs/protocol.md
// 1.5-1.9, 5.2). Contract in include/moos/database.hpp; the other rules live in
// database_notify.cpp (5.3), database_register.cpp (5.4-5.5), database_db_variables.cpp (5.7),
// database_server_requests.cpp (5.8) and database_mail.cpp (5.6).
//
// Algorithm: each call applies the rules of docs/protocol.md in order and appends mail to the
// pending queues of the clients it concerns. At the end of every public call, the pending mail of
// each asynchronous client is sent as one packet (protocol.md 5.6 SHOULD: deliver as soon as
// queued), while a synchronous client's mail waits for the reply to its next packet
// (protocol.md 5.6 MUST: no unsolicited packets). The requester's own reply is built first, so
// an echoed TIMING opens its packet.
//
// Data structures: variables live in a vector indexed by a small VarId, found by name
// through a hash map; each variable keeps its subscribers in a vector sorted by client id
// (fan-out order = connection order, deterministic); each client keeps the ids of the variables it is
// subscribed to, so a disconnect touches only those. Asynchronous clients with queued mail
// are listed once in `async_with_mail_`, so flushing costs nothing for idle clients (nor for
// clients with a mail sink, whose mail never waits).

#include "moos/database.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

#include "base/text.hpp"

namespace moos {

namespace {

namespace mt = msg_type;
namespace dt = data_type;

Message handshake_reply(char type, char data_type, double now) {
  Message m;
  m.id = kUnsetId;
  m.type = type;
  m.data_type = data_type;
  m.time = now;
  return m;
}

}  // namespace

std::string duplicate_name_reason(const std::string& name) {
  return "A client of this name (\"" + name + "\") already exists";
}

std::string overlong_name_reason(std::size_t name_bytes) {
  return "A client name of " + std::to_string(name_bytes) + " bytes is longer than the " +
         std::to_string(kMaxClientNameBytes) + " allowed";
}

std::optional<std::string> Database::handshake_refusal(
    const std::vector<Message>& identification) const {
  const Message* ident = identification.empty() ? nullptr : &identification.front();
  if (ident == nullptr || ident->sval.empty()) return std::string(kNoNameReason);
  if (ident->sval.size() > kMaxClientNameBytes) return overlong_name_reason(ident->sval.size());
  if (client_by_name_.count(ident->sval) != 0) return duplicate_name_reason(ident->sval);
  return std::nullopt;
}

Database::Database(DatabaseConfig config, double start_moos_s, LogSink log,
                   NotifyObserver observer)
    : config_(std::move(config)),
      db_name_("MOOSDB_" + config_.community),
      start_moos_s_(start_moos_s),
      log_(std::move(log)),
      notify_observer_(std::move(observer)) {
  refresh_db_variables(start_moos_s);
}

// ---------------------------------------------------------------------------------------
// Connections (protocol.md 1.5, 1.6, 1.9)

bool Database::connect(ClientId id, const std::vector<Message>& identification,
                       double now_moos_s, MailSink* mail_sink) {
  assert(clients_.count(id) == 0 && "connection ids are unique");
  const std::optional<std::string> poison_reason = handshake_refusal(identification);
  if (poison_reason) {
    Message poison = handshake_reply(mt::kPoison, dt::kString, now_moos_s);
    poison.sval = *poison_reason;
    send_packet(id, {std::move(poison)});
    return false;
  }

  const Message* ident = &identification.front();
  Client client;
  client.id = id;
  client.name = ident->sval;
  client.async = base::iequals(ident->key, kAsynchronousKey);
  client.sink = client.async ? mail_sink : nullptr;  // a synchronous client's mail waits
  client_by_name_[client.name] = id;
  const std::string name = client.name;
  clients_.emplace(id, std::move(client));

  // Skew = server MOOS time when the identification is processed - its time (protocol.md 1.8).
  Message welcome = handshake_reply(mt::kWelcome, dt::kDouble, now_moos_s);
  welcome.source_aux = "hostname=" + config_.hostname;
  welcome.community = config_.community;
  welcome.dval = now_moos_s - ident->time;
  welcome.sval = kAsynchronousKey;
  send_packet(id, {std::move(welcome)});

  publish_db_string("DB_EVENT", "connected=" + name, now_moos_s);
  publish_db_string("DB_CLIENTS", client_list(), now_moos_s);
  flush_async_mail();
  return true;
}

void Database::disconnect(ClientId id, double now_moos_s) {
  const auto it = clients_.find(id);
  if (it == clients_.end()) return;
  Client& client = it->second;
  for (const VarId var : client.subscribed) vars_[var].subscribers.erase(id);
  if (client.queued_for_flush)  // not left listed: the list points at clients
    async_with_mail_.erase(std::find(async_with_mail_.begin(), async_with_mail_.end(), &client));
  if (client.refusals > kLoggedRefusalsPerClient)
    log_(describe(id) + ": " + std::to_string(client.refusals) +
         " messages refused in total");
  const std::string name = client.name;
  client_by_name_.erase(name);
  Client*& cached = recent_senders_[id % kRecentSenders];
  if (cached == &client) cached = nullptr;
  clients_.erase(it);

  publish_db_string("DB_EVENT", "disconnected=" + name, now_moos_s);
  publish_db_string("DB_CLIENTS", client_list(), now_moos_s);
  flush_async_mail();
}

// ---------------------------------------------------------------------------------------
// Packets (protocol.md 5.2)

void Database::process_packet(ClientId id, std::vector<Message> packet, double now_moos_s) {
  process_messages(id, packet.data(), packet.data() + packet.size(), now_moos_s);
}

void Database::process_message(ClientId id, Message&& msg, double now_moos_s) {
  // The in-process bus's every posting: a lone NOTIFY, so no TIMING to echo and no loop.
  if (msg.type != mt::kNotify) return process_messages(id, &msg, &msg + 1, now_moos_s);
  Client* client = sender(id);
  if (!client) return;
  handle_notify(*client, std::move(msg), now_moos_s);
  if (client->async) {
    end_async_packet(*client);  // inline: the bus's every posting ends here
  } else {
    end_packet(*client, nullptr, now_moos_s);
  }
}

Database::Client* Database::sender(ClientId id) {
  Client*& cached = recent_senders_[id % kRecentSenders];
  if (!cached || cached->id != id) {
    const auto found = clients_.find(id);
    if (found == clients_.end()) return nullptr;
    cached = &found->second;
  }
  return cached;
}

void Database::process_messages(ClientId id, Message* first, Message* last, double now_moos_s) {
  Client* sending = sender(id);
  if (!sending) return;
  Client& client = *sending;
  // Step 2: a leading TIMING is echoed to asynchronous clients; synchronous clients never
  // receive TIMING (protocol.md 5.6), so theirs is dropped. TIMING elsewhere is ignored. The
  // echo is made after the other messages: handling them leaves this one as it is.
  Message* echo = nullptr;
  if (first != last && first->type == mt::kTiming) {
    if (client.async) echo = first;
    ++first;
  }
  for (; first != last; ++first) handle_message(client, std::move(*first), now_moos_s);
  end_packet(client, echo, now_moos_s);
}

void Database::end_packet(Client& client, Message* echo, double now_moos_s) {
  // Step 6: the reply. Sync: NULL first, always. Async: echo first, only if non-empty. Handling
  // erases no client (drops are requests), so `client` is still valid.
  if (client.async && !echo) return end_async_packet(client);
  std::vector<Message> reply;
  if (!client.async) {
    reply.push_back(null_reply(now_moos_s));
  } else {
    reply.push_back(std::move(*echo));
    reply.back().dval = now_moos_s;  // server local warped time; the DB's skew is 0
    reply.back().dval2 = 0.0;        // outgoing delay for this client, seconds (none)
  }
  take_pending(client, reply);
  send_packet(client.id, std::move(reply));
  // Step 7, for every asynchronous client and on every packet (protocol.md 5.6 SHOULD).
  flush_async_mail();
}

void Database::handle_message(Client& client, Message&& msg, double now) {
  const ClientId id = client.id;
  switch (msg.type) {
    case mt::kNotify: handle_notify(client, std::move(msg), now); break;
    case mt::kRegister: handle_register(id, msg, now); break;
    case mt::kUnregister: handle_unregister(id, msg); break;
    case mt::kWildcardRegister: handle_wildcard_register(id, msg, now); break;
    case mt::kWildcardUnregister: handle_wildcard_unregister(id, msg); break;
    case mt::kServerRequest: handle_server_request(id, msg, now); break;
    case mt::kNull:     // keep-alive
    case mt::kCommand:  // ignored by the reference DB
    case mt::kTiming:   // only meaningful first in a packet
      break;
    default:
      refuse(id, std::string("message of unknown type '") + msg.type + "' (key \"" +
                     base::excerpt(msg.key) + "\") ignored");
      break;
  }
}

// ---------------------------------------------------------------------------------------
// Diagnostics and queries

// `what` quotes the client's own text (names, patterns, types): escaped here, once, so a
// refusal can never end a log line or forge one.
void Database::refuse(ClientId id, const std::string& what) {
  Client& client = clients_.at(id);
  ++client.refusals;
  if (client.refusals <= kLoggedRefusalsPerClient) {
    log_(describe(id) + ": " + base::escape_for_log(what));
  } else if (client.refusals == kLoggedRefusalsPerClient + 1) {
    log_(describe(id) + ": more refused messages; further ones are counted, not logged");
  }
}

std::string Database::describe(ClientId id) const {
  const auto it = clients_.find(id);
  return it == clients_.end() ? "client #" + std::to_string(id)
                              : "client \"" + base::escape_for_log(it->second.name) + "\"";
}

std::optional<std::string> Database::client_name(ClientId id) const {
  const auto it = clients_.find(id);
  if (it == clients_.end()) return std::nullopt;
  return it->second.name;
}

bool Database::is_async(ClientId id) const {
  const auto it = clients_.find(id);
  return it != clients_.end() && it->second.async;
}

std::size_t Database::pending_bytes(ClientId id) const {
  const auto it = clients_.find(id);
  if (it == clients_.end()) return 0;
  const Client& client = it->second;
  return client.sink ? 0 : client.pending_bytes;  // a sink took it all
}

std::optional<Message> Database::latest(const std::string& name) const {
  const auto it = var_index_.find(name);
  if (it == var_index_.end() || !vars_[it->second].value) return std::nullopt;
  return snapshot(vars_[it->second]);
}

}  // namespace moos
