// libFuzzer target: BehaviorTree.CPP XML through parse_document, check_structure and write_document
// → parse_document.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fuzz/entry_points.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem =
      uabt::fuzz::check_bt_xml(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_bt_xml: invariant violated: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
