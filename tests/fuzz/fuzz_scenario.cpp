// libFuzzer target: scenario JSON through parse_scenario, check_scenario and a bounded run.
#include "fuzz/format_harnesses.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return uabt::fuzz::run_target<uabt::fuzz::ScenarioHarness>("fuzz_scenario", data, size);
}
