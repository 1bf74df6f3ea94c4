#pragma once
// pMarineViewer's buttons: `button_one = DEPLOY # DEPLOY_ALL=true # RETURN_ALL=false`: a label,
// then one or more `VAR=value` assignments separated by '#'. Pressing the button posts every
// assignment in order; a value that is a number (base::parse_number) is posted as a double,
// anything else as a string. button_one .. button_four are indices 1 .. 4.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace web_viewer {

inline constexpr int kMaxButtons = 4;

struct Assignment {
  std::string var;
  bool is_double = false;
  double dval = 0.0;
  std::string sval;
};

struct Button {
  int index = 0;  ///< 1..kMaxButtons
  std::string label;
  std::vector<Assignment> assignments;
};

/// 1..4 for button_one..button_four (any case); nullopt for any other key.
std::optional<int> button_index(std::string_view key);

/// Parses a button's value; nullopt with `error` set when the label is empty, there is no
/// assignment, or an assignment has no '=' or no variable name.
std::optional<Button> parse_button(int index, std::string_view value, std::string* error);

}  // namespace web_viewer
