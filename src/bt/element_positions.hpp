#pragma once
// Internal to src/bt: where each element of a parsed document starts (line and column of '<').
#include <tinyxml2.h>

#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "bt/xml_scan.hpp"

namespace uabt::bt::detail {

// tinyxml2 gives lines only. The scanner saw the start tags in the same document order, so the
// two sequences are zipped; a mismatch (which would be a scanner bug) falls back to searching
// the element's line for "<Name".
class ElementPositions {
 public:
  ElementPositions(const tinyxml2::XMLDocument& xml, const std::vector<ElementStart>& starts,
                   const std::string& text);

  // (line, column); column 0 when unknown.
  std::pair<int, int> of(const tinyxml2::XMLElement* e) const;
  // (line, column) of each attribute name of the start tag at (line, column), in document
  // order; empty when the element's column is unknown.
  std::vector<std::pair<int, int>> attributes_at(int line, int column) const;

 private:
  int search_column(int line, const std::string& name) const;
  std::pair<int, int> position_of(std::size_t offset) const;
  std::vector<std::size_t> line_starts_;  // byte offset of each line

  const std::string& text_;
  std::unordered_map<const tinyxml2::XMLElement*, std::pair<int, int>> positions_;
};

}  // namespace uabt::bt::detail
