// MOOSDB rule: NOTIFY and the store (docs/protocol.md 5.3; the fan-out is in database_mail.cpp).
// Contract in include/moos/database.hpp. Clients' NOTIFYs and the DB's own variables take
// the same path, so subscribers cannot tell them apart.

#include <string>
#include <utility>

#include "base/same_text.hpp"
#include "base/text.hpp"
#include "moos/database.hpp"

namespace moos {

namespace {

namespace mt = msg_type;
namespace dt = data_type;

/// Write-frequency estimate of a variable (dval2 of the `ALL` answer, protocol.md 5.8): writes
/// counted over windows of at least this many MOOS seconds.
constexpr double kFrequencyWindow_moos_s = 1.0;
/// Spare capacity a stored string may keep beyond twice its size (overwrite()).
constexpr std::size_t kSlackBytes = 64;

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

/// `to` = `from`, in `to`'s storage unless that is far larger than needed: the store's bound
/// (max_stored_bytes) counts the values' sizes, so a large write followed by small ones must not
/// keep its memory.
void overwrite(std::string& to, const std::string& from) {
  if (to.capacity() > 2 * from.size() + kSlackBytes) {
    // Not `to = std::string(from)`: a short string moved in is copied into to's long buffer,
    // which stays. The swap hands that buffer to the temporary, which frees it.
    std::string(from).swap(to);
  } else {
    to.assign(from);
  }
}

/// overwrite() unless `to` holds `from` already (a writer's name, a community: mostly what the
/// last write stored); comparing costs less than assigning.
void overwrite_if_changed(std::string& to, const std::string& from) {
  if (!base::same_text(to, from)) overwrite(to, from);
}

}  // namespace

void Database::handle_notify(Client& client, Message&& msg, double now) {
  // The refusals' texts are built out of line: the usual NOTIFY runs through compact code.
  if (msg.key.empty() || !is_value_type(msg.data_type))
    return refuse_notify_form(client.id, msg);
  if (msg.source.empty()) msg.source = client.name;
  if (msg.community.empty()) msg.community = config_.community;
  if (const std::size_t size = msg.encoded_size();
      size > kMaxMessageBytes || !fits_at_most(msg, true)) {
    if (refused_for_size(client.id, msg, size)) return;
  }
  const char type = msg.data_type;
  // A name the client posted before needs no hashing, nor another look at `published`.
  const PostedVariable* posted = find_posted(client, msg.key);
  const VarId var = posted ? posted->var : find_or_create(msg.key);
  publish(var, std::move(msg), now);
  if (vars_[var].data_type != type)
    return refuse_type_change(client.id, var, type);
  if (!posted) note_posted(client, var);
}

void Database::refuse_notify_form(ClientId id, const Message& msg) {
  if (msg.key.empty()) return refuse(id, "NOTIFY with an empty variable name refused");
  refuse(id, "NOTIFY " + base::excerpt(msg.key) + " with data type '" + msg.data_type +
                 "' refused (expected D, S or B)");
}

bool Database::refused_for_size(ClientId id, const Message& msg, std::size_t size) {
  if (size > kMaxMessageBytes) {
    refuse(id, "NOTIFY " + base::excerpt(msg.key) + " refused: its " + std::to_string(size) +
                   " bytes exceed the " + std::to_string(kMaxMessageBytes) +
                   " a client accepts in a message");
    return true;
  }
  const std::string why = store_refusal_near_bound(msg, true);
  if (why.empty()) return false;
  refuse(id, "NOTIFY " + base::excerpt(msg.key) + " refused: " + why);
  return true;
}

void Database::refuse_type_change(ClientId id, VarId var, char type) {
  refuse(id, "NOTIFY " + base::excerpt(vars_[var].name) + " as " + type_name(type) +
                 " refused: the variable is " + type_name(vars_[var].data_type) +
                 " (fixed by its first write)");
}

void Database::note_posted(Client& client, VarId var) {
  client.published.insert(var);
  remember_posted(client, var);
}

const Database::PostedVariable* Database::find_posted(const Client& client,
                                                      const std::string& name) {
  for (const PostedVariable& entry : client.posted_cache)
    if (base::same_text(entry.name, name)) return &entry;
  return nullptr;
}

void Database::remember_posted(Client& client, VarId var) const {
  const std::string& name = vars_[var].name;
  if (name.size() > kPostedCacheNameBytes) return;  // rare; bounds the cache's memory
  if (client.posted_cache.size() < kPostedCacheEntries) {
    client.posted_cache.push_back(PostedVariable{name, var});
    return;
  }
  // Full: the entries are replaced in turn (an app that posts more names than fit pays a hash
  // look-up for some, as without the cache).
  client.posted_cache[client.posted_cache_next] = PostedVariable{name, var};
  client.posted_cache_next = (client.posted_cache_next + 1) % kPostedCacheEntries;
}

void Database::publish_db_variable(Message msg, double now) {
  msg.community = config_.community;
  const char type = msg.data_type;
  const VarId var = find_or_create(msg.key);
  publish(var, std::move(msg), now);
  if (vars_[var].data_type != type)
    log_("DB variable " + vars_[var].name + " not written: a client wrote it first as " +
         type_name(vars_[var].data_type));
}

void Database::publish(VarId id, Message&& msg, double now) {
  if (vars_[id].write_count == 0) {
    // Step 2: the first write fixes the type and binds the wildcard filters.
    vars_[id].data_type = msg.data_type;
    bind_wildcard_filters(id, msg.source);
  }
  Variable& var = vars_[id];
  if (msg.data_type != var.data_type) return;  // step 3: the caller reports the refusal

  msg.type = mt::kNotify;
  if (msg.community.empty()) msg.community = config_.community;
  store(var, msg, now);
  if (notify_observer_) notify_observer_(msg);
  fan_out(var, std::move(msg), now);
}

void Database::store(Variable& var, const Message& msg, double now) {
  // Step 4: the value, its stamps and the write-frequency estimate.
  // Written over the last value: a variable written again and again (a node report) keeps its
  // strings' storage instead of allocating them anew for every write.
  if (var.value) {
    stored_bytes_ -= value_bytes(*var.value);
  } else {
    var.value = Value{};  // assigned: clang cannot emplace() a nested class with initializers here
  }
  Value& value = *var.value;
  if (msg.data_type == dt::kDouble) {
    value.dval = msg.dval;
    value.sval.clear();
  } else {
    value.dval = kUnsetDouble;
    overwrite(value.sval, msg.sval);
  }
  value.time_moos_s = msg.time;
  value.db_write_moos_s = now;
  overwrite_if_changed(value.writer, msg.source);
  overwrite_if_changed(value.writer_aux, msg.source_aux);
  overwrite_if_changed(value.community, msg.community);
  stored_bytes_ += value_bytes(value);

  WriteFrequency& f = var.frequency;
  if (var.write_count == 0) f.window_start_moos_s = now;
  ++var.write_count;
  const double window_s = now - f.window_start_moos_s;
  if (window_s >= kFrequencyWindow_moos_s) {
    f.hz = static_cast<double>(var.write_count - f.window_start_count) / window_s;
    f.window_start_moos_s = now;
    f.window_start_count = var.write_count;
  }
}

Database::VarId Database::find_or_create(const std::string& name) {
  const auto it = var_index_.find(name);
  if (it != var_index_.end()) return it->second;
  const VarId id = vars_.size();
  Variable var;
  var.name = name;
  stored_bytes_ += kVariableOverheadBytes + name.size();
  vars_.push_back(std::move(var));
  var_index_.emplace(name, id);
  return id;
}

std::size_t Database::value_bytes(const Value& value) {
  return value.sval.size() + value.writer.size() + value.writer_aux.size() +
         value.community.size();
}

std::string Database::store_refusal(const Message& msg, bool with_value) const {
  if (fits_at_most(msg, with_value)) return {};
  return store_refusal_near_bound(msg, with_value);
}

bool Database::fits_at_most(const Message& msg, bool with_value) const {
  return stored_bytes_ + most_stored_bytes(msg, with_value) <= config_.max_stored_bytes;
}

std::size_t Database::most_stored_bytes(const Message& msg, bool with_value) {
  return kVariableOverheadBytes + msg.key.size() +
         (with_value ? msg.sval.size() + msg.source.size() + msg.source_aux.size() +
                           msg.community.size()
                     : 0);
}

std::string Database::store_refusal_near_bound(const Message& msg, bool with_value) const {
  // What the variable holds now, and would hold after the write.
  const std::size_t name_bytes = kVariableOverheadBytes + msg.key.size();
  const std::size_t most_after = most_stored_bytes(msg, with_value);
  const auto it = var_index_.find(msg.key);
  const Variable* var = it == var_index_.end() ? nullptr : &vars_[it->second];
  const std::size_t before = var ? name_bytes + (var->value ? value_bytes(*var->value) : 0) : 0;
  const std::size_t after = with_value ? most_after : var ? before : name_bytes;
  if (after <= before || stored_bytes_ - before + after <= config_.max_stored_bytes) return {};
  return "the store would hold more than its " + std::to_string(config_.max_stored_bytes) +
         " bytes (" + std::to_string(stored_bytes_) + " held)";
}

}  // namespace moos
