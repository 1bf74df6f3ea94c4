#pragma once
// The sensor's mail between fetch and the engine: a bounded backlog handled with a
// per-iteration budget, shared fairly among the mail's sources (the posting clients).
//
// Contract:
// - add() appends mail in arrival order. Beyond kMaxBacklogMessages or kMaxBacklogBytes the
//   OLDEST mail of the source holding the most is dropped (and counted), so one flooding client
//   loses its own oldest mail, never another client's request.
// - take() hands over the mail to handle now. While the backlog holds at most
//   `per_iteration` messages (every normal mission: a 100-vehicle mission brings a few
//   hundred per iteration), that is all of it, in arrival order: exactly what the engine got
//   before there was a backlog. Above it (a flood), `per_iteration` messages: each source
//   gets the same share (a source with less gets all it has), in arrival order, each source's
//   mail in the order it was posted; the rest waits for the next take(). A request from a
//   well-behaved client therefore waits at most one iteration behind a flood, never behind
//   all of it. Why not "requests first": the engine's outcome depends on the order of a
//   vehicle's node reports and requests (a sensor request uses the last position), and its
//   random draws are shared by all vehicles, so reordering would change normal missions.
// Cost: add() and take() cost what they hand over or drop, not what the backlog holds: each
// source's messages and bytes are counted as they come and go, and a take() or a drop stops
// scanning once it has what it needs (a sensor that falls behind must not fall further behind
// because every iteration re-read a full backlog).
// Pure: no clock, no I/O.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <unordered_map>
#include <vector>

#include "moos/message.hpp"

namespace ufld_hazard_sensor {

/// Messages handed to the engine per iteration while a backlog exists.
inline constexpr std::size_t kMailPerIteration = 2000;
/// The backlog's bounds (those of the client's inbox, moos/tcp_client.hpp).
inline constexpr std::size_t kMaxBacklogMessages = 65536;
inline constexpr std::size_t kMaxBacklogBytes = std::size_t{64} * 1024 * 1024;

class MailBacklog {
 public:
  explicit MailBacklog(std::size_t per_iteration = kMailPerIteration,
                       std::size_t max_messages = kMaxBacklogMessages,
                       std::size_t max_bytes = kMaxBacklogBytes);

  /// Appends `mail`; returns how many messages the bounds dropped.
  std::size_t add(std::vector<moos::Message> mail);
  /// The mail to handle now (see the contract); removed from the backlog.
  std::vector<moos::Message> take();

  /// Whether `incoming` messages would all be taken at once: an empty backlog and no more than
  /// `per_iteration` of them. The caller then hands them over itself, without queuing a copy.
  bool passes_through(std::size_t incoming) const {
    return mail_.empty() && incoming <= per_iteration_;
  }
  bool empty() const { return mail_.empty(); }
  std::size_t size() const { return mail_.size(); }
  std::size_t bytes() const { return bytes_; }

 private:
  struct Held {
    std::size_t messages = 0;
    std::size_t bytes = 0;
  };
  /// Drops the oldest mail of the busiest source until the bounds hold; returns the count.
  std::size_t enforce_bounds();
  bool over_bounds() const {
    return mail_.size() > max_messages_ || (bytes_ > max_bytes_ && mail_.size() > 1);
  }
  /// The source holding the most (bytes when `by_bytes`, else messages); of equals, the
  /// smallest name.
  std::string busiest_source(bool by_bytes) const;
  /// The most each source may hand over in one take() of an over-budget backlog.
  std::size_t share_per_source() const;
  /// Counts `m` out of the backlog's totals.
  void forget(const moos::Message& m);
  /// Scans the backlog from the oldest message; `pick(m)` says whether m leaves (it is then
  /// counted out and handed to `leave`), `done()` when the scan may stop. The messages kept
  /// stay in their order.
  template <typename Pick, typename Leave, typename Done>
  void remove_in_order(Pick pick, Leave leave, Done done);

  std::size_t per_iteration_;
  std::size_t max_messages_;
  std::size_t max_bytes_;
  std::deque<moos::Message> mail_;
  std::size_t bytes_ = 0;
  std::unordered_map<std::string, Held> held_;  ///< by source
};

}  // namespace ufld_hazard_sensor
