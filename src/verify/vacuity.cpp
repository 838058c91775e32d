#include <algorithm>
#include <array>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "smt/assign.hpp"
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

// The guard for a note: whole up to a few lines, elided in the middle beyond (a guard of
// thousands of atoms, repeated in every finding about it, made megabytes of output).
std::string guard_note(const fretish::Expr& guard) {
  constexpr std::size_t kKeep = 160;  // characters kept at each end
  std::string text = fretish::to_fretish(guard);
  if (text.size() <= 3 * kKeep) return "guard: " + text;
  // Cut at spaces, which never split a quoted name's UTF-8 sequence.
  const std::size_t head = text.rfind(' ', kKeep);
  const std::size_t tail = text.find(' ', text.size() - kKeep);
  return "guard: " + text.substr(0, head) + " ... " + text.substr(tail + 1) + " (" +
         std::to_string(text.size()) + " characters)";
}

// Which atom occurrences decide the guard at one state: flipping a sensitive occurrence alone
// flips the guard. Values come from the model; the skeleton is walked once down from the root
// (a child of an `and` is sensitive when the `and` is and every sibling is true, and so on).
class Sensitivity {
 public:
  Sensitivity(const smt::Typing& typing,
              const std::unordered_map<const fretish::Expr*, bool>& atoms)
      : typing_(typing), atoms_(atoms) {}

  // Fills `sensitive` with the atom occurrences whose flip alone flips `guard`.
  void run(const fretish::Expr& guard, std::unordered_set<const fretish::Expr*>& sensitive) {
    value(guard);
    mark(guard, sensitive);
  }

 private:
  const smt::Typing& typing_;
  const std::unordered_map<const fretish::Expr*, bool>& atoms_;
  std::unordered_map<const fretish::Expr*, bool> values_;

  static bool combine(fretish::ExprKind kind, const std::vector<bool>& v) {
    using fretish::ExprKind;
    switch (kind) {
      case ExprKind::logical_not: return !v[0];
      case ExprKind::logical_and: return std::all_of(v.begin(), v.end(), [](bool b) { return b; });
      case ExprKind::logical_or: return std::any_of(v.begin(), v.end(), [](bool b) { return b; });
      case ExprKind::logical_xor:
      case ExprKind::iff: {
        bool acc = v[0];
        for (std::size_t i = 1; i < v.size(); ++i)
          acc = kind == ExprKind::logical_xor ? acc != v[i] : acc == v[i];
        return acc;
      }
      case ExprKind::implies: {  // right-associative, as the encoder reads it
        bool acc = v.back();
        for (std::size_t i = v.size() - 1; i-- > 0;) acc = !v[i] || acc;
        return acc;
      }
      case ExprKind::eq: return v[0] == v[1];
      case ExprKind::ne: return v[0] != v[1];
      default: return false;
    }
  }

  bool value(const fretish::Expr& e) {
    bool v = false;
    if (e.kind == fretish::ExprKind::bool_literal) {
      v = e.bool_value;
    } else if (smt::is_boolean_structure(e, typing_)) {
      std::vector<bool> args;
      for (const auto& a : e.args) args.push_back(value(*a));
      v = combine(e.kind, args);
    } else {
      v = atoms_.at(&e);
    }
    values_[&e] = v;
    return v;
  }

  void mark(const fretish::Expr& e, std::unordered_set<const fretish::Expr*>& sensitive) {
    if (e.kind == fretish::ExprKind::bool_literal) return;
    if (!smt::is_boolean_structure(e, typing_)) {
      sensitive.insert(&e);
      return;
    }
    std::vector<bool> args;
    for (const auto& a : e.args) args.push_back(values_.at(a.get()));
    const bool here = values_.at(&e);
    std::size_t falses = std::count(args.begin(), args.end(), false);
    for (std::size_t i = 0; i < e.args.size(); ++i) {
      bool flips = false;
      if (e.kind == fretish::ExprKind::logical_and) {
        flips = falses - (args[i] ? 0 : 1) == 0;
      } else if (e.kind == fretish::ExprKind::logical_or) {
        flips = (args.size() - falses) - (args[i] ? 1 : 0) == 0;
      } else {
        args[i] = !args[i];
        flips = combine(e.kind, args) != here;
        args[i] = !args[i];
      }
      if (flips) mark(*e.args[i], sensitive);
    }
  }
};

