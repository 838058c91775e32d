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
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i)
    if (text_[i] == '\n') line_starts_.push_back(i + 1);
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

std::pair<int, int> ElementPositions::position_of(std::size_t offset) const {
  const auto next = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const std::size_t line = static_cast<std::size_t>(next - line_starts_.begin());
  int column = 1;
  for (std::size_t k = line_starts_[line - 1]; k < offset; ++k)
    if ((static_cast<unsigned char>(text_[k]) & 0xC0) != 0x80) ++column;
  return {static_cast<int>(line), column};
}

std::vector<std::pair<int, int>> ElementPositions::attributes_at(int line, int column) const {
  std::vector<std::pair<int, int>> out;
  if (line < 1 || column < 1 || static_cast<std::size_t>(line) > line_starts_.size()) return out;
  std::size_t at = line_starts_[static_cast<std::size_t>(line) - 1];
  for (int c = 1; c < column && at < text_.size(); ++c) {  // to the '<', by code points
    ++at;
    while (at < text_.size() && (static_cast<unsigned char>(text_[at]) & 0xC0) == 0x80) ++at;
  }
  if (at >= text_.size() || text_[at] != '<') return out;
  const auto space = [](char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n'; };
  const auto name_end = [&](std::size_t i) {
    while (i < text_.size() && !space(text_[i]) && text_[i] != '=' && text_[i] != '/' &&
           text_[i] != '>')
      ++i;
    return i;
  };
  std::size_t i = name_end(at + 1);  // past the element's name
  while (true) {
    while (i < text_.size() && space(text_[i])) ++i;
    if (i >= text_.size() || text_[i] == '/' || text_[i] == '>') break;
    out.push_back(position_of(i));
    i = name_end(i);
    while (i < text_.size() && (space(text_[i]) || text_[i] == '=')) ++i;
    if (i >= text_.size() || (text_[i] != '"' && text_[i] != '\'')) break;
    const std::size_t close = text_.find(text_[i], i + 1);
    if (close == std::string::npos) break;
    i = close + 1;
  }
  return out;
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
