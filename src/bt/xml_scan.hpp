#pragma once
// Internal to src/bt: a single pass over raw XML text, before tinyxml2 sees it. It refuses what
// tinyxml2 would accept but uabt must not (binary data, invalid UTF-8, DTDs, absurd nesting),
// and records where each element's '<' is, which tinyxml2 does not (it gives lines only).
#include <optional>
#include <string>
#include <vector>

namespace uabt::bt::detail {

struct ElementStart {
  std::string name;
  int line = 0;
  int column = 0;  // 1-based, in characters (UTF-8 code points; a tab counts as one)
};

struct ScanProblem {
  std::string message;
  int line = 0;
  int column = 0;
};

struct ScanResult {
  std::vector<ElementStart> elements;  // start tags in document order
  std::optional<ScanProblem> problem;  // the first reason to refuse the text
};

// `max_depth`: deepest element nesting accepted (the document element is depth 1).
ScanResult scan_xml(const std::string& text, int max_depth);

}  // namespace uabt::bt::detail
