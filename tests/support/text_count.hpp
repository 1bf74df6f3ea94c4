#pragma once
// Counting a fragment in a program's output, shared by the process tests.
#include <cstddef>
#include <string>

namespace test_support {

/// Occurrences of `fragment` in `text`, overlapping ones included.
inline std::size_t count_of(const std::string& text, const std::string& fragment) {
  std::size_t n = 0;
  for (auto at = text.find(fragment); at != std::string::npos; at = text.find(fragment, at + 1))
    ++n;
  return n;
}

}  // namespace test_support
