#pragma once
// An in-process MOOS community for tests: the MOOSDB's register/notify/fetch semantics (wire spec
// 5.3-5.5) without sockets, threads or real time. Applications see it through the Comms
// interface, exactly as they see a TcpClient.
//
// Contract (as a MOOSDB, spec section 5):
// - NOTIFY: the first write fixes a variable's data type; later writes of another type (S vs B
//   included) are dropped and noted in diagnostics(). A stored message's empty community becomes
//   the bus community. Every subscriber whose interval has expired gets a copy (interval 0 =
//   every update; throttled updates are dropped, not delayed); the publisher is not excluded.
// - REGISTER sends a snapshot of a written variable at once (id -1, the last writer as source,
//   the last write's time stamp), on every REGISTER; an unwritten variable sends nothing until
//   its first write.
// - Wildcard filters match the variable name and the writer (the last writer for existing
//   variables, the first writer for new ones at their first write). WILDCARD_UNREGISTER removes
//   the matching subscriptions and, unlike the reference DB (spec 5.5 allows it), the identical
//   filter too.
// - Delivery is synchronous and deterministic: a message is in the subscribers' inboxes when
//   notify() returns, in posting order. Time is the bus clock x warp (skew 0).
// - No DB_* variables are published (apps under test do not need them).
// - Thread-safe; on-mail callbacks run on the posting thread with no lock held.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "moos/clock.hpp"
#include "moos/comms.hpp"
#include "moos/message.hpp"

namespace moos {

class BusClient;
struct BusCore;

class InProcessBus {
 public:
  struct Options {
    std::string community = "#1";  ///< the reference DB's default community (spec 5.11)
    double time_warp = 1.0;        ///< 0 < W <= 400 (spec 0.3)
  };

  /// `clock` must outlive the bus and every client (usually a ManualClock).
  explicit InProcessBus(Clock& clock);
  InProcessBus(Clock& clock, Options options);
  ~InProcessBus();
  InProcessBus(const InProcessBus&) = delete;
  InProcessBus& operator=(const InProcessBus&) = delete;

  /// A new, connected client. nullptr if the name is empty or already connected (a real DB
  /// would POISON the second one, spec 1.6).
  std::unique_ptr<BusClient> connect(const std::string& name);

  Clock& clock() const;
  double time_warp() const;
  double moos_time() const;
  const std::string& community() const;

  /// Every accepted NOTIFY, in order, as stored (community filled in).
  std::vector<Message> postings() const;
  /// Accepted NOTIFYs of one variable, in order.
  std::vector<Message> postings_of(const std::string& var) const;
  void clear_postings();
  /// The variable as a REGISTER snapshot would show it; nullopt if never written.
  std::optional<Message> latest(const std::string& var) const;
  /// Connected client names, sorted.
  std::vector<std::string> client_names() const;
  /// Notes about dropped messages (type mismatches), oldest first.
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
  std::vector<Message> fetch() override;

  /// As if the TCP connection dropped: the bus forgets this client's subscriptions, filters and
  /// undelivered mail; posts fail until simulate_reconnect().
  void simulate_disconnect();
  /// A new handshake: re-sends every remembered subscription, counts a connection and runs the
  /// on-connect callback. False if the name was taken meanwhile.
  bool simulate_reconnect();

 protected:
  bool transmit(Message msg) override;

 private:
  friend class InProcessBus;
  BusClient(std::shared_ptr<BusCore> core, std::string name);

  std::shared_ptr<BusCore> core_;
};

}  // namespace moos
