// --selection optimized: a selection tree that decides over the guards' atoms instead of
// trying the guards one after the other, emitted with BT.CPP 4.10 nodes only (IfThenElse,
// Sequence, Inverter, condition leaves, ScriptCondition; re-checked every tick: WhileDoElse,
// ReactiveSequence).
#include <algorithm>

#include "bt/node_kinds.hpp"
#include "bt/structure.hpp"
#include "compile/compile.hpp"
#include "fretish/requirement.hpp"

namespace uabt::compile {

namespace {

using K = bt::NodeKind;

class Emitter {
 public:
  Emitter(const load::Mission& m, const std::string& adaptable,
          const std::vector<const fretish::SelectionRequirement*>& reqs,
          const SelectionSpace& space, const Decision& decision, int bt_format, bool reactive)
      : m_(m),
        adaptable_(adaptable),
        reqs_(reqs),
        space_(space),
        decision_(decision),
        bt_format_(bt_format),
        reactive_(reactive) {}

  bt::Node root() {
    std::vector<std::size_t> cells(space_.cells());
    for (std::size_t c = 0; c < cells.size(); ++c) cells[c] = c;
    bt::Node n = emit(decision_.root, cells);
    // One requirement holds in every state: its leaf goes below a selector of its own, so that
    // the leaf keeps its requirement's name and the selector the node's.
    if (decision_.nodes[decision_.root].test < 0 && decision_.nodes[decision_.root].label >= 0)
      n = node(K::sequence, {std::move(n)});
    n.set_attribute("name", adaptable_);
    return n;
  }

  // Trace entries for the emitted tree, once it has its final shape. `in_leaf`: the
  // requirement of the leaf `n` lies in (its alternative call names it).
  void trace(const bt::Node& n, const std::string& path, std::vector<TraceEntry>& out,
             const fretish::SelectionRequirement* in_leaf = nullptr) const {
    TraceEntry e;
    e.tree_id = adaptable_;
    e.node_path = path;
    const fretish::SelectionRequirement* leaf = in_leaf;
    if (path.find('/') == path.rfind('/')) {
      e.atom = "selector";
    } else if (const auto* req = leaf_requirement(n)) {
      leaf = req;
      e.requirement = req->id;
      e.atom = "requirement";
      e.source = req->location;
    } else if (bt::node_kind(n.tag) == K::subtree && leaf != nullptr) {
      e.requirement = leaf->id;
      e.atom = "selected_alt = " + leaf->alternative;
      e.source = leaf->alternative_location;
    } else if (bt::node_kind(n.tag) == K::script_condition) {
      e.atom = *n.attribute("code");
      e.source = source_of(e.atom);
    } else if (n.children.empty()) {
      e.atom = n.tag;
      e.source = source_of(n.tag);
    } else {
      e.atom = bt::node_kind(n.tag) == K::inverter ? "!" : "decision";
    }
    out.push_back(e);
    for (std::size_t i = 0; i < n.children.size(); ++i)
      trace(n.children[i], bt::child_path(path, n.children[i], i), out, leaf);
  }

 private:
  // The requirement a leaf (a Sequence named after it, calling its alternative) selects for.
  const fretish::SelectionRequirement* leaf_requirement(const bt::Node& n) const {
    const std::string* name = n.attribute("name");
    if (bt::node_kind(n.tag) != K::sequence || name == nullptr || n.children.size() != 1)
      return nullptr;
    for (const auto* r : reqs_)
      if (r->id == *name) return r;
    return nullptr;
  }

  static bt::Node node(std::string tag, std::vector<bt::Node> children = {}) {
    bt::Node n;
    n.tag = std::move(tag);
    n.children = std::move(children);
    return n;
  }
  static bt::Node node(K kind, std::vector<bt::Node> children = {}) {
    return node(bt::kind_name(kind), std::move(children));
  }

  // The requirement's guard location whose atoms read what a test reads.
  SourceLocation source_of(const std::string& text) const {
    const std::string name = first_word(text);
    for (const auto* r : reqs_) {
      if (r->guard == nullptr) continue;
      const auto ids = fretish::identifiers_of(*r->guard);
      if (std::find(ids.begin(), ids.end(), name) != ids.end()) return r->guard_location;
    }
    return {};
  }
  static std::string first_word(const std::string& text) {
    const auto end = text.find_first_of(" =<>!");
    return text.substr(0, end);
  }

  bt::Node leaf(int label) const {
    const auto* req = reqs_[static_cast<std::size_t>(label)];
    const load::Alternative* alt = m_.find_alternative(adaptable_, req->alternative);
    bt::Node call = node(K::subtree);
    call.set_attribute("ID", alt ? alt->tree_id : req->alternative);
    call.set_attribute(bt_format_ == 3 ? "__shared_blackboard" : "_autoremap", "true");
    bt::Node branch = node(K::sequence, {std::move(call)});
    branch.set_attribute("name", req->id);
    return branch;
  }

