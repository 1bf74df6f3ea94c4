#pragma once
// The one result type of a fallible function in the base, hazard and mission layers
// (docs/architecture.md "Error convention"): the value, or the reason there is none.
//
// The reason is a complete phrase that names the place at fault as far as the function knows
// it: a parser names the field and the value ("field 'x' value 'nan' is not a number"), a file
// reader the path. The caller adds what only it knows (file and line, the variable's name) in
// front. Nothing in these layers throws for bad input.

#include <optional>
#include <string>
#include <utility>

namespace base {

template <class T>
struct Result {
  std::optional<T> value;
  std::string error;  ///< names the place at fault; empty when `value` is set

  static Result ok(T v) { return Result{std::move(v), {}}; }
  static Result fail(std::string why) { return Result{std::nullopt, std::move(why)}; }
  explicit operator bool() const { return value.has_value(); }
};

/// A fallible action with no value (writing a file, checking a setting): done, or why not.
template <>
struct Result<void> {
  bool done = false;
  std::string error;  ///< names the place at fault; empty when `done`

  static Result ok() { return Result{true, {}}; }
  static Result fail(std::string why) { return Result{false, std::move(why)}; }
  explicit operator bool() const { return done; }
};

}  // namespace base
