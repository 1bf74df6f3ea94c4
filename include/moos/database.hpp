#pragma once
// The MOOSDB's rules, once, without sockets, threads or clocks
// (docs/protocol.md sections 1.5-1.9 and 5). Two users: moosdb-lite (the
// server; src/apps/moosdb-lite turns bytes into packets and back) and moos::InProcessBus (the
// in-process community of the app tests, include/moos/bus.hpp).
//
// Contract:
// - Clients are known by a small integer id chosen by the caller (the connection layer) and
//   by the name they gave in the handshake; names are unique among connected clients.
// - Time comes in as `now_moos_s` (the server's MOOS time: unix seconds x warp, skew 0).
// - Every call appends the packets it wants sent to an output list, in the exact order they
//   must leave; take_output() hands them over. Order per client is preserved (protocol.md 5.6).
// - Synchronous clients get exactly one packet per packet they send, beginning with a NULL
//   that carries the server time, and nothing else ever (protocol.md 5.6 MUST); a reply holds
//   at most max_reply_bytes, the rest of their mail waits for the next one.
// - A NOTIFY larger than kMaxMessageBytes encoded (codec.hpp) is refused with a logged reason
//   naming the variable: no client could receive it. Asynchronous
//   clients never get a NULL or an empty packet; a TIMING that opened their packet is echoed
//   as the first message of the reply; and every mail queued for them (live updates, DB
//   variables, snapshots) is sent at the end of the call that queued it (protocol.md 5.6 SHOULD).
// - Bad messages inside a well-formed packet are refused one by one with a logged reason
//   that names the client; the rest of the packet is processed.
// - A client whose undelivered mail exceeds `max_pending_bytes` is reported through
//   take_drop_requests() (the connection layer disconnects it); no more mail is queued for it.
// - Subscriptions (protocol.md 5.3-5.5), as the reference MOOSDB keeps them:
//   * a subscription that never delivered is always due ("never" is explicit, not a time 0,
//     so a clock that starts at 0 behaves like one that starts today); a REGISTER snapshot
//     counts as a delivery and starts the throttle window;
//   * at a variable's first write every stored wildcard filter of a client that matches (app
//     pattern vs the writer, variable pattern vs the name) REPLACES that client's
//     subscription, an explicit REGISTER included: the filter's interval applies and the
//     subscription has never delivered. Of several matching filters of one client the one
//     with the greatest (app pattern, variable pattern) pair wins, as in the reference DB's
//     ordered filter set.
// - DB variables (protocol.md 5.7): DB_TIME, DB_UPTIME, DB_CLIENTS, DB_RWSUMMARY at construction
//   and on refresh_db_variables(); DB_EVENT and DB_CLIENTS on every connect and disconnect. With
//   `db_variables = false` none is written (the in-process bus, which has no refresh timer).
//
// Deviations from the reference DB (docs/moos.md section 3): malformed messages are refused
// with a logged reason; an empty NOTIFY source becomes the client's name; WILDCARD_UNREGISTER
// also removes the identical filter; a synchronous client's empty packet is answered; DB_QOS
// and DB_VARSUMMARY are not published.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "moos/codec.hpp"
#include "moos/message.hpp"
#include "moos/wildcard.hpp"