  // The condition of a test, written for the pieces the cells at this node can be in;
  // `negated` is set when the shorter text is that of the other side.
  bt::Node condition(const DecisionTest& t, const std::vector<std::size_t>& cells,
                     bool& negated) const {
    const Dimension& dim = space_.dimensions[t.dimension];
    negated = false;
    switch (dim.kind) {
      case Dimension::Kind::boolean: return node(dim.name);
      case Dimension::Kind::opaque:
        return guard_to_tree(*dim.atom, m_.domain, SelectionStyle::sequence);
      case Dimension::Kind::ordered: {
        std::size_t last = 0;  // the last piece where the test holds
        while (last + 1 < t.holds.size() && t.holds[last + 1]) ++last;
        const auto& here = dim.pieces[last];
        const auto& next = dim.pieces[last + 1];
        bt::Node n = node(K::script_condition);
        n.set_attribute("code", here.point
                                    ? dim.name + " <= " + here.text
                                    : dim.name + " < " + (next.point ? next.text : here.text));
        return n;
      }
      case Dimension::Kind::enumeration: {
        std::vector<bool> present(dim.pieces.size(), false);
        for (std::size_t c : cells) present[space_.piece(c, t.dimension)] = true;
        std::vector<std::string> yes, no;
        for (std::size_t p = 0; p < dim.pieces.size(); ++p)
          if (present[p]) (t.holds[p] ? yes : no).push_back(dim.pieces[p].text);
        negated = no.size() < yes.size();
        std::string code;
        for (const auto& lit : negated ? no : yes)
          code += (code.empty() ? "" : " || ") + dim.name + " == '" + lit + "'";
        bt::Node n = node(K::script_condition);
        n.set_attribute("code", code);
        return n;
      }
    }
    return node(K::always_failure);
  }

  bool is_gap(int at) const {
    return decision_.nodes[at].test < 0 && decision_.nodes[at].label < 0;
  }

  bt::Node emit(int at, const std::vector<std::size_t>& cells) const {
    const Decision::Node& d = decision_.nodes[at];
    if (d.test < 0) return d.label < 0 ? node(K::always_failure) : leaf(d.label);
    const DecisionTest& t = decision_.tests[d.test];
    std::vector<std::size_t> yes_cells, no_cells;
    for (std::size_t c : cells)
      (t.holds[space_.piece(c, t.dimension)] ? yes_cells : no_cells).push_back(c);
    bool negated = false;
    bt::Node test = condition(t, cells, negated);
    int yes = d.yes, no = d.no;
    if (negated) {
      std::swap(yes, no);
      std::swap(yes_cells, no_cells);
    }
    // A side where no requirement holds fails: Sequence[test, other side] (with the test
    // inverted when the gap is on its true side). Reactive: the test runs again every tick and
    // halts the side it no longer selects, as Fig. 4's ReactiveFallback does.
    const K guarded = reactive_ ? K::reactive_sequence : K::sequence;
    if (is_gap(no)) return node(guarded, {std::move(test), emit(yes, yes_cells)});
    if (is_gap(yes))
      return node(guarded, {node(K::inverter, {std::move(test)}), emit(no, no_cells)});
    return node(reactive_ ? K::while_do_else : K::if_then_else,
                {std::move(test), emit(yes, yes_cells), emit(no, no_cells)});
  }

  const load::Mission& m_;
  const std::string& adaptable_;
  const std::vector<const fretish::SelectionRequirement*>& reqs_;
  const SelectionSpace& space_;
  const Decision& decision_;
  int bt_format_;
  bool reactive_;
};

int depth_of(const bt::Node& n) {
  int d = 0;
  for (const auto& c : n.children) d = std::max(d, depth_of(c));
  return d + 1;
}

}  // namespace

std::optional<bt::Node> optimized_selector(const load::Mission& m, const std::string& adaptable,
                                           int bt_format, bool reactive,
                                           std::vector<TraceEntry>& trace, SelectionStats& stats) {
  const auto reqs = m.selections_for(adaptable);
  stats.adaptable = adaptable;
  stats.requirements = reqs.size();
  std::vector<fretish::ExprPtr> guards;
  for (const auto* r : reqs) guards.push_back(r->guard);
  const auto space = build_selection_space(guards, m.domain);
  if (!space) {
    stats.reason = "too many states to decide over";
    return std::nullopt;
  }
  stats.cells = space->cells();
  stats.algorithm1 = algorithm1_cost(*space);
  stats.optimized = stats.algorithm1;
  if (space->cells() == 0) {
    stats.reason = "the domain has no state";
    return std::nullopt;
  }
  const Decision decision = build_decision(*space);
  const SelectionCost cost = decision_cost(*space, decision);
  constexpr double eps = 1e-9;
  const bool cheaper =
      cost.average < stats.algorithm1.average - eps ||
      (cost.average <= stats.algorithm1.average + eps && cost.worst < stats.algorithm1.worst);
  if (!cheaper) {
    stats.reason = "Fig. 4 ticks no more conditions";
    return std::nullopt;
  }
  Emitter emitter(m, adaptable, reqs, *space, decision, bt_format, reactive);
  bt::Node root = emitter.root();
  if (depth_of(root) > bt::kMaxDepth) {  // its file could not be read back
    stats.reason = "the decision structure would nest too deep";
    return std::nullopt;
  }
  stats.optimized = cost;
  stats.optimized_used = true;
  emitter.trace(root, adaptable + "/" + root.tag, trace);
  return root;
}

}  // namespace uabt::compile
