#include <algorithm>
#include <set>
#include <unordered_map>
#include <utility>

#include "smt/atoms.hpp"
#include "verify/node.hpp"
#include "verify/region.hpp"

namespace uabt::verify::detail {

namespace {

// How many cubes of a region a finding lists before it says "and more".
constexpr std::size_t kMaxRegionCubes = 5;
constexpr std::size_t kMaxMinimisedCube = 64;  // literals

bool contains(const std::vector<z3::expr>& v, const z3::expr& x) {
  return std::any_of(v.begin(), v.end(), [&](const z3::expr& y) { return z3::eq(x, y); });
}

// The distinct atoms of the node's guards, each with a literal defined equivalent to it.
struct AtomTable {
  std::vector<const fretish::Expr*> atoms;
  std::vector<z3::expr> formulas;
  std::vector<z3::expr> literals;
};

AtomTable atom_table(const std::vector<const Guard*>& guards, Session& session) {
  AtomTable table;
  smt::Encoder& encoder = session.encoder();
  std::unordered_map<unsigned, std::size_t> seen;  // Z3 hash-conses: equal atoms share an id
  for (const Guard* g : guards) {
    if (g->is_default) continue;
    for (const fretish::Expr* atom :
         smt::atom_occurrences(*g->requirement->guard, encoder.typing())) {
      const z3::expr formula = encoder.lower(*atom);
      if (!seen.emplace(formula.id(), table.atoms.size()).second) continue;
      table.atoms.push_back(atom);
      table.formulas.push_back(formula);
      table.literals.push_back(session.define(formula, "atom"));
    }
  }
  return table;
}

// Adds to `out` the atoms, with their polarity, that hold wherever `f` has the truth value
// `positive`: the conjuncts of a conjunction, the negated disjuncts of a false disjunction.
void implied_atoms(const z3::expr& f, bool positive, std::set<std::pair<unsigned, bool>>& out) {
  const Z3_decl_kind kind = f.decl().decl_kind();
  if ((kind == Z3_OP_AND && positive) || (kind == Z3_OP_OR && !positive)) {
    for (unsigned i = 0; i < f.num_args(); ++i) implied_atoms(f.arg(i), positive, out);
  } else if (kind == Z3_OP_NOT) {
    implied_atoms(f.arg(0), !positive, out);
  } else {
    out.emplace(f.id(), positive);
  }
}

}  // namespace

RegionCubes describe_region(const std::vector<const Guard*>& guards, Session& session,
                            z3::model model, const std::vector<z3::expr>& inside,
                            const z3::expr& outside) {
  // Generalise each model of the region to a cube over the guards' atoms that lies wholly in
  // it (drop literals while D ∧ cube ∧ outside stays unsat), block it, repeat.
  RegionCubes region;
  const AtomTable table = atom_table(guards, session);
  // The atoms that hold throughout the region because `inside` asserts a guard of which they
  // are conjuncts: a cube of these alone contains the whole region, nothing is left to find.
  std::set<std::pair<unsigned, bool>> implied;
  std::unordered_map<unsigned, const Guard*> by_literal;
  for (const Guard* g : guards) by_literal.emplace(g->literal.id(), g);
  for (const auto& l : inside) {
    const bool negated = l.is_app() && l.decl().decl_kind() == Z3_OP_NOT;
    const auto it = by_literal.find(negated ? l.arg(0).id() : l.id());
    if (it != by_literal.end()) implied_atoms(it->second->formula, !negated, implied);
  }
  const z3::expr blocking = session.encoder().fresh_literal("regionblock");
  std::vector<z3::expr> search = inside;
  search.push_back(blocking);
  for (;;) {
    std::vector<z3::expr> cube;
    for (std::size_t k = 0; k < table.atoms.size(); ++k)
      cube.push_back(model.eval(table.formulas[k], true).is_true() ? table.literals[k]
                                                                   : !table.literals[k]);
    // The full cube fixes every atom at values of a state of the region, so it lies in the
    // region; the core and the minimisation only make it larger.
    std::vector<z3::expr> query{outside};
    query.insert(query.end(), cube.begin(), cube.end());
    if (session.check(query) == Answer::unsat) {
      const std::vector<z3::expr> core = session.core();
      std::vector<z3::expr> needed;
      for (const auto& l : cube)
        if (contains(core, l)) needed.push_back(l);
      // Minimising asks one question per literal, each as costly as the mission is large: a
      // cube the core leaves longer than that is shown as the core gives it, still inside.
      cube = needed.size() <= kMaxMinimisedCube ? session.minimise({outside}, needed) : needed;
    }
    std::vector<CubeLiteral> literals;
    bool covers_region = true;
    for (std::size_t k = 0; k < table.atoms.size(); ++k) {
      for (const bool positive : {true, false}) {
        if (!contains(cube, positive ? table.literals[k] : !table.literals[k])) continue;
        literals.push_back({table.atoms[k], positive});
        covers_region = covers_region && implied.count({table.formulas[k].id(), positive}) > 0;
      }
    }
    region.cubes.push_back(
        render_cube(literals, session.encoder().domain(), session.encoder().typing()));
    if (cube.empty()) break;  // the whole domain
    if (covers_region) {      // the whole region: whether more is left needs no question
      ++session.statistics().prefiltered;
      break;
    }
    z3::expr_vector conjunction(session.context());
    for (const auto& l : cube) conjunction.push_back(l);
    session.add(z3::implies(blocking, !z3::mk_and(conjunction)));
    const Answer next = session.check(search);
    if (next == Answer::unsat) break;
    if (next == Answer::unknown) {
      region.more = "… and possibly more (the solver could not tell)";
      break;
    }
    if (region.cubes.size() == kMaxRegionCubes) {
      region.more = "… and more";
      break;
    }
    model = session.model();
  }
  return region;
}

SourceLocation requirements_span(const std::vector<const Guard*>& guards) {
  SourceLocation span = guards.front()->requirement->location;
  for (const Guard* g : guards) {
    const SourceLocation& l = g->requirement->location;
    if (l.file == span.file && l.line > std::max(span.line, span.end_line)) span.end_line = l.line;
  }
  return span;
}

void check_gap(Node& node, Session& session, std::vector<std::string>& region) {
  region.clear();
  const bool has_default = std::any_of(node.guards.begin(), node.guards.end(),
                                       [](const Guard& g) { return g.is_default; });
  if (has_default) {  // the default is always enabled: no state is left uncovered
    ++session.statistics().prefiltered;
    return;
  }
  Session::Scope scope(session, node.guards.size() > Session::kWideScope);
  std::vector<z3::expr> none_hold;
  std::vector<const Guard*> all;
  for (const Guard& g : node.guards) {
    session.define(g.literal, g.formula);
    none_hold.push_back(!g.literal);
    all.push_back(&g);
  }
  // The gap belongs to the node's requirements as a whole: it is located at their span.
  const SourceLocation where = requirements_span(all);
  const Answer gap = session.check(none_hold);
  if (gap == Answer::unsat) return;
  if (gap == Answer::unknown) {
    report_inconclusive(node, session,
                        "whether some state selects no alternative of " + node.adaptable, where,
                        all);
    return;
  }
  const z3::model model = session.model();
  const State witness = session.encoder().state_of(model);
  z3::expr_vector guard_literals(session.context());
  for (const Guard& g : node.guards) guard_literals.push_back(g.literal);
  const z3::expr some_holds = session.define(z3::mk_or(guard_literals), "any");
  RegionCubes cubes = describe_region(all, session, model, none_hold, some_holds);
  region = cubes.cubes;

  Finding f = node_finding(node, "guard-gap",
                           "no requirement of " + node.adaptable +
                               " holds in some states: there the Fallback fails and " +
                               node.adaptable + " returns FAILURE",
                           where);
  for (const Guard& g : node.guards) {
    f.requirements.push_back(g.requirement->id);
    f.alternatives.push_back(g.requirement->alternative);
  }
  f.witness = witness;
  for (const auto& cube : region) f.notes.push_back("uncovered: " + cube);
  if (!cubes.more.empty()) {
    f.notes.push_back("uncovered: " + cubes.more);
    region.push_back(cubes.more);
  }
  f.notes.push_back("add a default requirement (no condition) or guards that cover these states");
  node.result->findings.push_back(std::move(f));
}

}  // namespace uabt::verify::detail