namespace moos {

using ClientId = std::uint64_t;

/// Default community of the reference MOOSDB (protocol.md 5.11).
inline constexpr const char* kDefaultCommunity = "#1";
/// Undelivered mail a client may accumulate before it is dropped, in bytes: twice moosdb-lite's
/// packet limit (256 MiB, sized from libMOOS's 2,048-message outbox), so a libMOOS client that
/// subscribes to what it posts always gets the echo of its largest packet.
inline constexpr std::size_t kDefaultMaxPendingBytes = 512u * 1024u * 1024u;
/// Refusals logged per client before further ones are only counted (keeps a misbehaving
/// client from flooding the log; the count is logged when it disconnects). A refusal quotes
/// the client's text (variable names, patterns) as a base::excerpt: a name can be as long as a
/// packet.
inline constexpr int kLoggedRefusalsPerClient = 20;

/// What the stored variables may hold in all, bytes: each variable's name and last
/// value with its writer and community, plus kVariableOverheadBytes for its bookkeeping. A
/// client that posts or registers ever new names grew the store without bound (3,000 variables
/// of 100 kB held 300 MB, outside the connections' memory budget); a 100-vehicle mission stores
/// a few megabytes. A client's NOTIFY or REGISTER that would go beyond it is refused (logged,
/// the client stays); the DB's own variables are always written.
inline constexpr std::size_t kDefaultMaxStoredBytes = 1024u * 1024u * 1024u;
inline constexpr std::size_t kVariableOverheadBytes = 256;

/// Where a connection layer in the same process (moos::InProcessBus) takes one asynchronous
/// client's mail instead of packets (Database::connect).
class MailSink {
 public:
  virtual ~MailSink() = default;
  /// Mail; `msg` is shared with the posting's other readers: copy what you keep.
  virtual void copy_mail(const Message& msg) = 0;
  /// Mail the Database is done with (a posting's last reader): take its contents (a move
  /// saves the copy); `msg` may be left holding anything.
  virtual void take_mail(Message& msg) = 0;
};

struct DatabaseConfig {
  std::string community = kDefaultCommunity;
  std::string hostname;  ///< sent in WELCOME as `hostname=<hostname>` (protocol.md 1.6)
  std::size_t max_pending_bytes = kDefaultMaxPendingBytes;
  /// The largest reply a synchronous client gets (the packet a client accepts, codec.hpp);
  /// mail beyond it waits for the next reply.
  std::size_t max_reply_bytes = kDefaultMaxPacketBytes;
  std::size_t max_stored_bytes = kDefaultMaxStoredBytes;
  bool db_variables = true;  ///< publish the DB_* variables of protocol.md 5.7
};

/// One packet for one client.
struct OutPacket {
  ClientId to = 0;
  std::vector<Message> messages;
};

struct DropRequest {
  ClientId id = 0;
  std::string reason;
};

/// Reasons of the reference DB's POISON messages (protocol.md 1.6), kept verbatim.
std::string duplicate_name_reason(const std::string& name);
inline constexpr const char* kNoNameReason = "Failed to read receive client's name";
/// The longest client name accepted, bytes. The reference DB has no bound, but a
/// name is repeated in DB_CLIENTS, DB_EVENT and every log line about its client, so a name as
/// long as a packet may be (hundreds of MB) would make each of those as long. libMOOS names
/// are a few dozen bytes.
inline constexpr std::size_t kMaxClientNameBytes = 1024;
/// The POISON text for a name longer than kMaxClientNameBytes (ours: the reference has none).
std::string overlong_name_reason(std::size_t name_bytes);

class Database {
 public:
  using LogSink = std::function<void(const std::string&)>;
  using NotifyObserver = std::function<void(const Message&)>;

  /// Creates the DB and writes its DB_* variables once (protocol.md 5.6 SHOULD), so a client
  /// registering before the first refresh gets a snapshot. `observer` (may be empty) is
  /// called with every NOTIFY the DB accepts, as stored and forwarded, DB variables
  /// included: this is what moosdb-lite's `--log` writes.
  Database(DatabaseConfig config, double start_moos_s, LogSink log, NotifyObserver observer = {});

  /// Handshake (protocol.md 1.5-1.6): `identification` is the decoded identification packet.
  /// Queues WELCOME (returns true; the client is now connected, DB_EVENT and DB_CLIENTS are
  /// published) or POISON (returns false; the caller closes the connection after sending).
  /// With a `mail_sink` (a connection layer in the same process, moos::InProcessBus), each mail
  /// of an asynchronous client (a NOTIFY: live update, snapshot or answer) is handed to it as it
  /// is queued, in the order it would have in the client's packets, instead of leaving in a
  /// packet through take_output(); protocol replies (WELCOME, POISON, TIMING echoes) still leave
  /// there, and the max_pending_bytes bound applies per call as without it. Not owned: it must
  /// last as long as the connection and must not call back into the Database.
  bool connect(ClientId id, const std::vector<Message>& identification, double now_moos_s,
               MailSink* mail_sink = nullptr);
  /// Why connect() would refuse `identification` now (the POISON's text), or nullopt.
  std::optional<std::string> handshake_refusal(const std::vector<Message>& identification) const;

