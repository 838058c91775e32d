#pragma once
// Internal: the line structure shared by requirements.fret and domain.fret.
#include <string>
#include <string_view>
#include <vector>

namespace uabt::fretish::detail {

struct Line {
  int number = 0;         // 1-based
  std::string_view text;  // without '\n', '\r' and the `#` comment
};

// Splits `content` into lines (LF or CRLF), drops a UTF-8 byte order mark and cuts each line
// at a `#` that is not inside a double-quoted string.
std::vector<Line> content_lines(std::string_view content);

bool is_blank(std::string_view text);

}  // namespace uabt::fretish::detail
