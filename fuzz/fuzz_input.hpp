#pragma once
// Helpers shared by the fuzz targets: the raw input as text, its lines, its arguments.
// Every target is a `LLVMFuzzerTestOneInput` that must never crash, hang, leak or trip a
// sanitizer on any input; a finding is a bug in the code under test, not in the target.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// The lines of `text` (split on '\n', the newline dropped; a last line without one is kept).
inline std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    lines.push_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return lines;
}

/// An argument list: one argument per NUL-separated field of `text`.
inline std::vector<std::string> arguments_of(std::string_view text) {
  std::vector<std::string> args;
  while (true) {
    const std::size_t end = text.find('\0');
    args.emplace_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return args;
}

/// Parses `text`; when accepted, formats the value and parses that too (what we write must read
/// back without a crash). Works for every parser returning hazard::Parsed<T>.
template <class Parse, class Format>
void parse_and_reread(std::string_view text, Parse parse, Format format) {
  const auto parsed = parse(text);
  if (parsed.value) (void)parse(format(*parsed.value));
}

}  // namespace fuzz
