#pragma once
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "compile/compile.hpp"

#include "mission_writer.hpp"

namespace uabt::testing {

// A random mission for the engines' differential sweep, wider than RandomMission: one or two
// adaptable nodes (sequence, reactive or optimized selection, or the style given to the gate)
// whose guards read booleans, integers, reals and enumerations of the environment; every
// control node and decorator the runtime has; actions whose world.json effects write booleans
// and an integer, some copying an environment value; domain assumptions and Environment
// requirements; guarantees with modes, upon/if/whenever conditions and
// always/never/immediately/within/for/until timings. With `temporal`, the guarantees also read
// FRET's temporal functions persisted, occurred, prevOcc and FTP (and the random choices differ).
// With Forms::every (the agreement test), it draws every form a user writes too: each timing
// FRET has (immediately, next, within/for/after N, until, before, eventually, always, never),
// each scope (in, not in, only in, after/before a mode or a condition, only after/before,
// while), a `tick 100 ms` / `tick 1 s` period, ParallelAll, and world.json contracts with or
// without `initial`, a number or a range of ticks, and effects left out; Forms::time_units also
// writes the durations in time units.
class SweepMission : public MissionWriter {
 public:
  enum class Forms { engines, every, time_units };

  // With `mixed`, atoms also compare the environment's real r and wide integer w with the
  // mission's own x (guards, scripts, effects, an assumption, guarantees): the explicit engine
  // cuts them in each state it explores.
  explicit SweepMission(unsigned seed, bool temporal = false, bool mixed = false,
                        Forms forms = Forms::engines)
      : MissionWriter(seed), temporal_(temporal), mixed_(mixed), forms_(forms) {
    style = static_cast<compile::SelectionStyle>(pick(3));
    integer_ = pick(2);
    real_ = mixed || pick(2);
    enum_ = pick(2);
    adaptables_ = 1 + pick(2);
    wide_ = pick(3) == 0;
    if (forms_ != Forms::engines) period_ = forms_ == Forms::time_units ? 1 + pick(2) : pick(3);
    std::string main = node(0, 3);
    for (int i = static_cast<int>(adaptable_ids_.size()); i < adaptables_; ++i)
      main = "<Sequence>" + adaptable() + main + "</Sequence>";
    // Sub's nodes exist in a run only when the main tree calls it: the guarantees read them only
    // then (without a call, the gate rightly says such a node is in no tree of the run).
    sub_first_ = names_;
    in_sub_ = true;
    const std::string sub = node(1, 3);
    in_sub_ = false;
    sub_end_ = names_;
    files["mission.xml"] =
        document("MainTree", main, "<BehaviorTree ID=\"Sub\">" + sub + "</BehaviorTree>\n");
    for (const std::string& id : adaptable_ids_)
      for (int k = 0; k < 3; ++k) {
        const std::string alt = id + "_alt" + std::to_string(k);
        files["alternatives/" + id + "/" + alt + ".xml"] = document(alt, node(2, 4));
      }
    files["domain.fret"] = domain();
    files["world.json"] = world();
    files["requirements.fret"] = requirements();
  }

  compile::SelectionStyle style;  // the gate's style for the nodes that declare none
  bool time_units = false;        // a duration is written in a unit of time, not in ticks

 private:
  template <class T>
  const T& any(const std::vector<T>& v) {
    return v[static_cast<std::size_t>(pick(static_cast<int>(v.size())))];
  }

  static std::string document(const std::string& id, const std::string& body,
                              const std::string& more = "") {
    return "<root BTCPP_format=\"4\" main_tree_to_execute=\"" + id + "\">\n<BehaviorTree ID=\"" +
           id + "\">" + body + "</BehaviorTree>\n" + more + "</root>\n";
  }

  std::string adaptable() {
    const std::string id = "ad" + std::to_string(adaptable_ids_.size());
    adaptable_ids_.push_back(id);
    static const char* styles[] = {"", " selection=\"sequence\"", " selection=\"reactive\"",
                                   " selection=\"optimized\""};
    return use("Adaptable", "<Adaptable ID=\"" + id + "\"" + styles[pick(4)] + "/>");
  }

