#pragma once
// An in-process MOOS community for tests: moos::Database (include/moos/database.hpp, the same
// rules moosdb-lite serves) without sockets, threads or real time. Applications see it through
// the Comms interface, exactly as they see a TcpClient.
//
// Contract (a thin adapter; the MOOSDB rules are moos::Database's, protocol.md section 5):
// - Every client is an asynchronous Database client; every message it transmits is one packet.
//   The NOTIFYs the Database sends it land in its inbox (fetch()); protocol replies (WELCOME)
//   are not mail. Delivery is synchronous and deterministic: a message is in the subscribers'
//   inboxes when notify() returns, in posting order.
// - Time is the bus clock x warp (skew 0), read when each message is processed, so a
//   ManualClock starting at 0 throttles like one starting today ("never delivered" is explicit).
// - Writes of another data type are refused by the Database; its log lines are diagnostics().
// - Settled with the server: a wildcard filter binding a variable at its first write replaces
//   an explicit REGISTER (the filter's interval applies), as in the reference DB.
// - Differs from the server only in: no DB_* variables (no refresh timer; apps under test do not
//   need them) and no SERVER_REQUEST traffic (Comms has no call that sends one).
// - Thread-safe; on-mail callbacks run on the posting thread with no lock held.

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "moos/clock.hpp"
#include "moos/comms.hpp"
#include "moos/database.hpp"
#include "moos/light_mutex.hpp"
#include "moos/message.hpp"

namespace moos {

class BusClient;
struct BusCore;
struct BusClientState;

class InProcessBus {
 public:
  struct Options {
    std::string community = kDefaultCommunity;  ///< protocol.md 5.11
    double time_warp = 1.0;        ///< 0 < W <= 400 (protocol.md 1.10)
    /// Keep every accepted NOTIFY for postings() (tests read them); a runner that reads the
    /// mail through a client instead saves a copy of every posting.
    bool keep_postings = true;
  };

  /// `clock` must outlive the bus and every client (usually a ManualClock).
  explicit InProcessBus(Clock& clock);
  InProcessBus(Clock& clock, Options options);
  ~InProcessBus();
  InProcessBus(const InProcessBus&) = delete;
  InProcessBus& operator=(const InProcessBus&) = delete;

  /// A new, connected client. nullptr if the name is empty or already connected (a real DB
  /// would POISON the second one, protocol.md 1.6).
  std::unique_ptr<BusClient> connect(const std::string& name);

  Clock& clock() const;
  double time_warp() const;
  double moos_time() const;
  const std::string& community() const;

  /// Every accepted NOTIFY, in order, as stored (community filled in); none without
  /// Options::keep_postings.
  std::vector<Message> postings() const;
  /// Accepted NOTIFYs of one variable, in order.
  std::vector<Message> postings_of(const std::string& var) const;
  void clear_postings();
  /// The variable as a REGISTER snapshot would show it; nullopt if never written.
  std::optional<Message> latest(const std::string& var) const;
  /// Connected client names, sorted.
  std::vector<std::string> client_names() const;
  /// The Database's log: refused messages (e.g. type mismatches), oldest first.
  std::vector<std::string> diagnostics() const;

 private:
  std::shared_ptr<BusCore> core_;
};

/// One application's connection to an InProcessBus.
class BusClient final : public Comms {
 public:
  ~BusClient() override;

  bool is_connected() const override;
  std::uint64_t connection_count() const override;
  std::string community() const override;
  Clock& clock() const override;
  double time_warp() const override;
  double skew_s() const override { return 0.0; }
  double moos_time() const override;
  void fetch_into(std::vector<Message>& mail) override;

  /// As if the TCP connection dropped: the bus forgets this client's subscriptions, filters and
  /// undelivered mail; postings wait in the bounded outbox until simulate_reconnect() (comms.hpp).
  void simulate_disconnect();
  /// A new handshake: re-sends every remembered subscription, then the postings kept while
  /// disconnected, counts a connection and runs the on-connect callback. False if the name was
  /// taken meanwhile.
  bool simulate_reconnect();

 protected:
  bool transmit(Message&& msg) override;

 private:
  friend class InProcessBus;
  BusClient(std::shared_ptr<BusCore> core, std::string name);
  /// fetch_into() past its lock-free check (apart, so that the check's call stays cheap).
  [[gnu::noinline]] void hand_over_mail(std::vector<Message>& mail);
  // transmit()'s rarer ends, out of line (bus lock held by `lock`): the on-mail callbacks of
  // the clients that got mail, called after the lock is released; a posting while disconnected.
  void wake_readers(std::unique_lock<LightMutex>& lock);
  [[gnu::cold]] bool keep_for_reconnect(Message&& msg, std::unique_lock<LightMutex>& lock);

  std::shared_ptr<BusCore> core_;
  BusClientState* state_ = nullptr;  ///< owned by the bus; set when connected, until destroyed
};

}  // namespace moos