// The questions "can this occurrence alone decide the guard in a state where it is v?" for
// every occurrence of one guard. Each occurrence gets a literal for the condition under which
// flipping it flips the guard (the guard's Boolean difference: every sibling of an `and` on
// its path true, every sibling of an `or` false, …), all defined once over the guard's own
// subterms, so a question is two assumptions. (A copy of the guard per occurrence made a
// guard of n atoms cost n^2 to encode and to solve.) An occurrence object that the tree
// shares stands in every place at once, as a substitution would, and is asked as one.
class VacuityQuestions {
 public:
  VacuityQuestions(const fretish::Expr& guard, const z3::expr& formula, Session& session)
      : session_(session), scope_(session), true_(session.context().bool_val(true)) {
    walk(guard, true_);
    smt::Encoder& encoder = session.encoder();
    for (auto& [atom, question] : questions_) {
      if (question.places > 1) {
        const z3::expr flipped = encoder.lower(guard, {{atom, !question.value}});
        smt::assign(question.decides, session.define(formula != flipped, "vacuity"));
      }
      question.literal.emplace(session.define(question.value, "vacuity_atom"));
    }
  }

  Answer ask(const fretish::Expr* atom, bool atom_value) {
    const Question& q = questions_.at(atom);
    return session_.check({q.decides, atom_value ? *q.literal : !*q.literal});
  }

  const z3::expr& atom_formula(const fretish::Expr* atom) const {
    return questions_.at(atom).value;
  }
  // The occurrence stands in one place only: flipping it is flipping one leaf.
  bool is_single(const fretish::Expr* atom) const { return questions_.at(atom).places == 1; }

 private:
  struct Question {
    z3::expr value;    // the atom itself
    z3::expr decides;  // a literal: flipping the occurrence flips the guard
    std::optional<z3::expr> literal;
    int places = 0;
  };

  Session& session_;
  Session::Scope scope_;  // every definition is retracted with it
  z3::expr true_;
  std::unordered_map<const fretish::Expr*, Question> questions_;
  std::unordered_map<const fretish::Expr*, z3::expr> terms_;

  z3::expr link(const z3::expr& formula) { return session_.define(formula, "vacuity_link"); }

  const z3::expr& term(const fretish::Expr& e) {
    if (const auto it = terms_.find(&e); it != terms_.end()) return it->second;
    return terms_.emplace(&e, session_.encoder().lower(e)).first->second;
  }

  void walk(const fretish::Expr& e, const z3::expr& path) {
    using fretish::ExprKind;
    if (e.kind == ExprKind::bool_literal) return;
    if (!smt::is_boolean_structure(e, session_.encoder().typing())) {
      ++questions_.try_emplace(&e, Question{term(e), path, {}, 0}).first->second.places;
      return;
    }
    const std::size_t n = e.args.size();
    std::vector<z3::expr> terms;
    for (const auto& a : e.args) terms.push_back(term(*a));
    switch (e.kind) {
      case ExprKind::logical_and:
      case ExprKind::logical_or: {
        // The others must all be true (and) or all false (or): prefix and suffix chains
        // keep the conditions of all n children linear in n. Each link is a literal of its
        // own: Z3 flattens nested conjunctions, which would copy every chain into every path.
        const bool is_and = e.kind == ExprKind::logical_and;
        auto neutral = [&](const z3::expr& t) { return is_and ? t : !t; };
        std::vector<z3::expr> suffix(n + 1, true_);
        for (std::size_t i = n; i-- > 0;)
          smt::assign(suffix[i], link(neutral(terms[i]) && suffix[i + 1]));
        z3::expr prefix = true_;
        for (std::size_t i = 0; i < n; ++i) {
          walk(*e.args[i], link(path && prefix && suffix[i + 1]));
          smt::assign(prefix, link(prefix && neutral(terms[i])));
        }
        return;
      }
      case ExprKind::implies: {
        // a0 -> (a1 -> … -> a(n-1)): ak decides when a0 … a(k-1) hold and the rest is false.
        std::vector<z3::expr> tail(n, terms[n - 1]);
        for (std::size_t i = n - 1; i-- > 0;)
          smt::assign(tail[i], link(z3::implies(terms[i], tail[i + 1])));
        z3::expr prefix = true_;
        for (std::size_t i = 0; i < n; ++i) {
          walk(*e.args[i], link(i + 1 < n ? path && prefix && !tail[i + 1] : path && prefix));
          smt::assign(prefix, link(prefix && terms[i]));
        }
        return;
      }
      default:  // not, xor, iff, = and != over booleans: every flip of one operand flips it
        for (const auto& a : e.args) walk(*a, path);
        return;
    }
  }
};

}  // namespace

