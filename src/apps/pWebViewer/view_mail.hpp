#pragma once
// What pWebViewer hands to the page: one MOOS posting as a "mail object", and the JSON texts of
// the server-sent events (docs/viewer.md, "Protocol").
//
// Contract
// - A Mail keeps a posting's variable, source, MOOS time and value (a double or a string);
//   binary values are not viewable and never become Mail (from_message returns nullopt).
// - The JSON texts are one line each (no raw newline inside), always valid UTF-8 (a byte of a
//   MOOS string that is not part of well-formed UTF-8 is written as the four characters \xNN,
//   NN its value in upper-case hex, so the page shows which bytes came), and safe to inline in an HTML <script> block: '<', '>' and '&' are
//   written as \u escapes, so a value can never close the script element.
// - Doubles are written in their shortest exact form; a non-finite double (which the MOOS
//   protocol can carry) is written as null.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "moos/message.hpp"

namespace web_viewer {

struct Mail {
  std::string var;
  std::string src;
  double time_s = 0.0;  ///< MOOS time of the posting
  bool is_double = false;
  double dval = 0.0;
  std::string sval;
};

/// The Mail of a NOTIFY message; nullopt for binary and unset values.
std::optional<Mail> from_message(const moos::Message& message);

/// `text` as a JSON string literal, quotes included (see the contract for the escapes).
std::string json_string(std::string_view text);
/// A double as JSON (null when not finite).
std::string json_number(double value);

/// {"type":"mail","var":...,"val":...,"src":...,"time":T}
std::string mail_json(const Mail& mail);

/// One configured button as the hello announces it.
struct ButtonLabel {
  int index = 0;
  std::string label;
};

/// What the hello tells the page.
struct Hello {
  std::string community;
  double time_s = 0.0;
  double warp = 1.0;
  bool replay = false;
  std::vector<ButtonLabel> buttons;
  std::optional<double> lat_origin_deg;   ///< the mission's LatOrigin, when known
  std::optional<double> lon_origin_deg;   ///< the mission's LongOrigin, when known
  std::size_t trail_length = 200;         ///< node reports the page keeps per vehicle
  std::size_t unlabelled_ring = 2000;     ///< unlabelled VIEW_* postings it keeps per variable
};
std::string hello_json(const Hello& hello);

/// {"type":"clock","time":T,"warp":W}
std::string clock_json(double time_s, double warp);

}  // namespace web_viewer
