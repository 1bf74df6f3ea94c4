// In-process MOOS community: an adapter between Comms clients and moos::Database; contract in
// include/moos/bus.hpp.
//
// Data structures: the Database (every rule of protocol.md 5); per client name, its current
// Database connection id (a reconnect is a new connection, as over TCP), its inbox and connection
// count; the connection ids back to names, to route the Database's output. One mutex guards
// everything; on-mail callbacks run after it is released.

#include "moos/bus.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <mutex>

#include "base/text.hpp"

namespace moos {

struct BusCore {
  struct ClientState {
    BusClient* handle = nullptr;  // for on-mail callbacks; cleared when the client goes away
    ClientId id = 0;              // the current Database connection
    bool connected = true;
    std::uint64_t connections = 1;
    std::vector<Message> inbox;
    std::vector<Message> outbox;  // postings made while disconnected (comms.hpp)
    OutboxBound outbox_bound;
  };

  BusCore(Clock& c, InProcessBus::Options o)
      : clock(c),
        options(std::move(o)),
        db(database_config(options), now(), [this](const std::string& line) { diagnostics.push_back(line); },
           [this](const Message& m) { postings.push_back(m); }) {}

  static DatabaseConfig database_config(const InProcessBus::Options& o) {
    DatabaseConfig config;
    config.community = o.community;
    config.db_variables = false;  // no refresh timer on the bus (see bus.hpp)
    return config;
  }

  double now() const { return clock.unix_now_s() * options.time_warp; }

  Clock& clock;
  const InProcessBus::Options options;
  mutable std::mutex mutex;
  std::vector<Message> postings;
  std::vector<std::string> diagnostics;
  Database db;  // after the two lists its callbacks fill
  std::map<std::string, ClientState> clients;
  std::map<ClientId, std::string> names_by_id;
  ClientId next_id = 1;

  // ---- mutex held ------------------------------------------------------------------------------

  /// A new Database connection for `name`; false if the Database refused it (POISON).
  bool open_connection(const std::string& name, ClientState& state) {
    Message ident;
    ident.type = msg_type::kData;
    ident.data_type = data_type::kString;
    ident.key = kAsynchronousKey;
    ident.sval = name;
    ident.time = now();
    const ClientId id = next_id++;
    const bool welcomed = db.connect(id, {ident}, now());
    if (welcomed) {
      state.id = id;
      names_by_id[id] = name;
    }
    return welcomed;
  }

  void close_connection(ClientState& state) {
    names_by_id.erase(state.id);
    db.disconnect(state.id, now());
    state.connected = false;
    state.inbox.clear();
  }

  /// Hands `messages` to the Database as `state`'s packet and routes the output; the on-mail
  /// callbacks of the clients that got mail are appended to `callbacks` (called after the lock).
  void deliver(ClientState& state, std::vector<Message> messages,
               std::vector<std::function<void()>>& callbacks) {
    std::vector<std::string> woken;
    db.process_packet(state.id, std::move(messages), now());
    route_output(woken);
    // Copied under the bus lock (lock order: bus, then a client's book), called after it.
    for (const auto& client : woken) {
      auto w = clients.find(client);
      if (w == clients.end() || !w->second.handle) continue;
      if (auto cb = w->second.handle->on_mail_callback()) callbacks.push_back(std::move(cb));
    }
  }