  // An environment reading for the tree's scripts and conditions.
  std::string env_check() {
    std::vector<std::string> checks = {"<E/>", "<C/>"};
    if (integer_) checks.push_back("<ScriptCondition code=\"n &gt;= 2\"/>");
    if (real_) checks.push_back("<ScriptCondition code=\"r &lt; 4.5\"/>");
    if (mixed_) {
      checks.push_back("<ScriptCondition code=\"r &gt; x + 1.5\"/>");
      checks.push_back("<ScriptCondition code=\"w &lt; 300000 * x\"/>");
    }
    return any(checks);
  }

  std::string leaf() {
    switch (pick(10)) {
      case 0: return use("AlwaysSuccess", "<AlwaysSuccess/>");
      case 1: return use("AlwaysFailure", "<AlwaysFailure/>");
      case 2: return use("Script", "<Script code=\"x = x &lt; 3 ? x + 1 : 0\"/>");
      case 3: return use("ScriptCondition", "<ScriptCondition code=\"x &gt;= 2\"/>");
      case 4: return use("Condition", pick(2) ? "<A/>" : "<B/>");
      case 5: return use("Condition", env_check());
      default: {
        const std::string a = "Act" + std::to_string(pick(3));
        actions_.insert(a);
        if (!in_sub_) run_actions_.insert(a);
        return use("Action", "<" + a + "/>");
      }
    }
  }

  std::string node(int depth, int max) {
    if (depth >= max || pick(4) == 0) {
      if (static_cast<int>(adaptable_ids_.size()) < adaptables_ && depth > 0 && pick(2))
        return adaptable();
      return leaf();
    }
    auto children = [&](int n) {
      std::string s;
      for (int i = 0; i < n; ++i) s += node(depth + 1, max);
      return s;
    };
    const std::string named = " name=\"N" + std::to_string(names_++) + "\"";
    // The kinds the symbolic engine models; the others only in a "wide" mission, which
    // only the explicit engine answers.
    switch (pick(wide_ ? (forms_ != Forms::engines ? 18 : 17) : 12)) {
      case 0: return wrap("Sequence", named, children(1 + pick(3)));
      case 1: return wrap("ReactiveSequence", named, children(1 + pick(3)));
      case 2: return wrap("Fallback", named, children(1 + pick(3)));
      case 3: return wrap("ReactiveFallback", named, children(1 + pick(3)));
      case 4: return wrap("IfThenElse", named, children(2 + pick(2)));
      case 5: return wrap("Inverter", named, children(1));
      case 6: return wrap("ForceSuccess", named, children(1));
      case 7: return wrap("ForceFailure", named, children(1));
      case 8: return wrap("KeepRunningUntilFailure", named, children(1));
      case 12: return wrap("SequenceWithMemory", named, children(1 + pick(3)));
      case 13: return wrap("RetryUntilSuccessful", named + " num_attempts=\"2\"", children(1));
      case 14: return wrap("RunOnce", named, children(1));
      case 15:
        return wrap(
            "Parallel",
            named + " success_count=\"" + std::to_string(1 + pick(2)) + "\" failure_count=\"1\"",
            children(2));
      case 16: return wrap("WhileDoElse", named, children(2 + pick(2)));
      case 17: return wrap("ParallelAll", named + " max_failures=\"1\"", children(2));
      case 9:
        if (!repeated_) {  // one Repeat at most: its wake-up re-ticks multiply the tick
          repeated_ = true;
          return wrap("Repeat", named + " num_cycles=\"" + std::to_string(1 + pick(2)) + "\"",
                      children(1));
        }
        [[fallthrough]];
      case 10:
        if (depth == 0 && !in_sub_) sub_called_ = true;
        if (depth == 0) return use("SubTree", "<SubTree ID=\"Sub\" _autoremap=\"true\"/>");
        [[fallthrough]];
      default: return wrap("Sequence", named, children(2));
    }
  }

