#include "manager/manager.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "base/diagnostics.hpp"
#include "base/text.hpp"
#include "gate/uplink.hpp"
#include "runtime/condition_count.hpp"
#include "runtime/property_monitor.hpp"
#include "runtime/runner.hpp"
#include "runtime/scenario_check.hpp"
#include "runtime/selection.hpp"
#include "runtime/source_map.hpp"

namespace uabt::manager {

using namespace runtime;

namespace fs = std::filesystem;

namespace {

fs::path package_path(const fs::path& dir, const std::string& uplink) {
  return dir / uplink;
}

load::Mission load_version(const fs::path& dir, const std::vector<std::string>& uplinks) {
  load::LoadOptions load_options;
  for (const auto& u : uplinks) load_options.uplinks.push_back(package_path(dir, u));
  std::string error;
  auto mission = load::load_mission(dir, load_options, error);
  if (!mission) throw std::runtime_error(dir.generic_string() + ": " + error);
  return std::move(*mission);
}

// A gated version: the gate read its compiled tree back from the bytes it passed (with
// `unverified`, from the bytes it compiled although its checks failed).
gate::Outcome admitted(gate::Outcome outcome, bool unverified = false) {
  if ((outcome.passed() || (unverified && !outcome.compiled_xml.empty())) && !outcome.compiled_tree)
    throw std::runtime_error("compiled tree does not read back: " +
                             format_text(outcome.report.findings));
  return outcome;
}

std::string alternative_name(const load::Mission& m, const std::string& adaptable,
                             const std::string& tree_id) {
  for (const auto& alt : m.alternatives)
    if (alt.adaptable == adaptable && alt.tree_id == tree_id) return alt.name;
  return tree_id;
}

// A counterexample must name a guarantee of the mission it replays on.
void check_counterexample_of(const Scenario& scenario, const load::Mission& mission) {
  std::string guarantees;
  for (const fretish::Requirement& r : mission.properties) {
    if (fretish::is_assumption(r)) continue;
    if (r.id == scenario.counterexample_of) return;
    guarantees += (guarantees.empty() ? "" : ", ") + r.id;
  }
  throw ScenarioError(
      scenario.where("/counterexample_of", true) + ": error: /counterexample_of: '" +
      scenario.counterexample_of + "' is not a guarantee of the mission (" +
      (guarantees.empty() ? "it states none" : "its guarantees: " + guarantees) + ")");
}

// One "file:line:col: error: …" line per misfit: a name the scenario wrote with "\n" (or
// another control character) in it is shown escaped, a newline as backslash-n.
std::string one_line(const std::string& message) {
  std::string out;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (u < 0x20 || u == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", u);
      out += escaped;
    } else {
      out += c;
    }
  }
  return out;
}

TraceEvent violation_event(const PropertyViolation& v) {
  TraceEvent e;
  e.tick = v.tick;
  e.event = "violation";
  e.requirement = v.result.id;
  e.role = v.result.assumption ? "assumption" : "guarantee";
  e.values = v.result.values;
  return e;
}

}  // namespace

BehaviorTreeManager::BehaviorTreeManager(fs::path mission_dir, Scenario scenario,
                                         ManagerOptions options)
    : dir_(std::move(mission_dir)), scenario_(std::move(scenario)), options_(std::move(options)) {}

// The scenario's names and values against the mission and every uplink it may receive.
void BehaviorTreeManager::fit_to_mission(const load::Mission& mission) {
  ScenarioVocabulary vocabulary;
  vocabulary.add(mission);
  std::vector<std::string> errors;
  for (const ScenarioEvent& event : scenario_.events) {
    if (event.uplink.empty()) continue;
    // A typo must not let a run go on without the uplink it was meant to test.
    std::error_code ec;
    if (!fs::is_directory(package_path(dir_, event.uplink), ec)) {
      errors.push_back(scenario_.where("/events/" + std::to_string(event.index) + "/uplink", true) +
                       ": error: uplink package '" + event.uplink +
                       "' is not a directory (a path from the mission directory " +
                       dir_.generic_string() + ")");
      continue;
    }
    load::LoadOptions with_uplink;
    with_uplink.uplinks.push_back(dir_ / event.uplink);
    std::string error;  // a package that does not load is the gate's to reject, at its tick
    if (auto merged = load::load_mission(dir_, with_uplink, error)) vocabulary.add(*merged);
  }
  type_numbers(scenario_, vocabulary);
  const std::vector<std::string> names = check_scenario(scenario_, vocabulary);
  errors.insert(errors.end(), names.begin(), names.end());
  if (errors.empty()) return;
  std::string text;
  for (const std::string& e : errors) text += (text.empty() ? "" : "\n") + one_line(e);
  throw ScenarioError(text);
}

