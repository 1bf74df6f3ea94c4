// Fuzz target: the UHZ_CONFIG_REQUEST mail parser; an accepted message is formatted and read back.

#include "fuzz_input.hpp"
#include "hazard/messages/config_request.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::parse_and_reread(fuzz::as_text(data, size), hazard::parse_config_request,
                         hazard::format_config_request);
  return 0;
}
