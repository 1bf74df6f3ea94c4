// In-process MOOS community: an adapter between Comms clients and moos::Database; contract in
// include/moos/bus.hpp.
//
// Data structures: the Database (every rule of protocol.md 5); per client name, its state: the
// current Database connection id (a reconnect is a new connection, as over TCP), its inbox and
// connection count; the connection ids back to the states, to route the Database's output. Each
// BusClient points at its state, which lives as long as it does. One mutex (a LightMutex: one
// atomic operation when nobody waits) guards everything; the flags a client checks every cycle
// (connected, mail waiting) are atomic so that the checks take no lock. On-mail callbacks run
// after the mutex is released.

#include "moos/bus.hpp"

#include <atomic>
#include <functional>
#include <map>
#include <mutex>

#include "base/text.hpp"
#include "moos/inbox.hpp"
#include "moos/light_mutex.hpp"

namespace moos {

/// One client name's connection to the bus, and the sink of its Database mail.
struct BusClientState final : MailSink {
  BusClientState(std::string n, std::vector<BusClientState*>* woken_list)
      : name(std::move(n)), woken(woken_list) {}
  const std::string name;
  BusClient* handle = nullptr;  // for on-mail callbacks
  ClientId id = 0;              // the current Database connection
  // Written under the bus mutex; read without it by the client's own per-cycle checks.
  std::atomic<bool> connected{true};
  std::atomic<std::uint64_t> connections{1};
  std::atomic<bool> has_mail{false};  // the inbox is not empty
  Inbox inbox;  // its mail is copied into the storage of the mail the app read before
  std::vector<Message> outbox;  // postings made while disconnected (comms.hpp)
  OutboxBound outbox_bound;
  // The clients with an on-mail callback that got mail in the current bus call, in order (the
  // bus's list), and whether this one is listed there. A client without a callback is not
  // listed: nothing is to be done for it after the call.
  std::vector<BusClientState*>* const woken;
  bool listed_as_woken = false;

  // The Database's mail, under the bus mutex: a copy into the storage the app's read mail left,
  // or the message itself moved in.
  void copy_mail(const Message& m) override {
    inbox.push_copy(m);
    got_mail();
  }
  void take_mail(Message& m) override {
    inbox.push_moved(m);
    got_mail();
  }
  void got_mail() {
    // Release suffices: fetch_into() takes the bus lock before it reads the inbox.
    has_mail.store(true, std::memory_order_release);
    if (listed_as_woken || !handle || !handle->has_on_mail()) return;
    listed_as_woken = true;
    woken->push_back(this);
  }
};

struct BusCore {
  using ClientState = BusClientState;

  BusCore(Clock& c, InProcessBus::Options o)
      : clock(c),
        options(std::move(o)),
        db(database_config(), now(), [this](const std::string& line) { diagnostics.push_back(line); },
           observer()) {}

  DatabaseConfig database_config() {
    DatabaseConfig config;
    config.community = options.community;
    config.db_variables = false;  // no refresh timer on the bus (see bus.hpp)
    return config;
  }

  Database::NotifyObserver observer() {
    if (!options.keep_postings) return {};
    return [this](const Message& m) { postings.push_back(m); };
  }

  double now() const { return clock.unix_now_s() * options.time_warp; }

  Clock& clock;
  const InProcessBus::Options options;
  mutable LightMutex mutex;  // taken per posting and per fetch with mail: cheap when free
  std::vector<Message> postings;
  std::vector<std::string> diagnostics;
  Database db;  // after the two lists its callbacks fill
  // Map nodes do not move: a BusClient keeps a pointer to its state for its lifetime.
  std::map<std::string, ClientState> clients;
  std::map<ClientId, ClientState*> states_by_id;
  ClientId next_id = 1;
  std::vector<OutPacket> output;  // kept between calls: the Database's output trades storage
  std::vector<ClientState*> woken;  // clients that got mail in the current call, in order

  // ---- mutex held ------------------------------------------------------------------------------

