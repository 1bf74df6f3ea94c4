// base::same_text, the comparison of names and keys that the bus, the store and the node report
// writer make for every message: it must agree with std::string's == for every length and
// every differing byte.
#include <gtest/gtest.h>

#include <string>

#include "base/same_text.hpp"

namespace base {
namespace {

std::string text_of(std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s.push_back(static_cast<char>('A' + i % 26));
  return s;
}

TEST(SameText, AgreesWithEqualityForEveryLengthAndEveryDifferingByte) {
  for (std::size_t n = 0; n <= 70; ++n) {
    const std::string a = text_of(n);
    EXPECT_TRUE(same_text(a, std::string(a))) << n;
    for (std::size_t i = 0; i < n; ++i) {
      std::string b = a;
      b[i] = static_cast<char>(b[i] ^ 0x20);
      EXPECT_FALSE(same_text(a, b)) << n << " " << i;
    }
    EXPECT_FALSE(same_text(a, a + "x")) << n;
    EXPECT_FALSE(same_text(a + "x", a)) << n;
  }
}

TEST(SameText, ComparesOnlyTheTextsBytes) {
  // Texts inside longer buffers: the bytes around them differ and must not count.
  const std::string left = "xxNODE_REPORTyy";
  const std::string right = "zzNODE_REPORTww";
  EXPECT_TRUE(same_text(std::string_view(left).substr(2, 11), std::string_view(right).substr(2, 11)));
  EXPECT_TRUE(same_text(std::string_view(left).substr(2, 3), std::string_view(right).substr(2, 3)));
  EXPECT_TRUE(same_text(std::string(1, '\0'), std::string(1, '\0')));
  EXPECT_FALSE(same_text(std::string(5, '\0'), std::string("\0\0\0\0\1", 5)));
}

}  // namespace
}  // namespace base
