// libFuzzer target: a FRET export through parse_fret_json and classify_selection.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fuzz/entry_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      uabt::fuzz::check_fret_json(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_fret_json: invariant violated: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
