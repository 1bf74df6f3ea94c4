#include "buttons.hpp"

#include "base/text.hpp"

namespace web_viewer {

std::optional<int> button_index(std::string_view key) {
  static const char* const kNames[kMaxButtons] = {"button_one", "button_two", "button_three",
                                                  "button_four"};
  for (int i = 0; i < kMaxButtons; ++i)
    if (base::iequals(key, kNames[i])) return i + 1;
  return std::nullopt;
}

std::optional<Button> parse_button(int index, std::string_view value, std::string* error) {
  const std::vector<std::string_view> pieces = base::split_trimmed(value, '#');
  Button button;
  button.index = index;
  button.label = std::string(pieces.front());
  if (button.label.empty() || button.label.find('=') != std::string::npos) {
    *error = "a button starts with its label, not '" + base::excerpt(button.label) + "'";
    return std::nullopt;
  }
  for (std::size_t i = 1; i < pieces.size(); ++i) {
    const std::string_view piece = pieces[i];
    if (piece.empty()) continue;
    const auto eq = piece.find('=');
    const std::string_view var = eq == std::string_view::npos ? piece : base::trim(piece.substr(0, eq));
    if (eq == std::string_view::npos || var.empty() || var.find_first_of(" \t,") != std::string_view::npos) {
      *error = "button assignment '" + base::excerpt(piece) + "' is not VAR=value";
      return std::nullopt;
    }
    Assignment a;
    a.var = std::string(var);
    const std::string_view text = base::trim(piece.substr(eq + 1));
    if (const auto number = base::parse_number(text)) {
      a.is_double = true;
      a.dval = *number;
    } else {
      a.sval = std::string(text);
    }
    button.assignments.push_back(std::move(a));
  }
  if (button.assignments.empty()) {
    *error = "button '" + base::excerpt(button.label) + "' has no VAR=value assignment";
    return std::nullopt;
  }
  return button;
}

}  // namespace web_viewer