  std::string domain() {
    std::string s = "boolean A, B, E\ninteger x in [0, 3]\n";
    if (integer_) s += "integer n in [0, 4]\n";
    if (real_) s += "real r in [0, 10]\n";
    if (enum_) s += "enum t in {p, q, s}\n";
    if (mixed_) s += "integer w in [0, 1000000]\nassume a1: r <= x + 8\n";
    if (period_ != 0) s += period_ == 1 ? "tick 100 ms\n" : "tick 1 s\n";
    const auto groups = env_groups();
    if (groups.size() > 1 && pick(2))
      s += "assume a0: !(E & " +
           any(groups[1 + static_cast<std::size_t>(pick(static_cast<int>(groups.size()) - 1))]) +
           ")\n";
    return s;
  }

  // Atoms over the environment, one list per variable.
  std::vector<std::vector<std::string>> env_groups() {
    std::vector<std::vector<std::string>> groups = {{"E", "!E"}};
    if (integer_) groups.push_back({"n >= 3", "n < 1", "n = 2"});
    if (real_ && mixed_) groups.push_back({"r < 4.5", "r >= x + 2", "r < 2 * x + 1"});
    if (real_ && !mixed_) groups.push_back({"r < 4.5", "r >= 7", "r > 2.5"});
    if (mixed_) groups.push_back({"w > 250000 * x", "w - 100000 * x <= 50000", "w < 500000"});
    if (enum_) groups.push_back({"t = p", "t != q", "t = s"});
    return groups;
  }
  std::vector<std::string> env_atoms() {
    std::vector<std::string> atoms;
    for (const auto& g : env_groups()) atoms.insert(atoms.end(), g.begin(), g.end());
    return atoms;
  }

  std::string world() {
    std::vector<std::string> effects = {"A = true", "A = false", "B = !B", "x = x < 3 ? x + 1 : x",
                                        "x = 0",    "A = E"};
    if (integer_) effects.push_back("x = n < 3 ? n : 3");
    if (real_) effects.push_back("B = r < 4.5");
    if (mixed_) effects.push_back("B = w >= 200000 * x + 100000");
    if (forms_ != Forms::engines) return every_world(effects);
    std::string s = "{\"initial\": \"x = 0 & !A\", \"actions\": {";
    for (int i = 0; i < 2; ++i) {
      const int lo = 1 + pick(2), hi = lo + pick(2);
      const std::string results = pick(3) == 0 ? "\"success\""
                                  : pick(2)    ? "\"success\", \"failure\""
                                               : "\"failure\"";
      s += std::string(i ? ", " : "") + "\"Act" + std::to_string(i) + "\": {\"ticks\": [" +
           std::to_string(lo) + ", " + std::to_string(hi) + "], \"results\": [" + results +
           "], \"on_success\": \"" + any(effects) + "\", \"on_failure\": \"" + any(effects) + "\"}";
    }
    return s + "}}";
  }

  // Forms::every's contracts: `initial` given or not (every state of the domain), `ticks` a
  // number or a range, each effect given or not; Act2 has none (any result on any tick).
  std::string every_world(const std::vector<std::string>& effects) {
    std::string s = "{";
    if (pick(4) != 0) s += "\"initial\": \"x = 0 & !A\", ";
    s += "\"actions\": {";
    for (int i = 0; i < 2; ++i) {
      const int lo = 1 + pick(2), hi = lo + pick(2);
      const std::string ticks =
          pick(2) ? std::to_string(lo) : "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
      const std::string results = pick(3) == 0 ? "\"success\""
                                  : pick(2)    ? "\"success\", \"failure\""
                                               : "\"failure\"";
      s += std::string(i ? ", " : "") + "\"Act" + std::to_string(i) + "\": {\"ticks\": " + ticks +
           ", \"results\": [" + results + "]";
      if (pick(3) != 0) s += ", \"on_success\": \"" + any(effects) + "\"";
      if (pick(3) != 0) s += ", \"on_failure\": \"" + any(effects) + "\"";
      s += "}";
    }
    return s + "}}";
  }