void BehaviorTreeManager::add_uplink(std::int64_t tick, const std::string& package) {
  ScenarioEvent event;
  event.at = tick;
  event.uplink = package;
  event.index = static_cast<int>(scenario_.events.size());
  scenario_.events.push_back(std::move(event));
  std::stable_sort(scenario_.events.begin(), scenario_.events.end(),
                   [](const ScenarioEvent& a, const ScenarioEvent& b) { return a.at < b.at; });
}

ManagerRun BehaviorTreeManager::run() {
  ManagerRun result;
  std::vector<std::string> accepted;
  // The mission a run starts from must be executable: the gate's checks. Its guarantees are
  // monitored by the run rather than required proved, because a run is also how a
  // counterexample of `uabt prove` is replayed. What changes a running mission, an uplink,
  // goes through the whole gate below, proofs included.
  gate::Outcome checked =
      gate::check_mission(load_version(dir_, accepted), options_.gate, "runtime");
  if (!scenario_.counterexample_of.empty() && checked.mission)
    check_counterexample_of(scenario_, *checked.mission);
  // `uabt prove` proves whatever compiles, checks failed or not: its counterexample replays on
  // the same compiled tree, unverified, and says so (ManagerRun::unverified).
  const bool replay =
      !checked.passed() && !scenario_.counterexample_of.empty() && !checked.compiled_xml.empty();
  if (!checked.passed() && !replay) throw NotAdmitted(checked.report.findings);
  if (replay)
    for (const Finding& f : checked.report.findings)
      if (f.severity == Severity::error) result.unverified.push_back(f);
  gate::Outcome running = admitted(std::move(checked), replay);

  fit_to_mission(*running.mission);

  RunOptions run_options;
  run_options.max_ticks = options_.max_ticks;
  run_options.log_conditions = false;  // the leaf log is not kept (see the loop below)
  run_options.engine.smart_selection = options_.smart_selection;
  std::vector<bt::NodeModel> robot_nodes;
  if (running.mission->nodes) robot_nodes = *running.mission->nodes;
  Runner runner(*running.compiled_tree, scenario_, run_options, robot_nodes);
  PropertyMonitor properties(*running.mission, runner.engine());

  SelectionObserver selections(runner.engine(), [&](const Selection& s) {
    TraceEvent e;
    e.tick = s.tick;
    e.event = "select";
    e.adaptable = s.adaptable;
    e.requirement = s.requirement;
    e.alternative = alternative_name(*running.mission, s.adaptable, s.alternative);
    properties.select(e.adaptable, e.alternative, e.requirement);
    result.trace.push_back(std::move(e));
  });
  runner.engine().add_observer(&selections);
  runner.engine().add_observer(&properties);

  runner.on_uplink = [&](const ScenarioEvent& event, Runner& r) {
    const auto started = std::chrono::steady_clock::now();
    TraceEvent e;
    e.tick = r.ticks() + 1;  // it takes effect before this tick
    e.event = "uplink";
    e.uplink = event.uplink;
    std::vector<std::string> candidate = accepted;
    candidate.push_back(event.uplink);
    // As `uabt gate MISSION --uplink DIR` decides it, against the version running now.
    gate::Outcome next = admitted(gate::run_uplink_gate(
        *running.mission, load_version(dir_, candidate), options_.gate, "runtime"));
    if (!next.passed()) {
      e.verdict = "rejected";
      for (const auto& f : next.report.findings)
        if (f.severity == Severity::error) e.findings.push_back(f);
    } else {
      e.verdict = "accepted";
      // New trees (alternatives) first, so that a changed selection tree can call them.
      for (const auto& def : next.compiled_tree->trees) {
        if (!r.engine().has_tree(def.id)) {
          r.engine().define_tree(def);
          e.swapped.push_back(def.id);
        }
      }
      for (const auto& def : next.compiled_tree->trees) {
        const bt::TreeDef* old = running.compiled_tree->find_tree(def.id);
        if (old == nullptr || old->root == def.root) continue;
        SwapResult swap = r.engine().replace_tree(def.id, def, SwapPolicy::halt_then_swap);
        e.halted += swap.halted;
        e.swapped.push_back(def.id);
      }
      accepted = std::move(candidate);
      running = std::move(next);
      // The new version's properties from the next tick on; the swapped-in trees' nodes are
      // observed too.
      for (const PropertyViolation& v : properties.adopt(*running.mission, r.ticks()))
        result.trace.push_back(violation_event(v));
    }
    e.latency_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    result.trace.push_back(std::move(e));
  };

  ConditionCounter conditions(runner.engine());
  runner.engine().add_observer(&conditions);

  NodeTracer tracer(runner.engine(), result.trace);
  if (options_.trace_nodes) runner.engine().add_observer(&tracer);

  NodeStatus last = NodeStatus::idle;
  while (!runner.done() && static_cast<std::int64_t>(runner.ticks()) < runner.max_ticks()) {
    const NodeStatus now = runner.step();
    runner.world().clear_log();  // memory stays bounded however long the run
    if (runner.error()) continue;
    if (now != last) {
      TraceEvent e;
      e.tick = runner.ticks();
      e.event = "status";
      e.status = lower_case(status_name(now));
      result.trace.push_back(std::move(e));
      last = now;
    }
    for (const PropertyViolation& v : properties.after_tick(runner.ticks()))
      result.trace.push_back(violation_event(v));
    if (options_.monitor_trace)
      result.monitor_trace += properties.monitor_trace_line(runner.ticks());
  }
  runner.engine().remove_observer(&tracer);
  for (const PropertyViolation& v : properties.at_end(runner.ticks()))
    result.trace.push_back(violation_event(v));
  result.properties = properties.results();
  // Held only because the run ended before a deadline (FRET's finite-trace meaning): said.
  for (const monitor::PropertyResult& p : result.properties) {
    if (!p.pending_since) continue;
    TraceEvent e;
    e.tick = runner.ticks();
    e.event = "pending";
    e.requirement = p.id;
    e.role = p.assumption ? "assumption" : "guarantee";
    e.message = p.pending;
    e.since = p.pending_since;
    result.trace.push_back(std::move(e));
  }
  result.guarantees_failed = properties.guarantees_failed();
  runner.engine().remove_observer(&properties);
  runner.engine().remove_observer(&selections);
  runner.engine().remove_observer(&conditions);
  result.condition_ticks = conditions.count();

  result.ticks = runner.ticks();
  result.status = runner.engine().last_result();
  result.verdict = runner.verdict();
  result.finished = result.verdict != "timeout" && result.verdict != "error";
  result.error = runner.error();
  if (result.error)  // at the line the user wrote, not at the compiled tree held in memory
    result.error->message = with_source_places(result.error->message, *running.compiled_tree,
                                               *running.mission, running.compiled.trace);
  result.accepted_uplinks = accepted;
  if (result.error) {
    TraceEvent e;
    e.tick = result.error->tick;
    e.event = "error";
    e.node = result.error->path;
    e.message = result.error->message;
    e.script = result.error->script;
    result.trace.push_back(std::move(e));
  }
  TraceEvent done;
  done.tick = result.ticks;
  done.event = "done";
  done.verdict = result.verdict;
  result.trace.push_back(std::move(done));
  return result;
}

std::string trace_summary(const ManagerRun& run, const std::string& path_prefix) {
  return trace_summary(run.trace, path_prefix);
}

std::string property_summary(const ManagerRun& run) {
  std::string out;
  for (const monitor::PropertyResult& p : run.properties) {
    out += std::string(p.assumption  ? "assumption "
                       : p.selection ? "selection "
                                     : "property ") +
           p.id + ": " +
           (p.verdict == monitor::Verdict::held ? monitor::held_text(p)
                                                : monitor::verdict_name(p.verdict));
    if (p.first_violation) out += " from tick " + std::to_string(*p.first_violation);
    if (p.monitored_from)
      out += " (added by an uplink: monitored from tick " + std::to_string(*p.monitored_from);
    if (p.monitored_until)
      out += std::string(p.monitored_from ? ", " : " (") + "monitored until tick " +
             std::to_string(*p.monitored_until) + ", when an uplink replaced or removed it";
    if (p.monitored_from || p.monitored_until) out += ")";
    if (!p.reason.empty()) out += ": " + p.reason;
    out += "\n";
  }
  return out;
}

}  // namespace uabt::manager
