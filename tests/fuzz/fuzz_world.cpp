// libFuzzer target: world.json for a fixed mission through parse_world and a bounded proof.
#include "fuzz/format_harnesses.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return uabt::fuzz::run_target<uabt::fuzz::WorldHarness>("fuzz_world", data, size);
}
