#pragma once
// The one interface through which an application talks to a MOOS community. Two
// implementations: TcpClient (a real MOOSDB or moosdb-lite over TCP, docs/protocol.md 1 and 4) and
// BusClient (an in-process bus with the same semantics, for tests).
//
// Contract (both implementations):
// - Subscriptions are remembered: register_* records the subscription and sends it now if
//   connected; after every (re)connect all remembered subscriptions are sent again, in the order
//   they were first made, BEFORE the on-connect callback runs (the server forgot them,
//   protocol.md 1.9). They return false only for invalid arguments (empty name, comma in a
//   pattern).
// - unregister_variable sends UNREGISTER only for a variable registered before (libMOOS, 4.1);
//   unregister_wildcard always sends (if connected) and forgets the pattern pair.
// - Delivery: a posting (notify/post) that returns true is sent once, in posting order, unless
//   the connection drops while it is being written (then it may be lost, as in libMOOS).
//   Postings made while disconnected (or before the first connection) wait in the outbox and
//   leave after the next handshake, behind the registration replay. The outbox is bounded
//   (kDefaultMaxOutboxMessages, kDefaultMaxOutboxBytes): a posting beyond the bound, or one
//   larger than kMaxMessageBytes encoded (codec.hpp: no client could receive it), returns
//   false, is counted (postings_dropped()) and named in last_post_error(). A closed or poisoned
//   client refuses postings (false, not counted). Registrations are never queued: the
//   remembered ones are replayed at each connection (below).
//   Posted NOTIFYs carry this client's name as source, unless given the MOOS time now, and
//   the transport's posted community (empty but for BusClient: see the constructor).
// - fetch() returns all mail received since the last fetch, in arrival order; TIMING and NULL
//   messages never reach it.
// - Time: local time = Clock real seconds x warp; MOOS time = local time + skew (protocol.md 1.10).
// - Every public function is thread-safe. Callbacks run on the implementation's own thread
//   (TcpClient: its comms thread) with no lock held; they may call any function of this object.

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "moos/clock.hpp"
#include "moos/message.hpp"
#include "moos/wildcard.hpp"

namespace moos {

/// The outbox a client keeps while it cannot send (disconnected, or a slow server): far above
/// what an app posts between a drop and its reconnect one MOOS second later, and room for two
/// of the largest messages.
inline constexpr std::size_t kDefaultMaxOutboxMessages = 65536;
inline constexpr std::size_t kDefaultMaxOutboxBytes = std::size_t{256} * 1024 * 1024;

/// An outbox's size, counted as the messages' encoded bytes, and its bounds.
struct OutboxBound {
  std::size_t max_messages = kDefaultMaxOutboxMessages;
  std::size_t max_bytes = kDefaultMaxOutboxBytes;
  std::size_t messages = 0;
  std::size_t bytes = 0;
  /// Why a message of `size` encoded bytes does not fit now ("" if it does).
  std::string refusal(std::size_t size) const;
  void add(std::size_t size) {
    ++messages;
    bytes += size;
  }
  void remove(std::size_t size) {
    --messages;
    bytes -= size;
  }
  void clear() { messages = bytes = 0; }
};

class Comms {
 public:
  Comms(const Comms&) = delete;
  Comms& operator=(const Comms&) = delete;
  virtual ~Comms();

  /// The client (registration) name; fixed at construction.
  const std::string& name() const { return name_; }
  virtual bool is_connected() const = 0;
  /// Successful handshakes so far (a reconnect increments it).
  virtual std::uint64_t connection_count() const = 0;
  /// The community the server announced (WELCOME), "" before the first connection.
  virtual std::string community() const = 0;

  virtual Clock& clock() const = 0;
  virtual double time_warp() const = 0;
  /// MOOS time minus local time, seconds (0 until a server says otherwise, protocol.md 1.8, 4.4).
  virtual double skew_s() const = 0;
  double local_time() const { return clock().unix_now_s() * time_warp(); }
  /// local_time() + skew_s(). Virtual only so that an implementation can answer with fewer
  /// calls (an app asks several times per cycle); the value is the same.
  virtual double moos_time() const { return local_time() + skew_s(); }

