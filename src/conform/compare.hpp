#pragma once
#include <optional>
#include <string>

#include "bt/tree.hpp"

namespace uabt::conform {

// The first place (pre-order) where a compiled subtree departs from its source.
struct Difference {
  const bt::Node* node = nullptr;  // in the compiled tree (the parent when a child is missing)
  std::string path;
  std::string what;  // "attribute speed is \"2.5\", expected \"2.0\""
};

// How an <Adaptable ID="A"/> of the source may look once compiled: nullptr when the source
// has no adaptable nodes (an alternative), else the compiled document's BT.CPP format.
struct AdaptableRule {
  int bt_format = 4;
};

// Compares a source node with its compiled counterpart: same tag, same attributes (XML
// attribute order carries no meaning), same children in the same order. With `adaptables`,
// a source <Adaptable ID="A"/> must have become <SubTree ID="A"/> (keeping its name, plus at
// most the format's remap attribute); a compiled <Adaptable> left in its place is not a
// difference here (compiled-adaptable-left reports it).
std::optional<Difference> first_difference(const bt::Node& source, const bt::Node& compiled,
                                           const std::string& path,
                                           const AdaptableRule* adaptables);

// Structural equality under the same rules, without an adaptable exception.
bool same_tree(const bt::Node& a, const bt::Node& b);

}  // namespace uabt::conform
