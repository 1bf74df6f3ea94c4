#pragma once
// A generated field for hazard_study (`--field`): gen_hazards' own options and generator
// (src/apps/gen_hazards), run in the process, one field per field seed.
//
// Contract:
// - `--field=OPTIONS`: gen_hazards' options as blank-separated words (no blank inside one):
//   --polygon (repeatable), --objects=N,TYPE (repeatable, at least one), --exp and the aspect
//   options, with gen_hazards' own ranges and messages (at most gen_hazards::kMaxTotalObjects
//   objects in all). --seed is refused (the field's seed is --field-seed) and so is --output
//   (the field stays in memory). Every refusal names --field and the word.
// - The field of seed N is the text `gen_hazards OPTIONS --seed=N` writes, byte for byte (its
//   header names the options and the seed), so a study's field can be written out and checked.
// - The hazard_file of every uFldHazardSensor and uFldHazardMetric block names it (field_name):
//   the text is served from memory (field_cache.hpp), no file is written.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "options.hpp"

namespace hazard_study {

/// Longest --field text: a few hundred polygons' worth.
inline constexpr std::size_t kMaxFieldText = 100000;

struct FieldSpec {
  gen_hazards::GeneratorConfig config;     ///< config.seed is set per field seed
  std::vector<std::string> recorded_args;  ///< for the header, as gen_hazards records them
};

struct ParsedField {
  std::optional<FieldSpec> spec;
  std::string error;  ///< when spec is empty: names --field
};

/// `--field`'s value (see the contract).
ParsedField parse_field(const std::string& text);

/// The name hazard_file is given for the field of `field_seed`; not a file's name.
std::string field_name(std::uint64_t field_seed);

/// The field's text for `field_seed` (the hazard file gen_hazards writes), or the generator's
/// error naming --field (a region too thin to place objects in).
struct FieldText {
  std::optional<std::string> text;
  std::string error;
};
FieldText generate_field(const FieldSpec& spec, std::uint64_t field_seed);

}  // namespace hazard_study
