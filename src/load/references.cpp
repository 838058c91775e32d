#include "load/references.hpp"

#include "base/suggest.hpp"
#include "base/text.hpp"
#include "bt/node_kinds.hpp"

#include <cctype>
#include <map>
#include <set>

namespace uabt::load {

using fretish::Expr;
using fretish::ExprKind;

std::vector<const Expr*> boolean_atoms(const Expr& root) {
  std::vector<const Expr*> atoms;
  std::vector<const Expr*> stack{&root};
  while (!stack.empty()) {
    const Expr* e = stack.back();
    stack.pop_back();
    if (e->kind == ExprKind::identifier) {
      atoms.push_back(e);
    } else if (fretish::is_boolean_connective(e->kind)) {
      for (auto it = e->args.rbegin(); it != e->args.rend(); ++it) stack.push_back(it->get());
    }
  }
  return atoms;
}

namespace {

void infer_from(const Expr& e, const SourceLocation& owner, fretish::Domain& domain,
                const std::set<std::string>& undeclared) {
  for (const Expr* atom : boolean_atoms(e)) {
    if (domain.find(atom->text) != nullptr || domain.enum_owning(atom->text) != nullptr ||
        undeclared.count(atom->text))
      continue;
    fretish::Variable v;
    v.name = atom->text;
    v.type = fretish::VarType::boolean;
    v.declared = false;
    v.location = start_of(atom->range, owner);
    domain.variables.push_back(std::move(v));
  }
}

void duplicate_requirement_ids(Mission& m) {
  std::map<std::string, const fretish::Requirement*> first;
  for (const auto& r : m.requirements) {
    auto [it, inserted] = first.emplace(r.id, &r);
    if (inserted) continue;
    Finding f =
        make_finding("ref-duplicate-id", "requirement id '" + r.id + "' is used twice", r.location);
    f.requirements = {r.id};
    f.notes.push_back("first used at " + it->second->location.file + ":" +
                      std::to_string(it->second->location.line));
    m.findings.push_back(std::move(f));
  }
}

void duplicate_adaptables(Mission& m) {
  std::map<std::string, const AdaptableSite*> first;
  for (const auto& site : m.adaptables) {
    if (site.id.empty()) continue;  // bt-structure reports the missing ID
    auto [it, inserted] = first.emplace(site.id, &site);
    if (inserted) continue;
    Finding f = make_finding("ref-duplicate-id",
                             "adaptable node '" + site.id + "' appears twice in the mission",
                             site.location);
    f.adaptable = site.id;
    f.notes.push_back("first appears at " + it->second->location.file + ":" +
                      std::to_string(it->second->location.line));
    m.findings.push_back(std::move(f));
  }
}

// The compiled tree holds the mission's trees, one selection tree per adaptable node (named
// after it) and every alternative's trees: their IDs must not clash.
void duplicate_tree_ids(Mission& m) {
  struct Owner {
    const bt::TreeDef* tree;
    std::string what;
  };
  std::map<std::string, Owner> owners;
  auto claim = [&](const bt::TreeDef& t, const std::string& what) {
    auto [it, inserted] = owners.emplace(t.id, Owner{&t, what});
    if (inserted) return;
    // The same subtree included by two alternatives is one tree, not a clash.
    if (it->second.tree != nullptr && it->second.tree->root == t.root) return;
    Finding f = make_finding("ref-duplicate-id",
                             "tree ID '" + t.id + "' of " + what + " is already used by " +
                                 it->second.what + "; the compiled tree would hold both",
                             {t.file, t.line, t.column});
    m.findings.push_back(std::move(f));
  };
  for (const auto& site : m.adaptables)
    if (!site.id.empty())
      owners.emplace(site.id,
                     Owner{nullptr, "the selection tree of adaptable node '" + site.id + "'"});
  for (const auto& t : m.tree.trees) claim(t, "the mission");
  for (const auto& alt : m.alternatives)
    for (const auto& t : alt.document.trees) claim(t, "alternative '" + alt.name + "'");
}

// Where an alternative's file would be, for the message that says it is missing.
std::string expected_file(const Mission& m, const std::string& adaptable, const std::string& alt) {
  if (m.layout == "replication") return "resource/" + adaptable + "/" + alt + "/" + alt + ".xml";
  return "alternatives/" + adaptable + "/" + alt + ".xml";
}

void selection_references(Mission& m) {
  std::set<std::string> adaptable_ids;
  bool id_missing = false;  // an <Adaptable> without ID: which node a scope means is unknown
  for (const auto& site : m.adaptables) {
    if (site.id.empty())
      id_missing = true;
    else
      adaptable_ids.insert(site.id);
  }
  std::set<std::pair<std::string, std::string>> selected;
  std::map<std::string, const fretish::SelectionRequirement*> defaults;

  for (const auto& s : m.selections) {
    selected.insert({s.adaptable, s.alternative});
    if (!adaptable_ids.count(s.adaptable)) {
      if (id_missing) continue;            // bt-structure reports the <Adaptable> without an ID
      if (m.tree.trees.empty()) continue;  // mission.xml is unreadable (reported): nodes unknown
      std::vector<std::string> known(adaptable_ids.begin(), adaptable_ids.end());
      Finding f =
          make_finding("ref-unknown-adaptable",
                       "requirement " + s.id + " is scoped to '" + s.adaptable +
                           "', but the mission has no <Adaptable ID=\"" + s.adaptable + "\"/>" +
                           (known.empty() ? "" : " (it has: " + join(known, ", ") + ")"),
                       s.location);
      f.adaptable = s.adaptable;
      f.requirements = {s.id};
      if (const std::string hint = did_you_mean(s.adaptable, known); !hint.empty())
        f.notes.push_back(hint);
      m.findings.push_back(std::move(f));
      continue;
    }
    const std::string key = s.adaptable + "/" + s.alternative;
    if (m.find_alternative(s.adaptable, s.alternative) == nullptr &&
        !m.unreadable_alternatives.count(key)) {  // an unreadable file is reported already
      Finding f = make_finding("ref-unknown-alternative",
                               "requirement " + s.id + " selects '" + s.alternative +
                                   "', but there is no file " +
                                   expected_file(m, s.adaptable, s.alternative),
                               s.alternative_location.line ? s.alternative_location : s.location);
      f.adaptable = s.adaptable;
      f.requirements = {s.id};
      f.alternatives = {s.alternative};
      std::vector<std::string> names;
      for (const auto& alt : m.alternatives)
        if (alt.adaptable == s.adaptable) names.push_back(alt.name);
      if (const std::string hint = did_you_mean(s.alternative, names); !hint.empty())
        f.notes.push_back(hint);
      m.findings.push_back(std::move(f));
    }
    if (!s.guard) {
      auto [it, inserted] = defaults.emplace(s.adaptable, &s);
      if (!inserted) {
        Finding f = make_finding(
            "ref-multiple-defaults",
            "requirement " + s.id + " is a second default (no condition) for '" + s.adaptable +
                "'; " + it->second->id + " already is one, so this one can never be selected",
            s.location);
        f.adaptable = s.adaptable;
        f.requirements = {it->second->id, s.id};
        f.alternatives = {s.alternative};
        m.findings.push_back(std::move(f));
      }
    }
  }

  std::set<std::string> reported;
  for (const auto& site : m.adaptables) {
    if (site.id.empty() || !reported.insert(site.id).second) continue;
    if (m.requirements_incomplete.count(site.id)) continue;  // its requirement may not parse
    bool has_requirement = false;
    for (const auto& s : m.selections) has_requirement |= s.adaptable == site.id;
    if (!has_requirement) {
      Finding f = make_finding("ref-adaptable-unresolved",
                               "adaptable node '" + site.id +
                                   "' has no selection requirement: nothing says which "
                                   "alternative runs there",
                               site.location);
      f.adaptable = site.id;
      m.findings.push_back(std::move(f));
    }
  }

  for (const auto& alt : m.alternatives) {
    if (selected.count({alt.adaptable, alt.name})) continue;
    // Unknowable: a requirement that does not parse, or a node without ID, may select it.
    if (id_missing || m.requirements_incomplete.count(alt.adaptable)) continue;
    const bt::TreeDef* main = alt.document.find_tree(alt.tree_id);
    Finding f = make_finding(
        "ref-orphan-alternative",
        "alternative '" + alt.name + "' of '" + alt.adaptable + "' is selected by no requirement",
        {alt.file, main ? main->line : 1, main ? main->column : 1});
    f.adaptable = alt.adaptable;
    f.alternatives = {alt.name};
    m.findings.push_back(std::move(f));
  }
}

// A boolean atom becomes a condition leaf <Name/> in the compiled tree: a quoted FRETISH
// identifier such as "On Dust" or "x&y" cannot be a BehaviorTree.CPP node ID (nor an XML name).
void unusable_condition_names(Mission& m) {
  for (const auto& s : m.selections) {
    if (!s.guard) continue;
    for (const Expr* atom : boolean_atoms(*s.guard)) {
      const fretish::Variable* v = m.domain.find(atom->text);
      if (v == nullptr || v->type != fretish::VarType::boolean) continue;
      const std::string& name = atom->text;
      const bool starts_well =
          !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
      if (starts_well && bt::is_valid_id(name)) continue;
      Finding f = make_finding("bt-structure",
                               "condition '" + name + "' in requirement " + s.id +
                                   " cannot become a BehaviorTree.CPP condition node: an ID "
                                   "starts with a letter and has no space or < > & \" ' / \\ : * "
                                   "? | . characters",
                               start_of(atom->range, s.location));
      f.adaptable = s.adaptable;
      f.requirements = {s.id};
      m.findings.push_back(std::move(f));
    }
  }
}

void unknown_conditions(Mission& m) {
  if (!m.nodes) return;
  std::set<std::string> conditions;
  for (const auto& model : *m.nodes) conditions.insert(model.id);
  const NameIndex suggestions({conditions.begin(), conditions.end()});
  for (const auto& s : m.selections) {
    if (!s.guard) continue;
    for (const Expr* atom : boolean_atoms(*s.guard)) {
      const fretish::Variable* v = m.domain.find(atom->text);
      if (v == nullptr || v->type != fretish::VarType::boolean || conditions.count(atom->text))
        continue;
      Finding f = make_finding("ref-unknown-condition",
                               "condition '" + atom->text + "' in requirement " + s.id +
                                   " is not a node of nodes.xml; the robot cannot check it",
                               start_of(atom->range, s.location));
      if (const std::string hint = suggestions.did_you_mean(atom->text); !hint.empty())
        f.notes.push_back(hint);
      f.adaptable = s.adaptable;
      f.requirements = {s.id};
      m.findings.push_back(std::move(f));
    }
  }
}

}  // namespace

void infer_condition_variables(Mission& m) {
  for (const auto& s : m.selections)
    if (s.guard) infer_from(*s.guard, s.location, m.domain, m.undeclared);
  for (const auto& a : m.domain.assumptions)
    if (a.expr) infer_from(*a.expr, a.location, m.domain, m.undeclared);
}

void check_references(Mission& m) {
  duplicate_requirement_ids(m);
  duplicate_adaptables(m);
  duplicate_tree_ids(m);
  selection_references(m);
  unknown_conditions(m);
  unusable_condition_names(m);
}

}  // namespace uabt::load
