#pragma once
// The MOOS side's half of the viewer: the retained state and the event hub under one lock, so
// that a page connecting now gets the hello, the retained state and then every later event,
// without a gap or a repeat (docs/viewer.md, "Retained state").

#include <functional>
#include <string>

#include "event_hub.hpp"
#include "retained_state.hpp"

namespace web_viewer {

struct FeedLimits {
  RetentionLimits retention;
  std::size_t max_clients = 8;
  std::size_t max_queued = 20000;  ///< live events queued per client before it is dropped
};

class LiveFeed {
 public:
  /// `hello` builds the hello's JSON for a page that connects (called on a server thread).
  LiveFeed(const FeedLimits& limits, std::function<std::string()> hello);

  /// Keeps `mail` in the retained state and sends it to every page.
  void on_mail(const Mail& mail);
  /// Sends a clock event to every page; the retained state's durations run out by this time.
  void on_clock(double time_s, double warp);

  EventHub& hub() { return hub_; }
  const EventHub& hub() const { return hub_; }
  /// Postings retained now; postings refused by a bound.
  std::size_t retained() const;
  std::uint64_t refused() const;

 private:
  std::vector<std::string> first_events();
  std::function<std::string()> hello_;
  RetainedState state_;  // guarded by the hub's lock (publish's update, first_events)
  EventHub hub_;
  std::size_t retained_ = 0;  // copies of the state's counters, read without the lock
  std::uint64_t refused_ = 0;
};

}  // namespace web_viewer
