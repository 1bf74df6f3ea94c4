#include "hazard/messages/node_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "base/fmt_fixed.hpp"
#include "base/same_text.hpp"
#include "base/text_appender.hpp"
#include "fields.hpp"
#include "hazard/messages/node_report_fields.hpp"
#include "hazard/ranges.hpp"

namespace hazard {

using detail::missing_field;
using detail::number_field;

namespace {

// A coordinate given as LAT/LON keeps its precision (about 1 mm at 8 decimals).
constexpr int kLatLonDecimals = 8;

using Field = NodeReportField;

std::optional<std::string_view> text_of(const Field& f) {
  return f.present ? std::optional<std::string_view>(f.text) : std::nullopt;
}

// A number read during the scan, else through the grammar (base::parse_number: the same
// number either way).
std::optional<double> optional_number(const Field& f) {
  if (!f.present) return std::nullopt;
  return f.has_number ? std::optional<double>(f.number) : base::parse_number(f.text);
}

// A required number's text read into a plain double: ten reports a second per vehicle, and a
// std::optional<double> built in memory and then copied whole costs a stalled load each.
enum class NumberText { kAbsent, kNumber, kNotANumber };
NumberText read_number(const Field& f, double& out) {
  if (!f.present) return NumberText::kAbsent;
  if (f.has_number) {
    out = f.number;
    return NumberText::kNumber;
  }
  const std::optional<double> v = base::parse_number(f.text);
  if (!v) return NumberText::kNotANumber;
  out = *v;
  return NumberText::kNumber;
}

// A LAT/LON-only position through the placement, or the reason it cannot be placed.
std::optional<glm::dvec2> place_lat_lon(const NodeReportFields& f, const GeoPlacement* placement,
                                        std::string& error) {
  const GeoPlacement none;
  if (!placement) placement = &none;
  if (!placement->projection) {
    error = "LAT/LON without X/Y cannot be placed (" + placement->unavailable + ")";
    return std::nullopt;
  }
  const auto lat = number_field("LAT", text_of(f.lat), error);
  const auto lon = number_field("LON", text_of(f.lon), error);
  if (!error.empty()) return std::nullopt;
  if (!valid_latitude(*lat)) {
    error = detail::field_value("LAT", f.lat.text) + " is outside [-90, 90]";
    return std::nullopt;
  }
  if (!valid_longitude(*lon)) {
    error = detail::field_value("LON", f.lon.text) + " is outside [-180, 360]";
    return std::nullopt;
  }
  return placement->projection->to_local(*lat, *lon);
}

// Physically meaningful ranges (ranges.hpp): a position beyond kMaxNodeCoordinate_m, or a
// speed that is negative or beyond kMaxNodeSpeed_mps, is refused; empty when in range.
std::string out_of_range(const NodeReportFields& f, glm::dvec2 position, double spd,
                         std::string_view spd_text) {
  if (std::fabs(position.x) > kMaxNodeCoordinate_m ||
      std::fabs(position.y) > kMaxNodeCoordinate_m) {
    const std::string given = f.x.present && f.y.present
                                  ? detail::field_value("X", f.x.text) + ", " +
                                        detail::field_value("Y", f.y.text)
                                         : "the position placed from LAT/LON";
    return given + ": beyond " + base::fmt(kMaxNodeCoordinate_m, 0) +
           " m from the origin (kMaxNodeCoordinate_m)";
  }
  if (!(spd >= 0.0 && spd <= kMaxNodeSpeed_mps)) {
    return detail::field_value("SPD", spd_text) + " is outside [0, " +
           base::fmt(kMaxNodeSpeed_mps, 0) + "] m/s";
  }
  return {};
}

// The report of a text's fields (found by the scan, or known from the writing), checked. Built
// in its place in the result (ten a second per vehicle: not moved out).
Parsed<NodeReport> build_node_report(const NodeReportFields& f, const GeoPlacement* placement,
                                     NodeReportKeep keep) {
  Parsed<NodeReport> result;
  NodeReport& r = result.value.emplace();
  std::string error;
  const auto fail = [](std::string why) { return Parsed<NodeReport>::fail(std::move(why)); };
  if (!detail::valid_vehicle_name("NAME", text_of(f.name), error)) return fail(error);
  r.name.assign(f.name.text.data(), f.name.text.size());

  double x = 0.0, y = 0.0, spd = 0.0, hdg = 0.0;
  const NumberText x_read = read_number(f.x, x);
  const NumberText y_read = read_number(f.y, y);
  const Field& spd_field = f.spd.present ? f.spd : f.speed;
  const Field& hdg_field = f.hdg.present ? f.hdg : f.heading;
  const NumberText spd_read = read_number(spd_field, spd);
  const NumberText hdg_read = read_number(hdg_field, hdg);
  // The first field at fault names the error: X, Y, SPD, HDG, then what is missing.
  if (x_read == NumberText::kNotANumber) return fail(detail::not_a_number("X", f.x.text));
  if (y_read == NumberText::kNotANumber) return fail(detail::not_a_number("Y", f.y.text));
  if (spd_read == NumberText::kNotANumber)
    return fail(detail::not_a_number("SPD", spd_field.text));
  if (hdg_read == NumberText::kNotANumber)
    return fail(detail::not_a_number("HDG", hdg_field.text));
  if (x_read == NumberText::kNumber && y_read == NumberText::kNumber) {
    r.x_m = x;
    r.y_m = y;
  } else if (f.lat.present && f.lon.present) {
    const std::optional<glm::dvec2> placed = place_lat_lon(f, placement, error);
    if (!placed) return fail(error);
    r.x_m = placed->x;
    r.y_m = placed->y;
    r.placed_from_lat_lon = true;
  } else {
    return fail(missing_field(x_read == NumberText::kAbsent ? "X" : "Y"));
  }
  if (spd_read == NumberText::kAbsent) return fail(missing_field("SPD"));
  if (hdg_read == NumberText::kAbsent) return fail(missing_field("HDG"));
  r.speed_mps = spd;
  r.heading_deg = base::norm360(hdg);
  const std::string why = out_of_range(f, {r.x_m, r.y_m}, r.speed_mps, spd_field.text);
  if (!why.empty()) return fail(why);
  if (keep == NodeReportKeep::kPose) return result;  // nothing below can reject the report
  r.lat_deg = optional_number(f.lat);
  r.lon_deg = optional_number(f.lon);
  r.time_s = optional_number(f.time);
  if (f.type.present && !f.type.text.empty()) r.type.emplace(f.type.text.data(), f.type.text.size());
  return result;
}

// Where a field's text lies in a written report (an offset: the string moves while it grows)
// and, for a number, what it reads as. No member initialisers: the writer sets every field,
// and zeroing the whole set first was a tenth of the writing.
struct WrittenField {
  std::size_t at;
  std::size_t size;
  bool present;
  bool has_number;
  double number;
};

struct WrittenFields {
  WrittenFields() {}  // NOLINT(modernize-use-equals-default): no zeroing (see WrittenField)
  WrittenField name, x, y, spd, hdg, lat, lon, time, type;
  bool numbers_known;  // false: a number outside write_fmt_fast's fast path
};

// Built through a stack buffer, numbers written in place (a vehicle posts one every iteration);
// the text is the same as appending each field with detail::append_field.
void write_node_report(const NodeReport& r, std::string& out) {
  base::TextAppender a(out);
  a.put("NAME=");
  a.put(r.name);
  a.put_field(",X=", r.x_m, 2);
  a.put_field(",Y=", r.y_m, 2);
  a.put_field(",SPD=", r.speed_mps, 2);
  a.put_field(",HDG=", r.heading_deg, 2);
  if (r.lat_deg) a.put_field(",LAT=", *r.lat_deg, kLatLonDecimals);
  if (r.lon_deg) a.put_field(",LON=", *r.lon_deg, kLatLonDecimals);
  if (r.time_s) a.put_field(",TIME=", *r.time_s, 3);
  if (r.type) {
    a.put(",TYPE=");
    a.put(*r.type);
  }
}

// The same text (NodeReportMemoFormat holds the two to each other), and in `w` where each field
// went and what each number reads as.
void write_node_report(const NodeReport& r, std::string& out, WrittenFields& w) {
  base::TextAppender a(out);
  w.numbers_known = true;
  const auto text = [&](std::string_view key, std::string_view value, WrittenField& f) {
    a.put(key);
    f = WrittenField{a.size(), value.size(), true, false, 0.0};
    a.put(value);
  };
  const auto number = [&](std::string_view key, double value, int decimals, WrittenField& f) {
    a.put(key);
    const std::size_t at = a.size();
    double read_back = 0.0;
    const bool known = a.put_fmt(value, decimals, read_back);
    f = WrittenField{at, a.size() - at, true, known, read_back};
    w.numbers_known = w.numbers_known && known;
  };
  constexpr WrittenField kAbsent{0, 0, false, false, 0.0};
  text("NAME=", r.name, w.name);
  number(",X=", r.x_m, 2, w.x);
  number(",Y=", r.y_m, 2, w.y);
  number(",SPD=", r.speed_mps, 2, w.spd);
  number(",HDG=", r.heading_deg, 2, w.hdg);
  w.lat = w.lon = w.time = w.type = kAbsent;
  if (r.lat_deg) number(",LAT=", *r.lat_deg, kLatLonDecimals, w.lat);
  if (r.lon_deg) number(",LON=", *r.lon_deg, kLatLonDecimals, w.lon);
  if (r.time_s) number(",TIME=", *r.time_s, 3, w.time);
  if (r.type) text(",TYPE=", *r.type, w.type);
}

// What a byte is to the scan: one that ends its piece (',') or holds it open ('{'), or a
// control byte (below 0x20, and 0x7F). A table, looked up without a branch per byte: the name
// and type of every report written are checked.
enum ByteClass : unsigned char { kEndsPiece = 1, kControlByte = 2 };
struct ByteClasses {
  unsigned char of[256];
};
constexpr ByteClasses make_byte_classes() {
  ByteClasses c{};
  for (int b = 0; b < 256; ++b) {
    const bool ends = b == ',' || b == '{';
    const bool control = b < 0x20 || b == 0x7F;
    c.of[b] = static_cast<unsigned char>((ends ? kEndsPiece : 0) | (control ? kControlByte : 0));
  }
  return c;
}
constexpr ByteClasses kByteClasses = make_byte_classes();

// The classes of all of `text`'s bytes together.
unsigned classes_of(std::string_view text) {
  unsigned seen = 0;
  for (const char c : text) seen |= kByteClasses.of[static_cast<unsigned char>(c)];
  return seen;
}

// A text field the scan finds byte for byte as written: nothing that ends its piece or holds
// it open, no blank at either end for the trim to take.
[[gnu::always_inline]] inline bool scans_as_written(std::string_view value) {
  if ((classes_of(value) & kEndsPiece) != 0) return false;
  return value.empty() ||
         (!base::detail::is_trimmed(value.front()) && !base::detail::is_trimmed(value.back()));
}

// A name that scans as written and that valid_vehicle_name accepts (non-empty, at most
// kMaxVehicleNameBytes, no control byte), in one pass: a control byte is also every blank the
// trim takes but ' '.
bool plain_vehicle_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxVehicleNameBytes) return false;
  if (classes_of(name) != 0) return false;
  return name.front() != ' ' && name.back() != ' ';
}