  /// Moves the Database's output into the inboxes (only NOTIFYs are mail; WELCOME is protocol)
  /// and lists the clients that got mail, for their on-mail callbacks.
  void route_output(std::vector<std::string>& woken) {
    for (auto& packet : db.take_output()) {
      const auto name = names_by_id.find(packet.to);
      if (name == names_by_id.end()) continue;  // a refused connection's POISON
      ClientState& state = clients.at(name->second);
      bool mail = false;
      for (auto& m : packet.messages) {
        if (m.type != msg_type::kNotify) continue;
        state.inbox.push_back(std::move(m));
        mail = true;
      }
      if (mail && std::find(woken.begin(), woken.end(), name->second) == woken.end())
        woken.push_back(name->second);
    }
    // The server would close these connections; so does the bus.
    for (const auto& drop : db.take_drop_requests()) {
      const auto name = names_by_id.find(drop.id);
      if (name == names_by_id.end()) continue;
      diagnostics.push_back("client \"" + name->second + "\" dropped: " + drop.reason);
      close_connection(clients.at(name->second));
    }
  }
};

// ---- InProcessBus ---------------------------------------------------------------------------

InProcessBus::InProcessBus(Clock& clock) : InProcessBus(clock, Options{}) {}

InProcessBus::InProcessBus(Clock& clock, Options options)
    : core_(std::make_shared<BusCore>(clock, std::move(options))) {}

InProcessBus::~InProcessBus() = default;

std::unique_ptr<BusClient> InProcessBus::connect(const std::string& name) {
  if (name.empty()) return nullptr;
  std::unique_ptr<BusClient> client(new BusClient(core_, name));
  std::vector<std::string> woken;
  {
    std::lock_guard<std::mutex> lock(core_->mutex);
    if (core_->clients.count(name) != 0) return nullptr;  // a real DB would POISON it (1.6)
    BusCore::ClientState state;
    if (!core_->open_connection(name, state)) return nullptr;
    state.handle = client.get();
    core_->clients.emplace(name, std::move(state));
    core_->route_output(woken);
  }
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
  return core_->db.latest(var);
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
  auto it = core_->clients.find(name());
  if (it == core_->clients.end() || it->second.handle != this) return;  // refused at connect
  if (it->second.connected) core_->close_connection(it->second);
  core_->clients.erase(it);
  std::vector<std::string> woken;
  core_->route_output(woken);  // no callbacks from a destructor: the mail waits in the inboxes
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
  std::vector<std::function<void()>> callbacks;
  std::string refusal;
  {
    std::lock_guard<std::mutex> lock(core_->mutex);
    auto it = core_->clients.find(name());
    if (it == core_->clients.end()) return false;
    BusCore::ClientState& state = it->second;
    if (state.connected) {
      core_->deliver(state, {std::move(msg)}, callbacks);
    } else {
      // Kept for the reconnect, as TcpClient keeps it; registrations are replayed instead.
      if (msg.type != msg_type::kNotify) return false;
      const std::size_t size = msg.encoded_size();
      refusal = state.outbox_bound.refusal(size);
      if (refusal.empty()) {
        state.outbox_bound.add(size);
        state.outbox.push_back(std::move(msg));
      }
    }
  }
  if (!refusal.empty()) {
    count_posting_dropped("NOTIFY " + base::excerpt(msg.key) + " refused: " + refusal);
    return false;
  }
  for (auto& cb : callbacks) cb();
  return true;
}

void BusClient::simulate_disconnect() {
  std::lock_guard<std::mutex> lock(core_->mutex);
  auto it = core_->clients.find(name());
  if (it == core_->clients.end() || !it->second.connected) return;
  core_->close_connection(it->second);
  std::vector<std::string> woken;
  core_->route_output(woken);
}

bool BusClient::simulate_reconnect() {
  // Taken before the bus lock (lock order: bus, then a client's book).
  std::vector<Message> packet = replay_messages();
  std::vector<std::function<void()>> callbacks;
  {
    std::lock_guard<std::mutex> lock(core_->mutex);
    auto it = core_->clients.find(name());
    if (it == core_->clients.end()) return false;
    BusCore::ClientState& state = it->second;
    if (state.connected) return true;
    if (!core_->open_connection(name(), state)) return false;
    state.connected = true;
    ++state.connections;
    std::vector<std::string> woken;
    core_->route_output(woken);
    // The replay, then the postings kept while disconnected, in order, before any new posting.
    for (auto& m : state.outbox) packet.push_back(std::move(m));
    state.outbox.clear();
    state.outbox_bound.clear();
    core_->deliver(state, std::move(packet), callbacks);
  }
  for (auto& cb : callbacks) cb();
  fire_on_connect();
  return true;
}

}  // namespace moos
