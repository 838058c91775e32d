// bb-type-conflict: BT.CPP types an entry by the first port that creates it; a later port of
// another type refuses the tree at load ("the port [x] was initially created with type [A]
// and, later type [B] was used somewhere else"), unless the first type is std::string, which
// converts to any type when read. Values scripts assign must fit the port's type too.
#include <cstdint>
#include <map>
#include <set>
#include <tuple>

#include "bt/port_types.hpp"
#include "verify/tree/blackboard_checks.hpp"

namespace uabt::verify::tree {

using bt::is_string_type;
using bt::literal_converts;
using bt::same_type;
using bt::strongly_typed;

namespace {

std::string use_text(const TypedUse& u) {
  if (u.from_script)
    return u.what + (u.type == "string" ? " (a string, '" + u.literal + "')" : " (a number)");
  return u.what + " (" + u.type + ")";
}

// Whether `later` may use an entry that `first` created, as BT.CPP decides it.
bool compatible(const TypedUse& first, const TypedUse& later) {
  if (!first.from_script && !later.from_script) {
    if (!strongly_typed(first.type) || !strongly_typed(later.type)) return true;
    if (is_string_type(first.type)) return true;
    return same_type(first.type, later.type);
  }
  const TypedUse& port = first.from_script ? later : first;
  const TypedUse& script = first.from_script ? first : later;
  if (port.from_script) return script.type == port.type || script.type == "string";
  if (!strongly_typed(port.type)) return true;
  if (script.type == "string") return literal_converts(script.literal, port.type);
  return !is_string_type(port.type);  // a number into a string entry
}

}  // namespace

std::vector<Finding> check_type_conflicts(const FlowGraph& g) {
  std::vector<Finding> out;
  std::map<std::uint32_t, const TypedUse*> first;  // the use that types each entry
  std::set<std::tuple<std::string, int, int, std::string, int, int>> reported;
  auto report = [&](const TypedUse& at, const TypedUse& other, const std::string& entry) {
    const SourceLocation& a = at.location;
    const SourceLocation& b = other.location;
    if (!reported.insert({a.file, a.line, a.column, b.file, b.line, b.column}).second) return;
    Finding f = make_finding("bb-type-conflict",
                             "blackboard entry " + entry + " is used by " + use_text(at) +
                                 " and by " + use_text(other) +
                                 ": BehaviorTree.CPP refuses to mix the two types in one entry",
                             a);
    f.related.push_back({b, "the other use: " + use_text(other)});
    f.notes.push_back(
        "use one type for the entry everywhere (the ports' type= in nodes.xml, the values "
        "scripts assign), or give each use its own entry");
    out.push_back(std::move(f));
  };
  for (const TypedUse& use : g.typed_uses) {
    auto [it, inserted] = first.emplace(use.entry, &use);
    if (inserted) continue;
    const TypedUse& prior = *it->second;
    if (prior.from_script && !use.from_script) {
      // A port fixes the type a script's value must fit: let the port type the entry.
      if (!compatible(use, prior)) {
        report(use, prior, g.entry_name(use.entry));
        report(prior, use, g.entry_name(use.entry));
      }
      it->second = &use;
      continue;
    }
    if (compatible(prior, use)) continue;
    report(use, prior, g.entry_name(use.entry));
    report(prior, use, g.entry_name(use.entry));
  }
  return out;
}

}  // namespace uabt::verify::tree
