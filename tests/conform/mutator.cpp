// First-order mutants of a compiled behavior tree, for the conformance checker's mutation test.
#include "mutator.hpp"

#include <cctype>
#include <functional>
#include <map>

#include "bt/node_kinds.hpp"

namespace uabt::testing::mutation {

namespace {

// A node of the document: a tree and the child indices from its root.
struct Ref {
  std::size_t tree = 0;
  std::vector<std::size_t> path;

  Ref child(std::size_t i) const {
    Ref r = *this;
    r.path.push_back(i);
    return r;
  }
  Ref parent() const {
    Ref r = *this;
    r.path.pop_back();
    return r;
  }
};

bt::Node& at(bt::Document& doc, const Ref& r) {
  bt::Node* n = &doc.trees[r.tree].root;
  for (std::size_t i : r.path) n = &n->children[i];
  return *n;
}
const bt::Node& at(const bt::Document& doc, const Ref& r) {
  const bt::Node* n = &doc.trees[r.tree].root;
  for (std::size_t i : r.path) n = &n->children[i];
  return *n;
}

std::string path_of(const bt::Document& doc, const Ref& r) {
  const bt::Node* n = &doc.trees[r.tree].root;
  std::string out = doc.trees[r.tree].id + "/" + n->tag;
  for (std::size_t i : r.path) {
    n = &n->children[i];
    out += "/" + n->tag + "[" + std::to_string(i) + "]";
  }
  return out;
}

bt::Node node(std::string tag, std::vector<bt::Node> children = {}) {
  bt::Node n;
  n.tag = std::move(tag);
  n.children = std::move(children);
  return n;
}

bool is_call(const bt::Node& n) {
  return n.kind() == "SubTree" || n.kind() == "SubTreePlus";
}
bool is_control(const std::string& k) {
  return k == "Sequence" || k == "ReactiveSequence" || k == "Fallback" || k == "ReactiveFallback";
}
bool is_conjunction(const std::string& k) {
  return k == "Sequence" || k == "ReactiveSequence";
}
std::string dual(const std::string& k) {
  if (k == "Sequence") return "Fallback";
  if (k == "Fallback") return "Sequence";
  if (k == "ReactiveSequence") return "ReactiveFallback";
  return "ReactiveSequence";
}
bool is_decorator(const bt::Node& n) {
  const bt::BuiltinNode* b = bt::find_builtin(n.kind());
  return b != nullptr && b->family == bt::Family::decorator;
}
// A condition leaf of the robot: not built in, not a call, no children.
bool is_condition_leaf(const bt::Node& n) {
  return n.children.empty() && !is_call(n) && n.tag != "Adaptable" &&
         bt::find_builtin(n.kind()) == nullptr;
}

void all_nodes(const bt::Document& doc, const Ref& from, std::vector<Ref>& out) {
  out.push_back(from);
  const bt::Node& n = at(doc, from);
  for (std::size_t i = 0; i < n.children.size(); ++i) all_nodes(doc, from.child(i), out);
}

// A branch's condition-checking subtree: where the branch holds it, and its body (the called
// tree's root when the branch calls a conditions tree, as the paper's generator does).
struct GuardSite {
  std::string adaptable;
  std::size_t branch = 0;
  Ref call_site;
  Ref body;
  bool behind_call = false;
};

// Script tokens that mutants change: identifiers, numbers, comparison operators.
struct ScriptToken {
  std::size_t offset, length;
  enum { name, number, comparison } kind;
};

std::vector<ScriptToken> script_tokens(const std::string& code) {
  std::vector<ScriptToken> out;
  for (std::size_t i = 0; i < code.size();) {
    const char c = code[i];
    if (c == '\'') {
      const std::size_t close = code.find('\'', i + 1);
      i = close == std::string::npos ? code.size() : close + 1;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < code.size() &&
             (std::isalnum(static_cast<unsigned char>(code[j])) || code[j] == '_'))
        ++j;
      const std::string word = code.substr(i, j - i);
      if (word != "true" && word != "false") out.push_back({i, j - i, ScriptToken::name});
      i = j;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t j = i;
      while (j < code.size() &&
             (std::isdigit(static_cast<unsigned char>(code[j])) || code[j] == '.'))
        ++j;
      out.push_back({i, j - i, ScriptToken::number});
      i = j;
    } else if (c == '<' || c == '>' || c == '=' || c == '!') {
      const bool two = i + 1 < code.size() && code[i + 1] == '=';
      if (c == '<' || c == '>' || two) out.push_back({i, two ? 2u : 1u, ScriptToken::comparison});
      i += two ? 2 : 1;
    } else {
      ++i;
    }
  }
  return out;
}

std::string swapped_comparison(const std::string& op) {
  static const std::map<std::string, std::string> swap = {{"<", "<="}, {"<=", "<"},  {">", ">="},
                                                          {">=", ">"}, {"==", "!="}, {"!=", "=="}};
  return swap.at(op);
}

std::string changed_value(const std::string& v) {
  if (v == "true") return "false";
  if (v == "false") return "true";
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (!v.empty() && end == v.c_str() + v.size()) {
    if (v.find_first_of(".eE") == std::string::npos) return std::to_string(std::stoll(v) + 1);
    return std::to_string(d + 0.5);
  }
  return v + "_x";
}

class Mutator {
 public:
  Mutator(const bt::Document& doc, const Layout& layout) : doc_(doc), layout_(layout) {
    for (std::size_t t = 0; t < doc_.trees.size(); ++t) index_[doc_.trees[t].id] = t;
    find_guards();
  }

