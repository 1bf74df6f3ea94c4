// Fuzz target: a whole hazard file, loaded into a field whose spatial index is then built and
// queried, as uFldHazardSensor and hazard_replay do at start-up.

#include <string>
#include <vector>

#include "fuzz_input.hpp"
#include "hazard/hazard_field.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hazard::HazardField field;
  std::vector<std::string> warnings;
  (void)hazard::load_hazard_file_text(fuzz::as_text(data, size), "fuzz.txt", field, warnings);
  field.build_index();
  // Query around every object, so a grid built from extreme positions is also read.
  for (hazard::ObjectId id = 0; id < field.size(); ++id) {
    const glm::dvec2 p = field.position(id);
    field.grid().for_each_in_box(hazard::Box{p.x - 10, p.y - 10, p.x + 10, p.y + 10},
                                 [](std::uint32_t, glm::dvec2) {});
  }
  return 0;
}
