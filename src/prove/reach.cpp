#include "prove/reach.hpp"

#include <nlohmann/json.hpp>

#include "monitor/property_set.hpp"

namespace uabt::prove {

fretish::Requirement trap_requirement(const Goal& goal) {
  fretish::Requirement r;
  r.id = goal.id;
  r.component = "uabt";
  if (goal.scope_of != nullptr) {
    r.scope = goal.scope_of->scope;
    r.location = goal.scope_of->location;
  }
  if (goal.at_judged_tick && goal.scope_of != nullptr) {
    const fretish::Requirement& g = *goal.scope_of;
    r.conditions = g.conditions;
    r.timing = g.timing;
    r.response = g.response;
    r.judged = goal.condition;
    r.text = "uabt shall never satisfy " + fretish::to_fretish(*goal.condition) +
             " where the response of " + g.id + " is judged (" + g.text + ")";
    return r;
  }
  r.timing.keyword = "always";
  r.response = fretish::make_expr(fretish::ExprKind::logical_not, {goal.condition});
  r.text = (r.scope ? r.scope->keyword + " " +
                          (r.scope->condition ? fretish::to_fretish(*r.scope->condition)
                                              : r.scope->mode) +
                          " "
                    : std::string()) +
           "uabt shall always satisfy " + fretish::to_fretish(*r.response);
  return r;
}

std::vector<Reach> reach(const load::Mission& mission, const bt::Document& compiled,
                         const WorldModel& world, const std::vector<Goal>& goals,
                         const Options& options) {
  std::vector<Reach> out(goals.size());
  if (goals.empty()) return out;
  load::Mission traps = mission;
  traps.properties.clear();
  for (const auto& p : mission.properties)
    if (fretish::is_assumption(p)) traps.properties.push_back(p);
  for (const Goal& g : goals) traps.properties.push_back(trap_requirement(g));
  const Result result = prove(traps, compiled, world, options);
  for (std::size_t k = 0; k < goals.size() && k < result.answers.size(); ++k) {
    const Answer& a = result.answers[k];
    Reach& r = out[k];
    r.verdict = a.verdict;
    r.depth = a.depth;
    r.witness = a.counterexample;
    // A witness is a scenario that gets there, not a counterexample of one of the mission's
    // guarantees: `uabt run` judges it as any other scenario.
    if (r.witness) {
      auto scenario = nlohmann::ordered_json::parse(r.witness->scenario);
      scenario.erase("counterexample_of");
      r.witness->scenario = scenario.dump(2) + "\n";
    }
    r.engine = result.engine;
    r.states = result.states;
    r.reason = a.reason;
    if (a.verdict == Verdict::vacuous && result.vacuity) r.reason = result.vacuity->message;
  }
  return out;
}

}  // namespace uabt::prove
