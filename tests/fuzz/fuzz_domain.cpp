// libFuzzer target: domain.fret text through parse_domain_file.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fuzz/entry_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      uabt::fuzz::check_domain_file(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_domain: invariant violated: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