// Whether NodeReportFields(text) finds what was written with `w` (every number read back by
// the writer, names and types taken as they are: each field is once in the text, with the key
// the scan looks for) and build_node_report accepts those fields without a placement: the name
// valid_vehicle_name's, the position and speed within out_of_range's limits.
bool accepted_as_written(std::string_view text, const WrittenFields& w) {
  if (!w.numbers_known) return false;
  if (!plain_vehicle_name(text.substr(w.name.at, w.name.size))) return false;
  if (w.type.present && !scans_as_written(text.substr(w.type.at, w.type.size))) return false;
  const double spd = w.spd.number;
  return std::fabs(w.x.number) <= kMaxNodeCoordinate_m &&
         std::fabs(w.y.number) <= kMaxNodeCoordinate_m && spd >= 0.0 && spd <= kMaxNodeSpeed_mps;
}

// What build_node_report makes of an accepted text's fields (kAll, no placement), written over
// `r`: an entry's report, whose strings keep their capacity from one report to the next.
void assign_as_written(std::string_view text, const WrittenFields& w, NodeReport& r) {
  const auto number = [](const WrittenField& f) {
    return f.present ? std::optional<double>(f.number) : std::nullopt;
  };
  // The entries take turns among a few vehicles: an entry's name and type are mostly already
  // the ones written, and a compare is a third of std::string::assign.
  const auto assign = [&](std::string& to, const WrittenField& f) {
    const std::string_view from = text.substr(f.at, f.size);
    if (to != from) to.assign(from.data(), from.size());
  };
  assign(r.name, w.name);
  r.x_m = w.x.number;
  r.y_m = w.y.number;
  r.speed_mps = w.spd.number;
  r.heading_deg = base::norm360(w.hdg.number);
  r.lat_deg = number(w.lat);
  r.lon_deg = number(w.lon);
  r.time_s = number(w.time);
  if (w.type.present && w.type.size > 0) {
    if (!r.type) r.type.emplace();
    assign(*r.type, w.type);
  } else {
    r.type.reset();
  }
  r.placed_from_lat_lon = false;
}

