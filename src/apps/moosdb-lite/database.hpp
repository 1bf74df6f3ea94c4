#pragma once
// The MOOSDB's data and delivery semantics, without sockets or clocks
// (../shared/spec/moos-wire-protocol.md sections 1.5-1.9 and 5).
//
// Contract:
// - Clients are known by a small integer id chosen by the caller (the connection layer) and
//   by the name they gave in the handshake; names are unique among connected clients.
// - Time comes in as `now_moos_s` (the server's MOOS time: unix seconds x warp, skew 0).
// - Every call appends the packets it wants sent to an output list, in the exact order they
//   must leave; take_output() hands them over. Order per client is preserved (spec 5.6).
// - Synchronous clients get exactly one packet per packet they send, beginning with a NULL
//   that carries the server time, and nothing else ever (spec 5.6 MUST). Asynchronous
//   clients never get a NULL or an empty packet; a TIMING that opened their packet is echoed
//   as the first message of the reply; and every mail queued for them (live updates, DB
//   variables, snapshots) is sent at the end of the call that queued it (spec 5.6 SHOULD).
// - Bad messages inside a well-formed packet are refused one by one with a logged reason
//   that names the client; the rest of the packet is processed.
// - A client whose undelivered mail exceeds `max_pending_bytes` is reported through
//   take_drop_requests() (the connection layer disconnects it); no more mail is queued for it.
//
// Deviations from the reference DB are listed in docs/moos.md.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "moos/message.hpp"
#include "moos/wildcard.hpp"

namespace moosdb_lite {

using ClientId = std::uint64_t;

/// Default community of the reference MOOSDB (spec 5.11).
inline constexpr const char* kDefaultCommunity = "#1";
/// Undelivered mail a client may accumulate before it is dropped: twice the default packet
/// limit (spec 3.4), so that one maximal message always fits.
inline constexpr std::size_t kDefaultMaxPendingBytes = 256u * 1024u * 1024u;
/// Refusals logged per client before further ones are only counted (keeps a misbehaving
/// client from flooding the log; the count is logged when it disconnects).
inline constexpr int kLoggedRefusalsPerClient = 20;

struct DatabaseConfig {
  std::string community = kDefaultCommunity;
  std::string hostname;  ///< sent in WELCOME as `hostname=<hostname>` (spec 1.6)
  std::size_t max_pending_bytes = kDefaultMaxPendingBytes;
};

/// One packet for one client.
struct OutPacket {
  ClientId to = 0;
  std::vector<moos::Message> messages;
};

struct DropRequest {
  ClientId id = 0;
  std::string reason;
};

/// Reasons of the reference DB's POISON messages (spec 1.6), kept verbatim.
std::string duplicate_name_reason(const std::string& name);
inline constexpr const char* kNoNameReason = "Failed to read receive client's name";

class Database {
 public:
  using LogSink = std::function<void(const std::string&)>;
  using NotifyObserver = std::function<void(const moos::Message&)>;

  /// Creates the DB and writes its DB_* variables once (spec 5.6 SHOULD), so a client
  /// registering before the first refresh gets a snapshot. `observer` (may be empty) is
  /// called with every NOTIFY the DB accepts, as stored and forwarded, DB variables
  /// included: this is what `--log` writes.
  Database(DatabaseConfig config, double start_moos_s, LogSink log, NotifyObserver observer = {});

  /// Handshake (spec 1.5-1.6): `identification` is the decoded identification packet.
  /// Queues WELCOME (returns true; the client is now connected, DB_EVENT and DB_CLIENTS are
  /// published) or POISON (returns false; the caller closes the connection after sending).
  bool connect(ClientId id, const std::vector<moos::Message>& identification,
               double now_moos_s);

  /// Disconnect clean-up of spec 1.9: subscriptions, filters and undelivered mail go, the
  /// name is free, DB_EVENT/DB_CLIENTS are published. Unknown ids are ignored.
  void disconnect(ClientId id, double now_moos_s);

  /// Processes one packet from a connected client (spec 5.2) and queues the replies.
  /// Taken by value: its NOTIFYs are moved into storage, not copied.
  void process_packet(ClientId id, std::vector<moos::Message> packet, double now_moos_s);

  /// Rewrites DB_TIME, DB_UPTIME, DB_CLIENTS and DB_RWSUMMARY (spec 5.7).
  void refresh_db_variables(double now_moos_s);

