// libFuzzer target: uplink.json in a package on a fixed mission through the merge and the uplink
// gate.
#include "fuzz/format_harnesses.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return uabt::fuzz::run_target<uabt::fuzz::UplinkHarness>("fuzz_uplink", data, size);
}
