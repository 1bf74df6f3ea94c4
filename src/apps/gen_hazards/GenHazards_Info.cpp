#include "GenHazards_Info.hpp"

#include <sstream>

#include "base/version.hpp"
#include "options.hpp"

namespace gen_hazards {

namespace {

/// Help lines stay within a classic 80-column terminal.
constexpr std::size_t kTextColumns = 80;
constexpr std::string_view kOptionIndent = "  ";
constexpr std::string_view kMeaningIndent = "      ";

/// Word-wraps `text` into lines that start with `indent` and end before kTextColumns.
std::string wrapped(const std::string& text, std::string_view indent) {
  std::istringstream words(text);
  std::string out;
  std::string line(indent);
  std::string word;
  while (words >> word) {
    if (line.size() > indent.size() && line.size() + 1 + word.size() > kTextColumns) {
      out += line + "\n";
      line = std::string(indent);
    }
    if (line.size() > indent.size()) line += ' ';
    line += word;
  }
  if (line.size() > indent.size()) out += line + "\n";
  return out;
}

std::string option_section() {
  std::string out;
  for (const auto& doc : option_docs()) {
    out += std::string(kOptionIndent) + doc.name + "\n";
    out += wrapped(doc.meaning, kMeaningIndent);
    if (doc.default_text != "-") {
      out += wrapped("Default: " + doc.default_text + ". Range: " + doc.range_text + ".",
                     kMeaningIndent);
    }
  }
  return out;
}

}  // namespace

std::string help_text() {
  std::string out;
  out += "Usage: gen_hazards --polygon=POLY [--polygon=POLY ...]\n";
  out += "                   --objects=N,TYPE [--objects=N,TYPE ...] [OPTIONS]\n\n";
  out += wrapped(
      "Writes a random hazard field for uFldHazardSensor and uFldHazardMetric: a header "
      "comment that regenerates the field (it ends with the seed in use), one `region = "
      "pts={...}` line per --polygon, then one `hazard = x=..,y=..,label=..,type=..` line per "
      "object. Positions are whole metres, so an object may lie up to 0.5 m outside its "
      "region in x and in y. Labels are unique integers.",
      "");
  out += "\nOptions:\n";
  out += option_section();
  out += "\nExample:\n";
  out += "  gen_hazards --polygon=-150,-75:-150,-400:400,-400:400,-75 --objects=5,hazard \\\n";
  out += "              --objects=10,benign --seed=7 > hazards.txt\n\n";
  out += wrapped("Exit status: " + std::to_string(kExitOk) + " on success, " +
                     std::to_string(kExitCannotWrite) + " if the output cannot be written, " +
                     std::to_string(kExitBadInput) +
                     " for a bad argument or a field that cannot be generated (then nothing "
                     "is written). Errors go to standard error, each naming its argument.",
                 "");
  out += "\nSee docs/gen_hazards.md for the differences from the original gen_hazards.\n";
  return out;
}

std::string version_text() {
  return base::version_line("gen_hazards");
}

}  // namespace gen_hazards
