#include "hazard/classify_queue.hpp"

namespace hazard {

void ClassifyQueue::push(const PendingAnswer& answer, double priority, bool top) {
  if (top) {
    tops_.push_back(answer);
  } else {
    buckets_[priority + 0.0].push_back(answer);  // + 0.0: -0 files under +0
  }
  ++size_;
}

std::optional<PendingAnswer> ClassifyQueue::pop() {
  if (size_ == 0) return std::nullopt;
  --size_;
  if (!tops_.empty()) {  // newest top first (D8)
    PendingAnswer answer = tops_.back();
    tops_.pop_back();
    return answer;
  }
  const auto best = buckets_.begin();  // highest priority; FIFO inside the bucket
  PendingAnswer answer = best->second.front();
  best->second.pop_front();
  if (best->second.empty()) buckets_.erase(best);
  return answer;
}

std::vector<PendingAnswer> ClassifyQueue::clear() {
  std::vector<PendingAnswer> out;
  out.reserve(size_);
  out.insert(out.end(), tops_.rbegin(), tops_.rend());
  for (const auto& [priority, bucket] : buckets_) out.insert(out.end(), bucket.begin(), bucket.end());
  tops_.clear();
  buckets_.clear();
  size_ = 0;
  return out;
}

}  // namespace hazard
