#pragma once
// The pieces of a `key=value` list one at a time, without a vector: the splitting rule of
// base::split_key_values (text.hpp), which is built on it. Defined here, in the header, because
// the hot parsers (NODE_REPORT, ten a second per vehicle) call next() for every piece: inlined,
// the piece stays in registers; called, it went through memory and each read of it back
// stalled (a store forwarded to a wider load).

#include <cstddef>
#include <string_view>

#include "base/text.hpp"

namespace base {

namespace detail::key_value {

// Bytes that end a run of a piece's ordinary bytes: '=', '{' and, in the table for the usual
// separator, ','. A table, so the scan costs a load and a test per byte.
struct PieceStops {
  bool stop[256];
  constexpr explicit PieceStops(char separator) : stop() {
    stop[static_cast<unsigned char>('=')] = true;
    stop[static_cast<unsigned char>('{')] = true;
    stop[static_cast<unsigned char>(separator)] = true;
  }
};
inline constexpr PieceStops kCommaStops(',');
inline constexpr PieceStops kStops('=');  // no separator in it: compared byte by byte

inline bool stops(const PieceStops& table, char c) {
  return table.stop[static_cast<unsigned char>(c)];
}

// The end of the run of ordinary bytes from `i`: at a separator, '=', '{' or `n`.
inline std::size_t run_end(const char* text, std::size_t i, std::size_t n, char separator) {
  if (separator == ',') {
    // Four bytes per bounds check: most runs are a key or a number of a few bytes.
    for (; i + 4 <= n; i += 4) {
      if (stops(kCommaStops, text[i])) return i;
      if (stops(kCommaStops, text[i + 1])) return i + 1;
      if (stops(kCommaStops, text[i + 2])) return i + 2;
      if (stops(kCommaStops, text[i + 3])) return i + 3;
    }
    while (i < n && !stops(kCommaStops, text[i])) ++i;
  } else {
    while (i < n && text[i] != separator && !stops(kStops, text[i])) ++i;
  }
  return i;
}

// The end of the piece that starts at `start`: the next separator outside {...} (braces count
// only when asked; an unmatched '}' is an ordinary byte, an unclosed '{' runs to the end).
// Also the first '=' of the piece, wherever it is (npos if none), found in the same pass.
inline std::size_t piece_end(std::string_view all, std::size_t start, char separator,
                             bool braces, std::size_t& equals) {
  const char* const text = all.data();
  const std::size_t n = all.size();
  std::size_t first_equals = std::string_view::npos;
  std::size_t i = start;
  while (true) {
    i = run_end(text, i, n, separator);
    if (i == n || text[i] == separator) break;
    if (text[i] == '=') {
      if (first_equals == std::string_view::npos) first_equals = i;
      ++i;
      continue;
    }
    if (!braces) {  // a '{' is an ordinary byte
      ++i;
      continue;
    }
    // A '{': on to the byte after its matching '}' (an '=' inside still counts as the first).
    int depth = 1;
    for (++i; i < n && depth > 0; ++i) {
      if (text[i] == '=' && first_equals == std::string_view::npos) first_equals = i;
      depth += text[i] == '{' ? 1 : text[i] == '}' ? -1 : 0;
    }
  }
  equals = first_equals;
  return i;
}

}  // namespace detail::key_value

/// The pieces split_key_values returns, one at a time and without a vector (hot parsers:
/// NODE_REPORT). `text` must outlive the reader and the views it hands out; `separator` is
/// none of `{`, `}` and `=`.
class KeyValueReader {
 public:
  explicit KeyValueReader(std::string_view text, char separator = ',',
                          bool respect_braces = false)
      : text_(text), separator_(separator), respect_braces_(respect_braces) {}

  /// The next piece into `kv`; false when none is left.
  bool next(KeyValue& kv) {
    const char* const text = text_.data();
    while (start_ <= text_.size()) {
      std::size_t equals = 0;
      const std::size_t end =
          detail::key_value::piece_end(text_, start_, separator_, respect_braces_, equals);
      const std::size_t start = start_;
      start_ = end + 1;
      // Views built from positions known to be in range (no substr checks).
      if (equals == std::string_view::npos) {
        const std::string_view piece = trim(std::string_view(text + start, end - start));
        if (piece.empty()) continue;
        kv = KeyValue{piece, {}, false};
      } else {
        kv = KeyValue{trim(std::string_view(text + start, equals - start)),
                      trim(std::string_view(text + equals + 1, end - equals - 1)), true};
      }
      return true;
    }
    return false;
  }

 private:
  std::string_view text_;
  char separator_;
  bool respect_braces_;
  std::size_t start_ = 0;
};

}  // namespace base
