#include "bt/element_positions.hpp"

#include <algorithm>

namespace uabt::bt::detail {

namespace {

using tinyxml2::XMLElement;

// Pre-order successor without recursion.
const XMLElement* next_in_document(const XMLElement* e) {
  if (const XMLElement* child = e->FirstChildElement()) return child;
  for (const tinyxml2::XMLNode* node = e; node != nullptr; node = node->Parent()) {
    if (const XMLElement* element = node->ToElement()) {
      if (const XMLElement* sibling = element->NextSiblingElement()) return sibling;
    }
  }
  return nullptr;
}

}  // namespace

ElementPositions::ElementPositions(const tinyxml2::XMLDocument& xml,
                                   const std::vector<ElementStart>& starts, const std::string& text)
    : text_(text) {
  std::size_t index = 0;
  for (const XMLElement* e = xml.FirstChildElement(); e != nullptr; e = next_in_document(e)) {
    const int line = e->GetLineNum();
    int column = 0;
    if (index < starts.size() && starts[index].name == e->Name() && starts[index].line == line) {
      column = starts[index].column;
    } else {
      column = search_column(line, e->Name());
    }
    ++index;
    positions_.emplace(e, std::pair{line, column});
  }
}

std::pair<int, int> ElementPositions::of(const XMLElement* e) const {
  const auto it = positions_.find(e);
  return it == positions_.end() ? std::pair{e->GetLineNum(), 0} : it->second;
}

int ElementPositions::search_column(int line, const std::string& name) const {
  std::size_t begin = 0;
  for (int l = 1; l < line; ++l) {
    begin = text_.find('\n', begin);
    if (begin == std::string::npos) return 0;
    ++begin;
  }
  const std::size_t end = std::min(text_.find('\n', begin), text_.size());
  const std::string needle = "<" + name;
  for (std::size_t at = text_.find(needle, begin); at != std::string::npos && at < end;
       at = text_.find(needle, at + 1)) {
    const std::size_t after = at + needle.size();
    const char next = after < text_.size() ? text_[after] : '>';
    if (next == ' ' || next == '\t' || next == '\r' || next == '\n' || next == '/' || next == '>') {
      int column = 1;
      for (std::size_t k = begin; k < at; ++k) {
        if ((static_cast<unsigned char>(text_[k]) & 0xC0) != 0x80) ++column;
      }
      return column;
    }
  }
  return 0;
}

}  // namespace uabt::bt::detail
