#pragma once
// The retained state: what a page that connects now receives before the live mail, so that it
// draws what a page connected since the start would draw (docs/viewer.md, "Retained state").
//
// Contract (pMarineViewer's rules, bounded):
// - VIEW_* variables: a posting with a `label` replaces the earlier posting of that variable
//   with that label; `active=false` removes it. Unlabelled postings are kept in a ring of the
//   newest `unlabelled_ring` per variable (an unlabelled active=false is not kept). At most
//   `max_labels` labels per variable: a new label beyond it evicts the oldest one.
// - NODE_REPORT: the newest `trail_length` reports per vehicle NAME; at most `max_vehicles`
//   vehicles (reports of more are not kept and are counted).
// - APPCAST: the newest per (node, proc); at most `max_appcasts` pairs.
// - Any other variable: its newest posting; for strings with a `vname` field (HAZARDSET_EVAL),
//   the newest per vname, as the score table has a row per vehicle.
// - A posting whose `duration` (MOOS seconds, from its `time` field, else the posting's time)
//   has run out by the viewer's own clock (set_clock: its MOOS time, as the clock events tell the
//   page) is left out of the snapshot (the page would expire it at once). The postings' own
//   times never move that clock: one stamped far in the future by a skewed clock hides nothing.
// - Strings longer than `max_value_bytes` are not kept (counted in `refused`).
// - snapshot() returns the kept postings in the order they arrived, oldest first.

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "view_mail.hpp"

namespace web_viewer {

struct RetentionLimits {
  std::size_t trail_length = 200;
  std::size_t max_vehicles = 100;
  std::size_t max_labels = 20000;
  std::size_t unlabelled_ring = 2000;
  std::size_t max_appcasts = 500;
  std::size_t max_value_bytes = 65536;
};

class RetainedState {
 public:
  explicit RetainedState(RetentionLimits limits = {}) : limits_(limits) {}

  void apply(const Mail& mail);
  /// The viewer's MOOS time, against which durations run out.
  void set_clock(double now_s) { clock_s_ = now_s; }
  std::vector<Mail> snapshot() const;
  /// Postings kept now.
  std::size_t size() const;
  /// Postings not kept because of a bound (vehicles, value size).
  std::uint64_t refused() const { return refused_; }
  const RetentionLimits& limits() const { return limits_; }

 private:
  struct Entry {
    std::uint64_t seq = 0;
    Mail mail;
  };
  struct Labelled {
    std::map<std::string, std::uint64_t> seq_of_label;
    std::map<std::uint64_t, Mail> by_seq;  // oldest first: the eviction order
  };
  void apply_view(const Mail& mail);
  void apply_node_report(const Mail& mail);
  void apply_appcast(const Mail& mail);
  Entry entry(const Mail& mail) { return Entry{next_seq_++, mail}; }

  RetentionLimits limits_;
  std::uint64_t next_seq_ = 0;
  std::uint64_t refused_ = 0;
  double clock_s_ = 0.0;
  std::map<std::string, Labelled> labelled_;                   // by VIEW_* variable
  std::map<std::string, std::deque<Entry>> unlabelled_;        // by VIEW_* variable
  std::map<std::string, std::deque<Entry>> trails_;            // by vehicle NAME
  std::map<std::pair<std::string, std::string>, Entry> appcasts_;  // by (node, proc)
  std::map<std::pair<std::string, std::string>, Entry> latest_;  // by (variable, vname)
};

/// The value of `key` (case-insensitive) in a comma list "a=1,b={x,y},c=2"; "" when absent.
std::string field_of(const std::string& value, std::string_view key);
/// The value of `key` in an APPCAST string (items separated by "!@#"); "" when absent.
std::string appcast_field(const std::string& value, std::string_view key);

}  // namespace web_viewer
