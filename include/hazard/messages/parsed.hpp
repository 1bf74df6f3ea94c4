#pragma once
// The result of parsing one message: the typed value, or the reason it was rejected.

#include <optional>
#include <string>
#include <utility>

namespace hazard {

template <class T>
struct Parsed {
  std::optional<T> value;
  std::string error;  ///< names the field and value at fault; empty when `value` is set

  static Parsed ok(T v) { return Parsed{std::move(v), {}}; }
  static Parsed fail(std::string why) { return Parsed{std::nullopt, std::move(why)}; }
  explicit operator bool() const { return value.has_value(); }
};

}  // namespace hazard