  std::string requirements() {
    std::string s;
    // Selection: two disjoint guards and a default per adaptable node, in priority order.
    for (const std::string& id : adaptable_ids_) {
      // Guards on two different variables when there are two: the second guard can hold.
      const auto groups = env_groups();
      const std::size_t v0 = static_cast<std::size_t>(pick(static_cast<int>(groups.size())));
      const std::size_t v1 = groups.size() == 1 ? v0 : (v0 + 1) % groups.size();
      const std::string g0 = any(groups[v0]), g1 = v1 == v0 ? "A" : any(groups[v1]);
      s += id + "0: In " + id + " if " + g0 + " Mission shall satisfy selected_alt = " + id +
           "_alt0\n";
      s += id + "1: In " + id + " if !(" + g0 + ") & " + g1 +
           " Mission shall satisfy selected_alt = " + id + "_alt1\n";
      s += id + "2: In " + id + " Mission shall satisfy selected_alt = " + id + "_alt2\n";
    }
    std::vector<std::string> obs = {"A", "B", "x >= 2", "x = 0"};
    for (const auto& a : env_atoms()) obs.push_back(a);
    // A node of a Sub nothing calls reads as B instead, in its place, so that the draws (and
    // the missions whose guarantees read only nodes of the run) stay as they were.
    for (const auto& a : actions_)
      for (const char* f : {".running", ".success", ".failure"})
        obs.push_back(runs(a) ? a + f : "B");
    for (int i = 0; i < names_; ++i)
      obs.push_back(runs(i) ? "N" + std::to_string(i) + ".running" : "B");
    for (const std::string& id : adaptable_ids_)
      for (int k = 0; k < 3; ++k)
        obs.push_back(id + ".selected = " + id + "_alt" + std::to_string(k));
    if (temporal_) {
      // Over what the tree and the environment do: FRET's past-time functions of them.
      const std::vector<std::string> base = obs;
      const auto some = [&] { return any(base); };
      for (int i = 0; i < 4; ++i) {
        const std::string n = std::to_string(pick(3));
        switch (pick(4)) {
          case 0: obs.push_back("persisted(" + n + ", " + some() + ")"); break;
          case 1: obs.push_back("occurred(" + n + ", " + some() + ")"); break;
          case 2: obs.push_back("prevOcc(" + some() + ", " + some() + ")"); break;
          default: obs.push_back("(FTP | " + some() + ")"); break;
        }
      }
    }
    if (forms_ != Forms::engines) return s + every_guarantees(obs);
    const std::vector<std::string> conditions = {"upon", "if", "whenever"};
    for (int i = 0; i < 4; ++i) {
      std::string id = "P" + std::to_string(i) + ": ";
      if (!adaptable_ids_.empty() && pick(3) == 0) id += "In " + any(adaptable_ids_) + " ";
      const std::string k = std::to_string(1 + pick(2));
      switch (pick(7)) {
        case 0: s += id + "Mission shall always satisfy " + any(obs) + " -> " + any(obs); break;
        case 1: s += id + "Mission shall never satisfy " + any(obs) + " & " + any(obs); break;
        case 2:
          s += id + any(conditions) + " " + any(obs) + " Mission shall within " + k +
               " ticks satisfy " + any(obs);
          break;
        case 3:
          s += id + any(conditions) + " " + any(obs) + " Mission shall for " + k +
               " ticks satisfy " + any(obs);
          break;
        case 4:
          s +=
              id + "upon " + any(obs) + " Mission shall until " + any(obs) + " satisfy " + any(obs);
          break;
        case 5:
          s += id + any(conditions) + " " + any(obs) + " Mission shall immediately satisfy " +
               any(obs);
          break;
        default: s += id + "Mission shall always satisfy !" + any(obs) + " | " + any(obs);
      }
      s += "\n";
    }
    if (pick(3) == 0) s += "Env: Environment shall always satisfy !C | " + any(env_atoms()) + "\n";
    return s;
  }

