// Fuzz target: the UHZ_SENSOR_CLEAR mail parser; an accepted message is formatted and read back.

#include "fuzz_input.hpp"
#include "hazard/messages/sensor_clear.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parsed = hazard::parse_sensor_clear(fuzz::as_text(data, size));
  if (parsed.value) (void)hazard::parse_sensor_clear(hazard::format_sensor_clear(*parsed.value));
  return 0;
}
