#pragma once
#include <string>

namespace uabt {

// A place in a mission file. Lines and columns are 1-based; 0 means "unknown".
// `file` is relative to the mission directory when the file lies inside it, so that
// reports never carry a path of the machine that produced them.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
  int end_line = 0;  // last line when the place spans several lines (a node's requirements)
};

// "requirements.fret:9:76": a file, line and column as every message names a place.
inline std::string place_text(const std::string& file, int line, int column) {
  return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}
inline std::string place_text(const SourceLocation& l) {
  return place_text(l.file, l.line, l.column);
}

// A span within one file (1-based, end inclusive of the last character).
struct SourceRange {
  int begin_line = 0;
  int begin_column = 0;
  int end_line = 0;
  int end_column = 0;
};

// Where `range` starts within an expression of `owner`: the owner's file at the range's line
// and column, or the owner itself when the range is unknown (a generated expression).
inline SourceLocation start_of(const SourceRange& range, const SourceLocation& owner) {
  if (range.begin_line == 0) return owner;
  return {owner.file, range.begin_line, range.begin_column};
}

}  // namespace uabt