// ---- the direct writing: the usual report, written at a pointer --------------------------------

// The longest TYPE the direct writing takes (a longer one is written the general way).
constexpr std::size_t kMaxDirectTypeBytes = 64;
// Room for the direct writing's longest text: every key, the name and type at their longest,
// and every number at base::kFmtFixedMaxChars.
constexpr std::size_t kDirectTextBytes = 64 + kMaxVehicleNameBytes + kMaxDirectTypeBytes +
                                         7 * base::kFmtFixedMaxChars;

// What the numbers of a directly written report read as (base::write_fmt_fixed's read-back).
struct DirectNumbers {
  double x, y, spd, hdg;               // always written
  double lat = 0, lon = 0, time = 0;  // written when the report has them
};

// FMT(value, Decimals) at `p` (base::write_fmt_fixed), out of line: one copy per precision
// that a report's numbers share. A copy inlined per field made format() 8 KB, fetched anew from
// L2 for every report (the other apps' code runs in between).
template <int Decimals>
[[gnu::noinline]] char* put_fixed(char* p, double value, double& read_back) {
  return base::write_fmt_fixed<Decimals>(p, value, read_back);
}

// ",TIME=" and FMT(t, 3): a time stamp's whole seconds (ten digits) are the same for a second of
// reports, from every vehicle of the process: `whole` keeps their digits.
[[gnu::noinline]] char* put_time(char* p, double value, double& read_back,
                                 base::LongWholeCache& whole) {
  std::memcpy(p, ",TIME=", 6);
  return base::write_fmt_fixed<3>(p + 6, value, read_back, &whole);
}

