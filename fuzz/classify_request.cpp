// Fuzz target: the UHZ_CLASSIFY_REQUEST mail parser; an accepted message is formatted and read
// back.

#include "fuzz_input.hpp"
#include "hazard/messages/classify_request.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::parse_and_reread(fuzz::as_text(data, size), hazard::parse_classify_request,
                         hazard::format_classify_request);
  return 0;
}
