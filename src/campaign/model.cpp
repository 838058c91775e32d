// The targets of a campaign, enumerated exactly over the coverage stage's space: discrete
// variables by value, real variables by the cells their guards' boundaries cut (ARCHITECTURE §5).
#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "base/number_text.hpp"
#include "campaign/campaign.hpp"
#include "campaign/node.hpp"
#include "fretish/build_expression.hpp"
#include "smt/atoms.hpp"
#include "smt/types.hpp"
#include "verify/coverage.hpp"

namespace uabt::campaign {

using verify::detail::Bits;
using verify::detail::Fraction;
using verify::detail::RealAxis;
using verify::detail::Truth;

const char* criterion_name(Criterion c) {
  switch (c) {
    case Criterion::decision: return "decision";
    case Criterion::mcdc: return "mcdc";
    case Criterion::boundary: return "boundary";
    case Criterion::guarantee: return "guarantee";
  }
  return "decision";
}

std::string Model::Node::key(std::uint64_t state) const {
  return std::string(reinterpret_cast<const char*>(&sigs[state * words]), words * 8);
}

bool Model::Node::atom_holds(std::uint64_t state, std::size_t atom) const {
  const std::size_t c = column[atom];
  return (((sigs[state * words + c / 64] >> (c % 64)) & 1) != 0) != inverted[atom];
}

State Model::Node::state_values(std::uint64_t state) const {
  State out;
  const auto& dims = space->dimensions();
  for (std::size_t d = 0; d < dims.size(); ++d) {
    const auto& dim = dims[d];
    const std::uint64_t digit = space->digit(state, d);
    if (dim.component < 0) {
      if (dim.sort == smt::Sort::integer)
        out.emplace_back(dim.name, Value::of_int(dim.number(digit)));
      else if (dim.sort == smt::Sort::enumeration)
        out.emplace_back(dim.name, Value::of_enum(dim.declaration->enum_values[digit]));
      else
        out.emplace_back(dim.name, Value::of_bool(digit != 0));
      continue;
    }
    const auto& comp = space->components()[static_cast<std::size_t>(dim.component)];
    const auto& cell = comp.cells[digit];
    for (std::size_t a = 0; a < comp.axes.size(); ++a) {
      Fraction x = cell.point[a];
      const RealAxis& axis = comp.axes[a];
      const std::size_t c = cell.axis_cell[a];
      // One variable: any number of the open interval lies in the same cell.
      if (comp.axes.size() == 1 && !RealAxis::is_point(c))
        x = simple_inside(axis.from(c), axis.to(c)).value_or(x);
      out.emplace_back(axis.variable, real_value(x));
    }
  }
  return in_domain_order(space->domain(), std::move(out));
}

std::optional<std::uint64_t> Model::Node::substitute(
    std::uint64_t state, const std::set<std::uint64_t>& excluded) const {
  if (!excluded.count(state)) return state;
  std::optional<std::uint64_t> best;
  auto scramble = [](std::uint64_t s) { return (s * 0x9E3779B97F4A7C15ull) ^ (s >> 7); };
  for (std::uint64_t s = 0; s < domain.size(); ++s) {
    if (!domain.test(s) || excluded.count(s) || (best && scramble(s) > scramble(*best))) continue;
    if (std::equal(&sigs[s * words], &sigs[s * words] + words, &sigs[state * words])) best = s;
  }
  return best;
}

std::optional<std::uint64_t> Model::Node::state_index(const State& state) const {
  const auto s = space->state_of(state);
  if (!s || !domain.test(*s)) return std::nullopt;
  return s;
}

// Builds one node's space, its truths and its targets; false (with `reason`) when the space
// cannot be enumerated exactly.
bool Model::Node::build(const load::Mission& mission, std::string& reason) {
  const fretish::Domain& dom = mission.domain;
  std::vector<Finding> ignored;
  for (const auto* r : reqs)
    if (r->guard && !smt::check_condition(*r->guard, dom, r->guard_location, typing, ignored)) {
      reason = "the guard of " + r->id + " does not type-check";
      return false;
    }
  std::vector<const fretish::Expr*> assumptions;
  for (const auto& a : dom.assumptions) {
    if (!a.expr) continue;
    if (!smt::check_condition(*a.expr, dom, a.location, typing, ignored)) continue;
    const smt::TypeInfo* t = typing.find(*a.expr);
    if (t != nullptr && t->sort == smt::Sort::boolean) assumptions.push_back(a.expr.get());
  }
  // The guards' variables, closed under "an assumption links them", as coverage counts them.
  std::vector<const fretish::Expr*> atoms;
  std::map<std::string, std::size_t> atom_index;
  for (std::size_t k = 0; k < reqs.size(); ++k) {
    req_atoms.emplace_back();
    if (!reqs[k]->guard) continue;
    verify::detail::variables_of(*reqs[k]->guard, typing, names);
    for (const fretish::Expr* a : smt::atom_occurrences(*reqs[k]->guard, typing)) {
      atoms.push_back(a);
      const std::string text = fretish::to_fretish(*a);
      auto [it, fresh] = atom_index.emplace(text, atom_text.size());
      if (fresh) {
        atom_text.push_back(text);
        atom_expr.push_back(a);
      }
      if (std::find(req_atoms[k].begin(), req_atoms[k].end(), it->second) == req_atoms[k].end())
        req_atoms[k].push_back(it->second);
    }
  }
  linked = verify::detail::link_assumptions(assumptions, typing, names, atoms);
  prepared = true;
  space = std::make_unique<verify::detail::Space>(dom, typing);
  try {
    reason = space->plan(names, atoms);
    if (!reason.empty()) return false;
    const std::uint64_t size = space->size();
    Truth d = Truth::exactly(Bits(size, true), Bits(size, false));
    for (const auto* a : linked) d = verify::detail::junction(true, {d, space->truth(*a)}, size);
    if (!d.exact() || d.none.any()) {
      reason = "an assumption cannot be decided cell by cell";
      return false;
    }
    domain = d.sure;
    Bits claimed(size, false);
    for (std::size_t k = 0; k < reqs.size(); ++k) {
      Bits on = domain;
      if (reqs[k]->guard) {
        const Truth g = space->truth(*reqs[k]->guard);
        if (!g.exact() || (g.none & domain).any()) {
          reason = "the guard of " + reqs[k]->id + " cannot be decided cell by cell" +
                   (space->unmeasured().empty() ? "" : " (" + space->unmeasured() + ")");
          return false;
        }
        on = g.sure & domain;
      }
      enabled.push_back(on);
      selected.push_back(on & ~claimed);
      claimed = claimed | on;
    }
    std::vector<Bits> columns;
    for (std::size_t a = 0; a < atom_text.size(); ++a) {
      const Truth t = space->truth(*atom_expr[a]);
      if (!t.exact()) {
        reason = "the atom " + atom_text[a] + " cannot be decided cell by cell";
        return false;
      }
      const Bits holds = t.sure & domain, fails = domain & ~t.sure;
      std::size_t c = 0;
      bool flip = false;
      for (; c < columns.size(); ++c) {
        if (columns[c] == holds) break;
        if (columns[c] == fails) {
          flip = true;
          break;
        }
      }
      if (c == columns.size()) columns.push_back(holds);
      column.push_back(c);
      inverted.push_back(flip);
    }
    words = std::max<std::size_t>(1, (columns.size() + 63) / 64);
    sigs.assign(size * words, 0);
    for (std::size_t c = 0; c < columns.size(); ++c)
      for (std::uint64_t s = 0; s < size; ++s)
        if (columns[c].test(s)) sigs[s * words + c / 64] |= std::uint64_t{1} << (c % 64);
    sel.assign(size, -2);
    for (std::uint64_t s = 0; s < size; ++s) {
      if (!domain.test(s)) continue;
      sel[s] = -1;
      for (std::size_t k = 0; k < reqs.size() && sel[s] < 0; ++k)
        if (selected[k].test(s)) sel[s] = static_cast<int>(k);
    }
  } catch (const verify::detail::FractionOverflow& e) {
    reason = e.what();
    return false;
  } catch (const smt::EvaluationError& e) {
    reason = e.what();
    return false;
  }
  return true;
}

void Model::Node::add(std::vector<Target>& all, Target t, Bits states) {
  Local local;
  local.target = all.size();
  if (t.reachable) {
    bool found = false;
    for (std::uint64_t s = 0; s < states.size() && !found; ++s)
      if (states.test(s)) {
        t.witness.push_back(state_values(s));
        found = true;
      }
    if (!found) t.reachable = false;
  }
  local.states = std::move(states);
  all.push_back(std::move(t));
  locals.push_back(std::move(local));
}

void Model::Node::decision_targets(std::vector<Target>& all) {
  for (std::size_t k = 0; k < reqs.size(); ++k) {
    Target t = select_target(adaptable, *reqs[k]);
    if (!selected[k].any()) {
      t.reachable = false;
      std::vector<std::string> earlier;
      for (std::size_t j = 0; j < k; ++j)
        if ((enabled[j] & enabled[k]).any()) earlier.push_back(reqs[j]->id);
      t.reason = unselectable(*reqs[k], enabled[k].any(), earlier);
    }
    add(all, std::move(t), selected[k]);
    locals.back().select = true;
    locals.back().req = k;
    locals.back().condition = selects_condition(k);
  }
  for (std::size_t k = 0; k < reqs.size(); ++k) {
    const auto* r = reqs[k];
    if (!r->guard) continue;
    const std::string guard = fretish::to_fretish(*r->guard);
    for (bool value : {true, false}) {
      Target t = guard_target(adaptable, *r, guard, value);
      Bits states = value ? enabled[k] : domain & ~enabled[k];
      if (!states.any()) {
        t.reachable = false;
        t.reason = guard_never(value);
      }
      add(all, std::move(t), std::move(states));
      locals.back().condition = (value ? "(" : "!(") + guard + ")";
    }
  }
}

void Model::Node::mcdc_targets(std::vector<Target>& all) {
  const std::uint64_t size = space->size();
  // One state per signature (the first), so that pairs are looked up by signature.
  std::unordered_map<std::string, std::uint64_t> first;
  std::vector<std::uint64_t> reps;
  auto key = [&](std::uint64_t s) { return this->key(s); };
  for (std::uint64_t s = 0; s < size; ++s)
    if (domain.test(s) && first.emplace(key(s), s).second) reps.push_back(s);
  for (std::size_t k = 0; k < reqs.size(); ++k) {
    const auto* r = reqs[k];
    for (std::size_t a : req_atoms[k]) {
      Target t = mcdc_target(adaptable, *r, atom_text[a]);
      Local local;
      local.pair = true;
      local.req = k;
      local.atom = a;
      bool alone = false, flips_guard = false, always = true, never = true;
      bool guard_true = false, guard_false = false;  // somewhere in the domain
      std::set<std::string> shadowing;
      for (std::uint64_t s : reps) {
        (atom_holds(s, a) ? never : always) = false;
        (enabled[k].test(s) ? guard_true : guard_false) = true;
        if (atom_holds(s, a)) continue;  // each pair once: from the state where it is false
        std::string other = key(s);
        const std::size_t c = column[a];
        other[c / 8] = static_cast<char>(other[c / 8] ^ (1 << (c % 8)));
        const auto it = first.find(other);
        if (it == first.end()) continue;
        const std::uint64_t u = it->second;
        alone = true;
        if (enabled[k].test(s) == enabled[k].test(u)) continue;
        flips_guard = true;
        if (sel[s] == sel[u]) {
          if (sel[s] >= 0 && static_cast<std::size_t>(sel[s]) < k)
            shadowing.insert(reqs[static_cast<std::size_t>(sel[s])]->id);
          continue;
        }
        local.pairs.emplace_back(s, u);
      }
      if (local.pairs.empty()) {
        t.reachable = false;
        const NoPair why = always || never                                ? NoPair::atom_fixed
                           : !alone                                       ? NoPair::atom_tied
                           : !flips_guard && !(guard_true && guard_false) ? NoPair::guard_fixed
                           : !flips_guard                                 ? NoPair::guard_masked
                                                                          : NoPair::same_selection;
        t.reason =
            no_pair(why, atom_text[a], r->id, why == NoPair::atom_fixed ? always : guard_true,
                    {shadowing.begin(), shadowing.end()});
      } else {
        t.witness.push_back(state_values(local.pairs.front().first));
        t.witness.push_back(state_values(local.pairs.front().second));
      }
      local.target = all.size();
      all.push_back(std::move(t));
      locals.push_back(std::move(local));
    }
  }
}

void Model::Node::boundary_targets(std::vector<Target>& all) {
  const std::uint64_t size = space->size();
  const auto& dims = space->dimensions();
  auto target = [&](Target t, Bits states, const std::string& condition) {
    if (!states.any()) {
      t.reachable = false;
      t.reason = kNoStateThere;
    }
    add(all, std::move(t), std::move(states));
    locals.back().condition = condition;
  };
  for (std::size_t d = 0; d < dims.size(); ++d) {
    const auto& dim = dims[d];
    if (dim.component < 0) {
      if (dim.sort != smt::Sort::integer) continue;
      // A boundary lies between v and v + 1 where some atom changes its value.
      const std::uint64_t stride = space->stride(d);
      std::vector<bool> cut(dim.radix, false);
      for (std::uint64_t s = 0; s < size; ++s) {
        const std::uint64_t v = space->digit(s, d);
        if (v + 1 >= dim.radix || cut[v]) continue;
        cut[v] =
            !std::equal(&sigs[s * words], &sigs[s * words] + words, &sigs[(s + stride) * words]);
      }
      for (std::uint64_t v = 0; v + 1 < dim.radix; ++v) {
        if (!cut[v]) continue;
        const std::string lo = number_text(dim.number(v)), hi = number_text(dim.number(v + 1));
        for (std::uint64_t side : {v, v + 1}) {
          Bits states(size, false);
          for (std::uint64_t s = 0; s < size; ++s)
            if (space->digit(s, d) == side && domain.test(s)) states.set(s);
          target(integer_boundary(adaptable, dim.name, lo, hi, side == v), std::move(states),
                 dim.name + " = " + number_condition(Fraction(dim.number(side))));
        }
      }
      continue;
    }
    const auto& comp = space->components()[static_cast<std::size_t>(dim.component)];
    auto cells_where = [&](auto&& pick) {
      Bits states(size, false);
      for (std::uint64_t s = 0; s < size; ++s)
        if (domain.test(s) && pick(comp.cells[space->digit(s, d)])) states.set(s);
      return states;
    };
    for (std::size_t a = 0; a < comp.axes.size(); ++a) {
      const RealAxis& axis = comp.axes[a];
      for (std::size_t b = 1; b + 1 < axis.breaks.size(); ++b) {
        const std::string before = axis.breaks[b - 1].decimal(), at = axis.breaks[b].decimal(),
                          after = axis.breaks[b + 1].decimal();
        const std::size_t point = 2 * b;
        const std::string& x = axis.variable;
        auto boundary = [&](int side) {
          return real_boundary(adaptable, x, side, before, at, after);
        };
        target(boundary(-1),
               cells_where([&](const auto& c) { return c.axis_cell[a] == point - 1; }),
               x + " > " + number_condition(axis.breaks[b - 1]) + " & " + x + " < " +
                   number_condition(axis.breaks[b]));
        target(boundary(0), cells_where([&](const auto& c) { return c.axis_cell[a] == point; }),
               x + " = " + number_condition(axis.breaks[b]));
        target(boundary(1), cells_where([&](const auto& c) { return c.axis_cell[a] == point + 1; }),
               x + " > " + number_condition(axis.breaks[b]) + " & " + x + " < " +
                   number_condition(axis.breaks[b + 1]));
      }
    }
    for (std::size_t l = 0; l < comp.lines.size(); ++l) {
      const auto& line = comp.lines[l];
      // a·x + b·y + c = 0 with a = 1: x + b·y = -c.
      const Fraction b = line.b;
      const std::string text = line_text(comp.axes[0].variable, b, comp.axes[1].variable);
      const std::string rhs = (-line.c).decimal();
      const char* words_of[] = {" < ", " = ", " > "};
      std::string lhs = comp.axes[0].variable;
      if (!b.is_zero()) lhs += " + " + number_condition(b) + " * " + comp.axes[1].variable;
      for (int sign = -1; sign <= 1; ++sign)
        target(line_boundary(adaptable, text, rhs, sign),
               cells_where([&](const auto& c) { return c.signs[l] == sign; }),
               lhs + words_of[sign + 1] + number_condition(-line.c));
    }
  }
}

Model::Model(const load::Mission& mission, const std::set<Criterion>& criteria,
             bool solve_every_node)
    : mission_(mission) {
  std::set<std::string> seen;
  for (const auto& site : mission.adaptables) {
    if (site.id.empty() || !seen.insert(site.id).second) continue;
    if (auto it = mission.not_verified.find(site.id); it != mission.not_verified.end()) {
      skipped_.emplace_back(site.id, "not verified: " + it->second);
      continue;
    }
    auto node = std::make_unique<Node>();
    node->adaptable = site.id;
    node->reqs = mission.selections_for(site.id);
    if (node->reqs.empty()) {
      skipped_.emplace_back(site.id, "no selection requirement names it");
      continue;
    }
    std::string reason;
    const bool enumerated = node->build(mission, reason) && !solve_every_node;
    if (!node->prepared) {
      skipped_.emplace_back(site.id, reason);
      continue;
    }
    if (!enumerated) {
      // Too many states, or conditions the cells cannot decide: each target is solved.
      std::string failure;
      if (!node->solve(mission, criteria, solve_every_node ? "every node solved" : reason, targets_,
                       failure)) {
        skipped_.emplace_back(site.id, reason + "; solving its targets failed: " + failure);
        continue;
      }
      nodes_.push_back(std::move(node));
      continue;
    }
    if (criteria.count(Criterion::decision)) node->decision_targets(targets_);
    if (criteria.count(Criterion::mcdc)) node->mcdc_targets(targets_);
    if (criteria.count(Criterion::boundary)) node->boundary_targets(targets_);
    nodes_.push_back(std::move(node));
  }
}

Model::~Model() = default;

std::vector<std::pair<std::string, std::string>> Model::solved() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& n : nodes_)
    if (n->solved) out.emplace_back(n->adaptable, n->solved->why);
  return out;
}

