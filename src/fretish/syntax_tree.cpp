#include "fretish/syntax_tree.hpp"

#include <algorithm>
#include <cstring>

namespace uabt::fretish::detail {

void ParseState::expect(std::size_t pos, const char* name) {
  if (!any_expected || pos > furthest) {
    any_expected = true;
    furthest = pos;
    expected.assign(1, name);
    return;
  }
  if (pos < furthest) return;
  const bool known = std::any_of(expected.begin(), expected.end(),
                                 [name](const char* e) { return std::strcmp(e, name) == 0; });
  if (!known) expected.push_back(name);
}

}  // namespace uabt::fretish::detail