// A key (a literal: its length is a constant and the copy a store or two) and the number FMT
// writes after it; nullptr when the number is outside base::write_fmt_fixed's fast path.
template <int Decimals, std::size_t N>
char* put_number(char* p, const char (&key)[N], double value, double& read_back) {
  std::memcpy(p, key, N - 1);
  return put_fixed<Decimals>(p + N - 1, value, read_back);
}

// A name or type (mostly 3 to 16 bytes) copied by two overlapping fixed-size loads, not a
// memcpy call (the call and its dispatch were more than the bytes); longer texts by the call.
// They compare by base::same_text.
template <typename Word>
void copy_ends(char* to, const char* from, std::size_t n) {
  std::memcpy(to, from, sizeof(Word));
  std::memcpy(to + n - sizeof(Word), from + n - sizeof(Word), sizeof(Word));
}

[[gnu::always_inline]] inline char* put_text(char* p, std::string_view text) {
  const std::size_t n = text.size();
  const char* const s = text.data();
  if (n > 16) {
    std::memcpy(p, s, n);
  } else if (n >= 8) {
    copy_ends<std::uint64_t>(p, s, n);
  } else if (n >= 4) {
    copy_ends<std::uint32_t>(p, s, n);
  } else if (n > 0) {
    p[0] = s[0];
    p[n / 2] = s[n / 2];
    p[n - 1] = s[n - 1];
  }
  return p + n;
}

