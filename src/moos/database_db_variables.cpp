// MOOSDB rule: the DB's own variables (docs/protocol.md 5.7). Contract in
// include/moos/database.hpp. They take the clients' NOTIFY path (database_notify.cpp).

#include "moos/database.hpp"

namespace moos {

void Database::refresh_db_variables(double now_moos_s) {
  publish_db_double("DB_TIME", now_moos_s, now_moos_s);
  publish_db_double("DB_UPTIME", now_moos_s - start_moos_s_, now_moos_s);
  publish_db_string("DB_CLIENTS", client_list(), now_moos_s);
  publish_db_string("DB_RWSUMMARY", rw_summary(), now_moos_s);
  flush_async_mail();
}

void Database::publish_db_string(const std::string& key, const std::string& value, double now) {
  if (!config_.db_variables) return;
  publish_db_variable(make_string_notify(key, value, db_name_, now), now);
}

void Database::publish_db_double(const std::string& key, double value, double now) {
  if (!config_.db_variables) return;
  publish_db_variable(make_double_notify(key, value, db_name_, now), now);
}

std::string Database::client_list() const {
  std::string names;
  for (const auto& [id, client] : clients_) names += client.name + ",";
  return names;
}

std::string Database::rw_summary() const {
  // `client=sub1:sub2&pub1:pub2` entries separated by `,` (protocol.md 5.7).
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

}  // namespace moos
