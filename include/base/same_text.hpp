#pragma once
// a == b for short texts without a library call: names, keys, communities and vehicle types,
// compared for every message the bus, the store and the node report writer handle.

#include <cstdint>
#include <cstring>
#include <string_view>

namespace base {

namespace detail {
template <typename Word>
Word load_word(const char* p) {
  Word w;
  std::memcpy(&w, p, sizeof w);  // one load: no alignment needed
  return w;
}
template <typename Word>
bool same_words_at_ends(const char* a, const char* b, std::size_t n) {
  return load_word<Word>(a) == load_word<Word>(b) &&
         load_word<Word>(a + n - sizeof(Word)) == load_word<Word>(b + n - sizeof(Word));
}
}  // namespace detail

/// a == b, without a library call for texts of at most 32 bytes. Words that may overlap cover
/// them; nothing beyond the texts is read.
inline bool same_text(std::string_view a, std::string_view b) {
  const std::size_t n = a.size();
  if (n != b.size()) return false;
  const char* x = a.data();
  const char* y = b.data();
  using detail::same_words_at_ends;
  if (n >= 8) {
    if (n <= 16) return same_words_at_ends<std::uint64_t>(x, y, n);
    if (n <= 32)  // the first 16 bytes and the last 16
      return same_words_at_ends<std::uint64_t>(x, y, 16) &&
             same_words_at_ends<std::uint64_t>(x + n - 16, y + n - 16, 16);
    return std::memcmp(x, y, n) == 0;
  }
  if (n >= 4) return same_words_at_ends<std::uint32_t>(x, y, n);
  // 0 to 3 bytes: the first, middle and last cover them.
  return n == 0 || (x[0] == y[0] && x[n / 2] == y[n / 2] && x[n - 1] == y[n - 1]);
}

}  // namespace base
