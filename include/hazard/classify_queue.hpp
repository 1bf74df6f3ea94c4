#pragma once
// A vehicle's queue of decided, not yet released classification answers (differences.md D8, D10).
//
// Contract: pop() returns entries by (top first, newest top first), then by priority (highest
// first), then first come first served. The order is structural, not the original's priority
// minus a growing fraction (N9), and there is no sequence counter that could overflow: entries
// of one priority wait in one FIFO bucket, `top` entries on one stack. clear() hands back every
// pending entry in release order (its credit is returned by the caller).
// Data structure: a map from priority to a deque (buckets, highest first) and a vector (tops).
// push and pop cost O(log P) for P distinct priorities waiting (P is small: requests use a few
// priorities), O(1) per entry otherwise; 10 million equal-priority entries push and pop in well
// under a second (tests/hazard/numerics_queue_test.cpp). Memory: 32 bytes per entry.
// Rejected alternative: one ordered map keyed by (top, priority, sequence): a node allocation
// (about 80 bytes) per entry and a 64-bit counter to keep.

#include <cstdint>
#include <deque>
#include <functional>
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
  /// `priority` finite (the parser guarantees it); -0 and +0 are the same priority.
  void push(const PendingAnswer& answer, double priority, bool top);
  std::optional<PendingAnswer> pop();
  /// Removes and returns every pending entry, in release order.
  std::vector<PendingAnswer> clear();
  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

 private:
  std::vector<PendingAnswer> tops_;  ///< `top` entries, oldest first (popped from the back)
  std::map<double, std::deque<PendingAnswer>, std::greater<double>> buckets_;
  std::size_t size_ = 0;
};

}  // namespace hazard
