#include "prove/prove.hpp"

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "monitor/monitor.hpp"
#include "prove/explore.hpp"
#include "prove/symbolic.hpp"
#include "prove/symbolic_value.hpp"
#include "runtime/runner.hpp"
#include "runtime/scenario_check.hpp"
#include "runtime/trace.hpp"

namespace uabt::prove {

using runtime::NodeStatus;
using runtime::ScriptValue;
using Json = nlohmann::ordered_json;

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::proved: return "proved";
    case Verdict::violated: return "violated";
    case Verdict::bounded: return "bounded";
    case Verdict::vacuous: return "vacuous";
    case Verdict::unsupported: return "unsupported";
  }
  return "?";
}

bool Result::passed() const {
  for (const Answer& a : answers)
    if (a.verdict != Verdict::proved) return false;
  return true;
}

namespace {

// Collects what the actions did along a path, as scenario "runs".
class RunRecorder : public ActionRecorder {
 public:
  explicit RunRecorder(Model& m) : m_(m), current_(m.choice->leaves().size()) {
    // Every action is listed, run or not, so that the simulated world takes it for one.
    for (std::uint32_t leaf = 0; leaf < m.choice->leaves().size(); ++leaf)
      if (!m.choice->leaves()[leaf].condition) runs_[label(leaf)];
  }
  void ticked(std::uint32_t leaf, bool first) override {
    if (first) {
      auto& list = runs_[label(leaf)];
      list.push_back(Json::object());
      current_[leaf] = list.size() - 1;
      ticks_[leaf] = 0;
    }
    ++ticks_[leaf];
  }
  void ended(std::uint32_t leaf, NodeStatus result) override {
    Json& run = runs_[label(leaf)][current_[leaf]];
    run["ticks"] = ticks_[leaf];
    run["result"] = result == NodeStatus::success ? "success" : "failure";
    const auto& writes = m_.choice->leaves()[leaf].writes;
    if (!writes.empty()) {
      Json effects = Json::object();
      for (const std::string& name : writes)
        if (const ScriptValue* v = m_.engine->blackboard().get(name))
          effects[name] = runtime::value_json(*v);
      run["effects"] = effects;
    }
    const auto& outputs = m_.choice->leaves()[leaf].outputs;
    if (!outputs.empty()) {
      Json written = Json::object();
      for (const auto& out : outputs)
        written[out.port] = runtime::value_json(m_.engine->blackboard().value(out.slot));
      run["outputs"] = written;
    }
  }
  // A halted start must not end before its halt: one tick more than it has run.
  void halted(std::uint32_t leaf) override {
    runs_[label(leaf)][current_[leaf]]["ticks"] = ticks_[leaf] + 1;
  }
  // Actions still running when the path ends: they would end after it.
  Json actions() {
    const auto& elapsed = m_.choice->elapsed();
    for (std::size_t leaf = 0; leaf < elapsed.size(); ++leaf) {
      if (m_.choice->leaves()[leaf].condition) continue;
      auto& list = runs_[label(static_cast<std::uint32_t>(leaf))];
      if (elapsed[leaf] > 0 && !list.empty() && !list[current_[leaf]].contains("ticks"))
        list[current_[leaf]]["ticks"] = ticks_[leaf] + 1;
    }
    Json out = Json::object();
    for (auto& [name, list] : runs_) {
      Json spec = Json::object();
      if (!list.empty()) spec["runs"] = list;
      out[name] = spec;
    }
    return out;
  }