std::size_t Model::nodes() const {
  return nodes_.size();
}
const std::string& Model::adaptable(std::size_t node) const {
  return nodes_[node]->adaptable;
}

State Model::default_state(std::size_t node) const {
  const Node& n = *nodes_[node];
  if (n.solved) return n.solved->first.value_or(State{});
  for (std::uint64_t s = 0; s < n.domain.size(); ++s)
    if (n.domain.test(s)) return n.state_values(s);
  return {};
}

std::string Model::expected(std::size_t node, const State& state) const {
  const Node& n = *nodes_[node];
  if (n.solved) {
    const auto s = n.solved_state(state);
    const int k = s ? n.solved_selection(*s) : -1;
    return k < 0 ? "" : n.reqs[static_cast<std::size_t>(k)]->alternative;
  }
  const auto s = n.state_index(state);
  if (!s || n.sel[*s] < 0) return "";
  return n.reqs[static_cast<std::size_t>(n.sel[*s])]->alternative;
}

namespace {

// The visited states of a solved node (restricted to its variables, each once) and the
// alternatives the runs selected there.
std::vector<State> solved_visits(const Model::Node& n, const std::vector<const Observation*>& seen,
                                 std::set<std::string>* alternatives = nullptr) {
  std::vector<State> states;
  std::set<std::string> keys;
  for (const Observation* o : seen) {
    const auto s = n.solved_state(o->state);
    std::string alt = o->alternative;
    if (s) {
      if (alt.empty() && n.solved_selection(*s) >= 0)
        alt = n.reqs[static_cast<std::size_t>(n.solved_selection(*s))]->alternative;
      if (keys.insert(state_json(*s).dump()).second) states.push_back(*s);
    }
    if (!alt.empty() && alternatives != nullptr) alternatives->insert(alt);
  }
  return states;
}

void solved_covered(const Model::Node& n, const std::vector<const Observation*>& seen,
                    std::vector<bool>& out) {
  std::set<std::string> alternatives;
  const std::vector<State> states = solved_visits(n, seen, &alternatives);
  for (const auto& goal : n.solved->goals) {
    bool hit = false;
    if (goal.kind == Model::Node::Goal::Kind::select)
      hit = alternatives.count(n.reqs[goal.req]->alternative) > 0;
    else if (goal.kind == Model::Node::Goal::Kind::pair)
      for (std::size_t i = 0; i < states.size() && !hit; ++i)
        for (std::size_t j = i + 1; j < states.size() && !hit; ++j)
          hit = n.solved_pair(goal, states[i], states[j]);
    else
      for (std::size_t i = 0; i < states.size() && !hit; ++i)
        hit = n.solved_reaches(goal, states[i]);
    out[goal.target] = hit;
  }
}

}  // namespace

