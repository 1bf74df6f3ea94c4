// The C++ side of the grammar differential test (test_grammar_differential.py): what
// base::parse_number makes of each text, and what hazard::load_hazard_file_text makes of a hazard
// file, written in a form Python reads without a second parser (texts as hex bytes, doubles as
// their 64 bits in hex).
//
//   grammar_probe numbers < TEXTS   one hex-encoded text a line in; "-" (not a number) or the
//                                    double's bits a line out
//   grammar_probe hazards NAME < FILE
//                                    the file's text in; "O label x y type hr aspect aspect_min
//                                    aspect_max width color shape source" per object and
//                                    "W warning" per warning out ("-" for an absent field)
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/text.hpp"
#include "hazard/hazard_field.hpp"

namespace {

std::string hex(std::string_view bytes) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  out.reserve(bytes.size() * 2);
  for (const char c : bytes) {
    const auto b = static_cast<unsigned char>(c);
    out.push_back(kDigits[b >> 4]);
    out.push_back(kDigits[b & 0xF]);
  }
  return out.empty() ? "=" : out;  // "=": the empty text (a field is never blank)
}

int nibble(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::optional<std::string> unhex(std::string_view text) {
  if (text.size() % 2 != 0) return std::nullopt;
  std::string out;
  for (std::size_t i = 0; i < text.size(); i += 2) {
    const int high = nibble(text[i]);
    const int low = nibble(text[i + 1]);
    if (high < 0 || low < 0) return std::nullopt;
    out.push_back(static_cast<char>(high * 16 + low));
  }
  return out;
}

std::string bits(std::optional<double> value) {
  if (!value) return "-";
  std::uint64_t b = 0;
  std::memcpy(&b, &*value, sizeof b);
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(b));
  return text;
}

std::string text_or_dash(const std::optional<std::string>& text) {
  return text ? hex(*text) : "-";
}

int probe_numbers() {
  for (std::string line; std::getline(std::cin, line);) {
    const std::optional<std::string> text = line == "=" ? std::string() : unhex(line);
    if (!text) {
      std::cerr << "grammar_probe: line is not hex: " << base::log_excerpt(line) << "\n";
      return 2;
    }
    std::cout << bits(base::parse_number(*text)) << "\n";
  }
  return 0;
}

int probe_hazards(std::string_view name) {
  const std::string text{std::istreambuf_iterator<char>(std::cin), {}};
  hazard::HazardField field;
  std::vector<std::string> warnings;
  hazard::GeoPlacement placement;
  placement.unavailable = "the tools know no mission origin";  // the Python reader's words
  hazard::load_hazard_file_text(text, name, field, warnings, &placement);
  for (hazard::ObjectId id = 0; id < field.size(); ++id) {
    const hazard::HazardObject o = field.object(id);
    std::cout << "O " << hex(o.label) << " " << bits(o.x_m) << " " << bits(o.y_m) << " "
              << hazard::type_name(o.type) << " " << bits(o.resemblance) << " "
              << bits(o.aspect_deg) << " " << bits(o.aspect_min_deg) << " "
              << bits(o.aspect_max_deg) << " " << bits(o.marker_width_m) << " "
              << text_or_dash(o.color) << " " << text_or_dash(o.shape) << " "
              << text_or_dash(o.source) << "\n";
  }
  for (const std::string& w : warnings) std::cout << "W " << hex(w) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string_view> args(argv + 1, argv + argc);
  if (args.size() == 1 && args[0] == "numbers") return probe_numbers();
  if (args.size() == 2 && args[0] == "hazards") return probe_hazards(args[1]);
  std::cerr << "usage: grammar_probe numbers < TEXTS | grammar_probe hazards NAME < FILE\n";
  return 2;
}
