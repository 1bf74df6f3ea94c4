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
// Pure: no clock, no I/O.

#include <cstddef>
#include <cstdint>
#include <deque>
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
  /// Drops the oldest mail of the busiest source until the bounds hold; returns the count.
  std::size_t enforce_bounds();
  /// The most each source may hand over in one take() of an over-budget backlog.
  std::size_t share_per_source() const;

  std::size_t per_iteration_;
  std::size_t max_messages_;
  std::size_t max_bytes_;
  std::deque<moos::Message> mail_;
  std::size_t bytes_ = 0;
};

}  // namespace ufld_hazard_sensor