  std::vector<Mutant> run() {
    reorder_branches();
    negate_guard();
    remove_inverter();
    drop_guard();
    drop_guard_leaf();
    drop_conjunct();
    drop_branch();
    duplicate_branch();
    rename_atom();
    swap_guards();
    change_attribute("change-attribute-alternative", layout_.alternative_trees);
    change_attribute("change-attribute-fixed", layout_.fixed_trees);
    change_kind("change-kind-fixed", layout_.fixed_trees);
    change_kind("change-kind-alternative", layout_.alternative_trees);
    change_kind_guard();
    break_arity();
    dangle_subtree();
    reinsert_adaptable();
    change_script();
    double_negation();
    reorder_conjuncts();
    de_morgan();
    flatten_nest();
    move_guard_subtree();
    return std::move(out_);
  }

 private:
  void emit(const std::string& op, const std::string& what, Kind kind,
            const std::function<void(bt::Document&)>& change) {
    Mutant m;
    m.op = op;
    m.description = what;
    m.kind = kind;
    m.document = doc_;
    change(m.document);
    out_.push_back(std::move(m));
  }

  std::vector<Ref> tree_nodes(const std::set<std::string>& ids) const {
    std::vector<Ref> refs;
    for (std::size_t t = 0; t < doc_.trees.size(); ++t)
      if (ids.count(doc_.trees[t].id) && !doc_.trees[t].root.tag.empty())
        all_nodes(doc_, Ref{t, {}}, refs);
    return refs;
  }

  void find_guards() {
    for (const auto& a : layout_.adaptables) {
      const auto it = index_.find(a);
      if (it == index_.end()) continue;
      selectors_.push_back(it->second);
      const bt::Node& root = doc_.trees[it->second].root;
      for (std::size_t b = 0; b < root.children.size(); ++b) {
        if (root.children[b].children.size() != 2) continue;
        GuardSite site;
        site.adaptable = a;
        site.branch = b;
        site.call_site = Ref{it->second, {b, 0}};
        site.body = site.call_site;
        const bt::Node& first = at(doc_, site.call_site);
        if (is_call(first)) {
          const auto target = index_.find(*first.attribute("ID"));
          if (target != index_.end()) {
            site.body = Ref{target->second, {}};
            site.behind_call = true;
          }
        }
        guards_.push_back(site);
      }
    }
    for (const auto& site : guards_) all_nodes(doc_, site.body, guard_nodes_);
  }

  bool in_guard(const Ref& r) const {
    for (const auto& g : guard_nodes_)
      if (g.tree == r.tree && g.path == r.path) return true;
    return false;
  }

  // ---- the selector ----
  void reorder_branches() {
    for (std::size_t t : selectors_) {
      const std::size_t n = doc_.trees[t].root.children.size();
      for (std::size_t i = 0; i + 1 < n; ++i)
        emit("reorder-branches",
             "swap branches " + std::to_string(i) + " and " + std::to_string(i + 1) + " of " +
                 doc_.trees[t].id,
             Kind::deviation, [=](bt::Document& d) {
               auto& c = d.trees[t].root.children;
               std::swap(c[i], c[i + 1]);
             });
    }
  }