  // A duration of 1 to 3 ticks: in ticks, or (Forms::time_units) in a unit of time that the
  // tick period rounds up to them.
  std::string duration() {
    const int n = 1 + pick(3);
    if (forms_ != Forms::time_units)
      return std::to_string(n) + (n == 1 && pick(2) ? " tick" : " ticks");
    time_units = true;
    if (period_ == 1) {  // tick 100 ms
      switch (pick(3)) {
        case 0: return std::to_string(100 * n) + " ms";
        case 1: return std::to_string(100 * n - 50) + " milliseconds";  // rounded up
        default: return n == 1 ? "0.1 s" : "0." + std::to_string(n) + " seconds";
      }
    }
    switch (pick(3)) {  // tick 1 s
      case 0: return std::to_string(n) + (n == 1 ? " second" : " seconds");
      case 1: return std::to_string(1000 * n - 500) + " ms";  // rounded up
      default: return std::to_string(n) + " s";
    }
  }

  // Forms::every's guarantees: a scope, conditions and a timing each drawn from every form.
  std::string every_guarantees(const std::vector<std::string>& obs) {
    const std::vector<std::string> conditions = {"upon", "if", "whenever", "when", "unless"};
    // A condition for a scope: in parentheses, so that it is not read as a mode's name.
    const auto cond = [&] { return "(" + any(obs) + ")"; };
    std::string s;
    for (int i = 0; i < 5; ++i) {
      s += "P" + std::to_string(i) + ": ";
      const std::string mode = adaptable_ids_.empty() ? "" : any(adaptable_ids_);
      switch (pick(mode.empty() ? 4 : 12)) {
        case 0: s += "after " + cond() + " "; break;
        case 1: s += "before " + cond() + " "; break;
        case 2: s += "only after " + cond() + " "; break;
        case 3: break;
        case 4: s += "In " + mode + " "; break;
        case 5: s += "when not in " + mode + " "; break;
        case 6: s += "only in " + mode + " "; break;
        case 7: s += "after " + mode + " "; break;
        case 8: s += "before " + mode + " "; break;
        case 9: s += "only before " + cond() + " "; break;
        case 10: s += "while " + cond() + " "; break;
        default: break;
      }
      if (pick(2)) s += any(conditions) + " " + any(obs) + " ";
      s += "Mission shall ";
      switch (pick(11)) {
        case 0: s += "immediately "; break;
        case 1: s += "at the next timepoint "; break;
        case 2: s += "within " + duration() + " "; break;
        case 3: s += "for " + duration() + " "; break;
        case 4: s += "after " + duration() + " "; break;
        case 5: s += "until " + any(obs) + " "; break;
        case 6: s += "before " + any(obs) + " "; break;
        case 7: s += "eventually "; break;
        case 8: s += "never "; break;
        case 9: break;  // FRET's default timing: eventually
        default: s += "always "; break;
      }
      s += "satisfy " + any(obs) + (pick(2) ? "" : " & " + any(obs)) + "\n";
    }
    if (pick(3) == 0) s += "Env: Environment shall always satisfy !C | " + any(env_atoms()) + "\n";
    return s;
  }

  std::set<std::string> actions_;
  std::set<std::string> run_actions_;  // the actions outside Sub
  bool in_sub_ = false, sub_called_ = false;
  int sub_first_ = 0, sub_end_ = 0;  // the names N<i> of Sub's nodes

  bool runs(const std::string& action) const {
    return sub_called_ || run_actions_.count(action) != 0;
  }
  bool runs(int name) const { return sub_called_ || name < sub_first_ || name >= sub_end_; }
  std::vector<std::string> adaptable_ids_;
  int names_ = 0, adaptables_ = 1;
  bool temporal_ = false, mixed_ = false;
  Forms forms_ = Forms::engines;
  int period_ = 0;  // the domain's tick period: none, 100 ms, 1 s
  bool repeated_ = false, wide_ = false, integer_ = false, real_ = false, enum_ = false;
};

}  // namespace uabt::testing
