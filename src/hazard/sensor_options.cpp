#include "hazard/sensor_options.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/key_value_reader.hpp"
#include "base/text.hpp"
#include "base/warning_budget.hpp"
#include "hazard/ranges.hpp"
#include "messages/fields.hpp"

namespace hazard {

namespace {

using detail::field_value;
using detail::missing_field;

// Range limits of differences.md "Validation".
constexpr double kMinExp = 1.0;
constexpr double kMinPclass = 0.5;
constexpr double kMaxPclass = 1.0;

}  // namespace

SensorConfigParse parse_sensor_config(std::string_view value) {
  SensorConfigParse out;
  base::WarningBudget budget{base::kMaxWarningsPerLine};  // a few warnings, then a count
  std::optional<std::string_view> width, exp, pclass, max;
  base::KeyValueReader pieces(value);  // one at a time: a line of a million keys, no vector
  for (base::KeyValue kv; pieces.next(kv);) {
    const std::string key = base::to_lower(kv.key);
    if (!kv.has_equals) {
      budget.add(out.warnings, "piece '" + base::excerpt(kv.key) + "' has no '='; ignored");
    } else if (key == "width") {
      width = kv.value;
    } else if (key == "exp") {
      exp = kv.value;
    } else if (key == "pclass" || key == "class") {
      pclass = kv.value;
    } else if (key == "max") {
      max = kv.value;
    } else {
      budget.add(out.warnings, "unknown key '" + base::excerpt(kv.key) + "' (value '" +
                                   base::excerpt(kv.value) + "') ignored");
    }
  }
  if (budget.dropped() > 0) out.warnings.push_back(budget.summary("warnings on this line"));
  auto fail = [&](std::string why) {
    out.error = std::move(why);
    return out;
  };
  if (!width) return fail(missing_field("width"));
  if (!exp) return fail(missing_field("exp"));
  if (!pclass) return fail(missing_field("pclass"));
  SensorOption o;
  const auto w = base::parse_number(*width);
  if (!w || !(*w > 0.0)) return fail(field_value("width", *width) + " is not a number > 0");
  if (*w > kMaxSwathWidth_m) {
    return fail(field_value("width", *width) + " is above " + base::fmt(kMaxSwathWidth_m) +
                " m (kMaxSwathWidth_m)");
  }
  const auto e = base::parse_number(*exp);
  if (!e || !(*e >= kMinExp)) return fail(field_value("exp", *exp) + " is not a number >= 1");

  const auto p = base::parse_number(*pclass);
  if (!p || !(*p >= kMinPclass && *p <= kMaxPclass)) {
    return fail(field_value("pclass", *pclass) + " is not a number in [0.5, 1]");
  }
  if (max) {
    const auto m = base::parse_unsigned(*max);
    if (!m || *m > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
      return fail(field_value("max", *max) + " is not a whole number >= 0");
    }
    o.max_vehicles = static_cast<int>(*m);
  }
  o.width_m = *w;
  o.exp = *e;
  o.pclass = *p;
  o.as_written = OptionsSummaryEntry{std::string(*width), std::string(*exp),
                                     std::string(*pclass), o.max_vehicles};
  out.option = std::move(o);
  return out;
}

base::Result<std::size_t> SensorOptions::add(SensorOption option) {
  for (const SensorOption& o : sorted_) {
    if (std::fabs(o.width_m - option.width_m) <= kWidthMatchTolerance_m) {
      return base::Result<std::size_t>::fail("width " + base::fmt(option.width_m) +
                                             " is already configured");
    }
  }
  config_order_.push_back(option.as_written);
  const auto pos = std::upper_bound(
      sorted_.begin(), sorted_.end(), option.width_m,
      [](double w, const SensorOption& o) { return w < o.width_m; });
  sorted_.insert(pos, std::move(option));
  return base::Result<std::size_t>::ok(sorted_.size());
}

OptionsSummary SensorOptions::summary() const { return OptionsSummary{config_order_}; }

double SensorOptions::default_width_m() const {
  const double average_m = (sorted_.front().width_m + sorted_.back().width_m) / 2.0;
  double best = sorted_.front().width_m;
  for (const SensorOption& o : sorted_) {
    if (o.width_m <= average_m + kWidthMatchTolerance_m) best = o.width_m;
  }
  return best;
}

std::optional<OptionIndex> SensorOptions::choose(
    double requested_width_m, const std::function<bool(OptionIndex)>& is_full) const {
  std::optional<OptionIndex> lower, higher;
  for (OptionIndex i = 0; i < sorted_.size(); ++i) {
    if (is_full(i)) continue;
    const double w = sorted_[i].width_m;
    if (std::fabs(w - requested_width_m) <= kWidthMatchTolerance_m) return i;
    if (w < requested_width_m) lower = i;            // ascending: the last one is the nearest
    if (w > requested_width_m && !higher) higher = i;  // the first one is the nearest
  }
  return lower ? lower : higher;
}

}  // namespace hazard
