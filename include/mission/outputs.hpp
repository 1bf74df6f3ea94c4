#pragma once
// What one call into a mission-side core produced: postings in order, plus texts for the
// application's report. Like hazard::Outputs, with one addition: a posting may be a MOOS double
// (uFldHazardMetric posts HAZARD_SEARCH_SCORE as a double, docs/mission-logic.md).

#include <optional>
#include <string>
#include <vector>

namespace mission {

struct Posting {
  std::string variable;
  std::string text;              ///< the string value; unused when `number` is set
  std::optional<double> number;  ///< set: post as a double
};

struct Outputs {
  std::vector<Posting> postings;  ///< in posting order
  std::vector<std::string> events;
  std::vector<std::string> run_warnings;
  std::vector<std::string> config_warnings;

  void post(std::string variable, std::string text) {
    postings.push_back({std::move(variable), std::move(text), std::nullopt});
  }
  void post_double(std::string variable, double value) {
    postings.push_back({std::move(variable), std::string(), value});
  }
  /// Appends everything `other` holds (keeps the order).
  void append(Outputs other);
  bool empty() const {
    return postings.empty() && events.empty() && run_warnings.empty() && config_warnings.empty();
  }
  /// Empties it, keeping the vectors' storage (a caller that fills one Outputs every cycle).
  void clear() {
    postings.clear();
    events.clear();
    run_warnings.clear();
    config_warnings.clear();
  }
};

}  // namespace mission
