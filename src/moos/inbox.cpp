// Contract in include/moos/inbox.hpp.

#include "moos/inbox.hpp"

#include <algorithm>
#include <utility>

namespace moos {

std::size_t Inbox::kept_bytes() const {
  std::size_t bytes = 0;
  for (std::size_t i = size_; i < slots_.size(); ++i) bytes += storage_bytes(slots_[i]);
  return bytes;
}

void Inbox::push_trade(Message& msg) {
  if (size_ < slots_.size()) {
    swap(slots_[size_], msg);
  } else {
    slots_.push_back(std::move(msg));
    msg = Message{};
  }
  ++size_;
}

void Inbox::drop_oldest(std::size_t n) {
  n = std::min(n, size_);
  const auto first = slots_.begin();
  std::rotate(first, first + static_cast<std::ptrdiff_t>(n),
              first + static_cast<std::ptrdiff_t>(size_));
  size_ -= n;
}

void Inbox::let_go(Message& read) {
  Message empty;  // swapped, not assigned: assigning small strings keeps the large storage
  swap(read, empty);
}

void Inbox::settle_kept(std::vector<Message>& mail, std::size_t handed) {
  if (slots_.size() > kMaxKept) slots_.resize(kMaxKept);
  // Kept: as many messages as the mail handed over now, the likely size of the next; the rest
  // of the kept ones go (moving them back at every call would cost more than they save).
  const std::size_t keep = std::min(std::max(slots_.size(), handed), kMaxKept);
  for (std::size_t i = handed; i < mail.size() && slots_.size() < keep; ++i)
    if (storage_bytes(mail[i]) <= kMaxKeptBytes) slots_.push_back(std::move(mail[i]));
  mail.resize(handed);
}

}  // namespace moos
