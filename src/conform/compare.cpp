// Node-for-node comparison of a compiled subtree with the file it came from.
#include "conform/compare.hpp"

#include <algorithm>
#include <vector>

#include "bt/node_kinds.hpp"
#include "conform/context.hpp"

namespace uabt::conform {

namespace {

using Attributes = std::vector<std::pair<std::string, std::string>>;

std::string quote(const std::string& s) {
  return "\"" + s + "\"";
}

// The first attribute that differs, in the source's order, then the compiled node's extras.
std::optional<std::string> attribute_difference(const Attributes& source,
                                                const Attributes& compiled) {
  auto find = [](const Attributes& attrs, const std::string& key) -> const std::string* {
    for (const auto& [k, v] : attrs)
      if (k == key) return &v;
    return nullptr;
  };
  for (const auto& [key, value] : source) {
    const std::string* other = find(compiled, key);
    if (other == nullptr) return "attribute " + key + "=" + quote(value) + " is missing";
    if (*other != value)
      return "attribute " + key + " is " + quote(*other) + ", expected " + quote(value);
  }
  for (const auto& [key, value] : compiled)
    if (find(source, key) == nullptr)
      return "attribute " + key + "=" + quote(value) + " is not in the source";
  return std::nullopt;
}

std::optional<std::string> adaptable_difference(const bt::Node& source, const bt::Node& compiled,
                                                int bt_format) {
  const std::string* id = source.attribute("ID");
  const std::string shown = "<Adaptable ID=" + quote(id ? *id : "") + ">";
  if (compiled.tag != bt::kind_name(bt::NodeKind::subtree))
    return shown + " became <" + compiled.tag + ">, expected <SubTree ID=" + quote(id ? *id : "") +
           ">";
  if (!compiled.children.empty()) return "the SubTree that replaces " + shown + " has children";
  Attributes expected;
  for (const auto& [key, value] : source.attributes)
    if (key == "ID" || key == "name") expected.emplace_back(key, value);
  Attributes actual;
  for (const auto& [key, value] : compiled.attributes) {
    if (is_remap_attribute(key, bt_format)) {
      if (value != "true")
        return "the SubTree that replaces " + shown + " has " + key + "=" + quote(value) +
               "; only \"true\" (or no remapping attribute) keeps the parent's blackboard";
      continue;
    }
    actual.emplace_back(key, value);
  }
  if (auto what = attribute_difference(expected, actual))
    return "the SubTree that replaces " + shown + ": " + *what;
  return std::nullopt;
}

// A node's attributes without the ID of the explicit form (<Action ID="X">).
std::vector<std::pair<std::string, std::string>> without_id(const bt::Node& n) {
  if (n.tag == n.kind()) return n.attributes;
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& a : n.attributes)
    if (a.first != "ID") out.push_back(a);
  return out;
}

struct Frame {
  const bt::Node* source;
  const bt::Node* compiled;
  std::string path;
};

}  // namespace

std::optional<Difference> first_difference(const bt::Node& source, const bt::Node& compiled,
                                           const std::string& path,
                                           const AdaptableRule* adaptables) {
  // Explicit stack: trees can be deep, and the comparison must not overflow.
  std::vector<Frame> pending{{&source, &compiled, path}};
  while (!pending.empty()) {
    Frame f = std::move(pending.back());
    pending.pop_back();
    const bt::Node& s = *f.source;
    const bt::Node& c = *f.compiled;
    if (adaptables != nullptr && s.tag == "Adaptable") {
      // An adaptable node left as it is: compiled-adaptable-left reports it, once.
      if (c.tag == "Adaptable") continue;
      if (auto what = adaptable_difference(s, c, adaptables->bt_format))
        return Difference{&c, f.path, *what};
      continue;
    }
    // <Condition ID="Stow"/> and <Stow/> are one node to BT.CPP: the ID is the node, not an
    // attribute, and the writer may give either form.
    if (s.tag != c.tag && s.kind() != c.kind())
      return Difference{&c, f.path, "<" + c.tag + "> where the source has <" + s.tag + ">"};
    if (auto what = attribute_difference(without_id(s), without_id(c)))
      return Difference{&c, f.path, *what};
    const std::size_t n = std::min(s.children.size(), c.children.size());
    if (s.children.size() != c.children.size()) {
      // A child added or removed: name the first position where the lists part.
      std::size_t i = 0;
      while (i < n && !first_difference(s.children[i], c.children[i], "", adaptables)) ++i;
      const std::string what = c.children.size() < s.children.size()
                                   ? "child " + std::to_string(i) + " of the source, <" +
                                         s.children[i].tag + ">, is missing"
                                   : "child " + std::to_string(i) + ", <" + c.children[i].tag +
                                         ">, is not in the source";
      return Difference{&c, f.path,
                        what + " (" + std::to_string(c.children.size()) + " children, expected " +
                            std::to_string(s.children.size()) + ")"};
    }
    for (std::size_t i = n; i-- > 0;)
      pending.push_back({&s.children[i], &c.children[i], child_path(f.path, c.children[i], i)});
  }
  return std::nullopt;
}

bool same_tree(const bt::Node& a, const bt::Node& b) {
  return !first_difference(a, b, "", nullptr).has_value();
}

}  // namespace uabt::conform
