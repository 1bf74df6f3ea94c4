// Fuzz target: hazard_study's command line (study_args.cpp), including --set, --seeds and
// --field, whose value is read as gen_hazards' options (field.cpp); a field small enough to
// generate in an instant is generated too, as the study would. The input is the argument
// list, one argument per NUL-separated field.

#include <string>
#include <vector>

#include "field.hpp"
#include "fuzz_input.hpp"
#include "study_args.hpp"

namespace {

/// Generating a field is linear in its objects: a bigger one would only slow the fuzzer.
constexpr std::uint64_t kMaxObjectsGenerated = 500;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string> args = fuzz::arguments_of(fuzz::as_text(data, size));
  const hazard_study::ParsedArgs parsed = hazard_study::parse_args(args);
  if (!parsed.options || !parsed.options->field) return 0;
  const hazard_study::FieldSpec& spec = *parsed.options->field;
  if (gen_hazards::total_objects(spec.config) <= kMaxObjectsGenerated)
    (void)hazard_study::generate_field(spec, parsed.options->first_field_seed);
  return 0;
}
