// The shared part of every Comms implementation: the book of subscriptions that is replayed after
// each reconnect, the published-names set, and message construction exactly as libMOOS fills the
// fields (docs/protocol.md 2.6). Contract in include/moos/comms.hpp.

#include "moos/comms.hpp"

#include <algorithm>

#include "base/same_text.hpp"
#include "base/text.hpp"
#include "moos/codec.hpp"
#include "moos/inbox.hpp"
#include "moos/wildcard.hpp"

namespace moos {

namespace {
/// UNREGISTER carries 0 in dval (protocol.md 2.6).
constexpr double kUnregisterDval = 0.0;

bool valid_pattern(const std::string& pattern) {
  return !pattern.empty() && pattern.find(',') == std::string::npos;
}

/// The book entry of a subscription: plain ones by variable name (their app pattern is empty),
/// wildcards by pattern pair.
template <typename Book>
auto find_subscription(Book& book, bool wildcard, const WildcardSpec& key) {
  return std::find_if(book.begin(), book.end(), [&](const auto& s) {
    return s.wildcard == wildcard && s.entry.same_patterns(key);
  });
}
}  // namespace

Comms::~Comms() = default;

Message Comms::control_message(char type, char data_type, const std::string& key) const {
  Message m;
  m.type = type;
  m.data_type = data_type;
  m.key = key;
  m.source = name_;
  m.time = moos_time();
  return m;
}

Message Comms::register_message(const std::string& var, double interval_s) const {
  Message m = control_message(msg_type::kRegister, data_type::kDouble, var);
  m.dval = interval_s;
  return m;
}

Message Comms::wildcard_message(char type, const WildcardSpec& spec) const {
  // The key of a wildcard message is the client's own name (ignored by the DB, protocol.md 2.6).
  Message m = control_message(type, data_type::kString, name_);
  m.sval = format_wildcard_spec(spec);
  return m;
}

bool Comms::register_variable(const std::string& var, double interval_s) {
  if (var.empty() || !(interval_s >= 0)) return false;
  {
    std::lock_guard<std::mutex> lock(book_mutex_);
    const WildcardSpec entry{{}, var, interval_s};
    auto it = find_subscription(subscriptions_, false, entry);
    if (it == subscriptions_.end())
      subscriptions_.push_back(Subscription{false, entry});
    else
      it->entry.interval_s = interval_s;  // registering again updates the interval
  }
  transmit(register_message(var, interval_s));
  return true;
}

bool Comms::unregister_variable(const std::string& var) {
  {
    std::lock_guard<std::mutex> lock(book_mutex_);
    auto it = find_subscription(subscriptions_, false, WildcardSpec{{}, var, 0.0});
    if (it == subscriptions_.end()) return false;  // never registered: nothing to send (4.1)
    subscriptions_.erase(it);
  }
  Message m = control_message(msg_type::kUnregister, data_type::kDouble, var);
  m.dval = kUnregisterDval;
  transmit(std::move(m));
  return true;
}

bool Comms::register_wildcard(const std::string& var_pattern, const std::string& app_pattern,
                              double interval_s) {
  if (!valid_pattern(var_pattern) || !valid_pattern(app_pattern) || !(interval_s >= 0)) return false;
  const WildcardSpec spec{app_pattern, var_pattern, interval_s};
  {
    std::lock_guard<std::mutex> lock(book_mutex_);
    auto it = find_subscription(subscriptions_, true, spec);
    if (it == subscriptions_.end())
      subscriptions_.push_back(Subscription{true, spec});
    else
      it->entry.interval_s = interval_s;
  }
  transmit(wildcard_message(msg_type::kWildcardRegister, spec));
  return true;
}

bool Comms::unregister_wildcard(const std::string& var_pattern, const std::string& app_pattern) {
  if (!valid_pattern(var_pattern) || !valid_pattern(app_pattern)) return false;
  const WildcardSpec spec{app_pattern, var_pattern, 0.0};
  bool known = false;
  {
    std::lock_guard<std::mutex> lock(book_mutex_);
    auto it = find_subscription(subscriptions_, true, spec);
    if (it != subscriptions_.end()) {
      subscriptions_.erase(it);
      known = true;
    }
  }
  const bool sent = transmit(wildcard_message(msg_type::kWildcardUnregister, spec));
  return sent || known;
}

std::string OutboxBound::refusal(std::size_t size) const {
  if (messages + 1 > max_messages)
    return "the outbox holds its " + std::to_string(max_messages) + " messages";
  if (bytes + size > max_bytes)
    return "the outbox would hold more than its " + std::to_string(max_bytes) + " bytes";
  return {};
}

void Comms::count_posting_dropped(std::string why) {
  ++postings_dropped_;
  std::lock_guard<std::mutex> lock(book_mutex_);
  last_post_error_ = std::move(why);
}

std::string Comms::last_post_error() const {
  std::lock_guard<std::mutex> lock(book_mutex_);
  return last_post_error_;
}

bool Comms::post_and_record(Message&& msg) {
  if (msg.key.empty()) return false;
  if (const std::size_t size = msg.encoded_size(); size > kMaxMessageBytes) {
    count_posting_dropped("NOTIFY " + base::excerpt(msg.key) + " refused: its " +
                          std::to_string(size) + " bytes exceed the " +
                          std::to_string(kMaxMessageBytes) + " a MOOS client accepts");
    return false;
  }
  // An app posts the same few names every cycle: the name is copied only the first time, and
  // looked up under the lock only when it was not among the latest.
  if (published_recently(msg.key)) return transmit(std::move(msg));
  std::string new_key;
  {
    std::lock_guard<std::mutex> lock(book_mutex_);
    const auto known = published_.find(msg.key);
    if (known == published_.end()) {
      new_key = msg.key;
    } else {
      remember_published(*known);
    }
  }
  if (!transmit(std::move(msg))) return false;
  if (new_key.empty()) return true;
  std::lock_guard<std::mutex> lock(book_mutex_);
  remember_published(*published_.insert(std::move(new_key)).first);
  return true;
}

bool Comms::published_recently(const std::string& key) const {
  for (const auto& recent : recent_published_) {
    const std::string* name = recent.load(std::memory_order_acquire);
    if (name && base::same_text(*name, key)) return true;
  }
  return false;
}

void Comms::remember_published(const std::string& name) {
  recent_published_[recent_published_next_].store(&name, std::memory_order_release);
  recent_published_next_ = (recent_published_next_ + 1) % kRecentPublished;
}

bool Comms::notify(const std::string& var, double value, std::optional<double> time_s,
                   const std::string& source_aux) {
  return post_notify(data_type::kDouble, var, value, nullptr, time_s, source_aux);
}

bool Comms::notify(const std::string& var, std::string value, std::optional<double> time_s,
                   const std::string& source_aux) {
  return post_notify(data_type::kString, var, kUnsetDouble, &value, time_s, source_aux);
}

bool Comms::notify_binary(const std::string& var, const std::string& bytes,
                          std::optional<double> time_s, const std::string& source_aux) {
  std::string value = bytes;
  return post_notify(data_type::kBinary, var, kUnsetDouble, &value, time_s, source_aux);
}

bool Comms::post_notify(char data_type, const std::string& var, double dval, std::string* sval,
                        std::optional<double> time_s, const std::string& source_aux) {
  const double time = time_s ? *time_s : moos_time();
  if (outgoing_in_use_.exchange(true, std::memory_order_acquire))
    return post_notify_apart(data_type, var, dval, sval, time, source_aux);
  fill_notify(outgoing_, data_type, var, dval, sval, time, source_aux);
  const bool posted = post_and_record(std::move(outgoing_));
  // Whatever storage the transport left in it stays for the next posting, within a bound.
  if (Inbox::storage_bytes(outgoing_) > Inbox::kMaxKeptBytes) outgoing_ = Message{};
  outgoing_in_use_.store(false, std::memory_order_release);
  return posted;
}

bool Comms::post_notify_apart(char data_type, const std::string& var, double dval,
                              std::string* sval, double time, const std::string& source_aux) {
  // Another posting (another thread, or a callback inside a posting) is using outgoing_.
  Message m;
  fill_notify(m, data_type, var, dval, sval, time, source_aux);
  return post_and_record(std::move(m));
}

void Comms::fill_notify(Message& m, char data_type, const std::string& var, double dval,
                        std::string* sval, double time, const std::string& source_aux) const {
  // As libMOOS fills a NOTIFY (protocol.md 2.2). Every field is written: `m` may hold anything
  // a transport left in it. Names are compared before they are assigned: mostly they are what
  // the last posting had.
  m.id = kUnsetId;
  m.type = msg_type::kNotify;
  m.data_type = data_type;
  if (!base::same_text(m.source, name_)) m.source = name_;
  if (source_aux.empty()) {
    m.source_aux.clear();
  } else {
    m.source_aux = source_aux;
  }
  if (posted_community_.empty()) {
    m.community.clear();
  } else if (!base::same_text(m.community, posted_community_)) {
    m.community = posted_community_;
  }
  if (!base::same_text(m.key, var)) m.key = var;
  m.time = time;
  m.dval = dval;
  m.dval2 = kUnsetDouble;
  if (sval) {
    m.sval = std::move(*sval);  // the caller's text, uncopied; it takes m's old storage away
  } else {
    m.sval.clear();
  }
}

bool Comms::post(Message notify) {
  notify.type = msg_type::kNotify;
  notify.source = name_;
  if (notify.time == kUnsetDouble) notify.time = moos_time();
  return post_and_record(std::move(notify));
}

std::vector<Message> Comms::fetch() {
  std::vector<Message> mail;
  fetch_into(mail);
  return mail;
}

void Comms::set_on_connect(std::function<void()> callback) {
  std::lock_guard<std::mutex> lock(book_mutex_);
  on_connect_ = std::move(callback);
}

void Comms::set_on_mail(std::function<void()> callback) {
  std::lock_guard<std::mutex> lock(book_mutex_);
  has_on_mail_ = static_cast<bool>(callback);
  on_mail_ = std::move(callback);
}

void Comms::fire_on_connect() {
  std::function<void()> callback;
  {
    std::lock_guard<std::mutex> lock(book_mutex_);
    callback = on_connect_;
  }
  if (callback) callback();
}

void Comms::fire_on_mail() {
  if (auto callback = on_mail_callback()) callback();
}

std::function<void()> Comms::on_mail_callback() const {
  std::lock_guard<std::mutex> lock(book_mutex_);
  return on_mail_;
}

std::vector<Message> Comms::replay_messages() const {
  std::vector<Subscription> copy;
  {
    std::lock_guard<std::mutex> lock(book_mutex_);
    copy = subscriptions_;
  }
  std::vector<Message> out;
  out.reserve(copy.size());
  for (const auto& s : copy) {
    if (s.wildcard)
      out.push_back(wildcard_message(msg_type::kWildcardRegister, s.entry));
    else
      out.push_back(register_message(s.entry.var_pattern, s.entry.interval_s));
  }
  return out;
}

std::set<std::string> Comms::registered_names() const {
  std::lock_guard<std::mutex> lock(book_mutex_);
  std::set<std::string> names;
  for (const auto& s : subscriptions_)
    if (!s.wildcard) names.insert(s.entry.var_pattern);
  return names;
}

std::set<std::string> Comms::published_names() const {
  std::lock_guard<std::mutex> lock(book_mutex_);
  return std::set<std::string>(published_.begin(), published_.end());
}

}  // namespace moos
