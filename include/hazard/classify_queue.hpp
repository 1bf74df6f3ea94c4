#pragma once
// A vehicle's queue of decided, not yet released classification answers (rulings D8, D10).
//
// Contract: pop() returns entries by (top first, newest top first), then by priority (highest
// first), then first come first served. The order is an explicit (class, priority, sequence)
// key, not the original's priority minus a growing fraction (N9). clear() hands back every
// pending entry (its credit is returned by the caller). O(log n) push and pop.

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "hazard/hazard_field.hpp"

namespace hazard {

/// One classification credit: a detection of one object by one vehicle (D7).
struct Credit {
  std::uint32_t pass = 0;    ///< the detection's pass number (dice key)
  double heading_deg = 0.0;  ///< the vehicle's heading at that detection (aspect)
};

/// A decided answer waiting for release.
struct PendingAnswer {
  ObjectId object = 0;
  ObjectType reported = ObjectType::kBenign;  ///< the perceived type
  bool aspect_affected = false;  ///< wrong only because of aspect degradation (pink cue)
  Credit credit;                 ///< returned if the entry is cleared
};

class ClassifyQueue {
 public:
  void push(const PendingAnswer& answer, double priority, bool top);
  std::optional<PendingAnswer> pop();
  /// Removes and returns every pending entry, in release order.
  std::vector<PendingAnswer> clear();
  bool empty() const { return entries_.empty(); }
  std::size_t size() const { return entries_.size(); }

 private:
  struct Key {
    bool top;
    double priority;
    std::uint64_t sequence;
  };
  struct Order {
    bool operator()(const Key& a, const Key& b) const {
      if (a.top != b.top) return a.top;                               // top entries first
      if (a.top) return a.sequence > b.sequence;                      // newest top first
      if (a.priority != b.priority) return a.priority > b.priority;   // highest priority first
      return a.sequence < b.sequence;                                 // then FIFO
    }
  };
  std::map<Key, PendingAnswer, Order> entries_;
  std::uint64_t next_sequence_ = 0;
};

}  // namespace hazard
