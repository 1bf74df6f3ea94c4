// Fuzz target: the UHZ_SENSOR_REQUEST mail parser; an accepted message is formatted and read back.

#include "fuzz_input.hpp"
#include "hazard/messages/sensor_request.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::parse_and_reread(fuzz::as_text(data, size), hazard::parse_sensor_request,
                         hazard::format_sensor_request);
  return 0;
}
