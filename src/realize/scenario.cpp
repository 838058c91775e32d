#include <algorithm>
#include <nlohmann/json.hpp>

#include "base/finding.hpp"
#include "base/number_text.hpp"
#include "realize/realize.hpp"

namespace uabt::realize {

namespace {

using Json = nlohmann::ordered_json;

}  // namespace

std::optional<std::string> defeat_scenario(const Result& result, const Component& component) {
  if (component.defeating_inputs.empty() || component.conflicts.empty()) return std::nullopt;
  const std::vector<std::string>& conflict = component.conflicts.front();
  Json initial = Json::object(), events = Json::array(), actions = Json::object();
  std::map<std::string, Value> held;  // what each input holds since it was last set
  std::map<std::string, std::set<std::string>> endings;  // action → how the inputs end it
  for (const Choice& choice : component.defeating_inputs) {
    Json set = Json::object();
    for (const auto& [name, value] : choice.inputs) {
      if (name.ends_with(".result")) {  // how the action ends, if it ends this tick
        const auto signal = std::find_if(result.signals.begin(), result.signals.end(),
                                         [&](const Signal& s) { return s.name == name; });
        const std::string action = signal == result.signals.end() ? "" : signal->action;
        // A label of leaves of several IDs: no one action to give the result to.
        endings[action.empty() ? name.substr(0, name.size() - 7) : action].insert(
            action.empty() ? std::string() : value.to_string());
        continue;
      }
      const auto it = held.find(name);
      if (choice.tick == 1)
        initial[name] = value_json(value);
      else if (it == held.end() || !(it->second == value))
        set[name] = value_json(value);
      held.insert_or_assign(name, value);
    }
    if (!set.empty()) events.push_back(Json{{"at", choice.tick}, {"set", set}});
  }
  std::string unfixed;  // actions the inputs end in more than one way, or nodes of several IDs
  for (const auto& [action, results] : endings) {
    if (results.size() == 1 && !results.begin()->empty())
      actions[action] = Json{{"ticks", 1}, {"result", *results.begin()}};
    else
      unfixed += (unfixed.empty() ? "" : ", ") + action;
  }
  Json s = Json::object();
  std::string description =
      "Inputs that defeat every behavior tree meeting " + listed_with_and(conflict) +
      " (uabt realizable): a tree that keeps running through tick " +
      std::to_string(component.defeating_inputs.back().tick) + " violates one of them";
  if (!unfixed.empty())
    description += "; how " + unfixed +
                   " end is left to the mission's world (the game ends them differently from "
                   "tick to tick, or the name stands for nodes of several IDs)";
  s["description"] = description;
  s["max_ticks"] = component.defeating_inputs.back().tick;
  s["initial"] = initial;
  s["actions"] = actions;
  if (!events.empty()) s["events"] = events;
  return s.dump(2) + "\n";
}

}  // namespace uabt::realize
