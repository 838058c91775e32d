#include <algorithm>
#include <optional>
#include <set>

#include "smt/atoms.hpp"
#include "verify/node.hpp"

namespace uabt::verify::detail {

namespace {

bool skeleton_has_constant(const fretish::Expr& e, const smt::Typing& typing) {
  if (e.kind == fretish::ExprKind::bool_literal) return true;
  if (!smt::is_boolean_structure(e, typing)) return false;
  return std::any_of(e.args.begin(), e.args.end(),
                     [&](const auto& a) { return skeleton_has_constant(*a, typing); });
}

// A guard over distinct, otherwise unconstrained boolean variables, each read once and
// combined without constants, depends on every one of them (no constant can stand for any
// of them): nothing to ask the solver.
bool read_once_over_free_booleans(const fretish::Expr& guard,
                                  const std::vector<const fretish::Expr*>& atoms,
                                  const smt::Typing& typing, const std::set<std::string>& assumed) {
  std::set<std::string> names;
  for (const fretish::Expr* a : atoms) {
    const smt::TypeInfo* t = typing.find(*a);
    if (a->kind != fretish::ExprKind::identifier || t == nullptr || t->sort != smt::Sort::boolean)
      return false;
    if (assumed.count(a->text) || !names.insert(a->text).second) return false;
  }
  return !skeleton_has_constant(guard, typing);
}

// The atom occurrences that are top-level conjuncts of the guard, with their polarity
// (`a & !b & (c | d)`: a true, b false). Fixing such an occurrence to the opposite of its
// polarity makes the guard false, which differs from a satisfiable guard: no query needed.
void top_level_literals(const fretish::Expr& e, bool positive,
                        std::vector<std::pair<const fretish::Expr*, bool>>& out) {
  if (e.kind == fretish::ExprKind::logical_and && positive) {
    for (const auto& arg : e.args) top_level_literals(*arg, true, out);
    return;
  }
  if (e.kind == fretish::ExprKind::logical_not && e.args.size() == 1) {
    top_level_literals(*e.args[0], !positive, out);
    return;
  }
  out.emplace_back(&e, positive);
}

SourceLocation atom_location(const fretish::Expr& atom, const SourceLocation& guard_location) {
  SourceLocation loc = guard_location;
  if (atom.range.begin_line > 0) {
    loc.line = atom.range.begin_line;
    loc.column = atom.range.begin_column;
  }
  return loc;
}

}  // namespace

void check_vacuous_atoms(Node& node, Session& session,
                         const std::vector<std::string>& assumed_names) {
  const std::set<std::string> assumed(assumed_names.begin(), assumed_names.end());
  smt::Encoder& encoder = session.encoder();
  for (const Guard& g : node.guards) {
    // An unsatisfiable guard is reported as such; every atom of it would be vacuous.
    if (g.is_default || g.satisfiable != Answer::sat) continue;
    const fretish::Expr& guard = *g.requirement->guard;
    const auto atoms = smt::atom_occurrences(guard, encoder.typing());
    // A lone atom is the whole guard: it matters unless the guard always holds under D
    // (`!(x = 1)` with x in [-3, 0]), which the question below finds like any other case.
    if (read_once_over_free_booleans(guard, atoms, encoder.typing(), assumed)) {
      session.statistics().prefiltered += atoms.size();
      continue;
    }
    const z3::expr original = g.formula;
    std::vector<std::pair<const fretish::Expr*, bool>> conjuncts;
    top_level_literals(guard, true, conjuncts);
    for (const fretish::Expr* atom : atoms) {
      const std::string atom_text = fretish::to_fretish(*atom);
      const SourceLocation where = atom_location(*atom, g.requirement->guard_location);
      // The occurrence is vacuous when a constant can stand for it: g ≡ g[atom := c] under D.
      std::optional<bool> replaceable_by;
      bool undecided = false;
      for (const bool constant : {true, false}) {
        if (std::any_of(conjuncts.begin(), conjuncts.end(),
                        [&](const auto& c) { return c.first == atom && c.second != constant; })) {
          ++session.statistics().prefiltered;
          continue;
        }
        const z3::expr replaced = encoder.lower(guard, {{atom, constant}});
        Answer differs = Answer::unsat;
        if (z3::eq(replaced, original)) {
          ++session.statistics().prefiltered;
        } else {
          Session::Scope scope(session);
          differs = session.check({session.guard(replaced != original, "vacuity")});
        }
        if (differs == Answer::unsat) {
          replaceable_by = constant;
          break;
        }
        if (differs == Answer::unknown) {  // reported with this question's reason
          undecided = true;
          break;
        }
      }
      if (!replaceable_by) {
        if (undecided)
          report_inconclusive(node, session,
                              "whether the atom '" + atom_text + "' matters in " + label(g), where,
                              {&g});
        continue;
      }
      const std::string constant = *replaceable_by ? "true" : "false";
      Finding f = node_finding(node, "guard-vacuous-atom",
                               "the atom '" + atom_text + "' in the guard of " + label(g) +
                                   " never changes it: under the domain the guard means the same "
                                   "with the atom replaced by " +
                                   constant,
                               where);
      f.requirements = {g.requirement->id};
      f.alternatives = {g.requirement->alternative};
      f.notes.push_back("guard: " + fretish::to_fretish(guard));
      // The guard is satisfiable (checked above), so a constant for its only atom makes it
      // always true: it is a default in disguise.
      if (atoms.size() == 1)
        f.notes.push_back("the guard always holds under the domain: " + label(g) +
                          " acts as a default");
      f.notes.push_back("drop the atom, or check whether another condition was meant");
      node.result->findings.push_back(std::move(f));
    }
  }
}

}  // namespace uabt::verify::detail