  /// REGISTER `var`; updates of it arrive at most once per `interval_s` MOOS seconds (0 = every
  /// update; throttled updates are dropped by the server, protocol.md 5.3).
  bool register_variable(const std::string& var, double interval_s = 0.0);
  bool unregister_variable(const std::string& var);
  /// WILDCARD_REGISTER: variables whose name matches `var_pattern` and whose (first) writer
  /// matches `app_pattern` (protocol.md 5.5). Patterns use `*` and `?` and cannot contain commas.
  bool register_wildcard(const std::string& var_pattern, const std::string& app_pattern = "*",
                         double interval_s = 0.0);
  bool unregister_wildcard(const std::string& var_pattern, const std::string& app_pattern = "*");

  /// NOTIFY a double / string / binary value. `time_s` defaults to the MOOS time now.
  bool notify(const std::string& var, double value, std::optional<double> time_s = std::nullopt,
              const std::string& source_aux = {});
  /// The value is taken by value: a caller done with its text moves it in, uncopied.
  bool notify(const std::string& var, std::string value,
              std::optional<double> time_s = std::nullopt, const std::string& source_aux = {});
  bool notify_binary(const std::string& var, const std::string& bytes,
                     std::optional<double> time_s = std::nullopt,
                     const std::string& source_aux = {});
  /// Posts a prepared NOTIFY (type forced to 'N'); a time of -1 means "now"
  /// (libMOOS, protocol.md 2.2).
  bool post(Message notify);

  /// All mail received since the last call, oldest first. The promise: every message that
  /// reached this client before the call (TcpClient: its packet was whole in the socket) is
  /// returned by this call or, if it could not be read then, announced by the on-mail callback
  /// without waiting for another fetch, and returned by the next one. TcpClient after
  /// expect_fetch_within(): fetch() reads the socket itself; when its comms thread is using the
  /// socket at that moment, or more than one read's worth waits, that thread reads the rest.
  std::vector<Message> fetch();
  /// fetch() into `mail`, replacing its contents. The client takes the messages `mail` held back
  /// and writes later mail over their strings' storage (moos::Inbox): a caller that passes the
  /// same vector every cycle (MoosApp) makes steady mail allocate no strings.
  virtual void fetch_into(std::vector<Message>& mail) = 0;
  /// Postings between hold_sends() and release_sends() may leave together: an implementation
  /// may wait for the release before it starts sending (TcpClient: one packet per app cycle,
  /// not one for the first posting and one for the rest). Postings are never lost or reordered.
  virtual void hold_sends() {}
  virtual void release_sends() {}
  /// The caller will call fetch() again within about `real_s` real seconds (0 or less: no
  /// promise, e.g. before a long sleep that mail must end). An implementation may then leave
  /// reading to fetch() and save its own wake-ups (TcpClient); the promise of fetch() holds.
  virtual void expect_fetch_within(double /*real_s*/) {}
  /// False when expect_fetch_within() ignores its promise (BusClient): a caller may skip
  /// working out its argument.
  bool takes_fetch_promises() const { return takes_fetch_promises_; }
  /// Mail dropped unread since the start because the inbox was full (never decreases).
  std::uint64_t mail_dropped() const { return mail_dropped_.load(); }
  /// Postings refused since the start because the outbox was full or the message too large
  /// (never decreases).
  std::uint64_t postings_dropped() const { return postings_dropped_.load(); }
  /// Why the last counted posting was refused, naming its variable ("" if none was).
  std::string last_post_error() const;

  /// Called after every successful (re)connect, after the registrations were re-sent.
  void set_on_connect(std::function<void()> callback);
  /// Called when new mail is waiting (use it to wake a loop; then call fetch()).
  void set_on_mail(std::function<void()> callback);
  /// A copy of the on-mail callback (empty if none), for code that calls it later.
  std::function<void()> on_mail_callback() const;
  /// Whether an on-mail callback is set: a check without copying it (the bus asks per posting).
  bool has_on_mail() const { return has_on_mail_.load(); }

  /// Remembered plain registrations (the `Subscribing` list of `<APP>_STATUS`, protocol.md 7.1).
  std::set<std::string> registered_names() const;
  /// Variables this client has posted (the `Publishing` list of `<APP>_STATUS`).
  std::set<std::string> published_names() const;