 private:
  const std::string& label(std::uint32_t leaf) const { return m_.choice->leaves()[leaf].label; }
  Model& m_;
  std::vector<std::size_t> current_;
  std::vector<std::uint64_t> ticks_ = std::vector<std::uint64_t>(current_.size(), 0);
  std::map<std::string, std::vector<Json>> runs_;
};

std::string scenario_of(Model& m, const Property& p, const Finding& f) {
  RunRecorder recorder(m);
  m.choice->recorder = &recorder;
  Json initial = Json::object(), events = Json::array();
  // What the simulated world holds for each variable (it keeps a value until an event sets it).
  std::vector<ScriptValue> held(m.vars.size());
  Json set = Json::object();
  auto give = [&](std::uint64_t tick, std::size_t i, const ScriptValue& v) {
    if (v.empty()) return;  // a variable nothing reads, with no value to give
    if (tick == 1)
      initial[m.vars[i].name] = runtime::value_json(v);
    else if (!(v == held[i]))
      set[m.vars[i].name] = runtime::value_json(v);
    held[i] = v;
  };
  const runtime::Blackboard& bb = m.engine->blackboard();
  replay_path(
      m, f.path,
      [&](std::uint64_t tick) {
        set = Json::object();
        // What is on the blackboard before the tick: the initial state, or a symbolic path's
        // environment; values still pending are given once the tick has chosen them.
        for (std::size_t i = 0; i < m.vars.size(); ++i)
          if (!bb.pending(m.vars[i].slot) && (tick == 1 || m.vars[i].env))
            give(tick, i, bb.value(m.vars[i].slot));
      },
      [&](std::uint64_t tick, NodeStatus, const std::vector<std::size_t>& chosen) {
        for (std::size_t i : chosen) give(tick, i, bb.value(m.vars[i].slot));
        if (!set.empty()) events.push_back(Json{{"at", tick}, {"set", set}});
        // The mission's own variables as the tick's effects left them.
        for (std::size_t i = 0; i < m.vars.size(); ++i)
          if (!m.vars[i].env) held[i] = bb.value(m.vars[i].slot);
      });
  m.choice->recorder = nullptr;
  Json s = Json::object();
  s["description"] = "Counterexample of " + p.requirement->id +
                     " found by uabt prove: violated at tick " + std::to_string(f.tick);
  // `uabt run` replays it even where the mission's checks fail, as prove proved it there.
  s["counterexample_of"] = p.requirement->id;
  s["max_ticks"] = f.tick;
  s["initial"] = initial;
  s["actions"] = recorder.actions();
  if (!events.empty()) s["events"] = events;
  return s.dump(2) + "\n";
}

// Runs the counterexample on the runtime's simulated world (what `uabt run` does) with the
// monitoring stage's own monitor; it must violate the property first at the same tick.
Counterexample replay(Model& m, const Property& p, const Finding& f, std::string scenario) {
  Counterexample cex;
  cex.tick = f.tick;
  cex.scenario = std::move(scenario);
  runtime::Scenario parsed = runtime::parse_scenario(cex.scenario, "counterexample.json");
  // Its numbers typed as `uabt run` types them, by the mission's declarations.
  runtime::ScenarioVocabulary vocabulary;
  vocabulary.add(m.mission);
  runtime::type_numbers(parsed, vocabulary);
  if (m.replay_runner) {
    m.replay_runner->restart(std::move(parsed));
  } else {
    std::vector<bt::NodeModel> models;
    if (m.mission.nodes) models = *m.mission.nodes;
    m.replay_runner =
        std::make_unique<runtime::Runner>(m.doc, std::move(parsed), runtime::RunOptions{}, models);
  }
  runtime::Runner& runner = *m.replay_runner;
  monitor::Variables variables;
  monitor::Symbols symbols;
  runtime::TickObservation obs(runner.engine(), m.mission, m.state_names, variables, symbols);
  const runtime::Observing observing(runner.engine(), obs);
  std::string reason;
  auto monitor = monitor::RequirementMonitor::compile(
      *p.requirement, [&](const std::string& n) { return obs.resolve(n); }, reason);
  if (!monitor) throw ProveError("internal error: replaying " + p.requirement->id + ": " + reason);
  std::vector<monitor::Val> frame;
  std::uint64_t first = 0;
  // The actions started and not ended yet, by node: each is shown running at every tick it
  // runs without starting or ending.
  std::map<runtime::NodeId, std::string> running;
  std::set<std::string, std::less<>> shown;  // every action the table names
  for (std::uint64_t t = 1; t <= f.tick && first == 0; ++t) {
    obs.begin_tick();
    const std::size_t log_before = runner.world().log().size();
    const auto running_before = running;
    const NodeStatus root = runner.step();
    if (runner.error())
      throw ProveError("internal error: the counterexample of " + p.requirement->id +
                       " stops at tick " + std::to_string(t) + " on " + runner.error()->message);
    obs.fill(frame);
    const bool holds = monitor->step(frame);
    if (monitor->failed())
      throw ProveError("internal error: replaying " + p.requirement->id + ": " + monitor->error());
    TickRow row;
    row.tick = t;
    row.root = runtime::status_name(root);
    for (int slot : monitor->variables())
      row.values.emplace_back(variables.name(slot), monitor::value_of(frame[slot], symbols));
    const auto& log = runner.world().log();
    std::set<runtime::NodeId> logged;
    for (std::size_t i = log_before; i < log.size(); ++i)
      if (log[i].event != runtime::LeafEvent::condition) logged.insert(log[i].node);
    for (const auto& [node, leaf] : running_before)
      if (!logged.contains(node)) row.actions.push_back(leaf + " running");
    for (std::size_t i = log_before; i < log.size(); ++i) {
      if (log[i].event == runtime::LeafEvent::condition) continue;
      std::string what = log[i].event == runtime::LeafEvent::action_finished
                             ? (log[i].status == NodeStatus::success ? "success" : "failure")
                             : runtime::leaf_event_name(log[i].event);
      row.actions.push_back(log[i].leaf + " " + what);
      if (log[i].event == runtime::LeafEvent::action_started)
        running[log[i].node] = log[i].leaf;
      else
        running.erase(log[i].node);
      shown.insert(log[i].leaf);
    }
    cex.rows.push_back(std::move(row));
    if (!holds && (monitor->final_violation() || runner.done())) first = t;
    if (runner.done() && first == 0) break;
  }
  // An action world.json says nothing of runs as long as the counterexample needs.
  for (const ChoiceWorld::Leaf& leaf : m.choice->leaves())
    if (!leaf.condition && leaf.contract == nullptr && shown.contains(leaf.label)) {
      cex.notes.push_back("action '" + leaf.label +
                          "' has no world.json entry, so it may run any number of ticks");
      shown.erase(leaf.label);  // once, however many leaves it names
    }
  if (first != f.tick)
    throw ProveError("internal error: the counterexample of " + p.requirement->id +
                     " violates it at tick " + std::to_string(f.tick) +
                     " in the model but its replay " +
                     (first == 0 ? std::string("does not violate it")
                                 : "violates it at tick " + std::to_string(first)));
  return cex;
}

}  // namespace

