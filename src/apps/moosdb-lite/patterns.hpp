#pragma once
// Checks that the server applies on top of libmoos's wildcard string parser
// (moos/wildcard.hpp; ../shared/spec/moos-wire-protocol.md 5.5).
//
// Contract:
// - wildcard_spec_problem(): libmoos reads `AppPattern=<a>,VarPattern=<v>,Interval=<x>` with
//   commas or blanks between items (pymoos2 uses blanks, spec 9.2) and, like the reference DB,
//   silently skips what it cannot read. The server refuses such a registration instead, with
//   a reason naming the item: an item without `=`, an unknown key (keys are case-sensitive),
//   or an interval that is not a finite number >= 0. Missing items are fine (a missing
//   pattern is the empty pattern, a missing interval is 0), as in the reference DB.
// - parse_finite_number(): a finite decimal number that is the whole of `text`.

#include <optional>
#include <string>
#include <string_view>

namespace moosdb_lite {

/// Why a WILDCARD_REGISTER / WILDCARD_UNREGISTER string must be refused, or nullopt.
std::optional<std::string> wildcard_spec_problem(std::string_view text);

/// Parses a finite decimal number made of the whole of `text` (no blanks), or nullopt.
std::optional<double> parse_finite_number(std::string_view text);

}  // namespace moosdb_lite
