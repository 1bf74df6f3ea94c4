#include "hazard/classify_queue.hpp"

namespace hazard {

void ClassifyQueue::push(const PendingAnswer& answer, double priority, bool top) {
  entries_.emplace(Key{top, priority, next_sequence_++}, answer);
}

std::optional<PendingAnswer> ClassifyQueue::pop() {
  if (entries_.empty()) return std::nullopt;
  const auto first = entries_.begin();
  PendingAnswer answer = first->second;
  entries_.erase(first);
  return answer;
}

std::vector<PendingAnswer> ClassifyQueue::clear() {
  std::vector<PendingAnswer> out;
  out.reserve(entries_.size());
  for (const auto& [key, answer] : entries_) out.push_back(answer);
  entries_.clear();
  return out;
}

}  // namespace hazard
