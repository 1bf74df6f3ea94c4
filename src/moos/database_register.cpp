// MOOSDB rules: REGISTER / UNREGISTER and wildcard filters (docs/protocol.md
// 5.4, 5.5). Contract in include/moos/database.hpp.

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>

#include "base/text.hpp"
#include "moos/database.hpp"

namespace moos {

Database::Subscription& Database::Subscribers::operator[](ClientId id) {
  const auto by_id = [](const Entry& e, ClientId key) { return e.first < key; };
  auto it = std::lower_bound(entries_.begin(), entries_.end(), id, by_id);
  if (it == entries_.end() || it->first != id) it = entries_.insert(it, Entry{id, Subscription{}});
  return it->second;
}

void Database::Subscribers::erase(ClientId id) {
  const auto by_id = [](const Entry& e, ClientId key) { return e.first < key; };
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), id, by_id);
  if (it != entries_.end() && it->first == id) entries_.erase(it);
}

void Database::handle_register(ClientId id, const Message& msg, double now) {
  if (msg.key.empty()) return refuse(id, "REGISTER with an empty variable name refused");
  if (!std::isfinite(msg.dval) || msg.dval < 0.0)
    return refuse(id, "REGISTER " + base::excerpt(msg.key) + " with interval " +
                          std::to_string(msg.dval) + " refused (expected a number >= 0)");
  if (const std::string why = store_refusal(msg, false); !why.empty())
    return refuse(id, "REGISTER " + base::excerpt(msg.key) + " refused: " + why);
  subscribe(id, find_or_create(msg.key), msg.dval, now);
}

void Database::subscribe(ClientId id, VarId var, double interval_s, double now) {
  // Add or replace; replacing forgets the last delivery (protocol.md 5.4).
  Variable& v = vars_[var];
  Client& client = clients_.at(id);
  Subscription& sub = v.subscribers[id];
  sub = Subscription{interval_s, std::nullopt, &client};
  client.subscribed.insert(var);
  if (v.value) {
    // Every REGISTER re-sends the current value and starts the throttle window (protocol.md 5.4).
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

void Database::bind_wildcard_filters(VarId var, const std::string& writer) {
  // protocol.md 5.3 step 2, as the reference DB does it: every matching filter (re)subscribes its
  // client, replacing an explicit REGISTER; the reference walks each client's filters in
  // (app pattern, variable pattern) order, so the greatest matching pair has the last word.
  Variable& v = vars_[var];
  for (auto& [id, client] : clients_) {
    const WildcardSpec* last_word = nullptr;
    for (const auto& filter : client.filters) {
      if (!filter.matches(writer, v.name)) continue;
      if (last_word == nullptr ||
          std::tie(filter.app_pattern, filter.var_pattern) >
              std::tie(last_word->app_pattern, last_word->var_pattern))
        last_word = &filter;
    }
    if (last_word == nullptr) continue;
    v.subscribers[id] = Subscription{last_word->interval_s, std::nullopt, &client};
    client.subscribed.insert(var);
  }
}

bool Database::matches(const WildcardSpec& spec, const Variable& var) {
  // An existing variable matches by its last writer (empty if never written), protocol.md 5.5.
  return spec.matches(var.value ? var.value->writer : std::string(), var.name);
}

void Database::handle_wildcard_register(ClientId id, const Message& msg, double now) {
  std::string problem;
  const WildcardSpec spec = parse_wildcard_spec(msg.sval, &problem);
  if (!problem.empty())
    return refuse(id, "WILDCARD_REGISTER \"" + base::excerpt(msg.sval) + "\" refused: " + problem);
  auto& filters = clients_.at(id).filters;
  const bool known = std::any_of(filters.begin(), filters.end(),
                                 [&](const WildcardSpec& f) { return f.same_patterns(spec); });
  if (!known) filters.push_back(spec);  // set semantics on the pair: the first interval stays
  for (VarId var = 0; var < vars_.size(); ++var) {
    if (matches(spec, vars_[var])) subscribe(id, var, spec.interval_s, now);
  }
}

void Database::handle_wildcard_unregister(ClientId id, const Message& msg) {
  std::string problem;
  const WildcardSpec spec = parse_wildcard_spec(msg.sval, &problem);
  if (!problem.empty())
    return refuse(id, "WILDCARD_UNREGISTER \"" + base::excerpt(msg.sval) +
                          "\" refused: " + problem);
  Client& client = clients_.at(id);
  auto& filters = client.filters;
  // Also the identical filter (documented deviation, protocol.md 5.5 allows it).
  const auto same = std::find_if(filters.begin(), filters.end(),
                                 [&](const WildcardSpec& f) { return f.same_patterns(spec); });
  if (same != filters.end()) filters.erase(same);
  for (VarId var = 0; var < vars_.size(); ++var) {
    if (matches(spec, vars_[var])) {
      vars_[var].subscribers.erase(id);
      client.subscribed.erase(var);
    }
  }
}

}  // namespace moos
