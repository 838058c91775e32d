// A node's targets as conditions of one tick on its variables: what the world model's search
// (world_reach.cpp) asks `uabt prove` to reach at the node.
#include "campaign/campaign.hpp"
#include "campaign/node.hpp"
#include "fretish/expr.hpp"

namespace uabt::campaign {

namespace {

// The MC/DC pairs of a target asked of the world model; beyond them it is not decided.
constexpr std::size_t kMaxPairs = 16;

std::string literal(const std::string& atom, bool holds) {
  return (holds ? "(" : "!(") + atom + ")";
}

}  // namespace

std::string Model::Node::selects_condition(std::size_t k) const {
  std::vector<std::string> parts;
  for (std::size_t j = 0; j < k; ++j)
    if (reqs[j]->guard) parts.push_back(literal(fretish::to_fretish(*reqs[j]->guard), false));
  if (reqs[k]->guard) parts.push_back(literal(fretish::to_fretish(*reqs[k]->guard), true));
  return parts.empty() ? "true" : join(parts, " & ");
}

std::string Model::Node::signature_condition(std::uint64_t state) const {
  // One atom per column: the first, which the column holds the truth of.
  std::vector<std::string> parts;
  std::vector<bool> done(words * 64, false);
  for (std::size_t a = 0; a < atom_text.size(); ++a) {
    const std::size_t c = column[a];
    if (done[c]) continue;
    done[c] = true;
    parts.push_back(literal(atom_text[a], atom_holds(state, a)));
  }
  return parts.empty() ? "true" : join(parts, " & ");
}

std::string Model::Node::signature_condition(const State& values) const {
  std::vector<std::string> parts;
  for (std::size_t a : solved->column_atom)
    parts.push_back(literal(atom_text[a], solved_holds(*atom_expr[a], values)));
  return parts.empty() ? "true" : join(parts, " & ");
}

std::string Model::Node::goal_condition(const Goal& goal) const {
  switch (goal.kind) {
    case Goal::Kind::select: return selects_condition(goal.req);
    case Goal::Kind::guard: return literal(fretish::to_fretish(*reqs[goal.req]->guard), goal.value);
    case Goal::Kind::pair: return "";
    case Goal::Kind::boundary: {
      if (goal.line) {
        const std::string lhs = goal.variable + " + " + number_condition(goal.slope) + " * " +
                                goal.variable2 + " + " + number_condition(goal.offset);
        return lhs + (goal.sign < 0 ? " < 0" : goal.sign == 0 ? " = 0" : " > 0");
      }
      if (goal.point) return goal.variable + " = " + number_condition(*goal.lo);
      std::vector<std::string> parts;
      if (goal.lo) parts.push_back(goal.variable + " > " + number_condition(*goal.lo));
      if (goal.hi) parts.push_back(goal.variable + " < " + number_condition(*goal.hi));
      return parts.empty() ? "true" : join(parts, " & ");
    }
  }
  return "";
}

const std::set<std::string>& Model::variables(std::size_t node) const {
  return nodes_[node]->names;
}

std::optional<Model::ReachCondition> Model::reach_condition(std::size_t target) const {
  if (target >= targets_.size()) return std::nullopt;
  for (std::size_t ni = 0; ni < nodes_.size(); ++ni) {
    const Node& n = *nodes_[ni];
    ReachCondition out;
    out.node = ni;
    if (n.solved) {
      for (const auto& g : n.solved->goals) {
        if (g.target != target) continue;
        if (g.kind != Node::Goal::Kind::pair) {
          out.single = n.goal_condition(g);
          return out;
        }
        // One pair was solved: other pairs may reach it where this one does not.
        out.complete = false;
        if (g.witness.size() == 2)
          out.pairs.emplace_back(n.signature_condition(n.solved->states[g.witness[0]]),
                                 n.signature_condition(n.solved->states[g.witness[1]]));
        return out;
      }
      continue;
    }
    for (const auto& local : n.locals) {
      if (local.target != target) continue;
      if (!local.pair) {
        out.single = local.condition;
        return out;
      }
      // The pairs are one per pair of signatures: each side is every state of its signature.
      for (const auto& [s, u] : local.pairs) {
        if (out.pairs.size() == kMaxPairs) {
          out.complete = false;
          break;
        }
        out.pairs.emplace_back(n.signature_condition(s), n.signature_condition(u));
      }
      return out;
    }
  }
  return std::nullopt;
}

}  // namespace uabt::campaign
