#include "hazard/style.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "base/text.hpp"

namespace hazard {

namespace {

// X11/CSS colour names in lower case without separators (sorted for binary search).
constexpr std::array<std::string_view, 150> kColorNames = {
    "aliceblue", "antiquewhite", "aqua", "aquamarine", "azure", "beige", "bisque", "black",
    "blanchedalmond", "blue", "blueviolet", "brown", "burlywood", "cadetblue", "chartreuse",
    "chocolate", "coral", "cornflowerblue", "cornsilk", "crimson", "cyan", "darkblue", "darkcyan",
    "darkgoldenrod", "darkgray", "darkgreen", "darkgrey", "darkkhaki", "darkmagenta",
    "darkolivegreen", "darkorange", "darkorchid", "darkred", "darksalmon", "darkseagreen",
    "darkslateblue", "darkslategray", "darkslategrey", "darkturquoise", "darkviolet", "deeppink",
    "deepskyblue", "dimgray", "dimgrey", "dodgerblue", "empty", "firebrick", "floralwhite",
    "forestgreen", "fuchsia", "gainsboro", "ghostwhite", "gold", "goldenrod", "gray", "green",
    "greenyellow", "grey", "honeydew", "hotpink", "indianred", "indigo", "invisible", "ivory",
    "khaki", "lavender", "lavenderblush", "lawngreen", "lemonchiffon", "lightblue", "lightcoral",
    "lightcyan", "lightgoldenrodyellow", "lightgray", "lightgreen", "lightgrey", "lightpink",
    "lightsalmon", "lightseagreen", "lightskyblue", "lightslategray", "lightslategrey",
    "lightsteelblue", "lightyellow", "lime", "limegreen", "linen", "magenta", "maroon",
    "mediumaquamarine", "mediumblue", "mediumorchid", "mediumpurple", "mediumseagreen",
    "mediumslateblue", "mediumspringgreen", "mediumturquoise", "mediumvioletred", "midnightblue",
    "mintcream", "mistyrose", "moccasin", "navajowhite", "navy", "oldlace", "olive", "olivedrab",
    "orange", "orangered", "orchid", "palegoldenrod", "palegreen", "paleturquoise",
    "palevioletred", "papayawhip", "peachpuff", "peru", "pink", "plum", "powderblue", "purple",
    "rebeccapurple", "red", "rosybrown", "royalblue", "saddlebrown", "salmon", "sandybrown",
    "seagreen", "seashell", "sienna", "silver", "skyblue", "slateblue", "slategray", "slategrey",
    "snow", "springgreen", "steelblue", "tan", "teal", "thistle", "tomato", "turquoise", "violet",
    "wheat", "white", "whitesmoke", "yellow", "yellowgreen",
};

constexpr int kMaxGrayLevel = 100;  // X11 defines gray0 .. gray100

std::string normalized_color_word(std::string_view text) {
  std::string out;
  for (char c : base::trim(text)) {
    if (c != '_' && c != ' ') out.push_back(c);
  }
  return base::to_lower(out);
}

bool is_gray_level(std::string_view word) {
  for (std::string_view prefix : {"gray", "grey"}) {
    if (word.size() > prefix.size() && word.substr(0, prefix.size()) == prefix) {
      const auto level = base::parse_unsigned(word.substr(prefix.size()));
      return level && *level <= kMaxGrayLevel;
    }
  }
  return false;
}

// "hex:RR,GG,BB" with two hex digits per channel.
bool is_hex_color(std::string_view word) {
  if (word.substr(0, 4) != "hex:") return false;
  const auto parts = base::split_trimmed(word.substr(4), ',');
  if (parts.size() != 3) return false;
  return std::all_of(parts.begin(), parts.end(), [](std::string_view p) {
    return p.size() == 2 && std::all_of(p.begin(), p.end(), [](char c) {
             return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
  });
}

bool is_fraction_triple(std::string_view word) {
  for (char sep : {',', ':', '%', '$', '#'}) {
    const auto parts = base::split_trimmed(word, sep);
    if (parts.size() != 3) continue;
    return std::all_of(parts.begin(), parts.end(), [](std::string_view p) {
      const auto v = base::parse_number(p);
      return v && *v >= 0.0 && *v <= 1.0;
    });
  }
  return false;
}

}  // namespace

bool is_known_color(std::string_view text) {
  const std::string word = normalized_color_word(text);
  if (word.empty()) return false;
  return std::binary_search(kColorNames.begin(), kColorNames.end(), std::string_view(word)) ||
         is_gray_level(word) || is_hex_color(word) || is_fraction_triple(word);
}

bool is_known_shape(std::string_view text) {
  for (std::string_view shape : {"circle", "square", "diamond", "triangle", "efield", "gateway"}) {
    if (text == shape) return true;
  }
  return false;
}

}  // namespace hazard
