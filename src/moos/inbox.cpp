// Contract in include/moos/inbox.hpp.

#include "moos/inbox.hpp"

#include <algorithm>
#include <utility>

namespace moos {

std::size_t Inbox::storage_bytes(const Message& msg) {
  return msg.source.capacity() + msg.source_aux.capacity() + msg.community.capacity() +
         msg.key.capacity() + msg.sval.capacity();
}

std::size_t Inbox::kept_bytes() const {
  std::size_t bytes = 0;
  for (std::size_t i = size_; i < slots_.size(); ++i) bytes += storage_bytes(slots_[i]);
  return bytes;
}

namespace {
void copy_string(std::string& to, const std::string& from) {
  if (from.empty()) {
    to.clear();
  } else {
    to = from;
  }
}

/// copy_string() unless `to` holds `from` already: a key, a source name or a community is
/// mostly what the kept message held, and comparing costs less than assigning.
void copy_if_changed(std::string& to, const std::string& from) {
  if (to != from) copy_string(to, from);
}

void move_string(std::string& to, std::string& from) {
  if (from.empty()) {
    to.clear();
  } else {
    to = std::move(from);
  }
}

// Field by field: a field added to Message must be added here too.
static_assert(sizeof(Message) == 8 + 5 * sizeof(std::string) + 3 * sizeof(double),
              "Inbox copies Message field by field");

void copy_scalars(Message& to, const Message& from) {
  to.id = from.id;
  to.type = from.type;
  to.data_type = from.data_type;
  to.time = from.time;
  to.dval = from.dval;
  to.dval2 = from.dval2;
}
}  // namespace

void Inbox::assign_copy(Message& to, const Message& from) {
  copy_scalars(to, from);
  copy_if_changed(to.source, from.source);
  copy_string(to.source_aux, from.source_aux);
  copy_if_changed(to.community, from.community);
  copy_if_changed(to.key, from.key);
  copy_string(to.sval, from.sval);  // a value mostly changes
}

void Inbox::assign_moved(Message& to, Message& from) {
  copy_scalars(to, from);
  move_string(to.source, from.source);
  move_string(to.source_aux, from.source_aux);
  // Mostly short and unchanged; moving a short string is a copy.
  copy_if_changed(to.community, from.community);
  copy_if_changed(to.key, from.key);
  move_string(to.sval, from.sval);
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

void Inbox::hand_over(std::vector<Message>& mail) {
  const auto large = [](const Message& m) { return storage_bytes(m) > kMaxKeptBytes; };
  for (Message& read : mail) {
    if (!large(read)) continue;
    Message empty;  // swapped, not assigned: assigning small strings keeps the large storage
    swap(read, empty);
  }
  mail.swap(slots_);  // `mail`: the mail, then the kept messages; slots_: the read ones
  if (slots_.size() > kMaxKept) slots_.resize(kMaxKept);
  // Kept: as many messages as the mail handed over now, the likely size of the next; the rest
  // of the kept ones go (moving them back at every call would cost more than they save).
  const std::size_t keep = std::min(std::max(slots_.size(), size_), kMaxKept);
  for (std::size_t i = size_; i < mail.size() && slots_.size() < keep; ++i)
    if (!large(mail[i])) slots_.push_back(std::move(mail[i]));
  mail.resize(size_);
  size_ = 0;
}

}  // namespace moos
