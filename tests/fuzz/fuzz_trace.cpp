// libFuzzer target: a monitor trace (JSON lines) through read_trace and check_trace.
#include "fuzz/format_harnesses.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return uabt::fuzz::run_target<uabt::fuzz::TraceHarness>("fuzz_trace", data, size);
}
