#pragma once
// The result of parsing one message: the typed value, or the reason it was rejected (the field
// and value at fault). The base layer's result type under the name the message parsers use.

#include "base/result.hpp"

namespace hazard {

template <class T>
using Parsed = base::Result<T>;

}  // namespace hazard
