// MOOSDB rule: server requests (docs/protocol.md 5.8): `ALL` by equality,
// the others by substring. Contract in include/moos/database.hpp.

#include <utility>

#include "base/text.hpp"
#include "moos/database.hpp"

namespace moos {

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
    refuse(id, "unknown server request \"" + base::excerpt(msg.key) + "\" ignored");
  }
}

void Database::answer_all(ClientId id, std::int32_t request_id) {
  for (const Variable& var : vars_) {
    // The snapshot fields, with the request id, the write frequency in dval2 and the time
    // of the last write relative to the DB start (-1 if never written or negative),
    // protocol.md 5.8.
    Message m = snapshot(var);
    m.id = request_id;
    m.dval2 = var.frequency.hz;
    m.time = kUnsetDouble;
    if (var.value) {
      const double since_start_s = var.value->db_write_moos_s - start_moos_s_;
      if (since_start_s >= 0.0) m.time = since_start_s;
    }
    queue_mail(id, std::move(m));
  }
}

void Database::answer_var_summary(ClientId id, std::int32_t request_id, double now) {
  std::string names;
  for (const Variable& var : vars_) {
    if (!names.empty()) names += ',';
    names += var.name;
  }
  Message m = make_string_notify("VAR_SUMMARY", std::move(names), db_name_, now);
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
    Message m = make_string_notify("PROC_SUMMARY", std::move(text), db_name_,
                                   now - start_moos_s_);
    m.id = request_id;
    m.community = config_.community;
    queue_mail(requester, std::move(m));
  }
}

void Database::clear_db() {
  // Values, types, writers and counters go; names and subscriptions stay (protocol.md 5.8).
  for (Variable& var : vars_) {
    Variable cleared;
    cleared.name = std::move(var.name);
    cleared.subscribers = std::move(var.subscribers);
    if (var.value) stored_bytes_ -= value_bytes(*var.value);
    var = std::move(cleared);
  }
  for (auto& [id, client] : clients_) {
    client.pending.clear();
    client.pending_bytes = 0;
    client.published.clear();
    client.posted_cache.clear();  // its entries promise membership of `published`
    client.posted_cache_next = 0;
  }
}

}  // namespace moos