std::vector<bool> Model::covered(const std::vector<RunRecord>& runs) const {
  std::vector<bool> out(targets_.size(), false);
  std::map<std::string, std::vector<const Observation*>> by_node;
  for (const auto& run : runs)
    for (const auto& o : run.observations) by_node[o.adaptable].push_back(&o);
  for (const auto& node : nodes_) {
    const Node& n = *node;
    if (n.solved) {
      solved_covered(n, by_node[n.adaptable], out);
      continue;
    }
    std::set<std::uint64_t> states;
    std::set<std::string> alternatives;
    for (const Observation* seen : by_node[n.adaptable]) {
      const auto s = n.state_index(seen->state);
      std::string alt = seen->alternative;
      if (s) {
        states.insert(*s);
        if (alt.empty() && n.sel[*s] >= 0)
          alt = n.reqs[static_cast<std::size_t>(n.sel[*s])]->alternative;
      }
      if (!alt.empty()) alternatives.insert(alt);
    }
    std::unordered_map<std::string, std::vector<std::uint64_t>> visited;  // by signature
    for (std::uint64_t s : states) visited[n.key(s)].push_back(s);
    for (const auto& local : n.locals) {
      const Target& t = targets_[local.target];
      if (!t.reachable) continue;
      bool hit = false;
      if (local.pair) {
        // The partner of each visited state: the same atoms' values but this one's.
        const std::size_t c = n.column[local.atom];
        for (auto s = states.begin(); s != states.end() && !hit; ++s) {
          std::string other = n.key(*s);
          other[c / 8] = static_cast<char>(other[c / 8] ^ (1 << (c % 8)));
          const auto it = visited.find(other);
          if (it == visited.end()) continue;
          for (std::uint64_t u : it->second)
            hit = hit || (n.enabled[local.req].test(*s) != n.enabled[local.req].test(u) &&
                          n.sel[*s] != n.sel[u]);
        }
      } else if (local.select) {
        hit = alternatives.count(n.reqs[local.req]->alternative) > 0;
      } else {
        for (auto s = states.begin(); s != states.end() && !hit; ++s) hit = local.states.test(*s);
      }
      out[local.target] = hit;
    }
  }
  return out;
}

