#pragma once
// Internal: where the requirements and variables of a FRET export stand in the JSON text,
// so that findings name the line of a requirement's "fulltext" (nlohmann::json keeps no
// positions).
#include <cstddef>
#include <string_view>
#include <vector>

namespace uabt::fretish::detail {

struct JsonPosition {
  int line = 1;
  int column = 1;
};

struct JsonElement {
  JsonPosition start;          // the element's first character
  bool has_text = false;       // a "fulltext" string member was found
  JsonPosition text;           // first character inside the "fulltext" quotes
  std::size_t text_quote = 0;  // offset of the "fulltext" value's opening quote
};

struct JsonLayout {
  std::vector<JsonElement> requirements;  // elements of the requirements array, in order
  std::vector<JsonPosition> variables;    // elements of the "variables" array, in order
};

// Expects text that nlohmann::json accepted.
JsonLayout scan_fret_export(std::string_view text);

JsonPosition position_of(std::string_view text, std::size_t offset);

}  // namespace uabt::fretish::detail
