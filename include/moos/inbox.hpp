#pragma once
// A client's inbox whose messages keep their strings' storage after they are read. New mail is
// written over a kept message (a copy-assignment, or a trade with a decoded one) instead of
// being built anew, so a client whose mail is as large as before allocates nothing: the
// in-process bus and TcpClient hold their mail in one, and Comms::fetch_into() hands the
// caller's read mail back to it.
//
// Bounded: at most kMaxKept messages are kept, and a read message whose strings hold more than
// kMaxKeptBytes is let go (a rare large value does not stay behind). Not thread-safe: the owner
// guards it with its inbox lock.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "base/same_text.hpp"
#include "moos/message.hpp"

namespace moos {

class Inbox {
 public:
  /// Messages kept at most after hand_over(): as many as the mail it handed over or the read
  /// mail it took back, whichever is more, up to this bound.
  static constexpr std::size_t kMaxKept = 4096;
  /// Storage a read message's strings may hold in all to be kept, bytes.
  static constexpr std::size_t kMaxKeptBytes = 4096;

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }
  const Message& operator[](std::size_t i) const { return slots_[i]; }
  /// Read messages kept for their storage.
  std::size_t kept() const { return slots_.size() - size_; }

  /// Appends a copy of `msg`, written over a kept message when there is one.
  void push_copy(const Message& msg) {
    if (size_ < slots_.size()) {
      assign_copy(slots_[size_], msg);
    } else {
      slots_.push_back(msg);
    }
    ++size_;
  }
  /// Appends `msg`'s contents; `msg` gets a kept message in exchange (empty if none was kept).
  void push_trade(Message& msg);
  /// Appends `msg`'s contents, moved: cheaper than push_trade() (no string swaps); `msg` is left
  /// valid with unspecified contents (with libstdc++, a kept message's string storage).
  void push_moved(Message& msg) {
    if (size_ < slots_.size()) {
      assign_moved(slots_[size_], msg);
    } else {
      slots_.push_back(std::move(msg));
    }
    ++size_;
  }
  /// Drops the `n` oldest messages (at most all), keeping their storage.
  void drop_oldest(std::size_t n);
  /// Drops every message, keeping their storage.
  void clear() { size_ = 0; }
  /// Replaces `mail`'s contents with the inbox's messages, oldest first, and keeps `mail`'s
  /// old messages (read) for their storage; the inbox is then empty. Inline: an app's every
  /// cycle with mail calls it.
  void hand_over(std::vector<Message>& mail) {
    for (Message& read : mail)
      if (storage_bytes(read) > kMaxKeptBytes) let_go(read);
    mail.swap(slots_);  // `mail`: the mail, then the kept messages; slots_: the read ones
    const std::size_t handed = size_;
    size_ = 0;
    // Mostly as many messages were read as are handed over now, and none was kept beyond them.
    if (mail.size() != handed || slots_.size() > kMaxKept) settle_kept(mail, handed);
  }

  /// The storage the kept messages' strings hold, bytes (a walk over them).
  std::size_t kept_bytes() const;
  /// The storage a message's strings hold, bytes (their capacities).
  static std::size_t storage_bytes(const Message& msg) {
    return msg.source.capacity() + msg.source_aux.capacity() + msg.community.capacity() +
           msg.key.capacity() + msg.sval.capacity();
  }

 private:
  /// Frees the storage of a read message too large to keep.
  static void let_go(Message& read);
  /// hand_over() after the swap, when `mail` holds kept messages behind the `handed` ones or
  /// too many were read: the bounds of what stays.
  void settle_kept(std::vector<Message>& mail, std::size_t handed);

  // Field by field (inline: they run for every message of every reader); an empty string is
  // cleared, not assigned (a library call).
  static void assign_copy(Message& to, const Message& from) {
    copy_scalars(to, from);
    copy_if_changed(to.source, from.source);
    copy_string(to.source_aux, from.source_aux);
    copy_if_changed(to.community, from.community);
    copy_if_changed(to.key, from.key);
    copy_string(to.sval, from.sval);  // a value mostly changes
  }
  static void assign_moved(Message& to, Message& from) {
    copy_scalars(to, from);
    // Mostly short and unchanged (moving a short string is a copy), and a poster that keeps its
    // message between postings (Comms) keeps its name in it.
    copy_if_changed(to.source, from.source);
    move_string(to.source_aux, from.source_aux);
    copy_if_changed(to.community, from.community);
    copy_if_changed(to.key, from.key);
    move_string(to.sval, from.sval);
  }
  static void copy_scalars(Message& to, const Message& from) {
    to.id = from.id;
    to.type = from.type;
    to.data_type = from.data_type;
    to.time = from.time;
    to.dval = from.dval;
    to.dval2 = from.dval2;
  }
  static void copy_string(std::string& to, const std::string& from) {
    if (from.empty()) {
      to.clear();
    } else {
      to = from;
    }
  }
  /// copy_string() unless `to` holds `from` already: a key, a source name or a community is
  /// mostly what the kept message held, and comparing costs less than assigning.
  static void copy_if_changed(std::string& to, const std::string& from) {
    if (!base::same_text(to, from)) copy_string(to, from);
  }
  static void move_string(std::string& to, std::string& from) {
    if (from.empty()) {
      to.clear();
    } else {
      to = std::move(from);
    }
  }
  // Field by field: a field added to Message must be added here too.
  static_assert(sizeof(Message) == 8 + 5 * sizeof(std::string) + 3 * sizeof(double),
                "Inbox copies Message field by field");

  std::vector<Message> slots_;  ///< [0, size_): the mail, oldest first; the rest kept
  std::size_t size_ = 0;
};

}  // namespace moos
