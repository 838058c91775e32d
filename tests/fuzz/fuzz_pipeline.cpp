// libFuzzer target: the whole gate (load → verify → compile → write → conform) on a fixed
// mission whose requirements.fret and domain.fret come from the input, split at a line "%%".
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fuzz/pipeline_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static uabt::fuzz::PipelineHarness harness;  // the mission directory, written once
  const std::string problem =
      harness.check(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_pipeline: invariant violated: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
