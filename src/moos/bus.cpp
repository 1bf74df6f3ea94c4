// In-process MOOS community. The core processes each client message as the MOOSDB does (wire spec
// 5.2 step 3, 5.3-5.5); contract in include/moos/bus.hpp.
//
// Data structures: variables by name (std::map, so iteration order and therefore wildcard
// matching order are deterministic); per variable, its subscribers by client name with the
// interval and the MOOS time of the last delivery ("never" as nullopt); per client, its inbox,
// wildcard filters and connection count. One mutex guards everything; callbacks run after it is
// released.

#include "moos/bus.hpp"

#include <algorithm>
#include <map>
#include <mutex>

#include "moos/wildcard.hpp"

namespace moos {

struct BusCore {
  struct Subscription {
    double interval_s = 0.0;
    std::optional<double> last_delivery_moos_s;  // nullopt: never delivered
  };
  struct Variable {
    char data_type = data_type::kNotSet;
    std::uint64_t writes = 0;
    Message last;  // the last accepted write, community filled in
    std::map<std::string, Subscription> subscribers;
  };
  struct ClientState {
    BusClient* handle = nullptr;  // for on-mail callbacks; cleared when the client goes away
    bool connected = true;
    std::uint64_t connections = 1;
    std::vector<Message> inbox;
    std::vector<WildcardSpec> filters;
  };

  BusCore(Clock& c, InProcessBus::Options o) : clock(c), options(std::move(o)) {}

  double now() const { return clock.unix_now_s() * options.time_warp; }

  Clock& clock;
  const InProcessBus::Options options;
  mutable std::mutex mutex;
  std::map<std::string, Variable> variables;
  std::map<std::string, ClientState> clients;
  std::vector<Message> postings;
  std::vector<std::string> diagnostics;

  // ---- message processing (mutex held); returns the clients that received mail ----------------
  void deliver(const std::string& client, Message copy, std::vector<std::string>& woken) {
    auto it = clients.find(client);
    if (it == clients.end() || !it->second.connected) return;
    copy.type = msg_type::kNotify;
    it->second.inbox.push_back(std::move(copy));
    if (std::find(woken.begin(), woken.end(), client) == woken.end()) woken.push_back(client);
  }

  static Message snapshot_of(const Variable& v) {
    Message m = v.last;
    m.id = kUnsetId;  // snapshots carry id -1 (spec 2.6)
    m.type = msg_type::kNotify;
    return m;
  }

  void subscribe(const std::string& client, const std::string& var, double interval_s,
                 std::vector<std::string>& woken) {
    Variable& v = variables[var];  // created unwritten ('~') if absent (spec 5.4)
    Subscription& sub = v.subscribers[client];
    sub = Subscription{interval_s, std::nullopt};
    if (v.writes > 0) {
      deliver(client, snapshot_of(v), woken);
      sub.last_delivery_moos_s = now();
    }
  }

  void on_notify(Message msg, std::vector<std::string>& woken) {
    Variable& v = variables[msg.key];
    if (v.writes == 0) {
      v.data_type = msg.data_type;
      // New variables are matched against stored filters at their first write (spec 5.3 step 2).
      for (auto& [client, state] : clients)
        for (const auto& f : state.filters)
          if (f.matches(msg.source, msg.key))
            v.subscribers[client] = Subscription{f.interval_s, std::nullopt};
    }
    if (msg.data_type != v.data_type) {
      diagnostics.push_back("dropped " + msg.key + " from " + msg.source + ": data type '" +
                            std::string(1, msg.data_type) + "' but the variable is '" +
                            std::string(1, v.data_type) + "'");
      return;
    }
    if (msg.community.empty()) msg.community = options.community;
    msg.type = msg_type::kNotify;
    v.last = msg;
    ++v.writes;
    postings.push_back(msg);
    const double t = now();
    for (auto& [client, sub] : v.subscribers) {
      const bool due = sub.interval_s <= 0 || !sub.last_delivery_moos_s ||
                       t - *sub.last_delivery_moos_s >= sub.interval_s;
      if (!due) continue;  // throttled: dropped, not delayed (spec 5.3 step 5)
      deliver(client, msg, woken);
      sub.last_delivery_moos_s = t;
    }
  }

  // An existing variable matches by its last writer ("" while unwritten), spec 5.5.
  static bool matches(const WildcardSpec& spec, const std::string& name, const Variable& v) {
    return spec.matches(v.writes > 0 ? std::string_view(v.last.source) : std::string_view(), name);
  }

  void on_wildcard_register(const std::string& client, const WildcardSpec& spec,
                            std::vector<std::string>& woken) {
    auto& filters = clients[client].filters;
    const bool known = std::any_of(filters.begin(), filters.end(),
                                   [&](const WildcardSpec& f) { return f.same_patterns(spec); });
    // Set semantics on the pattern pair: the first filter's interval stays (spec 5.5).
    if (!known) filters.push_back(spec);
    std::vector<std::string> matching;
    for (const auto& [name, v] : variables)
      if (matches(spec, name, v)) matching.push_back(name);
    for (const auto& name : matching) subscribe(client, name, spec.interval_s, woken);
  }

  void on_wildcard_unregister(const std::string& client, const WildcardSpec& spec) {
    for (auto& [name, v] : variables)
      if (matches(spec, name, v)) v.subscribers.erase(client);
    auto& filters = clients[client].filters;
    filters.erase(std::remove_if(filters.begin(), filters.end(),
                                 [&](const WildcardSpec& f) { return f.same_patterns(spec); }),
                  filters.end());
  }

