#pragma once
// Internal: maps byte offsets of a parsed text to file positions, and turns a failed parse
// into a `fretish-syntax` finding.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "base/finding.hpp"
#include "fretish/parse.hpp"
#include "fretish/syntax_tree.hpp"

namespace uabt::fretish::detail {

class TextMap {
 public:
  TextMap(std::string_view text, const TextOrigin& origin);

  SourceLocation location(std::size_t offset) const;
  // [begin, end) as an inclusive file range.
  SourceRange range(std::size_t begin, std::size_t end) const;
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  int line_ = 1;
  int column_ = 1;
  std::vector<std::size_t> line_starts_;
};

// The finding for a failed parse: "expected X[ after 'op'], found Y" at the furthest point.
// `end_name` says what the end of the text is ("end of requirement", "end of line").
Finding syntax_finding(const ParseOutcome& outcome, std::string_view text, const TextMap& map,
                       const char* end_name);

// 'word', keyword 'word', end of …: what stands at `offset`, for messages.
std::string describe_token(std::string_view text, std::size_t offset, const char* end_name);

bool is_reserved_word(std::string_view word);

// Length of `text` once trailing blanks and one final '.' are removed (FRET strips the
// sentence's '.' before lexing, since identifiers may contain '.').
std::size_t without_final_period(std::string_view text);

}  // namespace uabt::fretish::detail