  /// Disconnect clean-up of protocol.md 1.9: subscriptions, filters and undelivered mail go, the
  /// name is free, DB_EVENT/DB_CLIENTS are published. Unknown ids are ignored.
  void disconnect(ClientId id, double now_moos_s);

  /// Processes one packet from a connected client (protocol.md 5.2) and queues the replies.
  /// Taken by value: its NOTIFYs are moved into storage, not copied.
  void process_packet(ClientId id, std::vector<Message> packet, double now_moos_s);
  /// process_packet() of a packet that holds `msg` alone (moved from), without building one.
  void process_message(ClientId id, Message&& msg, double now_moos_s);

  /// Rewrites DB_TIME, DB_UPTIME, DB_CLIENTS and DB_RWSUMMARY (protocol.md 5.7).
  void refresh_db_variables(double now_moos_s);

  /// Packets to send, oldest first; the list is emptied.
  std::vector<OutPacket> take_output();
  /// The same into `out`, whose old contents are dropped: the two lists trade their storage, so
  /// a caller that keeps `out` between calls allocates no list per call (the in-process bus).
  void take_output(std::vector<OutPacket>& out);
  /// Clients to disconnect because their undelivered mail overflowed; the list is emptied.
  std::vector<DropRequest> take_drop_requests();
  /// Whether take_output() or take_drop_requests() has anything to hand over.
  bool has_output() const { return !output_.empty() || !drops_.empty(); }

  bool is_connected(ClientId id) const { return clients_.count(id) != 0; }
  std::optional<std::string> client_name(ClientId id) const;
  bool is_async(ClientId id) const;
  /// Encoded bytes of the mail queued for a client and not yet handed to take_output() (a
  /// synchronous client's mail waits for its next packet); 0 for unknown ids.
  std::size_t pending_bytes(ClientId id) const;
  /// The snapshot a REGISTER of `name` would send now (protocol.md 2.6); nullopt while unwritten.
  std::optional<Message> latest(const std::string& name) const;
  /// What the store holds now, counted as for DatabaseConfig::max_stored_bytes.
  std::size_t stored_bytes() const { return stored_bytes_; }

 private:
  using VarId = std::size_t;

  /// A variable a client has posted, found again by comparing names instead of hashing them.
  struct PostedVariable {
    std::string name;
    VarId var = 0;
  };

  struct Client {
    ClientId id = 0;
    std::string name;
    bool async = false;
    MailSink* sink = nullptr;  ///< see connect(); null for a synchronous client
    std::vector<Message> pending;  ///< undelivered mail, in order
    /// Bytes of `pending`; for a client with a mail sink, of the mail the sink got in call
    /// `sink_call` (the bound is per call, and such a client is never listed for the flush).
    std::size_t pending_bytes = 0;
    std::uint64_t sink_call = 0;
    bool queued_for_flush = false;  ///< already listed in async_with_mail_
    bool overflowed = false;
    std::vector<WildcardSpec> filters;
    std::set<VarId> subscribed;
    std::set<VarId> published;
    /// The variables of its latest accepted NOTIFYs, each also in `published` (an app posts the
    /// same few every cycle); at most kPostedCacheEntries, names of at most
    /// kPostedCacheNameBytes. VarIds never change, so only DB_CLEAR (which empties `published`)
    /// empties it.
    std::vector<PostedVariable> posted_cache;
    std::size_t posted_cache_next = 0;  ///< the entry a new name replaces when it is full
    int refusals = 0;
  };
  static constexpr std::size_t kPostedCacheEntries = 8;
  static constexpr std::size_t kPostedCacheNameBytes = 64;

  struct Subscription {
    double interval_s = 0.0;  ///< 0: every update
    std::optional<double> last_delivery_moos_s;  ///< nullopt: never delivered
    /// The subscriber (clients_ nodes do not move; a client's subscriptions go before it does).
    Client* client = nullptr;
  };