// Whether write_direct takes a report's name and type (when not known to pass already).
// Out of line: a vehicle's report is mostly checked once, when its name is first written.
[[gnu::noinline]] bool direct_strings(const NodeReport& r) {
  return plain_vehicle_name(r.name) &&
         !(r.type && (r.type->size() > kMaxDirectTypeBytes || !scans_as_written(*r.type)));
}

// The usual report's text at `out` (room for kDirectTextBytes), the same bytes
// write_node_report writes: its length, and in `n` what each number reads as. 0 for anything
// else (a name that is not plain, a long or unscannable type, a number outside the fast path):
// `checked` when the name and type are known to pass (same_name_and_type). `time_whole`: TIME's
// whole seconds, kept from the last report written.
// those go the general way. Such a text is accepted as written (accepted_as_written) exactly
// when its numbers are within out_of_range's limits (direct_in_range).
std::size_t write_direct(const NodeReport& r, char* out, DirectNumbers& n, bool checked,
                         base::LongWholeCache& time_whole) {
  if (!checked && !direct_strings(r)) return 0;
  char* p = put_text(out, "NAME=");
  p = put_text(p, r.name);
  if (!(p = put_number<2>(p, ",X=", r.x_m, n.x))) return 0;
  if (!(p = put_number<2>(p, ",Y=", r.y_m, n.y))) return 0;
  if (!(p = put_number<2>(p, ",SPD=", r.speed_mps, n.spd))) return 0;
  if (!(p = put_number<2>(p, ",HDG=", r.heading_deg, n.hdg))) return 0;
  if (r.lat_deg && !(p = put_number<kLatLonDecimals>(p, ",LAT=", *r.lat_deg, n.lat))) return 0;
  if (r.lon_deg && !(p = put_number<kLatLonDecimals>(p, ",LON=", *r.lon_deg, n.lon))) return 0;
  if (r.time_s && !(p = put_time(p, *r.time_s, n.time, time_whole))) return 0;
  if (r.type) {
    p = put_text(p, ",TYPE=");
    p = put_text(p, *r.type);
  }
  return static_cast<std::size_t>(p - out);
}

// accepted_as_written's number limits, on a direct writing's read-backs.
bool direct_in_range(const DirectNumbers& n) {
  return std::fabs(n.x) <= kMaxNodeCoordinate_m && std::fabs(n.y) <= kMaxNodeCoordinate_m &&
         n.spd >= 0.0 && n.spd <= kMaxNodeSpeed_mps;
}

// Whether a report kept from a direct writing has `r`'s name and type (an empty type is none):
// then they passed write_direct's checks, and assign_direct need not copy them.
bool same_name_and_type(const NodeReport& kept, const NodeReport& r) {
  if (!base::same_text(kept.name, r.name)) return false;
  if (!r.type || r.type->empty()) return !kept.type;
  return kept.type && base::same_text(*kept.type, *r.type);
}

// A direct writing's name and type into `r` (an empty type is none), when they are not known to
// be the ones `r` holds. Out of line: a vehicle's entry mostly holds them already.
[[gnu::noinline]] void assign_direct_strings(const NodeReport& from, NodeReport& r) {
  if (!base::same_text(r.name, from.name)) r.name.assign(from.name);
  if (from.type && !from.type->empty()) {
    if (!r.type) r.type.emplace();
    if (!base::same_text(*r.type, *from.type)) r.type->assign(*from.type);
  } else {
    r.type.reset();
  }
}

// assign_as_written for a direct writing: the name and type are the report's own bytes
// (`same_strings`: r has them already).
void assign_direct(const NodeReport& from, const DirectNumbers& n, NodeReport& r,
                   bool same_strings) {
  if (!same_strings) assign_direct_strings(from, r);
  r.x_m = n.x;
  r.y_m = n.y;
  r.speed_mps = n.spd;
  // norm360 leaves a heading in [0, 360) as it is (a read-back is never -0): the usual one
  // skips the call.
  r.heading_deg = n.hdg >= 0.0 && n.hdg < 360.0 ? n.hdg : base::norm360(n.hdg);
  r.lat_deg = from.lat_deg ? std::optional<double>(n.lat) : std::nullopt;
  r.lon_deg = from.lon_deg ? std::optional<double>(n.lon) : std::nullopt;
  r.time_s = from.time_s ? std::optional<double>(n.time) : std::nullopt;
  r.placed_from_lat_lon = false;
}

}  // namespace

