// libFuzzer target: a mission's nodes.xml through load_mission and verify (as `uabt verify`
// and the gate read it) and through `uabt schema`.
#include "fuzz/nodes_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return uabt::fuzz::run_target<uabt::fuzz::NodesHarness>("fuzz_nodes", data, size);
}
