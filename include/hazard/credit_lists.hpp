#pragma once
// CreditLists: one vehicle's unused classification credits (differences.md "Credits"), a list per
// object, all in one pool.
//
// Contract: a list (CreditList, kept in the object's record) holds credits in pass order, oldest
// first. push_back appends a new detection's credit (its pass is above every pass in the list);
// pop_front takes the oldest; insert_in_pass_order puts back a credit a clear returned. A taken
// credit's slot is reused by the next credit granted, so the pool holds at most as many slots as
// the vehicle ever held credits at one time (every unused credit is kept, differences.md
// "Credits"). Data structure: a singly linked list per object through a std::deque of 16-byte nodes
// {pass, next, heading} (the link fills the padding a Credit has anyway). Memory: 16 bytes per
// credit plus one 512-byte deque block of slack per vehicle; no allocation per object, so nothing
// is left behind in the allocator as lists grow (with a std::vector per object the soak's
// heap held 35 bytes more per credit added: its spare capacity and the smaller buffers freed).
// Costs: push_back, pop_front O(1); insert_in_pass_order and the walks O(list length), which
// kMaxCreditsPerObject bounds (plus the credits a clear returns).
// Slot ids are 32-bit: a vehicle holds at most kMaxCreditsPerObject (100) credits per object
// plus kMaxClassifyQueue returned ones, and a hazard file within kMaxInputFileBytes (512 MiB)
// holds fewer than 34 million objects (a line takes at least 16 bytes), so fewer than 2^32 - 1
// slots (kNone is the last id), long after memory has run out (16 bytes each).

#include <cstdint>
#include <deque>
#include <limits>
#include <vector>

#include "hazard/classify_queue.hpp"

namespace hazard {

/// One object's credits: where its list starts and ends in the vehicle's pool.
struct CreditList {
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t first = kNone;
  std::uint32_t last = kNone;
  std::uint32_t size = 0;

  bool empty() const { return size == 0; }
};

class CreditLists {
 public:
  /// Appends `credit`; its pass must be above the passes in `list` (a new detection).
  void push_back(CreditList& list, const Credit& credit);
  /// The oldest credit of a non-empty list.
  Credit front(const CreditList& list) const;
  /// Removes and returns the oldest credit of a non-empty list; its slot is reused.
  Credit pop_front(CreditList& list);
  /// Inserts `credit` before the first credit of a higher pass (a credit a clear returns).
  void insert_in_pass_order(CreditList& list, const Credit& credit);
  /// The credits of `list`, oldest first.
  std::vector<Credit> to_vector(const CreditList& list) const;

  /// Slots in the pool (credits held plus free slots) and free slots, for the invariants.
  std::size_t slots() const { return nodes_.size(); }
  std::size_t free_slots() const;

 private:
  struct Node {
    std::uint32_t pass = 0;
    std::uint32_t next = CreditList::kNone;
    double heading_deg = 0.0;
  };
  std::uint32_t new_node(const Credit& credit);

  std::deque<Node> nodes_;
  std::uint32_t free_ = CreditList::kNone;  ///< first free slot; linked through `next`
};

}  // namespace hazard
