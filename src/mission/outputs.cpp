#include "mission/outputs.hpp"

#include <iterator>

namespace mission {

void Outputs::append(Outputs other) {
  auto move_all = [](auto& to, auto& from) {
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
  };
  move_all(postings, other.postings);
  move_all(events, other.events);
  move_all(run_warnings, other.run_warnings);
  move_all(config_warnings, other.config_warnings);
}

}  // namespace mission