Parsed<NodeReport> parse_node_report(std::string_view text) {
  return parse_node_report(text, nullptr);
}

Parsed<NodeReport> parse_node_report(std::string_view text, const GeoPlacement* placement,
                                     NodeReportKeep keep) {
  return build_node_report(NodeReportFields(text, keep == NodeReportKeep::kPose), placement, keep);
}

NodeReportMemo& NodeReportMemo::this_thread() {
  thread_local NodeReportMemo memo;
  return memo;
}

const Parsed<NodeReport>& NodeReportMemo::parse(std::string_view text,
                                                const GeoPlacement* placement) {
  for (std::size_t i = 0; i < used_; ++i)
    if (entries_[i].text == text) return entries_[i].parsed;
  ++texts_read_;
  // Without a placement only X and Y place a report, and no placement changes that: what this
  // parse accepts is kept for every reader. A failure may be a LAT/LON-only report that the
  // caller's placement would place, or fail for another reason.
  Parsed<NodeReport> parsed = parse_node_report(text);
  if (!parsed) {
    unkept_ = placement ? parse_node_report(text, placement) : std::move(parsed);
    return unkept_;
  }
  return keep(text, std::move(parsed));
}

// (Inlined: one call per report written.)
[[gnu::always_inline]] inline NodeReportMemo::Entry& NodeReportMemo::next_entry(
    std::string_view text) {
  Entry& e = entries_[next_];
  next_ = (next_ + 1) % kKept;
  used_ = std::max(used_, next_ == 0 ? kKept : next_);
  // Within the kept capacity: a report of the same length (the usual one) is a copy over the
  // old bytes, another one a clear() and append(); assign() is twice their cost.
  if (e.text.size() == text.size()) {
    std::memcpy(e.text.data(), text.data(), text.size());
  } else {
    e.text.clear();
    e.text.append(text.data(), text.size());
  }
  return e;
}

const Parsed<NodeReport>& NodeReportMemo::keep(std::string_view text, Parsed<NodeReport>&& parsed) {
  Entry& e = next_entry(text);
  e.direct = false;
  e.parsed = std::move(parsed);
  return e.parsed;
}

// The parse is known from what was written, without reading the text back: what the scan and
// build_node_report would give (accepted_as_written, assign_as_written), written into the
// entry in place. The usual report is written directly at a stack buffer (write_direct); the
// rest through the general writer, which records where each field went.
std::string NodeReportMemo::format(const NodeReport& report) {
  // The entry replaced next mostly holds this vehicle's previous report (the vehicles take
  // turns): its name and type need no check and no copy.
  const Entry& replaced = entries_[next_];
  const bool known = replaced.direct && replaced.parsed.value &&
                     same_name_and_type(*replaced.parsed.value, report);
  char buffer[kDirectTextBytes];
  DirectNumbers numbers;
  const std::size_t size = write_direct(report, buffer, numbers, known, time_whole_);
  if (size == 0) return format_general(report);
  const std::string_view text(buffer, size);
  // Without a placement, as parse() keeps it: a written report always has X and Y.
  if (direct_in_range(numbers)) {
    Entry& e = next_entry(text);  // (the entry `replaced`)
    e.direct = true;
    e.parsed.error.clear();  // (a kept entry has none; a fresh one is empty)
    if (!e.parsed.value) e.parsed.value.emplace();
    assign_direct(report, numbers, *e.parsed.value, known);
  }
  return std::string(text);
}

std::string NodeReportMemo::format_general(const NodeReport& report) {
  std::string text;
  WrittenFields written;
  write_node_report(report, text, written);
  // A text the writing cannot vouch for is read when it arrives.
  if (!accepted_as_written(text, written)) return text;
  Entry& e = next_entry(text);
  e.direct = false;
  e.parsed.error.clear();
  if (!e.parsed.value) e.parsed.value.emplace();
  assign_as_written(text, written, *e.parsed.value);
  return text;
}

std::string format_node_report(const NodeReport& r) {
  std::string out;
  write_node_report(r, out);
  return out;
}

}  // namespace hazard
