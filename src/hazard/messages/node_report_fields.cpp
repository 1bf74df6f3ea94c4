#include "hazard/messages/node_report_fields.hpp"

#include <cstddef>
#include <cstdint>

#include "base/key_value_reader.hpp"
#include "base/text.hpp"

namespace hazard {

namespace {

namespace kv = base::detail::key_value;

// A key of up to eight bytes as one integer, each byte with bit 5 set. Compared with a key
// spelled in lower-case letters this is base::iequals: (b | 0x20) is a lower-case letter only
// for that letter in either case. No lowered copy, no compare per byte.
constexpr std::uint64_t folded(std::string_view key) {
  std::uint64_t v = 0;
  for (std::size_t i = key.size(); i-- > 0;)
    v = v << 8 | (static_cast<unsigned char>(key[i]) | 0x20U);
  return v;
}

constexpr std::size_t kLongestKey = 7;  // HEADING

// The slot of a key, or nullptr; the length leaves a few candidates, compared whole.
NodeReportField* slot_for(NodeReportFields& f, std::string_view key) {
  if (key.empty() || key.size() > kLongestKey) return nullptr;
  const std::uint64_t k = folded(key);
  switch (key.size()) {
    case 1:
      return k == folded("x") ? &f.x : k == folded("y") ? &f.y : nullptr;
    case 3:
      return k == folded("spd")   ? &f.spd
             : k == folded("hdg") ? &f.hdg
             : k == folded("lat") ? &f.lat
             : k == folded("lon") ? &f.lon
                                  : nullptr;
    case 4:
      return k == folded("name")   ? &f.name
             : k == folded("time") ? &f.time
             : k == folded("type") ? &f.type
                                   : nullptr;
    case 5:
      return k == folded("speed") ? &f.speed : nullptr;
    case 7:
      return k == folded("heading") ? &f.heading : nullptr;
    default:
      return nullptr;
  }
}

// The end of the piece that starts at `start`, its first '=' at `value - 1`: the next ',' outside
// {...}. Runs without a brace (nearly all) are scanned here; a brace sends the piece through the
// generic rule.
std::size_t value_end(std::string_view all, std::size_t start, std::size_t value) {
  const std::size_t n = all.size();
  std::size_t i = value;
  while (true) {
    i = kv::run_end(all.data(), i, n, ',');
    if (i == n || all[i] == ',') return i;
    if (all[i] == '{') {
      std::size_t equals = 0;
      return kv::piece_end(all, start, ',', /*braces=*/true, equals);
    }
    ++i;  // a later '=' is part of the value
  }
}

// A number value that is a plain decimal ending its piece (at ',' or the end): read into `field`
// where it stands; its end, or 0 when it is anything else (a blank, an exponent, a brace).
std::size_t read_number_value(std::string_view all, std::size_t value, NodeReportField& field) {
  double number = 0.0;
  const std::size_t length = base::read_plain_decimal(all.substr(value), number);
  const std::size_t end = value + length;
  if (length == 0 || (end < all.size() && all[end] != ',')) return 0;
  field = NodeReportField{all.substr(value, length), true, true, number};
  return end;
}

}  // namespace

NodeReportFields::NodeReportFields(std::string_view all, bool pose_only) {
  const char* const text = all.data();
  const std::size_t n = all.size();
  std::size_t i = 0;
  while (i < n) {  // (an empty last piece, after a trailing ',', holds nothing)
    const std::size_t start = i;
    i = kv::run_end(text, i, n, ',');
    if (i == n) break;  // the last piece has no '=': no value
    if (text[i] == ',') {  // nor has this one
      ++i;
      continue;
    }
    if (text[i] == '{') {  // a key with a brace is none of ours: on past its piece
      std::size_t equals = 0;
      i = kv::piece_end(all, start, ',', /*braces=*/true, equals) + 1;
      continue;
    }
    NodeReportField* const slot = slot_for(*this, base::trim(all.substr(start, i - start)));
    const std::size_t value = i + 1;
    const bool number = slot && slot != &name && slot != &type &&
                        !(pose_only && (slot == &lat || slot == &lon || slot == &time));
    if (number) {
      if (const std::size_t end = read_number_value(all, value, *slot)) {
        i = end + 1;
        continue;
      }
    }
    const std::size_t end = value_end(all, start, value);
    if (slot) *slot = NodeReportField{base::trim(all.substr(value, end - value)), true, false, 0.0};
    i = end + 1;
  }
}

}  // namespace hazard
