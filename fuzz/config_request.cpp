// Fuzz target: the UHZ_CONFIG_REQUEST mail parser; an accepted message is formatted and read back.

#include "fuzz_input.hpp"
#include "hazard/messages/config_request.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto parsed = hazard::parse_config_request(fuzz::as_text(data, size));
  if (parsed.value) (void)hazard::parse_config_request(hazard::format_config_request(*parsed.value));
  return 0;
}
