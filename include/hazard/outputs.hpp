#pragma once
// What one engine call produced (a step's outputs are one value).
// The app posts `postings` to MOOS in order; hazard_replay writes them to the .alog.

#include <string>
#include <vector>

namespace hazard {

struct Posting {
  std::string variable;
  std::string value;
};

struct Outputs {
  std::vector<Posting> postings;                    ///< in posting order
  std::vector<std::string> events;                  ///< for the report's event list
  std::vector<std::string> run_warnings;
  std::vector<std::string> retracted_run_warnings;  ///< texts whose condition has cleared
  std::vector<std::string> config_warnings;

  void post(std::string variable, std::string value) {
    postings.push_back({std::move(variable), std::move(value)});
  }
  bool empty() const {
    return postings.empty() && events.empty() && run_warnings.empty() &&
           retracted_run_warnings.empty() && config_warnings.empty();
  }
};

}  // namespace hazard