  void drop_branch() {
    for (std::size_t t : selectors_)
      for (std::size_t i = 0; i < doc_.trees[t].root.children.size(); ++i)
        emit("drop-branch", "remove branch " + std::to_string(i) + " of " + doc_.trees[t].id,
             Kind::deviation, [=](bt::Document& d) {
               auto& c = d.trees[t].root.children;
               c.erase(c.begin() + static_cast<long>(i));
             });
  }

  void duplicate_branch() {
    for (std::size_t t : selectors_)
      for (std::size_t i = 0; i < doc_.trees[t].root.children.size(); ++i)
        emit("duplicate-branch", "repeat branch " + std::to_string(i) + " of " + doc_.trees[t].id,
             Kind::deviation, [=](bt::Document& d) {
               auto& c = d.trees[t].root.children;
               bt::Node copy = c[i];
               c.insert(c.begin() + static_cast<long>(i) + 1, std::move(copy));
             });
  }

  void reinsert_adaptable() {
    std::set<std::string> adaptables(layout_.adaptables.begin(), layout_.adaptables.end());
    for (const Ref& r : tree_nodes(layout_.fixed_trees)) {
      const bt::Node& n = at(doc_, r);
      const std::string* id = n.attribute("ID");
      if (!is_call(n) || !id || !adaptables.count(*id)) continue;
      emit("reinsert-adaptable", "put <Adaptable ID=" + *id + "> back at " + path_of(doc_, r),
           Kind::deviation, [=, a = *id](bt::Document& d) {
             bt::Node adaptable = node("Adaptable");
             adaptable.set_attribute("ID", a);
             at(d, r) = adaptable;
           });
    }
    for (std::size_t t : selectors_) {
      const bt::Node& root = doc_.trees[t].root;
      for (std::size_t b = 0; b < root.children.size(); ++b) {
        const Ref call = Ref{t, {b, root.children[b].children.size() - 1}};
        emit("reinsert-adaptable", "replace the alternative call at " + path_of(doc_, call),
             Kind::deviation, [=, a = doc_.trees[t].id](bt::Document& d) {
               bt::Node adaptable = node("Adaptable");
               adaptable.set_attribute("ID", a);
               at(d, call) = adaptable;
             });
      }
    }
  }

  // ---- guards: the oracle decides ----
  void negate_guard() {
    for (const auto& g : guards_)
      emit("negate-guard", "wrap " + path_of(doc_, g.call_site) + " in an Inverter", Kind::guard,
           [=](bt::Document& d) {
             bt::Node& n = at(d, g.call_site);
             n = node("Inverter", {n});
           });
  }

  void remove_inverter() {
    for (const Ref& r : guard_nodes_) {
      const bt::Node& n = at(doc_, r);
      if (n.kind() != "Inverter" || n.children.size() != 1) continue;
      emit("remove-inverter", "replace " + path_of(doc_, r) + " by its child", Kind::guard,
           [=](bt::Document& d) {
             bt::Node child = at(d, r).children[0];
             at(d, r) = std::move(child);
           });
    }
  }

  void drop_guard() {
    for (const auto& g : guards_)
      emit("drop-guard", "remove the guard " + path_of(doc_, g.call_site), Kind::guard,
           [=](bt::Document& d) {
             auto& c = at(d, g.call_site.parent()).children;
             c.erase(c.begin());
           });
  }

  bool multi_conjunction(const Ref& r) const {
    const bt::Node& n = at(doc_, r);
    return is_conjunction(n.kind()) && n.children.size() >= 2;
  }

  void drop_guard_leaf() {
    for (const Ref& r : guard_nodes_) {
      if (r.path.empty() || !in_guard(r.parent())) continue;
      if (!at(doc_, r).children.empty() || multi_conjunction(r.parent())) continue;
      emit("drop-guard-leaf", "remove the leaf " + path_of(doc_, r), Kind::guard,
           [=](bt::Document& d) {
             auto& c = at(d, r.parent()).children;
             c.erase(c.begin() + static_cast<long>(r.path.back()));
           });
    }
  }

  void drop_conjunct() {
    for (const Ref& r : guard_nodes_) {
      if (r.path.empty() || !in_guard(r.parent()) || !multi_conjunction(r.parent())) continue;
      emit("drop-conjunct", "remove the conjunct " + path_of(doc_, r), Kind::guard,
           [=](bt::Document& d) {
             auto& c = at(d, r.parent()).children;
             c.erase(c.begin() + static_cast<long>(r.path.back()));
           });
    }
  }

