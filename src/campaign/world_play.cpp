#include "campaign/world_play.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

#include "base/number_text.hpp"
#include "bt/script/value.hpp"
#include "runtime/blackboard.hpp"
#include "runtime/script/program.hpp"
#include "runtime/trace.hpp"
#include "smt/evaluate.hpp"

namespace uabt::campaign {

namespace {

bool fits(const load::Mission& mission, const prove::WorldModel& world, const State& state) {
  if (world.initial && !smt::try_evaluate(*world.initial, mission.domain, state).value_or(false))
    return false;
  for (const auto& a : mission.domain.assumptions)
    if (a.expr && !smt::try_evaluate(*a.expr, mission.domain, state).value_or(false)) return false;
  return true;
}

void collect_numbers(const fretish::Expr& e, std::vector<std::string>& out) {
  if (e.kind == fretish::ExprKind::number) out.push_back(e.text);
  for (const auto& a : e.args) collect_numbers(*a, out);
}

// The values tried for a variable: its own first, then the others of its type the
// conditions name (a number n also as n - 1 and n + 1).
std::vector<Value> candidates(const fretish::Variable& v, const Value& now,
                              const std::vector<std::string>& numbers) {
  std::vector<Value> out{now};
  switch (v.type) {
    case fretish::VarType::boolean: out.push_back(Value::of_bool(!now.boolean)); break;
    case fretish::VarType::enumeration:
      for (const auto& e : v.enum_values)
        if (e != now.text) out.push_back(Value::of_enum(e));
      break;
    case fretish::VarType::integer:
      for (const auto& n : numbers) try {
          const long long x = std::stoll(n);
          for (long long d : {0LL, -1LL, 1LL}) out.push_back(Value::of_int(x + d));
        } catch (const std::exception&) {
        }
      break;
    case fretish::VarType::real:
      for (const auto& n : numbers) try {
          const double x = std::stod(n);
          for (double d : {0.0, -1.0, 1.0})
            out.push_back(Value::of_real(x + d, number_text(x + d)));
        } catch (const std::exception&) {
        }
      break;
  }
  return out;
}

Value first_value(const fretish::Variable& v) {
  switch (v.type) {
    case fretish::VarType::boolean: return Value::of_bool(false);
    case fretish::VarType::enumeration:
      return v.enum_values.empty() ? Value::of_enum("") : Value::of_enum(v.enum_values.front());
    case fretish::VarType::integer: return Value::of_int(0);
    case fretish::VarType::real: return Value::of_real(0, "0");
  }
  return Value::of_bool(false);
}

}  // namespace

State world_initial(const load::Mission& mission, const prove::WorldModel& world, State state) {
  // What world.json's `initial` reads gets a value too (a condition the domain infers).
  std::set<std::string> literals;
  for (const auto& v : mission.domain.variables)
    literals.insert(v.enum_values.begin(), v.enum_values.end());
  if (world.initial)
    for (const auto& id : fretish::identifiers_of(*world.initial)) {
      if (find_value(state, id) != nullptr || literals.count(id)) continue;
      const fretish::Variable* v = mission.domain.find(id);
      state.emplace_back(id, v != nullptr ? first_value(*v) : Value::of_bool(false));
    }
  if (fits(mission, world, state)) return state;
  // The targets' variables stay as planned.
  std::set<std::string> guarded;
  for (const auto& s : mission.selections)
    if (s.guard)
      for (const auto& id : fretish::identifiers_of(*s.guard)) guarded.insert(id);
  std::set<std::string> read;
  std::vector<std::string> numbers;
  auto scan = [&](const fretish::ExprPtr& e) {
    if (!e) return;
    for (const auto& id : fretish::identifiers_of(*e)) read.insert(id);
    collect_numbers(*e, numbers);
  };
  scan(world.initial);
  for (const auto& a : mission.domain.assumptions) scan(a.expr);
  std::vector<std::size_t> free;
  std::vector<std::vector<Value>> values;
  fretish::Variable condition;  // a name the domain does not declare: a condition
  condition.type = fretish::VarType::boolean;
  for (std::size_t k = 0; k < state.size(); ++k) {
    const std::string& name = state[k].first;
    if (!read.count(name) || guarded.count(name)) continue;
    const fretish::Variable* v = mission.domain.find(name);
    free.push_back(k);
    values.push_back(candidates(v != nullptr ? *v : condition, state[k].second, numbers));
  }
  // Odometer over the candidates, the first variable fastest, a bounded number of tries.
  std::vector<std::size_t> digit(free.size(), 0);
  for (int tries = 0; tries < 4096; ++tries) {
    State trial = state;
    for (std::size_t i = 0; i < free.size(); ++i) trial[free[i]].second = values[i][digit[i]];
    if (fits(mission, world, trial)) return trial;
    std::size_t i = 0;
    for (; i < free.size(); ++i) {
      if (++digit[i] < values[i].size()) break;
      digit[i] = 0;
    }
    if (i == free.size()) break;
  }
  return state;
}

nlohmann::ordered_json world_actions(const prove::WorldModel& world, const State& initial) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [name, contract] : world.actions) {
    nlohmann::ordered_json a = nlohmann::ordered_json::object();
    const runtime::NodeStatus result =
        contract.results.empty() ? runtime::NodeStatus::success : contract.results.front();
    a["ticks"] = std::max<std::int64_t>(1, contract.min_ticks);
    a["result"] = result == runtime::NodeStatus::failure ? "failure" : "success";
    const std::string& code =
        result == runtime::NodeStatus::failure ? contract.on_failure : contract.on_success;
    const std::vector<std::string> written = prove::assigned_names(code);
    if (!written.empty()) {
      // The effect run on the initial state: what it assigns, as values.
      runtime::Blackboard board;
      for (const auto& variable : written) board.set(variable, runtime::ScriptValue{});
      for (const auto& [variable, value] : initial)
        board.set(variable, bt::script::from_value(value));
      nlohmann::ordered_json effects = nlohmann::ordered_json::object();
      try {
        auto program = runtime::script::Program::parse(code);
        program.bind(board, runtime::Blackboard::kRootScope);
        program.run(board);
        for (const auto& variable : written)
          if (const runtime::ScriptValue* v = board.get(variable))
            effects[variable] = runtime::value_json(*v);
      } catch (const std::exception&) {
        // An effect that does not run on the initial state: the action's run has none.
      }
      if (!effects.empty()) a["effects"] = effects;
    }
    if (!contract.outputs.empty()) {
      nlohmann::ordered_json outputs = nlohmann::ordered_json::object();
      for (const auto& [port, value] : contract.outputs) outputs[port] = runtime::value_json(value);
      a["outputs"] = outputs;
    }
    out[name] = a;
  }
  return out;
}

}  // namespace uabt::campaign