namespace {

// What the questions found for one atom occurrence.
struct Decision {
  std::optional<bool> replaceable_by;  // the constant that can stand for it
  bool undecided = false;              // the solver could not tell
};

// Decides every occurrence of `guard` (a satisfiable guard, or an independent part of one).
void decide_occurrences(const fretish::Expr& guard, Session& session,
                        const std::set<std::string>& assumed,
                        std::unordered_map<const fretish::Expr*, Decision>& decisions) {
  smt::Encoder& encoder = session.encoder();
  const auto atoms = smt::atom_occurrences(guard, encoder.typing());
  // A lone atom is the whole guard: it matters unless the guard always holds under D
  // (`!(x = 1)` with x in [-3, 0]), which the question below finds like any other case.
  if (read_once_over_free_booleans(guard, atoms, encoder.typing(), assumed)) {
    session.statistics().prefiltered += atoms.size();
    for (const fretish::Expr* atom : atoms) decisions[atom] = {};
    return;
  }
  std::vector<std::pair<const fretish::Expr*, bool>> conjuncts;
  top_level_literals(guard, true, conjuncts);
  VacuityQuestions questions(guard, encoder.lower(guard), session);
  // An occurrence matters when states where it alone decides the guard exist with the
  // atom true and with it false. Every model found shows, for all occurrences at once,
  // which ones decide the guard there: most need no question of their own.
  // Reading a model costs about as much as a question, so models stop being read while
  // they teach little (each skip twice as long), and are read again once one teaches.
  std::unordered_map<const fretish::Expr*, std::array<bool, 2>> decides_when;
  std::size_t skip = 0, skipped = 0;
  // A model holds every variable of the mission, so reading one costs what the mission costs;
  // a small part (each `(a | b)` of a long conjunction) is cheaper to ask about directly.
  constexpr std::size_t kLearnFrom = 8;  // occurrences
  auto learn = [&]() {
    if (atoms.size() < kLearnFrom) return;
    if (skipped < skip) {
      ++skipped;
      return;
    }
    skipped = 0;
    const z3::model model = session.model();
    std::unordered_map<const fretish::Expr*, bool> values;
    for (const fretish::Expr* atom : atoms) {
      const z3::expr v = model.eval(questions.atom_formula(atom), true);
      if (!v.is_true() && !v.is_false()) return;  // not evaluated to a constant: learn nothing
      values[atom] = v.is_true();
    }
    std::unordered_set<const fretish::Expr*> sensitive;
    Sensitivity(encoder.typing(), values).run(guard, sensitive);
    std::size_t learnt = 0;
    for (const fretish::Expr* atom : sensitive) {
      if (!questions.is_single(atom)) continue;
      bool& known = decides_when[atom][values.at(atom) ? 1 : 0];
      learnt += known ? 0 : 1;
      known = true;
    }
    skip = learnt > 2 ? 0 : std::min<std::size_t>(std::max<std::size_t>(2 * skip, 1), 64);
  };
  for (const fretish::Expr* atom : atoms) {
    // The occurrence is vacuous when a constant c can stand for it: g ≡ g[atom := c] under
    // D, that is, no state where the atom is !c decides the guard through it alone.
    Decision& d = decisions[atom];
    for (const bool constant : {true, false}) {
      if (decides_when[atom][constant ? 0 : 1] ||
          std::any_of(conjuncts.begin(), conjuncts.end(),
                      [&](const auto& c) { return c.first == atom && c.second != constant; })) {
        ++session.statistics().prefiltered;
        continue;
      }
      const Answer differs = questions.ask(atom, !constant);
      if (differs == Answer::sat) learn();
      if (differs == Answer::unsat) {
        d.replaceable_by = constant;
        break;
      }
      if (differs == Answer::unknown) {  // reported with this question's reason
        d.undecided = true;
        break;
      }
    }
  }
}

void flatten_and(const fretish::ExprPtr& e, std::vector<fretish::ExprPtr>& out) {
  if (e->kind == fretish::ExprKind::logical_and) {
    for (const auto& a : e->args) flatten_and(a, out);
    return;
  }
  out.push_back(e);
}

// The guard's top-level conjuncts grouped into parts that share no variable, directly or
// through an assumption (names are joined whenever one conjunct or assumption reads them
// together). With g = A ∧ B over disjoint variables and assumptions, an occurrence in A decides
// g exactly where it decides A and B holds, and B holds somewhere independently of A (g is
// satisfiable), so each part is asked on its own: a question then costs what its part costs,
// not what the whole guard does. One part: the guard itself.
std::vector<fretish::ExprPtr> independent_parts(const fretish::ExprPtr& guard,
                                                const fretish::Domain& domain) {
  std::vector<fretish::ExprPtr> conjuncts;
  flatten_and(guard, conjuncts);
  if (conjuncts.size() < 2) return {guard};
  std::unordered_map<std::string, std::string> parent;
  auto find = [&](std::string x) {
    auto it = parent.try_emplace(x, x).first;
    while (it->second != x) {
      x = it->second;
      it = parent.find(x);
    }
    return x;
  };
  auto join = [&](const std::vector<std::string>& names) {
    for (std::size_t i = 1; i < names.size(); ++i) {
      const std::string a = find(names[0]), b = find(names[i]);
      if (a != b) parent[b] = a;
    }
  };
  std::vector<std::vector<std::string>> names(conjuncts.size());
  for (std::size_t i = 0; i < conjuncts.size(); ++i) {
    names[i] = fretish::identifiers_of(*conjuncts[i]);
    join(names[i]);
  }
  for (const auto& a : domain.assumptions)
    if (a.expr) join(fretish::identifiers_of(*a.expr));  // one that did not parse is not in D
  // Parts in the order of their first conjunct; a conjunct that reads no name (a constant
  // comparison) stays with the first part.
  std::string first_root;
  std::unordered_map<std::string, std::size_t> part_of_root;
  std::vector<std::vector<fretish::ExprPtr>> members;
  for (std::size_t i = 0; i < conjuncts.size(); ++i) {
    const std::string root = names[i].empty() ? first_root : find(names[i][0]);
    const auto [it, added] = part_of_root.try_emplace(root, members.size());
    if (added) {
      if (members.empty()) first_root = root;
      members.emplace_back();
    }
    members[it->second].push_back(conjuncts[i]);
  }
  if (members.size() == 1) return {guard};
  std::vector<fretish::ExprPtr> parts;
  for (auto& m : members)
    parts.push_back(m.size() == 1 ? m[0] : fretish::make_expr(fretish::ExprKind::logical_and, m));
  return parts;
}

}  // namespace

