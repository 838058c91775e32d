#pragma once
#include <cctype>
#include <string>
#include <string_view>

namespace uabt {

// `text` in lower case, ASCII only: FRETISH's keywords and BT.CPP's status names are ASCII.
inline std::string lower_case(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace uabt