  void rename_atom() {
    for (const Ref& r : guard_nodes_) {
      const bt::Node& n = at(doc_, r);
      if (is_condition_leaf(n)) {
        emit("rename-atom", "rename the condition " + path_of(doc_, r), Kind::guard,
             [=](bt::Document& d) {
               bt::Node& m = at(d, r);
               if (m.tag != m.kind())
                 m.set_attribute("ID", m.kind() + "_renamed");
               else
                 m.tag += "_renamed";
             });
      } else if (n.kind() == "ScriptCondition") {
        const std::string code = *n.attribute("code");
        for (const auto& tok : script_tokens(code)) {
          if (tok.kind != ScriptToken::name) continue;
          std::string changed = code;
          changed.insert(tok.offset + tok.length, "_renamed");
          emit("rename-atom", "rename a variable of " + path_of(doc_, r) + ": " + changed,
               Kind::guard, [=](bt::Document& d) { at(d, r).set_attribute("code", changed); });
        }
      }
    }
  }

  void swap_guards() {
    for (std::size_t i = 0; i < guards_.size(); ++i)
      for (std::size_t j = i + 1; j < guards_.size(); ++j) {
        if (guards_[i].adaptable != guards_[j].adaptable) continue;
        const Ref a = guards_[i].call_site, b = guards_[j].call_site;
        emit("swap-guards", "swap the guards " + path_of(doc_, a) + " and " + path_of(doc_, b),
             Kind::guard, [=](bt::Document& d) { std::swap(at(d, a), at(d, b)); });
      }
  }

  void change_kind_guard() {
    for (const Ref& r : guard_nodes_) {
      const std::string k = at(doc_, r).kind();
      if (!is_control(k) || at(doc_, r).tag != k) continue;
      emit("change-kind-guard", path_of(doc_, r) + " becomes " + dual(k), Kind::guard,
           [=](bt::Document& d) { at(d, r).tag = dual(k); });
    }
  }

  void change_script() {
    for (std::size_t t = 0; t < doc_.trees.size(); ++t) {
      std::vector<Ref> refs;
      if (!doc_.trees[t].root.tag.empty()) all_nodes(doc_, Ref{t, {}}, refs);
      for (const Ref& r : refs) {
        const bt::Node& n = at(doc_, r);
        if (n.kind() != "ScriptCondition" || !n.attribute("code")) continue;
        const std::string code = *n.attribute("code");
        const Kind kind = in_guard(r) ? Kind::guard : Kind::deviation;
        for (const auto& tok : script_tokens(code)) {
          if (tok.kind == ScriptToken::name) continue;
          std::string changed = code;
          const std::string text = code.substr(tok.offset, tok.length);
          const bool is_op = tok.kind == ScriptToken::comparison;
          changed.replace(tok.offset, tok.length,
                          is_op ? swapped_comparison(text) : changed_value(text));
          emit(is_op ? "change-script-operator" : "change-script-constant",
               path_of(doc_, r) + ": \"" + code + "\" → \"" + changed + "\"", kind,
               [=](bt::Document& d) { at(d, r).set_attribute("code", changed); });
        }
      }
    }
  }

  // ---- fixed part and alternatives: any change is a deviation ----
  void change_attribute(const std::string& op, const std::set<std::string>& trees) {
    for (const Ref& r : tree_nodes(trees)) {
      const bt::Node& n = at(doc_, r);
      for (std::size_t a = 0; a < n.attributes.size(); ++a) {
        const auto& [key, value] = n.attributes[a];
        emit(op, path_of(doc_, r) + ": " + key + "=\"" + changed_value(value) + "\"",
             Kind::deviation,
             [=](bt::Document& d) { at(d, r).attributes[a].second = changed_value(value); });
      }
      if (n.attributes.empty() && n.children.empty() && !is_call(n))
        emit(op, path_of(doc_, r) + ": add a port", Kind::deviation,
             [=](bt::Document& d) { at(d, r).set_attribute("mutated_port", "1"); });
    }
  }

