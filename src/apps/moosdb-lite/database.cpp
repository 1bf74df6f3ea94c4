// MOOSDB semantics (../shared/spec/moos-wire-protocol.md 1.5-1.9, 5.1-5.8). See database.hpp.
//
// Algorithm: each call applies the spec's rules in order and appends mail to the pending
// queues of the clients it concerns. At the end of every public call, the pending mail of
// each asynchronous client is sent as one packet (spec 5.6 SHOULD: deliver as soon as
// queued), while a synchronous client's mail waits for the reply to its next packet
// (spec 5.6 MUST: no unsolicited packets). The requester's own reply is built first, so
// an echoed TIMING opens its packet.
//
// Data structures: variables live in a vector indexed by a small VarId, found by name
// through a hash map; each variable keeps its subscribers in an ordered map (fan-out order
// = connection order, deterministic); each client keeps the ids of the variables it is
// subscribed to, so a disconnect touches only those. Asynchronous clients with queued mail
// are listed once in `async_with_mail_`, so flushing costs nothing for idle clients.
//
// Deviations from the reference DB (documented in docs/moos.md): malformed messages are
// refused with a logged reason; an empty NOTIFY source is replaced by the client name; a
// wildcard filter does not override an existing explicit subscription at a variable's
// first write; WILDCARD_UNREGISTER also removes the identical filter; sync clients are
// answered even for an empty packet; DB_QOS and DB_VARSUMMARY are not published.

#include "database.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include "base/text.hpp"