  void process(const std::string& client, Message msg, std::vector<std::string>& woken) {
    switch (msg.type) {
      case msg_type::kNotify:
        msg.source = client;
        on_notify(std::move(msg), woken);
        break;
      case msg_type::kRegister:
        subscribe(client, msg.key, msg.dval > 0 ? msg.dval : 0.0, woken);
        break;
      case msg_type::kUnregister:
        if (auto it = variables.find(msg.key); it != variables.end()) it->second.subscribers.erase(client);
        break;
      case msg_type::kWildcardRegister:
        on_wildcard_register(client, parse_wildcard_spec(msg.sval), woken);
        break;
      case msg_type::kWildcardUnregister:
        on_wildcard_unregister(client, parse_wildcard_spec(msg.sval));
        break;
      default:
        break;  // NULL, COMMAND and others are ignored, as by the DB (spec 5.2 step 3)
    }
  }

  void forget_client(const std::string& client) {
    for (auto& [name, v] : variables) v.subscribers.erase(client);
    auto it = clients.find(client);
    if (it == clients.end()) return;
    it->second.filters.clear();
    it->second.inbox.clear();
  }
};

// ---- InProcessBus ---------------------------------------------------------------------------

InProcessBus::InProcessBus(Clock& clock) : InProcessBus(clock, Options{}) {}

InProcessBus::InProcessBus(Clock& clock, Options options)
    : core_(std::make_shared<BusCore>(clock, std::move(options))) {}

InProcessBus::~InProcessBus() = default;

std::unique_ptr<BusClient> InProcessBus::connect(const std::string& name) {
  if (name.empty()) return nullptr;
  {
    std::lock_guard<std::mutex> lock(core_->mutex);
    auto it = core_->clients.find(name);
    if (it != core_->clients.end()) return nullptr;
    core_->clients[name] = BusCore::ClientState{};
  }
  std::unique_ptr<BusClient> client(new BusClient(core_, name));
  std::lock_guard<std::mutex> lock(core_->mutex);
  core_->clients[name].handle = client.get();
  return client;
}

Clock& InProcessBus::clock() const { return core_->clock; }
double InProcessBus::time_warp() const { return core_->options.time_warp; }
double InProcessBus::moos_time() const { return core_->now(); }
const std::string& InProcessBus::community() const { return core_->options.community; }

std::vector<Message> InProcessBus::postings() const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  return core_->postings;
}

std::vector<Message> InProcessBus::postings_of(const std::string& var) const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  std::vector<Message> out;
  for (const auto& m : core_->postings)
    if (m.key == var) out.push_back(m);
  return out;
}

void InProcessBus::clear_postings() {
  std::lock_guard<std::mutex> lock(core_->mutex);
  core_->postings.clear();
}

std::optional<Message> InProcessBus::latest(const std::string& var) const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  auto it = core_->variables.find(var);
  if (it == core_->variables.end() || it->second.writes == 0) return std::nullopt;
  return BusCore::snapshot_of(it->second);
}

std::vector<std::string> InProcessBus::client_names() const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  std::vector<std::string> names;
  for (const auto& [name, state] : core_->clients)
    if (state.connected) names.push_back(name);
  return names;
}

std::vector<std::string> InProcessBus::diagnostics() const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  return core_->diagnostics;
}

// ---- BusClient ------------------------------------------------------------------------------

BusClient::BusClient(std::shared_ptr<BusCore> core, std::string name)
    : Comms(std::move(name)), core_(std::move(core)) {}

BusClient::~BusClient() {
  std::lock_guard<std::mutex> lock(core_->mutex);
  core_->forget_client(name());
  core_->clients.erase(name());
}

bool BusClient::is_connected() const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  auto it = core_->clients.find(name());
  return it != core_->clients.end() && it->second.connected;
}

std::uint64_t BusClient::connection_count() const {
  std::lock_guard<std::mutex> lock(core_->mutex);
  auto it = core_->clients.find(name());
  return it == core_->clients.end() ? 0 : it->second.connections;
}

std::string BusClient::community() const { return core_->options.community; }
Clock& BusClient::clock() const { return core_->clock; }
double BusClient::time_warp() const { return core_->options.time_warp; }

std::vector<Message> BusClient::fetch() {
  std::lock_guard<std::mutex> lock(core_->mutex);
  auto it = core_->clients.find(name());
  if (it == core_->clients.end()) return {};
  std::vector<Message> mail;
  mail.swap(it->second.inbox);
  return mail;
}

bool BusClient::transmit(Message msg) {
  std::vector<std::string> woken;
  std::vector<std::function<void()>> callbacks;
  {
    std::lock_guard<std::mutex> lock(core_->mutex);
    auto it = core_->clients.find(name());
    if (it == core_->clients.end() || !it->second.connected) return false;
    core_->process(name(), std::move(msg), woken);
    // Copied under the bus lock (lock order: bus, then a client's book), called after it.
    for (const auto& client : woken) {
      auto w = core_->clients.find(client);
      if (w == core_->clients.end() || !w->second.handle) continue;
      if (auto cb = w->second.handle->on_mail_callback()) callbacks.push_back(std::move(cb));
    }
  }
  for (auto& cb : callbacks) cb();
  return true;
}

void BusClient::simulate_disconnect() {
  std::lock_guard<std::mutex> lock(core_->mutex);
  auto it = core_->clients.find(name());
  if (it == core_->clients.end() || !it->second.connected) return;
  core_->forget_client(name());
  it->second.connected = false;
}

bool BusClient::simulate_reconnect() {
  {
    std::lock_guard<std::mutex> lock(core_->mutex);
    auto it = core_->clients.find(name());
    if (it == core_->clients.end()) return false;
    if (it->second.connected) return true;
    it->second.connected = true;
    ++it->second.connections;
  }
  for (auto& m : replay_messages()) transmit(std::move(m));
  fire_on_connect();
  return true;
}

}  // namespace moos
