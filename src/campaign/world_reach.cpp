// Selection targets searched for with prove's world model: each one a trap `uabt prove`
// tries to reach (prove/reach.hpp), the runs it finds replayed as `uabt run` runs them.
#include "campaign/world_reach.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "base/text.hpp"
#include "campaign/node.hpp"
#include "fretish/parse.hpp"

namespace uabt::campaign {

namespace {

using Json = nlohmann::ordered_json;

// A goal of one target, or of one state of each pair of an MC/DC target.
struct Open {
  std::size_t target = 0;
  Model::ReachCondition reach;
  std::size_t single = 0;                                  // goal index
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // goal indices
};

}  // namespace

prove::Goal node_goal(const load::Mission& mission, const Model& model, std::size_t node,
                      const std::string& condition, const std::string& id) {
  std::string text = "(" + condition + ")";
  // A read of each variable, so that the run gives it a value: the state the node selects in
  // is what its targets are about.
  for (const auto& name : model.variables(node)) {
    const fretish::Variable* v = mission.domain.find(name);
    text += v != nullptr && v->type == fretish::VarType::boolean
                ? " & (" + name + " | !" + name + ")"
                : " & " + name + " = " + name;
  }
  std::vector<Finding> findings;
  fretish::ExprPtr parsed = fretish::parse_expression(text, {"<" + id + ">", 1, 1}, findings);
  if (!parsed)
    throw std::runtime_error("internal error: the condition of " + id + " (" + text +
                             ") does not parse");
  prove::Goal goal;
  goal.id = id;
  goal.condition = fretish::make_expr(fretish::ExprKind::logical_and,
                                      {fretish::make_identifier(model.adaptable(node)), parsed});
  return goal;
}

bool unreached(const prove::Reach& a, std::string& reason) {
  switch (a.verdict) {
    case prove::Verdict::proved: return true;
    case prove::Verdict::vacuous: reason = "world.json leaves no run: " + a.reason; return true;
    case prove::Verdict::bounded:
      reason = "not decided within " + count_text(a.depth, "tick");
      break;
    case prove::Verdict::unsupported:
      reason = "not decided: prove cannot read it: " + a.reason;
      break;
    case prove::Verdict::violated: break;
  }
  return false;
}

void reach_in_world(const load::Mission& mission, const Model& model, const Replayer& replayer,
                    const Options& options, Campaign& c) {
  std::vector<RunRecord> runs;
  for (const auto& s : c.scenarios) runs.push_back(s.run);
  const std::vector<bool> before = model.covered(runs);

  // The goals: per node with a target left, the node ticked at all; per target its condition,
  // or both states of each of its pairs. Each condition once.
  std::vector<prove::Goal> goals;
  std::map<std::pair<std::size_t, std::string>, std::size_t> known;
  auto ask = [&](std::size_t node, const std::string& condition) {
    const auto [it, fresh] = known.emplace(std::make_pair(node, condition), goals.size());
    if (fresh) {
      goals.push_back(
          node_goal(mission, model, node, condition,
                    "reach/" + model.adaptable(node) + "/" + std::to_string(it->second)));
    }
    return it->second;
  };
  std::vector<Open> open;
  std::map<std::size_t, std::size_t> ticked;  // node: the goal of its being ticked at all
  for (std::size_t t = 0; t < c.targets.size() && t < before.size(); ++t) {
    if (before[t] || !c.targets[t].reachable || c.targets[t].criterion == Criterion::guarantee)
      continue;
    auto reach = model.reach_condition(t);
    if (!reach) continue;
    Open o;
    o.target = t;
    o.reach = std::move(*reach);
    if (!ticked.count(o.reach.node)) ticked[o.reach.node] = ask(o.reach.node, "true");
    if (o.reach.pairs.empty() && !o.reach.single.empty())
      o.single = ask(o.reach.node, o.reach.single);
    for (const auto& [s, u] : o.reach.pairs)
      o.pairs.emplace_back(ask(o.reach.node, s), ask(o.reach.node, u));
    open.push_back(std::move(o));
  }
  if (open.empty()) return;

  const prove::WorldModel unconstrained;
  const prove::WorldModel& world = options.world != nullptr ? *options.world : unconstrained;
  const bool contracts = options.world != nullptr && !world.file.empty();
  std::vector<prove::Reach> answers;
  try {
    prove::Options prove_options;
    prove_options.depth = options.prove_depth;
    prove_options.max_states = options.prove_max_states;
    answers = prove::reach(mission, replayer.document(), world, goals, prove_options);
  } catch (const std::exception& e) {
    for (const Open& o : open) {
      Target& target = c.targets[o.target];
      target.reachable = false;
      target.undecided = true;
      target.reason =
          std::string("not decided: uabt prove cannot search this mission: ") + e.what();
    }
    c.notes.push_back(std::to_string(open.size()) +
                      " selection targets the runs missed were not searched with the world "
                      "model: " +
                      e.what());
    return;
  }

  // Each run prove found, replayed as `uabt run` runs it, to the tick it reaches its goal.
  std::vector<std::optional<RunRecord>> played(goals.size());
  std::vector<std::string> scenario(goals.size()), problem(goals.size());
  for (std::size_t g = 0; g < goals.size(); ++g) {
    if (answers[g].verdict != prove::Verdict::violated || !answers[g].witness) continue;
    scenario[g] = answers[g].witness->scenario;
    try {
      played[g] = replayer.run(scenario[g], "reach.json");
    } catch (const std::exception& e) {
      problem[g] = std::string("its scenario does not run: ") + e.what();
    }
  }

  // Greedy set cover: the run (both runs of a pair) that covers most targets left, first found
  // first.
  std::vector<std::vector<std::size_t>> units;
  for (const Open& o : open) {
    if (o.reach.pairs.empty()) {
      if (played[o.single]) units.push_back({o.single});
      continue;
    }
    for (const auto& [s, u] : o.pairs)
      if (played[s] && played[u]) units.push_back(s == u ? std::vector{s} : std::vector{s, u});
  }
  std::vector<std::size_t> chosen;
  std::vector<std::vector<std::size_t>> purposes;  // per chosen goal
  auto covered_with = [&](const std::vector<std::size_t>& extra) {
    std::vector<RunRecord> all = runs;
    for (std::size_t g : chosen) all.push_back(*played[g]);
    for (std::size_t g : extra)
      if (std::find(chosen.begin(), chosen.end(), g) == chosen.end()) all.push_back(*played[g]);
    return model.covered(all);
  };
  std::vector<bool> now = before;
  for (;;) {
    std::size_t best = units.size(), best_gain = 0;
    std::vector<bool> best_covered;
    for (std::size_t u = 0; u < units.size(); ++u) {
      const std::vector<bool> with = covered_with(units[u]);
      std::size_t gain = 0;
      for (const Open& o : open) gain += with[o.target] && !now[o.target];
      if (gain > best_gain) {
        best = u;
        best_gain = gain;
        best_covered = with;
      }
    }
    if (best == units.size()) break;
    // Each run is for what it covers itself, and both runs of a pair for the pair's target.
    std::vector<std::vector<bool>> alone;
    for (std::size_t g : units[best]) alone.push_back(covered_with({g}));
    for (std::size_t i = 0; i < units[best].size(); ++i) {
      const std::size_t g = units[best][i];
      auto at = std::find(chosen.begin(), chosen.end(), g);
      if (at == chosen.end()) {
        chosen.push_back(g);
        purposes.emplace_back();
        at = chosen.end() - 1;
      }
      auto& p = purposes[static_cast<std::size_t>(at - chosen.begin())];
      for (const Open& o : open)
        if (best_covered[o.target] && !now[o.target] && (alone[i][o.target] || !o.pairs.empty()))
          p.push_back(o.target);
    }
    now = best_covered;
  }
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const std::size_t g = chosen[i];
    Scenario s;
    std::sort(purposes[i].begin(), purposes[i].end());
    s.purpose = purposes[i];
    s.name = model.adaptable(model.reach_condition(s.purpose.front())->node) + "-00";
    for (std::size_t t : s.purpose)
      s.description += (s.description.empty() ? "" : "; ") + c.targets[t].text;
    s.description = "Test campaign: " + s.description;
    Json j = Json::parse(scenario[g]);
    j["description"] = s.description;
    s.json = j.dump(2) + "\n";
    s.run = *played[g];
    c.scenarios.push_back(std::move(s));
  }