  /// A variable's subscriptions by client id (= connection order: the fan-out's deterministic
  /// order), in a sorted vector: walked at every write, changed only by (un)registrations and
  /// disconnects.
  class Subscribers {
   public:
    using Entry = std::pair<ClientId, Subscription>;
    /// The subscription of `id`, added (default) if it had none.
    Subscription& operator[](ClientId id);
    void erase(ClientId id);
    std::vector<Entry>::iterator begin() { return entries_.begin(); }
    std::vector<Entry>::iterator end() { return entries_.end(); }

   private:
    std::vector<Entry> entries_;
  };

  /// The last accepted write of a variable.
  struct Value {
    double dval = kUnsetDouble;   ///< the wire's -1 for string and binary values
    std::string sval;
    double time_moos_s = 0.0;     ///< the publisher's time stamp
    double db_write_moos_s = 0.0; ///< DB time of the write
    std::string writer;
    std::string writer_aux;
    std::string community;
  };

  /// Write-frequency estimate (dval2 of the `ALL` answer, protocol.md 5.8).
  struct WriteFrequency {
    double hz = 0.0;
    double window_start_moos_s = 0.0;
    std::uint64_t window_start_count = 0;
  };

  struct Variable {
    std::string name;
    char data_type = data_type::kNotSet;
    std::optional<Value> value;  ///< nullopt: never written (or cleared by DB_CLEAR)
    std::uint64_t write_count = 0;
    WriteFrequency frequency;
    Subscribers subscribers;
  };

  /// process_packet() of the messages [first, last), which it moves from.
  void process_messages(ClientId id, Message* first, Message* last, double now_moos_s);
  /// The connected client `id` (the latest sender is found without a look-up), or null.
  Client* sender(ClientId id);
  /// The end of a packet from `client` (protocol.md 5.2 steps 6-7): its reply, with `echo` (a
  /// leading TIMING of an asynchronous client) first, and every asynchronous client's mail.
  void end_packet(Client& client, Message* echo, double now_moos_s);
  /// end_packet() of an asynchronous client's packet without a TIMING to echo: its mail, if
  /// any waits (a client with a mail sink has none), leaves now.
  void end_async_packet(Client& client) {
    if (!client.pending.empty()) send_packet(client.id, std::move(client.pending));
    client.pending.clear();
    client.pending_bytes = 0;
    flush_async_mail();
  }
  // One handler per message type (protocol.md 5.2 step 3), each in the file of its rule.
  void handle_message(Client& client, Message&& msg, double now);
  void handle_notify(Client& client, Message&& msg, double now);
  // handle_notify()'s rare ends, out of line.
  [[gnu::cold]] void refuse_notify_form(ClientId id, const Message& msg);
  /// Refuses `msg` (`size` bytes encoded) if it is too large for a client or the store.
  [[gnu::cold]] bool refused_for_size(ClientId id, const Message& msg, std::size_t size);
  [[gnu::cold]] void refuse_type_change(ClientId id, VarId var, char type);
  /// Lists a variable the client posted for the first time in `published` and posted_cache.
  [[gnu::cold]] void note_posted(Client& client, VarId var);
  void handle_register(ClientId id, const Message& msg, double now);
  void handle_unregister(ClientId id, const Message& msg);
  void handle_wildcard_register(ClientId id, const Message& msg, double now);
  void handle_wildcard_unregister(ClientId id, const Message& msg);
  void handle_server_request(ClientId id, const Message& msg, double now);

  // NOTIFY storage (database_notify.cpp). publish() writes `msg` to variable `id` (its name) and
  // fans it out; the write was refused if the variable's type differs from the message's
  // afterwards.
  void publish(VarId id, Message&& msg, double now);
  void store(Variable& var, const Message& msg, double now);
  VarId find_or_create(const std::string& name);
  /// The client's posted_cache entry of `name`, or null.
  static const PostedVariable* find_posted(const Client& client, const std::string& name);
  void remember_posted(Client& client, VarId var) const;
  /// Why a client's write of `msg` (or, without a value, a new name) would take the store
  /// beyond max_stored_bytes; empty when it fits.
  std::string store_refusal(const Message& msg, bool with_value) const;
  /// Whether the most a write of `msg` could add fits: then it fits, without looking the
  /// variable up (the usual case; store_refusal's first test).
  bool fits_at_most(const Message& msg, bool with_value) const;
  /// The most a write of `msg` can add to the store (its value, if `with_value`, and its name).
  static std::size_t most_stored_bytes(const Message& msg, bool with_value);
  /// store_refusal() when the most the write could add would not fit: the exact count.
  std::string store_refusal_near_bound(const Message& msg, bool with_value) const;
  static std::size_t value_bytes(const Value& value);