namespace moosdb_lite {

namespace {

using moos::Message;
namespace mt = moos::msg_type;
namespace dt = moos::data_type;

/// Write-frequency estimate of a variable (dval2 of the `ALL` answer, spec 5.8): writes
/// counted over windows of at least this many MOOS seconds.
constexpr double kFrequencyWindow_moos_s = 1.0;

bool is_value_type(char data_type) {
  return data_type == dt::kDouble || data_type == dt::kString || data_type == dt::kBinary;
}

std::string type_name(char data_type) {
  switch (data_type) {
    case dt::kDouble: return "double";
    case dt::kString: return "string";
    case dt::kBinary: return "binary";
    default: return std::string("type '") + data_type + "'";
  }
}

Message handshake_reply(char type, char data_type, double now) {
  Message m;
  m.id = moos::kUnsetId;
  m.type = type;
  m.data_type = data_type;
  m.time = now;
  return m;
}

}  // namespace

std::string duplicate_name_reason(const std::string& name) {
  return "A client of this name (\"" + name + "\") already exists";
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
// Connections (spec 1.5, 1.6, 1.9)

bool Database::connect(ClientId id, const std::vector<Message>& identification,
                       double now_moos_s) {
  assert(clients_.count(id) == 0 && "connection ids are unique");
  const Message* ident = identification.empty() ? nullptr : &identification.front();
  std::optional<std::string> poison_reason;
  if (ident == nullptr || ident->sval.empty()) {
    poison_reason = kNoNameReason;
  } else if (client_by_name_.count(ident->sval) != 0) {
    poison_reason = duplicate_name_reason(ident->sval);
  }
  if (poison_reason) {
    Message poison = handshake_reply(mt::kPoison, dt::kString, now_moos_s);
    poison.sval = *poison_reason;
    send_packet(id, {std::move(poison)});
    return false;
  }

  Client client;
  client.name = ident->sval;
  client.async = base::iequals(ident->key, moos::kAsynchronousKey);
  client_by_name_[client.name] = id;
  const std::string name = client.name;
  clients_.emplace(id, std::move(client));

  // Skew = server MOOS time when the identification is processed - its time (spec 1.8).
  Message welcome = handshake_reply(mt::kWelcome, dt::kDouble, now_moos_s);
  welcome.source_aux = "hostname=" + config_.hostname;
  welcome.community = config_.community;
  welcome.dval = now_moos_s - ident->time;
  welcome.sval = moos::kAsynchronousKey;
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
  if (client.refusals > kLoggedRefusalsPerClient)
    log_("client \"" + client.name + "\": " + std::to_string(client.refusals) +
         " messages refused in total");
  const std::string name = client.name;
  client_by_name_.erase(name);
  clients_.erase(it);

  publish_db_string("DB_EVENT", "disconnected=" + name, now_moos_s);
  publish_db_string("DB_CLIENTS", client_list(), now_moos_s);
  flush_async_mail();
}

// ---------------------------------------------------------------------------------------
// Packets (spec 5.2)

void Database::process_packet(ClientId id, std::vector<Message> packet, double now_moos_s) {
  if (clients_.count(id) == 0) return;
  // Step 2: a leading TIMING is echoed to asynchronous clients; synchronous clients never
  // receive TIMING (spec 5.6), so theirs is dropped. TIMING elsewhere is ignored.
  std::optional<Message> echo;
  std::size_t first = 0;
  if (!packet.empty() && packet.front().type == mt::kTiming) {
    first = 1;
    if (clients_.at(id).async) {
      echo = packet.front();
      echo->dval = now_moos_s;  // server local warped time; the DB's skew is 0
      echo->dval2 = 0.0;        // outgoing delay for this client, seconds (none)
    }
  }
  for (std::size_t i = first; i < packet.size(); ++i)
    handle_message(id, std::move(packet[i]), now_moos_s);

  // Step 6: the reply. Sync: NULL first, always. Async: echo first, only if non-empty.
  Client& client = clients_.at(id);
  std::vector<Message> reply;
  if (!client.async) {
    reply.push_back(null_reply(now_moos_s));
  } else if (echo) {
    reply.push_back(std::move(*echo));
  }
  for (auto& mail : client.pending) reply.push_back(std::move(mail));
  client.pending.clear();
  client.pending_bytes = 0;
  if (!reply.empty()) send_packet(id, std::move(reply));
  // Step 7, for every asynchronous client and on every packet (spec 5.6 SHOULD).
  flush_async_mail();
}

void Database::handle_message(ClientId id, Message msg, double now) {
  switch (msg.type) {
    case mt::kNotify: handle_notify(id, std::move(msg), now); break;
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
      refuse(id, std::string("message of unknown type '") + msg.type + "' (key \"" + msg.key +
                     "\") ignored");
      break;
  }
}

// ---------------------------------------------------------------------------------------
// NOTIFY (spec 5.3)

void Database::handle_notify(ClientId id, Message msg, double now) {
  if (msg.key.empty()) return refuse(id, "NOTIFY with an empty variable name refused");
  if (!is_value_type(msg.data_type))
    return refuse(id, "NOTIFY " + msg.key + " with data type '" + msg.data_type +
                          "' refused (expected D, S or B)");
  Client& client = clients_.at(id);
  if (msg.source.empty()) msg.source = client.name;
  const char type = msg.data_type;
  const VarId var = publish(std::move(msg), now);
  if (vars_[var].data_type != type)
    return refuse(id, "NOTIFY " + vars_[var].name + " as " + type_name(type) +
                          " refused: the variable is " + type_name(vars_[var].data_type) +
                          " (fixed by its first write)");
  client.published.insert(var);
}

Database::VarId Database::publish(Message msg, double now) {
  const VarId id = find_or_create(msg.key);
  if (vars_[id].write_count == 0) {
    // Step 2: the first write fixes the type and binds the wildcard filters.
    vars_[id].data_type = msg.data_type;
    bind_wildcard_filters(id, msg.source);
  }
  Variable& var = vars_[id];
  if (msg.data_type != var.data_type) return id;  // step 3: the caller reports the refusal

  // Step 4: store.
  msg.type = mt::kNotify;
  if (msg.community.empty()) msg.community = config_.community;
  if (msg.data_type == dt::kDouble) {
    var.dval = msg.dval;
    var.sval.clear();
  } else {
    var.dval = moos::kUnsetDouble;
    var.sval = msg.sval;
  }
  var.time_moos_s = msg.time;
  var.db_write_moos_s = now;
  var.writer = msg.source;
  var.writer_aux = msg.source_aux;
  var.community = msg.community;
  if (var.write_count == 0) var.frequency_window_start_moos_s = now;
  ++var.write_count;
  const double window_s = now - var.frequency_window_start_moos_s;
  if (window_s >= kFrequencyWindow_moos_s) {
    var.frequency_hz =
        static_cast<double>(var.write_count - var.frequency_window_start_count) / window_s;
    var.frequency_window_start_moos_s = now;
    var.frequency_window_start_count = var.write_count;
  }
  if (notify_observer_) notify_observer_(msg);

  // Steps 5-6: fan out, publisher included; throttled updates are dropped, not delayed.
  for (auto& [subscriber, sub] : var.subscribers) {
    if (sub.interval_s > 0.0 && now - sub.last_delivery_moos_s < sub.interval_s) continue;
    sub.last_delivery_moos_s = now;
    queue_mail(subscriber, msg);
  }
  return id;
}

void Database::bind_wildcard_filters(VarId var, const std::string& writer) {
  Variable& v = vars_[var];
  for (auto& [id, client] : clients_) {
    if (v.subscribers.count(id) != 0) continue;  // an explicit registration wins
    for (const auto& filter : client.filters) {
      if (filter.matches(writer, v.name)) {
        v.subscribers[id] = Subscription{filter.interval_s, 0.0};
        client.subscribed.insert(var);
        break;
      }
    }
  }
}

bool Database::matches(const moos::WildcardSpec& spec, const Variable& var) {
  // An existing variable matches by its last writer (empty if never written), spec 5.5.
  return spec.matches(var.writer, var.name);
}

Database::VarId Database::find_or_create(const std::string& name) {
  const auto it = var_index_.find(name);
  if (it != var_index_.end()) return it->second;
  const VarId id = vars_.size();
  Variable var;
  var.name = name;
  vars_.push_back(std::move(var));
  var_index_.emplace(name, id);
  return id;
}

// ---------------------------------------------------------------------------------------
// REGISTER / UNREGISTER (spec 5.4) and wildcards (spec 5.5)

void Database::handle_register(ClientId id, const Message& msg, double now) {
  if (msg.key.empty()) return refuse(id, "REGISTER with an empty variable name refused");
  if (!std::isfinite(msg.dval) || msg.dval < 0.0)
    return refuse(id, "REGISTER " + msg.key + " with interval " + std::to_string(msg.dval) +
                          " refused (expected a number >= 0)");
  subscribe(id, find_or_create(msg.key), msg.dval, now);
}

void Database::subscribe(ClientId id, VarId var, double interval_s, double now) {
  Variable& v = vars_[var];
  Subscription& sub = v.subscribers[id];
  sub = Subscription{interval_s, 0.0};
  clients_.at(id).subscribed.insert(var);
  if (v.write_count > 0) {
    // Every REGISTER re-sends the current value (spec 5.4).
    sub.last_delivery_moos_s = now;
    queue_mail(id, snapshot(v));
  }
}

void Database::handle_unregister(ClientId id, const Message& msg) {
  const auto it = var_index_.find(msg.key);
  if (it == var_index_.end()) return;
  vars_[it->second].subscribers.erase(id);
  clients_.at(id).subscribed.erase(it->second);
}

void Database::handle_wildcard_register(ClientId id, const Message& msg, double now) {
  std::string problem;
  const moos::WildcardSpec spec = moos::parse_wildcard_spec(msg.sval, &problem);
  if (!problem.empty())
    return refuse(id, "WILDCARD_REGISTER \"" + msg.sval + "\" refused: " + problem);
  auto& filters = clients_.at(id).filters;
  const bool known = std::any_of(filters.begin(), filters.end(), [&](const moos::WildcardSpec& f) {
    return f.same_patterns(spec);
  });
  if (!known) filters.push_back(spec);  // set semantics on the pair: the first interval stays
  for (VarId var = 0; var < vars_.size(); ++var) {
    if (matches(spec, vars_[var])) subscribe(id, var, spec.interval_s, now);
  }
}

void Database::handle_wildcard_unregister(ClientId id, const Message& msg) {
  std::string problem;
  const moos::WildcardSpec spec = moos::parse_wildcard_spec(msg.sval, &problem);
  if (!problem.empty())
    return refuse(id, "WILDCARD_UNREGISTER \"" + msg.sval + "\" refused: " + problem);
  Client& client = clients_.at(id);
  auto& filters = client.filters;
  const auto same = std::find_if(filters.begin(), filters.end(), [&](const moos::WildcardSpec& f) {
    return f.same_patterns(spec);
  });
  if (same != filters.end()) filters.erase(same);
  for (VarId var = 0; var < vars_.size(); ++var) {
    if (matches(spec, vars_[var])) {
      vars_[var].subscribers.erase(id);
      client.subscribed.erase(var);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Server requests (spec 5.8): `ALL` by equality, the others by substring.

void Database::handle_server_request(ClientId id, const Message& msg, double now) {
  if (msg.key == "ALL") {
    answer_all(id, msg.id);
  } else if (msg.key.find("VAR_SUMMARY") != std::string::npos) {
    answer_var_summary(id, msg.id, now);
  } else if (msg.key.find("PROC_SUMMARY") != std::string::npos) {
    answer_proc_summary(id, msg.id, now);
  } else if (msg.key.find("DB_CLEAR") != std::string::npos) {
    log_(describe(id) + ": DB_CLEAR: every variable and all undelivered mail cleared");
    clear_db();
  } else {
    refuse(id, "unknown server request \"" + msg.key + "\" ignored");
  }
}

void Database::answer_all(ClientId id, std::int32_t request_id) {
  for (const Variable& var : vars_) {
    // The snapshot fields, with the request id, the write frequency in dval2 and the time
    // of the last write relative to the DB start (-1 if never written), spec 5.8.
    Message m = snapshot(var);
    m.id = request_id;
    m.dval2 = var.frequency_hz;
    const double since_start_s = var.db_write_moos_s - start_moos_s_;
    m.time = since_start_s < 0.0 ? moos::kUnsetDouble : since_start_s;
    queue_mail(id, std::move(m));
  }
}

void Database::answer_var_summary(ClientId id, std::int32_t request_id, double now) {
  std::string names;
  for (const Variable& var : vars_) {
    if (!names.empty()) names += ',';
    names += var.name;
  }
  Message m = moos::make_string_notify("VAR_SUMMARY", std::move(names), db_name_, now);
  m.id = request_id;
  m.community = config_.community;
  queue_mail(id, std::move(m));
}

void Database::answer_proc_summary(ClientId requester, std::int32_t request_id, double now) {
  for (const auto& [id, c] : clients_) {
    std::string text = c.name + ":SUBSCRIBED=";
    for (const VarId var : c.subscribed) text += "," + vars_[var].name;
    text += ",PUBLISHED=";
    for (const VarId var : c.published) text += "," + vars_[var].name;
    Message m = moos::make_string_notify("PROC_SUMMARY", std::move(text), db_name_,
                                         now - start_moos_s_);
    m.id = request_id;
    m.community = config_.community;
    queue_mail(requester, std::move(m));
  }
}

void Database::clear_db() {
  for (Variable& var : vars_) {
    Variable cleared;
    cleared.name = std::move(var.name);
    cleared.subscribers = std::move(var.subscribers);
    var = std::move(cleared);
  }
  for (auto& [id, client] : clients_) {
    client.pending.clear();
    client.pending_bytes = 0;
    client.published.clear();
  }
}

// ---------------------------------------------------------------------------------------
// DB variables (spec 5.7)

void Database::refresh_db_variables(double now_moos_s) {
  publish_db_double("DB_TIME", now_moos_s, now_moos_s);
  publish_db_double("DB_UPTIME", now_moos_s - start_moos_s_, now_moos_s);
  publish_db_string("DB_CLIENTS", client_list(), now_moos_s);
  publish_db_string("DB_RWSUMMARY", rw_summary(), now_moos_s);
  flush_async_mail();
}

void Database::publish_db_string(const std::string& key, const std::string& value, double now) {
  publish_db_variable(moos::make_string_notify(key, value, db_name_, now), now);
}

void Database::publish_db_double(const std::string& key, double value, double now) {
  publish_db_variable(moos::make_double_notify(key, value, db_name_, now), now);
}

void Database::publish_db_variable(Message msg, double now) {
  msg.community = config_.community;
  const char type = msg.data_type;
  const VarId var = publish(std::move(msg), now);
  if (vars_[var].data_type != type)
    log_("DB variable " + vars_[var].name + " not written: a client wrote it first as " +
         type_name(vars_[var].data_type));
}

std::string Database::client_list() const {
  std::string names;
  for (const auto& [id, client] : clients_) names += client.name + ",";
  return names;
}

std::string Database::rw_summary() const {
  // `client=sub1:sub2&pub1:pub2` entries separated by `,` (spec 5.7).
  std::string text;
  for (const auto& [id, client] : clients_) {
    if (!text.empty()) text += ',';
    text += client.name + "=";
    const char* sep = "";
    for (const VarId var : client.subscribed) {
      text += sep + vars_[var].name;
      sep = ":";
    }
    text += '&';
    sep = "";
    for (const VarId var : client.published) {
      text += sep + vars_[var].name;
      sep = ":";
    }
  }
  return text;
}

// ---------------------------------------------------------------------------------------
// Mail

Message Database::snapshot(const Variable& var) const {
  // Spec 2.6 "NOTIFY S->C snapshot on REGISTER".
  Message m;
  m.id = moos::kUnsetId;
  m.type = mt::kNotify;
  m.data_type = var.data_type;
  m.source = var.writer;
  m.source_aux = var.writer_aux;
  m.community = var.community;
  m.key = var.name;
  m.time = var.time_moos_s;
  m.dval = var.dval;
  m.dval2 = moos::kUnsetDouble;
  m.sval = var.sval;
  return m;
}

void Database::queue_mail(ClientId id, Message msg) {
  Client& client = clients_.at(id);
  if (client.overflowed) return;
  const std::size_t size = msg.encoded_size();
  if (client.pending_bytes + size > config_.max_pending_bytes) {
    client.overflowed = true;
    drops_.push_back(DropRequest{
        id, "undelivered mail would exceed " + std::to_string(config_.max_pending_bytes) +
                " bytes (the client does not collect its mail)"});
    return;
  }
  client.pending_bytes += size;
  client.pending.push_back(std::move(msg));
  if (client.async && !client.queued_for_flush) {
    client.queued_for_flush = true;
    async_with_mail_.push_back(id);
  }
}

void Database::flush_async_mail() {
  for (const ClientId id : async_with_mail_) {
    const auto it = clients_.find(id);
    if (it == clients_.end()) continue;
    Client& client = it->second;
    client.queued_for_flush = false;
    if (client.pending.empty()) continue;
    send_packet(id, std::move(client.pending));
    client.pending.clear();
    client.pending_bytes = 0;
  }
  async_with_mail_.clear();
}

void Database::send_packet(ClientId to, std::vector<Message> messages) {
  output_.push_back(OutPacket{to, std::move(messages)});
}

Message Database::null_reply(double now) const {
  // Spec 2.6 "NULL S->C": dval carries the server's local warped time, time is -1.
  Message m;
  m.id = moos::kUnsetId;
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

std::vector<DropRequest> Database::take_drop_requests() {
  std::vector<DropRequest> out;
  out.swap(drops_);
  return out;
}

// ---------------------------------------------------------------------------------------
// Diagnostics

void Database::refuse(ClientId id, const std::string& what) {
  Client& client = clients_.at(id);
  ++client.refusals;
  if (client.refusals <= kLoggedRefusalsPerClient) {
    log_(describe(id) + ": " + what);
  } else if (client.refusals == kLoggedRefusalsPerClient + 1) {
    log_(describe(id) + ": more refused messages; further ones are counted, not logged");
  }
}

std::string Database::describe(ClientId id) const {
  const auto it = clients_.find(id);
  return it == clients_.end() ? "client #" + std::to_string(id)
                              : "client \"" + it->second.name + "\"";
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

}  // namespace moosdb_lite