 protected:
  /// `posted_community`: the community field of posted NOTIFYs. Empty, as libMOOS sends them
  /// (the server fills in its own, protocol.md 5.3); a transport whose server is known to fill
  /// in exactly this text (BusClient) may pass it, so that the server only compares.
  explicit Comms(std::string name, bool takes_fetch_promises = true,
                 std::string posted_community = {})
      : name_(std::move(name)),
        takes_fetch_promises_(takes_fetch_promises),
        posted_community_(std::move(posted_community)) {}

  /// Hands one message to the server: now when connected; a NOTIFY also while disconnected,
  /// queued for the next connection (the delivery contract above). False (nothing sent) when it
  /// was not taken: a registration while disconnected, a closed client, a full outbox (then
  /// count_posting_dropped() was called). Called with no lock of this base class held. `msg` may
  /// be moved from, taken or not.
  virtual bool transmit(Message&& msg) = 0;
  /// REGISTER and WILDCARD_REGISTER messages for every remembered subscription, in the order the
  /// subscriptions were first made (the reconnect replay).
  std::vector<Message> replay_messages() const;
  void fire_on_connect();
  void fire_on_mail();
  /// Counts mail the implementation dropped unread (a bounded inbox overflowed).
  void count_mail_dropped(std::uint64_t messages) { mail_dropped_ += messages; }
  /// Counts a posting refused for `why` (it names the variable), for postings_dropped().
  void count_posting_dropped(std::string why);

 private:
  Message control_message(char type, char data_type, const std::string& key) const;
  Message register_message(const std::string& var, double interval_s) const;
  Message wildcard_message(char type, const WildcardSpec& spec) const;
  /// notify() of any type: `sval` (null for a double) is taken, uncopied.
  bool post_notify(char data_type, const std::string& var, double dval, std::string* sval,
                   std::optional<double> time_s, const std::string& source_aux);
  /// post_notify() in a message of its own, while another posting uses outgoing_ (rare).
  [[gnu::cold]] bool post_notify_apart(char data_type, const std::string& var, double dval,
                                       std::string* sval, double time,
                                       const std::string& source_aux);
  void fill_notify(Message& m, char data_type, const std::string& var, double dval,
                   std::string* sval, double time, const std::string& source_aux) const;
  bool post_and_record(Message&& msg);
  bool published_recently(const std::string& key) const;
  /// Lists `name`, an element of published_, among recent_published_; book_mutex_ held.
  void remember_published(const std::string& name);

  const std::string name_;
  const bool takes_fetch_promises_;
  const std::string posted_community_;
  mutable std::mutex book_mutex_;
  /// Subscriptions in first-made order: a plain variable (var_pattern is the name, app_pattern
  /// unset) or a wildcard pair.
  struct Subscription {
    bool wildcard = false;
    WildcardSpec entry;
  };
  std::vector<Subscription> subscriptions_;
  /// Unordered: looked up at every posting; published_names() sorts a copy. Names are never
  /// erased.
  std::unordered_set<std::string> published_;
  /// Elements of published_ posted lately (null: none yet): a posting of one of them needs no
  /// lock and no hashing. Their strings stay put (elements of an unordered_set do not move) and
  /// are never changed. Written under book_mutex_, in turn.
  static constexpr std::size_t kRecentPublished = 4;
  std::array<std::atomic<const std::string*>, kRecentPublished> recent_published_{};
  std::size_t recent_published_next_ = 0;  ///< under book_mutex_
  std::function<void()> on_connect_;
  std::function<void()> on_mail_;
  std::atomic<bool> has_on_mail_{false};
  std::atomic<std::uint64_t> mail_dropped_{0};
  std::atomic<std::uint64_t> postings_dropped_{0};
  std::string last_post_error_;  ///< under book_mutex_
  /// The message notify() builds, kept with whatever storage the transport left in it (the bus
  /// hands back that of the inbox message it wrote over): a steady posting then allocates no
  /// string. Used by one posting at a time (outgoing_in_use_); a concurrent one builds its own.
  Message outgoing_;
  std::atomic<bool> outgoing_in_use_{false};
};

}  // namespace moos