namespace {

// The note both engines give the first tick that stops with an error (tick_error_text).
const std::string kTickErrorNote = "a reachable tick stops with an error: ";

Answer answer_of(const Property& p) {
  Answer a;
  a.requirement = p.requirement->id;
  a.text = p.requirement->text;
  a.location = p.requirement->location;
  if (!p.layout) {
    a.verdict = Verdict::unsupported;
    a.reason = p.unsupported;
  }
  return a;
}

// One answer per guarantee: not checked, violated (with its replayed counterexample), or
// what `decide` says of the others.
void add_answers(Model& model, const std::vector<std::optional<Finding>>& violations, Result& r,
                 const std::function<void(std::size_t, Answer&)>& decide) {
  for (std::size_t i = 0; i < model.properties.size(); ++i) {
    const Property& p = model.properties[i];
    if (p.assumption) continue;
    Answer a = answer_of(p);
    if (p.layout && violations[i]) {
      const Finding& f = *violations[i];
      a.verdict = Verdict::violated;
      a.depth = f.tick;
      try {
        a.counterexample = replay(model, p, f, scenario_of(model, p, f));
      } catch (const runtime::TickException& e) {
        throw ProveError("internal error: the counterexample of " + p.requirement->id +
                         " stops the model's engine: " + e.error.message);
      }
    } else if (p.layout) {
      decide(i, a);
    }
    r.answers.push_back(std::move(a));
  }
}

Result prove_explicit(Model& model, const Options& options) {
  const SearchResult search = explore(model, options);
  Result r;
  r.engine = "explicit";
  r.states = search.states;
  r.transitions = search.transitions;
  r.depth = search.depth;
  r.complete = search.complete;
  if (search.tick_error) r.notes.push_back(kTickErrorNote + *search.tick_error);
  if (!search.budget_spent.empty())
    r.notes.push_back("the explicit-state engine spent its budget (" + search.budget_spent +
                      ") at tick " + std::to_string(search.depth) +
                      "; give the actions `ticks` in world.json, or try --engine symbolic");
  if (search.vacuous) r.vacuity = Vacuity{search.vacuous->message, search.vacuous->location};
  add_answers(model, search.violations, r, [&](std::size_t i, Answer& a) {
    a.verdict = search.vacuous    ? Verdict::vacuous
                : search.complete ? Verdict::proved
                                  : Verdict::bounded;
    a.depth = search.depth;
    a.first_trigger = search.first_trigger[i];
    a.has_trigger = model.properties[i].has_trigger();
  });
  return r;
}

Result prove_symbolic(Model& model, const Options& options) {
  const SymbolicSearch search = symbolic_search(model, options);
  Result r;
  r.engine = "symbolic";
  r.depth = search.depth;
  r.induction_k = search.induction_k;
  r.complete = true;
  if (search.no_first_tick)
    r.vacuity = vacuity_of(model, model.world.initial ? Stuck::initial : Stuck::assumptions);
  else if (search.deadlock_after != 0)
    r.vacuity = vacuity_of(model, Stuck::deadlock, search.deadlock_after);
  // The runtime's own error at the tick BMC found (the explicit engine's note).
  if (search.error)
    r.notes.push_back(kTickErrorNote + replay_tick_error(model, search.error->path));
  if (!search.stopped_early.empty()) r.notes.push_back(search.stopped_early);
  if (!search.error_decided && !r.vacuity)
    r.notes.push_back("no tick up to tick " + std::to_string(search.depth) +
                      " stops with an error; whether a later one does is not decided");
  add_answers(model, search.violations, r, [&](std::size_t i, Answer& a) {
    if (r.vacuity) {
      a.verdict = Verdict::vacuous;
      r.complete = false;
      return;
    }
    a.has_trigger = model.properties[i].has_trigger();
    a.first_trigger = search.first_trigger[i];
    a.trigger_decided = search.trigger_decided[i];
    if (search.proved[i]) {
      a.verdict = Verdict::proved;
      a.depth = search.proved_k[i];
      a.by_pdr = search.by_pdr[i];
      if (search.by_pdr[i])
        r.notes.push_back(a.requirement + " is proved by IC3/PDR (Z3's Spacer)");
      if (a.has_trigger && !a.trigger_decided)
        r.notes.push_back(a.requirement +
                          " is proved, but whether its trigger holds on any run is not decided");
    } else {
      a.verdict = Verdict::bounded;
      a.depth = search.depth;
      r.complete = false;
    }
  });
  return r;
}

}  // namespace

Result prove(const load::Mission& mission, const bt::Document& compiled, const WorldModel& world,
             const Options& options) {
  if (options.engine != "auto" && options.engine != "explicit" && options.engine != "symbolic")
    throw ProveError("unknown engine '" + options.engine + "' (auto, explicit or symbolic)");
  Model model(mission, compiled, world);
  std::string engine = options.engine;
  if (engine == "auto") engine = model.explicit_refusal.empty() ? "explicit" : "symbolic";
  if (engine == "explicit") return prove_explicit(model, options);
  try {
    Result r = prove_symbolic(model, options);
    if (options.engine == "auto") r.engine_reason = model.explicit_refusal;
    return r;
  } catch (const z3::exception& e) {
    throw ProveError(std::string("internal error: the symbolic engine: Z3: ") + e.msg());
  } catch (const SymbolicUnsupported& e) {
    if (options.engine == "symbolic")
      throw ProveError(std::string("the symbolic engine cannot model this mission: ") + e.what());
    // auto: the explicit engine's answer, or its reason for refusing.
    if (!model.explicit_refusal.empty())
      throw ProveError(model.explicit_refusal + "; nor can the symbolic engine: " + e.what());
    return prove_explicit(model, options);
  }
}

}  // namespace uabt::prove
