#pragma once
// Random BT.CPP script conditions over an integer (battery), a real (slope) and an enum
// (terrain), states near their constants (within float epsilon of them too), and the
// engine's answer in a state: for the tests that check a reading of scripts against the engine.
#include <optional>
#include <random>
#include <string>

#include "fretish/domain.hpp"
#include "runtime/blackboard.hpp"
#include "runtime/script/program.hpp"

namespace uabt::testing {

inline fretish::Domain rover_domain() {
  fretish::Domain d;
  d.variables = {
      {"battery", fretish::VarType::integer, "0", "100", {}, {}, true, ""},
      {"slope", fretish::VarType::real, "-45", "45", {}, {}, true, ""},
      {"terrain", fretish::VarType::enumeration, "", "", {"sand", "rocks"}, {}, true, ""},
  };
  return d;
}

class ConditionWriter {
 public:
  explicit ConditionWriter(unsigned seed) : random_(seed) {}

  std::string condition(int depth) {
    switch (depth > 0 ? pick(5) : pick(2)) {
      case 0: return term(2) + " " + pick_of({"==", "!=", "<", "<=", ">", ">="}) + " " + term(2);
      case 1:
        return std::string("terrain ") + pick_of({"==", "!="}) + " '" + pick_of({"sand", "rocks"}) +
               "'";
      case 2: return "(" + condition(depth - 1) + " && " + condition(depth - 1) + ")";
      case 3: return "(" + condition(depth - 1) + " || " + condition(depth - 1) + ")";
      default: return "!(" + condition(depth - 1) + ")";
    }
  }

 private:
  std::string term(int depth) {
    switch (depth > 0 ? pick(9) : pick(4)) {
      case 0: return "battery";
      case 1: return "slope";
      case 2: return pick_of({"0", "1", "2", "3", "5"});
      case 3: return pick_of({"0.5", "2.5", "0.1", "1.5"});
      case 4: return "(" + term(depth - 1) + " + " + term(depth - 1) + ")";
      case 5: return "(" + term(depth - 1) + " - " + term(depth - 1) + ")";
      case 6: return "(" + term(depth - 1) + " * " + term(depth - 1) + ")";
      case 7: return "(" + term(depth - 1) + " / " + pick_of({"2", "3", "0.5", "4"}) + ")";
      default: return "(" + condition(0) + " ? " + term(depth - 1) + " : " + term(depth - 1) + ")";
    }
  }
  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(random_); }
  const char* pick_of(std::initializer_list<const char*> options) {
    return options.begin()[pick(static_cast<int>(options.size()))];
  }
  std::mt19937 random_;
};

struct State {
  std::int64_t battery;
  double slope;
  std::string terrain;
};

inline State random_state(std::mt19937& random) {
  static const std::int64_t batteries[] = {0, 1, 2, 3, 4, 5, 7, 10};
  static const double slopes[] = {0, 0.5, 1, 1.5, 2.5, 0.1, -0.5, 5};
  // Within float epsilon (2^-23, about 1.19e-7) of a constant, and just beyond it.
  static const double offsets[] = {0, 0, 1e-7, -1e-7, 3e-7, -3e-7};
  auto index = [&](std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(random);
  };
  return {batteries[index(std::size(batteries))],
          slopes[index(std::size(slopes))] + offsets[index(std::size(offsets))],
          index(2) == 0 ? "sand" : "rocks"};
}

// The engine's answer: the truth of the condition, or nothing where the script stops the tick.
inline std::optional<bool> engine_truth(const std::string& code, const State& s) {
  runtime::Blackboard bb;
  bb.set("battery", runtime::ScriptValue::of_int(s.battery));
  bb.set("slope", runtime::ScriptValue::of_real(s.slope));
  bb.set("terrain", runtime::ScriptValue::of_string(s.terrain));
  runtime::script::Program program = runtime::script::Program::parse(code);
  program.bind(bb, runtime::Blackboard::kRootScope);
  try {
    return program.run(bb).as_double() != 0.0;
  } catch (const runtime::script::ScriptError&) {
    return std::nullopt;
  }
}

}  // namespace uabt::testing
