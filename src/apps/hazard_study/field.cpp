// hazard_study's generated field. Contract in field.hpp.

#include "field.hpp"


#include "base/text.hpp"
#include "generator.hpp"

namespace hazard_study {

namespace {

/// The words of `text`, split at blanks and tabs.
std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (const char c : text + ' ') {
    if (c != ' ' && c != '\t') {
      word += c;
    } else if (!word.empty()) {
      words.push_back(std::move(word));
      word.clear();
    }
  }
  return words;
}

/// Why a word gen_hazards takes is refused inside --field; "" when it is not.
std::string refused(const std::string& word) {
  const std::string key = word.substr(0, word.find('='));
  if (key == "--seed") return "the field's seed is --field-seed (or --field-seeds)";
  if (key == "--output") return "the field stays in memory: hazard_study writes no hazard file";
  return {};
}

}  // namespace

ParsedField parse_field(const std::string& text) {
  auto fail = [](std::string why) { return ParsedField{std::nullopt, "--field: " + why}; };
  if (text.size() > kMaxFieldText || text.find_first_of("\r\n") != std::string::npos)
    return fail("needs gen_hazards options on one line of at most " +
                std::to_string(kMaxFieldText) + " characters");
  const std::vector<std::string> words = words_of(text);
  for (const std::string& word : words)
    if (const std::string why = refused(word); !why.empty())
      return fail("'" + base::excerpt(word) + "': " + why);
  gen_hazards::CommandLine cli = gen_hazards::parse_command_line(words);
  if (cli.help || cli.version)
    return fail(
        "takes gen_hazards' field options (see gen_hazards --help), not --help or --version");
  if (!cli.errors.empty()) return fail(cli.errors.front());
  if (cli.config.sets.empty())
    return fail("needs at least one --objects=N,TYPE and a --polygon: '" + base::excerpt(text) +
                "'");
  return ParsedField{FieldSpec{std::move(cli.config), std::move(cli.recorded_args)}, {}};
}

std::string field_name(std::uint64_t field_seed) {
  return "--field (field seed " + std::to_string(field_seed) + ")";
}

FieldText generate_field(const FieldSpec& spec, std::uint64_t field_seed) {
  gen_hazards::GeneratorConfig config = spec.config;
  config.seed = field_seed;
  auto file = gen_hazards::build_hazard_file(
      gen_hazards::header_line(spec.recorded_args, field_seed), config);
  if (!file) return FieldText{std::nullopt, "--field: " + file.error};
  return FieldText{std::move(file.value), {}};
}

}  // namespace hazard_study
