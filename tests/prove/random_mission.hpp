#pragma once
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "mission_writer.hpp"

namespace uabt::testing {

// A small random mission over the node kinds the symbolic engine models (Repeat at most
// once): a main tree and a
// SubTree, booleans A, B (B written by an action), an environment condition C, an integer x
// in [0, 3], three actions with random world.json contracts (Act2 without one), and random
// properties over the observables.
class RandomMission : public MissionWriter {
 public:
  explicit RandomMission(unsigned seed) : MissionWriter(seed) {
    const std::string main = node(0, 3), sub = node(0, 2);
    files["mission.xml"] =
        "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
        "  <BehaviorTree ID=\"MainTree\">\n" +
        main +
        "\n  </BehaviorTree>\n"
        "  <BehaviorTree ID=\"Sub\">\n" +
        sub + "\n  </BehaviorTree>\n</root>\n";
    files["domain.fret"] = "boolean A, B\ninteger x in [0, 3]\n";
    files["world.json"] = world();
    files["requirements.fret"] = properties();
  }

 private:
  std::string leaf() {
    switch (pick(9)) {
      case 0: return use("AlwaysSuccess", "<AlwaysSuccess/>");
      case 1: return use("AlwaysFailure", "<AlwaysFailure/>");
      case 2: return use("Script", "<Script code=\"x = x &lt; 3 ? x + 1 : 0\"/>");
      case 3: return use("ScriptCondition", "<ScriptCondition code=\"x &gt;= 2\"/>");
      case 4: return use("Condition", pick(2) ? "<A/>" : "<C/>");
      case 5: return use("Condition", "<B/>");
      default: {
        const std::string a = "Act" + std::to_string(pick(3));
        actions_.insert(a);
        return use("Action", "<" + a + "/>");
      }
    }
  }

  std::string node(int depth, int max) {
    if (depth >= max || pick(4) == 0) return leaf();
    auto children = [&](int n) {
      std::string s;
      for (int i = 0; i < n; ++i) s += node(depth + 1, max);
      return s;
    };
    const std::string named = " name=\"N" + std::to_string(names_++) + "\"";
    switch (pick(12)) {
      case 0: return wrap("Sequence", named, children(1 + pick(3)));
      case 1: return wrap("ReactiveSequence", named, children(1 + pick(3)));
      case 2: return wrap("Fallback", named, children(1 + pick(3)));
      case 3: return wrap("ReactiveFallback", named, children(1 + pick(3)));
      case 4: return wrap("IfThenElse", named, children(2 + pick(2)));
      case 5: return wrap("Inverter", named, children(1));
      case 6: return wrap("ForceSuccess", named, children(1));
      case 7: return wrap("ForceFailure", named, children(1));
      case 10: return wrap("KeepRunningUntilFailure", named, children(1));
      case 9:
        if (!repeated_) {  // one Repeat at most: its wake-up re-ticks multiply the tick
          repeated_ = true;
          return wrap("Repeat", named + " num_cycles=\"" + std::to_string(1 + pick(2)) + "\"",
                      children(1));
        }
        [[fallthrough]];
      case 8:
        if (max > 2) return use("SubTree", "<SubTree ID=\"Sub\" _autoremap=\"true\"/>");
        [[fallthrough]];
      default: return wrap("Sequence", named, children(2));
    }
  }

  std::string world() {
    static const char* effects[] = {"A = true", "A = false", "B = !B", "x = x &lt; 3 ? x + 1 : x",
                                    "x = 0"};
    std::string s = "{\"initial\": \"x = 0\", \"actions\": {";
    for (int i = 0; i < 2; ++i) {
      const int lo = 1 + pick(2), hi = lo + pick(2);
      const std::string results = pick(3) == 0 ? "\"success\""
                                  : pick(2)    ? "\"success\", \"failure\""
                                               : "\"failure\"";
      std::string effect = effects[pick(5)];
      for (auto at = effect.find("&lt;"); at != std::string::npos; at = effect.find("&lt;"))
        effect.replace(at, 4, "<");
      s += std::string(i ? ", " : "") + "\"Act" + std::to_string(i) + "\": {\"ticks\": [" +
           std::to_string(lo) + ", " + std::to_string(hi) + "], \"results\": [" + results +
           "], \"on_success\": \"" + effect + "\", \"on_failure\": \"B = true\"}";
    }
    return s + "}}";
  }

  std::string properties() {
    std::vector<std::string> obs = {"A", "B", "x >= 2", "x = 0"};
    for (const auto& a : actions_)
      for (const char* f : {".running", ".success", ".failure"}) obs.push_back(a + f);
    for (int i = 0; i < names_; ++i) obs.push_back("N" + std::to_string(i) + ".running");
    auto any = [&] { return obs[static_cast<std::size_t>(pick(static_cast<int>(obs.size())))]; };
    std::string s;
    for (int i = 0; i < 3; ++i) {
      const std::string id = "P" + std::to_string(i) + ": ";
      switch (pick(4)) {
        case 0: s += id + "Mission shall always satisfy " + any() + " -> " + any() + "\n"; break;
        case 1: s += id + "Mission shall never satisfy " + any() + " & " + any() + "\n"; break;
        case 2:
          s += id + "upon " + any() + " Mission shall within 2 ticks satisfy " + any() + "\n";
          break;
        default: s += id + "Mission shall always satisfy !" + any() + " | " + any() + "\n";
      }
    }
    if (pick(3) == 0) s += "E: Environment shall always satisfy !C | A\n";
    return s;
  }

  std::set<std::string> actions_;
  int names_ = 0;
  bool repeated_ = false;
};

}  // namespace uabt::testing