  void change_kind(const std::string& op, const std::set<std::string>& trees) {
    static const std::map<std::string, std::vector<std::string>> changes = {
        {"Sequence", {"Fallback", "ReactiveSequence"}},
        {"Fallback", {"Sequence", "ReactiveFallback"}},
        {"ReactiveFallback", {"Fallback"}},
        {"ReactiveSequence", {"Sequence"}}};
    for (const Ref& r : tree_nodes(trees)) {
      const auto it = changes.find(at(doc_, r).tag);
      if (it == changes.end()) continue;
      for (const auto& to : it->second)
        emit(op, path_of(doc_, r) + " becomes " + to, Kind::deviation,
             [=](bt::Document& d) { at(d, r).tag = to; });
    }
  }

  void break_arity() {
    for (std::size_t t = 0; t < doc_.trees.size(); ++t) {
      std::vector<Ref> refs;
      if (!doc_.trees[t].root.tag.empty()) all_nodes(doc_, Ref{t, {}}, refs);
      for (const Ref& r : refs) {
        if (!is_decorator(at(doc_, r)) || at(doc_, r).children.size() != 1) continue;
        emit("break-arity", path_of(doc_, r) + " gets a second child", Kind::deviation,
             [=](bt::Document& d) {
               bt::Node& n = at(d, r);
               n.children.push_back(n.children[0]);
             });
      }
    }
    for (const auto& g : guards_)
      emit("break-arity", "wrap " + path_of(doc_, g.call_site) + " in an Inverter with 2 children",
           Kind::deviation, [=](bt::Document& d) {
             bt::Node& n = at(d, g.call_site);
             n = node("Inverter", {n, n});
           });
  }

  void dangle_subtree() {
    for (std::size_t t = 0; t < doc_.trees.size(); ++t) {
      std::vector<Ref> refs;
      if (!doc_.trees[t].root.tag.empty()) all_nodes(doc_, Ref{t, {}}, refs);
      for (const Ref& r : refs) {
        const bt::Node& n = at(doc_, r);
        if (!is_call(n) || !n.attribute("ID")) continue;
        emit("dangle-subtree", path_of(doc_, r) + " calls a tree that does not exist",
             Kind::deviation, [=](bt::Document& d) {
               bt::Node& m = at(d, r);
               m.set_attribute("ID", *m.attribute("ID") + "_missing");
             });
      }
    }
  }

  // ---- equivalent rewrites: must be accepted ----
  void double_negation() {
    std::vector<Ref> sites = guard_nodes_;
    for (const auto& g : guards_)
      if (g.behind_call) sites.push_back(g.call_site);
    for (const Ref& r : sites)
      emit("double-negation", "wrap " + path_of(doc_, r) + " in two Inverters", Kind::rewrite,
           [=](bt::Document& d) {
             bt::Node& n = at(d, r);
             n = node("Inverter", {node("Inverter", {n})});
           });
  }

  void reorder_conjuncts() {
    for (const Ref& r : guard_nodes_) {
      const bt::Node& n = at(doc_, r);
      if (!is_control(n.kind()) || n.children.size() < 2) continue;
      emit("reorder-conjuncts", "reverse the children of " + path_of(doc_, r), Kind::rewrite,
           [=](bt::Document& d) {
             auto& c = at(d, r).children;
             std::reverse(c.begin(), c.end());
           });
    }
  }

  void de_morgan() {
    for (const Ref& r : guard_nodes_) {
      const bt::Node& n = at(doc_, r);
      if (n.kind() == "Inverter" && n.children.size() == 1 && is_control(n.children[0].tag) &&
          n.children[0].attributes.empty()) {
        // !(a | b) → !a & !b, !(a & b) → !a | !b
        emit("de-morgan", "push the Inverter " + path_of(doc_, r) + " inwards", Kind::rewrite,
             [=](bt::Document& d) {
               bt::Node inner = at(d, r).children[0];
               bt::Node out = node(dual(inner.tag));
               for (auto& c : inner.children) out.children.push_back(node("Inverter", {c}));
               at(d, r) = std::move(out);
             });
      }
      if (is_control(n.tag) && n.attributes.empty()) {
        // a & b → !(!a | !b), a | b → !(!a & !b)
        emit("de-morgan", "write " + path_of(doc_, r) + " as the negation of its dual",
             Kind::rewrite, [=](bt::Document& d) {
               bt::Node& m = at(d, r);
               bt::Node inner = node(dual(m.tag));
               for (auto& c : m.children) inner.children.push_back(node("Inverter", {c}));
               m = node("Inverter", {inner});
             });
      }
    }
  }

