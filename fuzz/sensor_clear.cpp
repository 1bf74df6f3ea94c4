// Fuzz target: the UHZ_SENSOR_CLEAR mail parser; an accepted message is formatted and read back.

#include "fuzz_input.hpp"
#include "hazard/messages/sensor_clear.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::parse_and_reread(fuzz::as_text(data, size), hazard::parse_sensor_clear,
                         hazard::format_sensor_clear);
  return 0;
}
