// Help and version text of gen_hazards (the text comes from the option table)
// and the user page that must document the same options.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "GenHazards_Info.hpp"
#include "base/version.hpp"
#include "options.hpp"

namespace gen_hazards {
namespace {

/// Help lines fit a classic terminal.
constexpr std::size_t kMaxHelpColumns = 80;

// Runs of blanks and newlines become one blank, so wrapped text can be searched as one line.
std::string flattened(const std::string& text) {
  std::string out;
  bool blank = false;
  for (char c : text) {
    const bool is_blank = c == ' ' || c == '\n' || c == '\t';
    if (is_blank && !blank) out += ' ';
    if (!is_blank) out += c;
    blank = is_blank;
  }
  return out;
}

TEST(GenHazardsInfo, HelpDocumentsEveryOptionWithItsDefaultAndRange) {
  const std::string help = flattened(help_text());
  ASSERT_GE(option_docs().size(), 13u);
  for (const auto& doc : option_docs()) {
    EXPECT_NE(help.find(doc.name), std::string::npos) << doc.name;
    EXPECT_NE(help.find(flattened(doc.meaning)), std::string::npos) << doc.name;
    if (doc.default_text == "-") continue;  // --help and --version take no value
    EXPECT_NE(help.find("Default: " + doc.default_text + ". Range: " + doc.range_text + "."),
              std::string::npos)
        << doc.name;
  }
}

TEST(GenHazardsInfo, HelpStatesTheRangesTheParserEnforces_D31) {
  const std::string help = flattened(help_text());
  EXPECT_NE(help.find("--exp=E"), std::string::npos);
  EXPECT_NE(help.find("Range: [0.01, 10]"), std::string::npos);
  EXPECT_NE(help.find("Range: [0, 360]"), std::string::npos);
  EXPECT_NE(help.find("Range: [0, 90]"), std::string::npos);
}

TEST(GenHazardsInfo, HelpLinesFitEightyColumns) {
  std::istringstream lines(help_text());
  for (std::string line; std::getline(lines, line);) {
    EXPECT_LE(line.size(), kMaxHelpColumns) << line;
  }
}

TEST(GenHazardsInfo, VersionNamesTheProgramAndTheRelease) {
  EXPECT_EQ(version_text(), "gen_hazards " + std::string(base::release_version()) + " (HazardSensor)\n");
}

TEST(GenHazardsInfo, UserPageDocumentsEveryOptionAndTheDifferences) {
  std::ifstream in(std::string(HAZARD_SOURCE_DIR) + "/docs/gen_hazards.md");
  ASSERT_TRUE(in) << "docs/gen_hazards.md is missing";
  std::stringstream text;
  text << in.rdbuf();
  const std::string page = text.str();
  for (const auto& doc : option_docs()) {
    const std::string key = doc.name.substr(0, doc.name.find_first_of("=,"));
    EXPECT_NE(page.find("`" + key), std::string::npos) << key;
  }
  EXPECT_NE(page.find("## Differences from the original"), std::string::npos);
}

}  // namespace
}  // namespace gen_hazards