  void flatten_nest() {
    for (const Ref& r : guard_nodes_) {
      const bt::Node& n = at(doc_, r);
      if (is_control(n.tag) && n.children.size() >= 2)
        emit("flatten-nest", "nest the later children of " + path_of(doc_, r), Kind::rewrite,
             [=](bt::Document& d) {
               bt::Node& m = at(d, r);
               bt::Node nested = node(m.tag);
               nested.children.assign(m.children.begin() + 1, m.children.end());
               m.children.resize(1);
               m.children.push_back(std::move(nested));
             });
      if (is_control(n.tag) && n.children.size() == 1)
        emit("flatten-nest", "replace the one-child " + path_of(doc_, r) + " by its child",
             Kind::rewrite, [=](bt::Document& d) {
               bt::Node child = at(d, r).children[0];
               at(d, r) = std::move(child);
             });
      for (std::size_t i = 0; i < n.children.size(); ++i) {
        const bt::Node& c = n.children[i];
        if (!is_control(n.tag) || c.tag != n.tag || !c.attributes.empty()) continue;
        emit("flatten-nest", "splice " + path_of(doc_, r.child(i)) + " into its parent",
             Kind::rewrite, [=](bt::Document& d) {
               bt::Node& m = at(d, r);
               std::vector<bt::Node> grandchildren = m.children[i].children;
               m.children.erase(m.children.begin() + static_cast<long>(i));
               m.children.insert(m.children.begin() + static_cast<long>(i), grandchildren.begin(),
                                 grandchildren.end());
             });
      }
      if (n.children.empty())
        emit("flatten-nest", "wrap " + path_of(doc_, r) + " in a one-child Sequence", Kind::rewrite,
             [=](bt::Document& d) {
               bt::Node& m = at(d, r);
               m = node("Sequence", {m});
             });
    }
  }

  // A guard moves behind a SubTree call, or a called conditions tree is inlined.
  void move_guard_subtree() {
    for (const auto& g : guards_) {
      if (g.behind_call) {
        emit("inline-guard-subtree", "inline the called tree at " + path_of(doc_, g.call_site),
             Kind::rewrite, [=](bt::Document& d) {
               bt::Node body = at(d, g.body);
               at(d, g.call_site) = std::move(body);
             });
        continue;
      }
      const std::string id = g.adaptable + "_guard_" + std::to_string(g.branch);
      emit("extract-guard-subtree",
           "move " + path_of(doc_, g.call_site) + " into a tree " + id + " and call it",
           Kind::rewrite, [=](bt::Document& d) {
             bt::TreeDef tree;
             tree.id = id;
             tree.root = at(d, g.call_site);
             bt::Node call = node("SubTree");
             call.set_attribute("ID", id);
             call.set_attribute(d.format == 3 ? "__shared_blackboard" : "_autoremap", "true");
             at(d, g.call_site) = std::move(call);
             d.trees.push_back(std::move(tree));
           });
    }
  }

  const bt::Document& doc_;
  const Layout& layout_;
  std::map<std::string, std::size_t> index_;
  std::vector<std::size_t> selectors_;
  std::vector<GuardSite> guards_;
  std::vector<Ref> guard_nodes_;
  std::vector<Mutant> out_;
};

}  // namespace

std::vector<Mutant> all_mutants(const bt::Document& compiled, const Layout& layout) {
  return Mutator(compiled, layout).run();
}

const std::vector<std::string>& operator_names() {
  static const std::vector<std::string> names = {"reorder-branches",
                                                 "negate-guard",
                                                 "remove-inverter",
                                                 "drop-guard",
                                                 "drop-guard-leaf",
                                                 "drop-conjunct",
                                                 "drop-branch",
                                                 "duplicate-branch",
                                                 "rename-atom",
                                                 "swap-guards",
                                                 "change-attribute-alternative",
                                                 "change-attribute-fixed",
                                                 "change-kind-fixed",
                                                 "change-kind-alternative",
                                                 "change-kind-guard",
                                                 "break-arity",
                                                 "dangle-subtree",
                                                 "reinsert-adaptable",
                                                 "change-script-operator",
                                                 "change-script-constant",
                                                 "double-negation",
                                                 "reorder-conjuncts",
                                                 "de-morgan",
                                                 "flatten-nest",
                                                 "inline-guard-subtree",
                                                 "extract-guard-subtree"};
  return names;
}

}  // namespace uabt::testing::mutation