  /// Packets to send, oldest first; the list is emptied.
  std::vector<OutPacket> take_output();
  /// Clients to disconnect because their undelivered mail overflowed; the list is emptied.
  std::vector<DropRequest> take_drop_requests();

  bool is_connected(ClientId id) const { return clients_.count(id) != 0; }
  std::optional<std::string> client_name(ClientId id) const;
  bool is_async(ClientId id) const;
  /// `MOOSDB_<community>`: the source of DB-generated messages (spec 5.7).
  const std::string& db_name() const { return db_name_; }
  const std::string& community() const { return config_.community; }
  /// Names of connected clients, each followed by a comma (the DB_CLIENTS value).
  std::string client_list() const;

 private:
  using VarId = std::size_t;

  struct Subscription {
    double interval_s = 0.0;
    double last_delivery_moos_s = 0.0;
  };

  struct Variable {
    std::string name;
    char data_type = moos::data_type::kNotSet;
    double dval = moos::kUnsetDouble;
    std::string sval;
    double time_moos_s = moos::kUnsetDouble;      ///< publisher's time stamp of the last write
    double db_write_moos_s = moos::kUnsetDouble;  ///< DB time of the last write
    std::string writer;
    std::string writer_aux;
    std::string community;
    std::uint64_t write_count = 0;
    double frequency_hz = 0.0;
    double frequency_window_start_moos_s = 0.0;
    std::uint64_t frequency_window_start_count = 0;
    std::map<ClientId, Subscription> subscribers;  ///< ordered: deterministic fan-out
  };

  struct Client {
    std::string name;
    bool async = false;
    std::vector<moos::Message> pending;  ///< undelivered mail, in order
    std::size_t pending_bytes = 0;
    bool queued_for_flush = false;       ///< already listed in async_with_mail_
    bool overflowed = false;
    std::vector<moos::WildcardSpec> filters;
    std::set<VarId> subscribed;
    std::set<VarId> published;
    int refusals = 0;
  };

  // One handler per message type (spec 5.2 step 3).
  void handle_message(ClientId id, moos::Message msg, double now);
  void handle_notify(ClientId id, moos::Message msg, double now);
  void handle_register(ClientId id, const moos::Message& msg, double now);
  void handle_unregister(ClientId id, const moos::Message& msg);
  void handle_wildcard_register(ClientId id, const moos::Message& msg, double now);
  void handle_wildcard_unregister(ClientId id, const moos::Message& msg);
  void handle_server_request(ClientId id, const moos::Message& msg, double now);

  // Core operations shared by clients and the DB's own variables.
  /// Stores and fans out a NOTIFY (spec 5.3); returns its variable. The write was refused
  /// if the variable's type differs from the message's afterwards.
  VarId publish(moos::Message msg, double now);
  void subscribe(ClientId id, VarId var, double interval_s, double now);
  void bind_wildcard_filters(VarId var, const std::string& writer);
  static bool matches(const moos::WildcardSpec& spec, const Variable& var);
  VarId find_or_create(const std::string& name);
  void publish_db_string(const std::string& key, const std::string& value, double now);
  void publish_db_double(const std::string& key, double value, double now);
  void publish_db_variable(moos::Message msg, double now);

  // Server requests (spec 5.8).
  void answer_all(ClientId id, std::int32_t request_id);
  void answer_var_summary(ClientId id, std::int32_t request_id, double now);
  void answer_proc_summary(ClientId requester, std::int32_t request_id, double now);
  void clear_db();

  // Mail and replies.
  moos::Message snapshot(const Variable& var) const;
  void queue_mail(ClientId id, moos::Message msg);
  void flush_async_mail();
  void send_packet(ClientId to, std::vector<moos::Message> messages);
  moos::Message null_reply(double now) const;

  void refuse(ClientId id, const std::string& what);
  std::string describe(ClientId id) const;
  std::string rw_summary() const;

  DatabaseConfig config_;
  std::string db_name_;
  double start_moos_s_;
  LogSink log_;
  NotifyObserver notify_observer_;

  std::vector<Variable> vars_;
  std::unordered_map<std::string, VarId> var_index_;
  std::map<ClientId, Client> clients_;  ///< ordered by id = connection order
  std::unordered_map<std::string, ClientId> client_by_name_;
  std::vector<ClientId> async_with_mail_;

  std::vector<OutPacket> output_;
  std::vector<DropRequest> drops_;
};

}  // namespace moosdb_lite