  /// A new Database connection for `state`; false if the Database refused it (POISON).
  bool open_connection(ClientState& state) {
    Message ident;
    ident.type = msg_type::kData;
    ident.data_type = data_type::kString;
    ident.key = kAsynchronousKey;
    ident.sval = state.name;
    ident.time = now();
    const ClientId id = next_id++;
    states_by_id[id] = &state;  // before the handshake: mail may follow the WELCOME at once
    // Mail goes straight into the inbox: no packet per message to build and route.
    const bool welcomed = db.connect(id, {ident}, now(), &state);
    if (welcomed) {
      state.id = id;
    } else {
      states_by_id.erase(id);
    }
    return welcomed;
  }

  void close_connection(ClientState& state) {
    states_by_id.erase(state.id);
    db.disconnect(state.id, now());
    state.connected = false;
    state.inbox.clear();
    state.has_mail = false;
  }

  /// Hands `messages` to the Database as one packet of `state`'s and routes the output; the
  /// on-mail callbacks of the clients that got mail are appended to `callbacks` (called after
  /// the lock). BusClient::transmit() does the same for one message.
  void deliver(ClientState& state, std::vector<Message> messages,
               std::vector<std::function<void()>>& callbacks) {
    db.process_packet(state.id, std::move(messages), now());
    settle(&callbacks);
  }

  /// After a Database call: routes its output and, with `callbacks`, collects the on-mail
  /// callbacks of the clients that got mail (none from a destructor: the mail waits).
  void settle(std::vector<std::function<void()>>* callbacks = nullptr) {
    if (db.has_output()) route_output();  // the usual call: all its mail went to the sinks
    if (woken.empty()) return;  // the usual call: nobody to wake
    // Copied under the bus lock (lock order: bus, then a client's book), called after it.
    if (callbacks) {
      for (ClientState* client : woken) {
        if (auto cb = client->handle->on_mail_callback()) callbacks->push_back(std::move(cb));
      }
    }
    for (ClientState* client : woken) client->listed_as_woken = false;
    woken.clear();
  }