  // Subscriptions (database_register.cpp).
  void subscribe(ClientId id, VarId var, double interval_s, double now);
  void bind_wildcard_filters(VarId var, const std::string& writer);
  static bool matches(const WildcardSpec& spec, const Variable& var);

  // DB variables (database_db_variables.cpp).
  void publish_db_string(const std::string& key, const std::string& value, double now);
  void publish_db_double(const std::string& key, double value, double now);
  void publish_db_variable(Message msg, double now);
  /// Names of connected clients, each followed by a comma (the DB_CLIENTS value).
  std::string client_list() const;
  std::string rw_summary() const;

  // Server requests (database_server_requests.cpp).
  void answer_all(ClientId id, std::int32_t request_id);
  void answer_var_summary(ClientId id, std::int32_t request_id, double now);
  void answer_proc_summary(ClientId requester, std::int32_t request_id, double now);
  void clear_db();

  // Mail and replies (database_mail.cpp).
  void fan_out(Variable& var, Message&& msg, double now);
  Message snapshot(const Variable& var) const;
  void queue_mail(ClientId id, Message&& msg);
  /// A posting's mail of `size` encoded bytes for `client`: a copy of `msg` (a fan-out's reader
  /// but the last), or with `take` the message itself, which a mail sink may take apart.
  void queue_fan_out_mail(Client& client, Message& msg, std::size_t size, bool take);
  /// The mail bound's check and count for `size` more bytes to `client`: false when it takes no
  /// more mail.
  bool admit_mail(Client& client, std::size_t size);
  /// Marks `client` overflowed and asks for its drop (admit_mail()'s rare end).
  [[gnu::cold]] void overflow(Client& client);
  /// Lists an asynchronous client without a mail sink for the flush of this call.
  void list_for_flush(Client& client);
  /// Sends the listed clients' mail (protocol.md 5.6) and ends the call (calls_).
  void flush_async_mail() {
    if (!async_with_mail_.empty()) send_listed_mail();  // none with only mail-sink clients
    ++calls_;
  }
  void send_listed_mail();
  /// Moves the client's pending mail behind `reply`: all of it for an asynchronous client,
  /// what fits in config_.max_reply_bytes for a synchronous one.
  void take_pending(Client& client, std::vector<Message>& reply);
  void send_packet(ClientId to, std::vector<Message> messages);
  Message null_reply(double now) const;

  void refuse(ClientId id, const std::string& what);
  std::string describe(ClientId id) const;

  DatabaseConfig config_;
  std::string db_name_;  ///< `MOOSDB_<community>`: the source of DB-generated messages (5.7)
  double start_moos_s_;
  LogSink log_;
  NotifyObserver notify_observer_;

  std::vector<Variable> vars_;
  std::size_t stored_bytes_ = 0;  ///< see stored_bytes()
  std::unordered_map<std::string, VarId> var_index_;
  std::map<ClientId, Client> clients_;  ///< ordered by id = connection order
  std::unordered_map<std::string, ClientId> client_by_name_;
  /// Listed at most once each (queued_for_flush) and never across a disconnect; clients with a
  /// mail sink are not listed (their mail left as it was queued).
  std::vector<Client*> async_with_mail_;
  /// Public calls completed (each ends in flush_async_mail()): Client::sink_call's clock.
  std::uint64_t calls_ = 0;
  /// Clients that sent lately, by id modulo kRecentSenders (null, or a connected client):
  /// the clients of a community take turns posting, and each is found again without a look-up
  /// (connection layers number their connections in turn, so ids seldom share a place).
  static constexpr std::size_t kRecentSenders = 16;
  std::array<Client*, kRecentSenders> recent_senders_{};

  std::vector<OutPacket> output_;
  std::vector<DropRequest> drops_;
};

}  // namespace moos