namespace {

// A solved node's picks: each MC/DC pair's witnesses, then for each other target a state
// already chosen that reaches it, else its witness. Witnesses in `excluded` are not used.
void solved_picks(const Model::Node& n, std::size_t ni, const std::set<std::uint64_t>& excluded,
                  const std::vector<Target>& targets, std::vector<Model::Pick>& picks) {
  using Kind = Model::Node::Goal::Kind;
  std::map<std::uint64_t, std::vector<std::size_t>> chosen;
  // A goal whose witness did not reach the node is solved again away from such states.
  auto usable = [&](const Model::Node::Goal& g) {
    if (!targets[g.target].reachable || g.witness.empty()) return false;
    for (std::size_t w : g.witness)
      if (excluded.count(w))
        return n.solved_retry(static_cast<std::size_t>(&g - n.solved->goals.data()), excluded);
    return true;
  };
  for (const auto& g : n.solved->goals)
    if (g.kind == Kind::pair && usable(g))
      for (std::size_t w : g.witness) chosen[w].push_back(g.target);
  for (const auto& g : n.solved->goals) {
    if (g.kind == Kind::pair || !usable(g)) continue;
    bool done = false;
    for (auto& [s, purposes] : chosen)
      if (n.solved_reaches(g, n.solved->states[s])) {
        purposes.push_back(g.target);
        done = true;
        break;
      }
    if (!done) chosen[g.witness.front()].push_back(g.target);
  }
  for (auto& [s, purposes] : chosen) {
    std::sort(purposes.begin(), purposes.end());
    purposes.erase(std::unique(purposes.begin(), purposes.end()), purposes.end());
    picks.push_back({ni, s, n.solved->states[s], std::move(purposes)});
  }
}

}  // namespace