  // What no run reaches: unreachable where prove shows it, else not decided.
  const std::string nobody =
      contracts ? "no run that world.json allows"
                : "no run (whatever its actions return: no world.json bounds them)";
  auto why_not = [&](std::size_t g, std::string& reason) {
    const prove::Reach& a = answers[g];
    if (a.verdict != prove::Verdict::violated) return unreached(a, reason);
    reason = "not decided: uabt prove reaches it at tick " + std::to_string(a.depth) +
             " but the replay of its run does not" +
             (problem[g].empty() ? std::string() : " (" + problem[g] + ")");
    return false;
  };
  std::size_t reached = 0, unreachable = 0, undecided = 0;
  for (const Open& o : open) {
    Target& target = c.targets[o.target];
    if (now[o.target]) {
      ++reached;
      continue;
    }
    target.reachable = false;
    const std::string& node = model.adaptable(o.reach.node);
    std::string ticked_reason;
    if (why_not(ticked.at(o.reach.node), ticked_reason)) {
      target.reason = ticked_reason.empty() ? "a path no run takes: " + nobody + " ticks " + node
                                            : ticked_reason;
      ++unreachable;
      continue;
    }
    std::string reason;
    bool proved = false;
    if (o.reach.pairs.empty()) {
      proved = why_not(o.single, reason);
      if (proved && reason.empty())
        reason = nobody + " ticks " + node + " in a state where " + o.reach.single;
    } else {
      proved = o.reach.complete;
      std::string first;
      for (const auto& [s, u] : o.pairs) {
        std::string rs, ru;
        const bool none = why_not(s, rs) || why_not(u, ru);
        if (!none && first.empty()) first = !rs.empty() ? rs : ru;
        proved = proved && none;
      }
      if (proved)
        reason = nobody + " ticks " + node + " in both states of any of its " +
                 std::to_string(o.pairs.size()) + (o.pairs.size() == 1 ? " pair" : " pairs");
      else if (!o.reach.complete && first.empty())
        reason = "not decided: " + nobody + " ticks " + node + " in both states of the " +
                 std::to_string(o.pairs.size()) + " of its pairs searched";
      else
        reason = first;
    }
    target.reason = reason;
    target.undecided = !proved;
    ++(proved ? unreachable : undecided);
  }
  c.notes.push_back(std::to_string(open.size()) +
                    (open.size() == 1 ? " selection target" : " selection targets") +
                    " the planned runs miss, searched for with the world model uabt prove "
                    "explores: " +
                    std::to_string(reached) + " reached, " + std::to_string(unreachable) +
                    " unreachable, " + std::to_string(undecided) + " not decided");
}

}  // namespace uabt::campaign