// Most atom occurrences a guard may have for check_vacuous_atoms to ask about each.
constexpr std::size_t kMaxVacuityAtoms = 1000;

void check_vacuous_atoms(Node& node, Session& session,
                         const std::vector<std::string>& assumed_names) {
  const std::set<std::string> assumed(assumed_names.begin(), assumed_names.end());
  smt::Encoder& encoder = session.encoder();
  for (const Guard& g : node.guards) {
    // An unsatisfiable guard is reported as such; every atom of it would be vacuous.
    if (g.is_default || g.satisfiable != Answer::sat) continue;
    const fretish::Expr& guard = *g.requirement->guard;
    const auto atoms = smt::atom_occurrences(guard, encoder.typing());
    if (atoms.size() > kMaxVacuityAtoms) {
      // One solver question per atom, each over the whole guard: a guard of 60,000 atoms
      // would take hours. The guard's other checks (satisfiable, shadowed, overlap, gap) are
      // made as always.
      Finding f = node_finding(node, "verification-skipped",
                               "the atoms of the guard of " + label(g) +
                                   " are not checked for vacuity: it has " +
                                   std::to_string(atoms.size()) + " atoms, more than the " +
                                   std::to_string(kMaxVacuityAtoms) + " uabt checks one by one",
                               g.requirement->guard_location);
      f.requirements = {g.requirement->id};
      f.alternatives = {g.requirement->alternative};
      f.notes.push_back(
          "its satisfiability, shadowing, overlaps and gaps are checked; to have each atom "
          "checked, split the guard or write a range (`depth >= 0 & depth <= 59999`) for a "
          "run of values");
      node.result->findings.push_back(std::move(f));
      continue;
    }
    std::unordered_map<const fretish::Expr*, Decision> decisions;
    for (const fretish::ExprPtr& part : independent_parts(g.requirement->guard, encoder.domain())) {
      if (encoder.typing().find(*part) == nullptr) {  // a conjunction made of several conjuncts
        std::vector<Finding> none;  // its conjuncts are typed already: nothing to report
        if (!encoder.lower_condition(*part, g.requirement->guard_location, none)) continue;
        node.made.push_back(part);
      }
      decide_occurrences(*part, session, assumed, decisions);
    }
    std::string note;  // made once, for the first finding that needs it
    for (const fretish::Expr* atom : atoms) {
      const Decision& d = decisions[atom];
      const std::string atom_text = fretish::to_fretish(*atom);
      const SourceLocation where = start_of(atom->range, g.requirement->guard_location);
      if (!d.replaceable_by) {
        if (d.undecided)
          report_inconclusive(node, session,
                              "whether the atom '" + atom_text + "' matters in " + label(g), where,
                              {&g});
        continue;
      }
      const std::string constant = *d.replaceable_by ? "true" : "false";
      Finding f = node_finding(node, "guard-vacuous-atom",
                               "the atom '" + atom_text + "' in the guard of " + label(g) +
                                   " never changes it: under the domain the guard means the same "
                                   "with the atom replaced by " +
                                   constant,
                               where);
      f.requirements = {g.requirement->id};
      f.alternatives = {g.requirement->alternative};
      if (note.empty()) note = guard_note(guard);
      f.notes.push_back(note);
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