std::vector<Model::Pick> Model::minimise(
    const std::vector<std::set<std::uint64_t>>& excluded) const {
  std::vector<Pick> picks;
  for (std::size_t ni = 0; ni < nodes_.size(); ++ni) {
    const Node& n = *nodes_[ni];
    static const std::set<std::uint64_t> none;
    const std::set<std::uint64_t>& out = ni < excluded.size() ? excluded[ni] : none;
    if (n.solved) {
      solved_picks(n, ni, out, targets_, picks);
      continue;
    }
    std::map<std::uint64_t, std::vector<std::size_t>> chosen;  // state -> purposes
    // MC/DC first: a pair whose states are already chosen costs nothing.
    for (const auto& local : n.locals) {
      if (!local.pair || local.pairs.empty()) continue;
      std::pair<std::uint64_t, std::uint64_t> best;
      int best_score = -1;
      for (std::size_t p = 0; p < local.pairs.size() && best_score < 2; ++p) {
        // A state that did not reach the node gives way to another of the same atoms' values.
        const auto first = n.substitute(local.pairs[p].first, out);
        const auto second = n.substitute(local.pairs[p].second, out);
        if (!first || !second) continue;
        const int score =
            static_cast<int>(chosen.count(*first)) + static_cast<int>(chosen.count(*second));
        if (score > best_score) {
          best_score = score;
          best = {*first, *second};
        }
      }
      if (best_score < 0) continue;  // every pair has a state that does not reach the node
      chosen[best.first].push_back(local.target);
      chosen[best.second].push_back(local.target);
    }
    // Greedy set cover of the single-state targets.
    const std::uint64_t size = n.space->size();
    std::vector<std::size_t> open;
    for (std::size_t l = 0; l < n.locals.size(); ++l) {
      const auto& local = n.locals[l];
      if (local.pair || !targets_[local.target].reachable) continue;
      bool done = false;
      for (auto& [s, purposes] : chosen)
        if (local.states.test(s)) {
          purposes.push_back(local.target);
          done = true;
          break;
        }
      if (!done) open.push_back(l);
    }
    std::vector<std::uint32_t> count(size, 0);
    for (std::size_t l : open)
      for (std::uint64_t s = 0; s < size; ++s)
        if (n.locals[l].states.test(s) && !out.count(s)) ++count[s];
    std::vector<bool> closed(n.locals.size(), false);
    // Ties go to the first state; once runs showed states that do not reach the node, to a
    // spread of states instead (a fixed scramble of the index), so that the next try differs
    // in every variable rather than in the last one.
    auto scramble = [&](std::uint64_t s) {
      return out.empty() ? s : (s * 0x9E3779B97F4A7C15ull) ^ (s >> 7);
    };
    for (std::size_t remaining = open.size(); remaining > 0;) {
      std::uint64_t best = 0;
      for (std::uint64_t s = 1; s < size; ++s)
        if (count[s] > count[best] || (count[s] == count[best] && scramble(s) < scramble(best)))
          best = s;
      if (count[best] == 0) break;
      auto& purposes = chosen[best];
      for (std::size_t l : open) {
        if (closed[l] || !n.locals[l].states.test(best)) continue;
        closed[l] = true;
        --remaining;
        purposes.push_back(n.locals[l].target);
        for (std::uint64_t s = 0; s < size; ++s)
          if (n.locals[l].states.test(s) && !out.count(s)) --count[s];
      }
    }
    for (auto& [s, purposes] : chosen) {
      std::sort(purposes.begin(), purposes.end());
      purposes.erase(std::unique(purposes.begin(), purposes.end()), purposes.end());
      picks.push_back({ni, s, n.state_values(s), std::move(purposes)});
    }
  }
  return picks;
}

}  // namespace uabt::campaign
