// libFuzzer target: a scenario with uplink events through the Behavior Tree Manager, which
// takes each uplink through the gate mid-run.
#include "fuzz/format_harnesses.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return uabt::fuzz::run_target<uabt::fuzz::ScenarioUplinkHarness>("fuzz_scenario_uplink", data,
                                                                   size);
}
