#pragma once
// Short pieces of text appended to a string through a buffer on the stack.
//
// Why: a std::string append costs a call, a capacity check and a memcpy call however few bytes
// it carries; a swath polygon is twenty-odd pieces of one to eight bytes, posted for every
// vehicle every iteration. Here each piece is a store into the buffer, and the string grows
// once per buffer's worth. The text is the same as appending each piece in turn.

#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

#include "base/text.hpp"

namespace base {

class TextAppender {
 public:
  explicit TextAppender(std::string& out) : out_(out) {}
  ~TextAppender() { flush(); }
  TextAppender(const TextAppender&) = delete;
  TextAppender& operator=(const TextAppender&) = delete;

  void put(char c) {
    make_room(1);
    *end_++ = c;
  }
  void put(std::string_view text) {
    if (text.size() > kBufferBytes) {  // longer than the buffer: straight through
      flush();
      out_.append(text.data(), text.size());
      return;
    }
    make_room(text.size());
    std::memcpy(end_, text.data(), text.size());
    end_ += text.size();
  }
  /// FMT(v, d), as append_fmt writes it.
  void put_fmt(double value, int decimals) {
    make_room(kFastFmtMaxChars);
    if (char* const after = write_fmt_fast(end_, value, decimals)) {
      end_ = after;
      return;
    }
    flush();  // the rare value outside the fast path
    append_fmt(out_, value, decimals);
  }
  /// FMT(v, d), and in `read_back` the number it reads as (write_fmt_fast); false, with the text
  /// written all the same, for a value outside the fast path.
  bool put_fmt(double value, int decimals, double& read_back) {
    make_room(kFastFmtMaxChars);
    if (char* const after = write_fmt_fast(end_, value, decimals, read_back)) {
      end_ = after;
      return true;
    }
    flush();
    append_fmt(out_, value, decimals);
    return false;
  }
  /// `key` (such as ",x=") and FMT(value, decimals) after it: a field of a posting.
  void put_field(std::string_view key, double value, int decimals) {
    put(key);
    put_fmt(value, decimals);
  }
  /// The length of the text so far (the string's and the buffer's).
  std::size_t size() const { return out_.size() + static_cast<std::size_t>(end_ - buffer_); }
  /// Everything put so far is in the string (also done at destruction).
  void flush() {
    out_.append(buffer_, static_cast<std::size_t>(end_ - buffer_));
    end_ = buffer_;
  }

 private:
  static constexpr std::size_t kBufferBytes = 256;

  void make_room(std::size_t n) {
    if (static_cast<std::size_t>(buffer_ + kBufferBytes - end_) < n) flush();
  }

  std::string& out_;
  char buffer_[kBufferBytes];
  char* end_ = buffer_;
};

}  // namespace base