  /// The Database's packets: protocol replies, which are not mail. Then the clients it drops.
  void route_output() {
    db.take_output(output);
    for (auto& packet : output) {
      const auto to = states_by_id.find(packet.to);
      if (to == states_by_id.end()) continue;  // a refused connection's POISON
      for (auto& m : packet.messages)
        if (m.type == msg_type::kNotify) to->second->take_mail(m);  // the packet's to give
    }
    output.clear();
    // The server would close these connections; so does the bus.
    for (const auto& drop : db.take_drop_requests()) {
      const auto to = states_by_id.find(drop.id);
      if (to == states_by_id.end()) continue;
      diagnostics.push_back("client \"" + to->second->name + "\" dropped: " + drop.reason);
      close_connection(*to->second);
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
  {
    std::lock_guard<LightMutex> lock(core_->mutex);
    // A real DB would POISON a second client of one name (1.6).
    const auto [it, fresh] = core_->clients.try_emplace(name, name, &core_->woken);
    if (!fresh) return nullptr;
    BusCore::ClientState& state = it->second;
    if (!core_->open_connection(state)) {
      core_->clients.erase(it);
      return nullptr;
    }
    state.handle = client.get();
    client->state_ = &state;
    core_->settle();
  }
  return client;
}

Clock& InProcessBus::clock() const { return core_->clock; }
double InProcessBus::time_warp() const { return core_->options.time_warp; }
double InProcessBus::moos_time() const { return core_->now(); }
const std::string& InProcessBus::community() const { return core_->options.community; }

std::vector<Message> InProcessBus::postings() const {
  std::lock_guard<LightMutex> lock(core_->mutex);
  return core_->postings;
}

std::vector<Message> InProcessBus::postings_of(const std::string& var) const {
  std::lock_guard<LightMutex> lock(core_->mutex);
  std::vector<Message> out;
  for (const auto& m : core_->postings)
    if (m.key == var) out.push_back(m);
  return out;
}

void InProcessBus::clear_postings() {
  std::lock_guard<LightMutex> lock(core_->mutex);
  core_->postings.clear();
}

std::optional<Message> InProcessBus::latest(const std::string& var) const {
  std::lock_guard<LightMutex> lock(core_->mutex);
  return core_->db.latest(var);
}

std::vector<std::string> InProcessBus::client_names() const {
  std::lock_guard<LightMutex> lock(core_->mutex);
  std::vector<std::string> names;
  for (const auto& [name, state] : core_->clients)
    if (state.connected) names.push_back(name);
  return names;
}

std::vector<std::string> InProcessBus::diagnostics() const {
  std::lock_guard<LightMutex> lock(core_->mutex);
  return core_->diagnostics;
}

// ---- BusClient ------------------------------------------------------------------------------

BusClient::BusClient(std::shared_ptr<BusCore> core, std::string name)
    // The Database fills an empty community with the bus's: posted with it, it only compares.
    : Comms(std::move(name), /*takes_fetch_promises=*/false, core->options.community),
      core_(std::move(core)) {}

BusClient::~BusClient() {
  if (!state_) return;  // refused at connect
  std::lock_guard<LightMutex> lock(core_->mutex);
  if (state_->connected) core_->close_connection(*state_);
  core_->settle();  // no callbacks from a destructor: the mail waits in the inboxes
  core_->clients.erase(state_->name);  // after settle(), which clears the woken list
}

// The state's flags are atomic: an app's per-cycle checks take no lock.
bool BusClient::is_connected() const { return state_ && state_->connected; }

std::uint64_t BusClient::connection_count() const { return state_ ? state_->connections.load() : 0; }

std::string BusClient::community() const { return core_->options.community; }
Clock& BusClient::clock() const { return core_->clock; }
double BusClient::time_warp() const { return core_->options.time_warp; }
// Comms::moos_time() in one call: local time + the skew, 0 (added, as there, so that the
// value is the same to the bit).
double BusClient::moos_time() const { return core_->now() + skew_s(); }

void BusClient::fetch_into(std::vector<Message>& mail) {
  // Mail that reached the inbox before this call set has_mail before it (under the lock). The
  // usual cycle of an app without mail returns here, without the lock.
  if (state_ && !state_->has_mail && mail.empty()) return;
  hand_over_mail(mail);
}

void BusClient::hand_over_mail(std::vector<Message>& mail) {
  if (!state_) {
    mail.clear();
    return;
  }
  std::lock_guard<LightMutex> lock(core_->mutex);
  state_->inbox.hand_over(mail);
  state_->has_mail = false;
}

bool BusClient::transmit(Message&& msg) {
  if (!state_) return false;
  std::unique_lock<LightMutex> lock(core_->mutex);
  if (!state_->connected) return keep_for_reconnect(std::move(msg), lock);
  core_->db.process_message(state_->id, std::move(msg), core_->now());
  if (core_->db.has_output()) core_->route_output();  // the usual posting: all its mail was sunk
  if (!core_->woken.empty()) wake_readers(lock);
  return true;
}

void BusClient::wake_readers(std::unique_lock<LightMutex>& lock) {
  std::vector<std::function<void()>> callbacks;
  core_->settle(&callbacks);
  lock.unlock();
  for (auto& cb : callbacks) cb();
}

bool BusClient::keep_for_reconnect(Message&& msg, std::unique_lock<LightMutex>& lock) {
  // Kept for the reconnect, as TcpClient keeps it; registrations are replayed instead.
  if (msg.type != msg_type::kNotify) return false;
  const std::size_t size = msg.encoded_size();
  const std::string refusal = state_->outbox_bound.refusal(size);
  if (refusal.empty()) {
    state_->outbox_bound.add(size);
    state_->outbox.push_back(std::move(msg));
    return true;
  }
  lock.unlock();
  count_posting_dropped("NOTIFY " + base::excerpt(msg.key) + " refused: " + refusal);
  return false;
}

void BusClient::simulate_disconnect() {
  if (!state_) return;
  std::lock_guard<LightMutex> lock(core_->mutex);
  if (!state_->connected) return;
  core_->close_connection(*state_);
  core_->settle();
}

bool BusClient::simulate_reconnect() {
  if (!state_) return false;
  // Taken before the bus lock (lock order: bus, then a client's book).
  std::vector<Message> packet = replay_messages();
  std::vector<std::function<void()>> callbacks;
  {
    std::lock_guard<LightMutex> lock(core_->mutex);
    BusCore::ClientState& state = *state_;
    if (state.connected) return true;
    if (!core_->open_connection(state)) return false;
    state.connected = true;
    ++state.connections;
    core_->settle();
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
