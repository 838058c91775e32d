// Guarantee targets: for every guarantee with a trigger (a mode, an `upon`/`if`/`when`
// condition), the trigger firing, and each atom of the condition and of the response deciding
// it, either way (FRET's FLIP obligations). Each is a trap the prove engines try over
// world.json; a reached trap's counterexample is the scenario, replayed here with the runtime's
// own property monitor.
#include <algorithm>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "base/diagnostics.hpp"
#include "campaign/guarantee.hpp"
#include "campaign/node.hpp"
#include "campaign/world_reach.hpp"
#include "monitor/check_trace.hpp"
#include "monitor/monitor.hpp"
#include "monitor/property_set.hpp"
#include "monitor/trace.hpp"
#include "prove/reach.hpp"
#include "prove/world_model.hpp"
#include "runtime/property_monitor.hpp"
#include "runtime/runner.hpp"
#include "runtime/selection.hpp"

namespace uabt::campaign {

namespace {

using Json = nlohmann::ordered_json;
using fretish::ExprKind;
using fretish::ExprPtr;

struct Planned {
  prove::Goal goal;
  Target target;
};

// The atomic propositions of a condition, once each by their text, in order.
void atoms_of(const ExprPtr& e, std::vector<ExprPtr>& out, std::set<std::string>& seen) {
  if (!e || e->kind == ExprKind::bool_literal) return;
  if (fretish::is_boolean_connective(e->kind)) {
    for (const auto& a : e->args) atoms_of(a, out, seen);
    return;
  }
  if (seen.insert(fretish::to_fretish(*e)).second) out.push_back(e);
}

// `e` with every occurrence of the atom `text` replaced by `value`.
ExprPtr substitute(const ExprPtr& e, const std::string& text, bool value) {
  if (fretish::to_fretish(*e) == text) return fretish::make_bool(value);
  if (!fretish::is_boolean_connective(e->kind)) return e;
  std::vector<ExprPtr> args;
  for (const auto& a : e->args) args.push_back(substitute(a, text, value));
  return fretish::make_expr(e->kind, std::move(args));
}

// The atom decides `e` and has `value`: changing it alone changes e's value.
ExprPtr deciding(const ExprPtr& e, const ExprPtr& atom, bool value) {
  const std::string text = fretish::to_fretish(*atom);
  const ExprPtr differs = fretish::make_expr(
      ExprKind::logical_xor, {substitute(e, text, true), substitute(e, text, false)});
  return fretish::make_expr(
      ExprKind::logical_and,
      {differs, value ? atom : fretish::make_expr(ExprKind::logical_not, {atom})});
}

std::string scope_text(const fretish::Requirement& r) {
  if (!r.scope) return "";
  return r.scope->keyword + " " +
         (r.scope->condition ? fretish::to_fretish(*r.scope->condition) : r.scope->mode);
}

// The ticks at which the timing of `r` judges its response, in words, for a timing that judges
// it after the trigger (monitor::judges_later); "" for the others, judged at the trigger.
std::string judged_ticks(const fretish::Requirement& r, const monitor::Shape& shape) {
  const std::string ticks =
      std::to_string(shape.duration) + (shape.duration == 1 ? " tick" : " ticks");
  const std::string stop =
      r.timing.stop_condition ? fretish::to_fretish(*r.timing.stop_condition) : std::string();
  switch (shape.timing) {
    case monitor::TimingKind::next: return "at the tick after its trigger";
    case monitor::TimingKind::eventually: return "at the first tick it holds after its trigger";
    case monitor::TimingKind::within:
      return "at the first tick it holds within " + ticks +
             " of its trigger, else at the last tick of that window";
    case monitor::TimingKind::for_ticks:
      return "at the first tick it fails within " + ticks +
             " of its trigger, else at the last tick of that window";
    case monitor::TimingKind::after:
      return "at the first tick it holds within " + ticks + " of its trigger, too early, else " +
             std::to_string(shape.duration + 1) + " ticks after the trigger";
    case monitor::TimingKind::until:
      return "at a tick from its trigger until " + stop + ", while it held before";
    case monitor::TimingKind::before:
      return "at the first tick it holds after its trigger and before " + stop + ", else at " +
             stop;
    default: return "";
  }
}

std::vector<Planned> plan(const load::Mission& mission) {
  std::vector<Planned> out;
  for (const fretish::Requirement& r : mission.properties) {
    if (fretish::is_assumption(r) || r.freeform || !r.response) continue;
    const ExprPtr condition = r.folded_condition();
    if (!r.scope && !condition) continue;
    // A timing that judges the response after the trigger has its response atoms decide there
    // (FRET's "only" scopes, which turn the timing round, keep the trigger's tick).
    const monitor::Classified shape = monitor::classify(r);
    const bool only = r.scope && r.scope->keyword.rfind("only", 0) == 0;
    const std::string later = shape.shape && !only && monitor::judges_later(shape.shape->timing)
                                  ? judged_ticks(r, *shape.shape)
                                  : std::string();
    auto add = [&](const std::string& id, const std::string& text, ExprPtr goal,
                   bool judged = false) {
      Planned p;
      p.goal.id = "guarantee/" + r.id + "/" + id;
      p.goal.scope_of = &r;
      p.goal.condition = std::move(goal);
      p.goal.at_judged_tick = judged;
      p.target.id = p.goal.id;
      p.target.criterion = Criterion::guarantee;
      p.target.text = text;
      out.push_back(std::move(p));
    };
    const std::string trigger =
        scope_text(r) + (r.scope && condition ? ", " : "") +
        (condition ? "upon " + fretish::to_fretish(*condition) : std::string());
    add("trigger", "the trigger of " + r.id + " fires (" + trigger + ")",
        condition ? condition : fretish::make_bool(true));
    std::vector<ExprPtr> atoms;
    std::set<std::string> seen;
    atoms_of(condition, atoms, seen);
    for (const auto& atom : atoms)
      for (bool value : {true, false}) {
        const std::string text = fretish::to_fretish(*atom);
        add("condition/" + text + "/" + (value ? "true" : "false"),
            text + " is " + (value ? "true" : "false") + " and decides the condition of " + r.id,
            deciding(condition, atom, value));
      }
    atoms.clear();
    seen.clear();
    atoms_of(r.response, atoms, seen);
    for (const auto& atom : atoms)
      for (bool value : {true, false}) {
        const std::string text = fretish::to_fretish(*atom);
        ExprPtr goal = deciding(r.response, atom, value);
        if (condition && later.empty())
          goal = fretish::make_expr(ExprKind::logical_and, {condition, goal});
        add("response/" + text + "/" + (value ? "true" : "false"),
            text + " is " + (value ? "true" : "false") + " and decides the response of " + r.id +
                " (" + (later.empty() ? "at a tick its trigger holds" : later) + ")",
            std::move(goal), !later.empty());
      }
  }
  return out;
}

// A scenario run with the runtime's monitor watching every trap: the first tick each is
// violated at, i.e. its goal reached.
struct Play {
  RunRecord run;
  std::map<std::string, std::uint64_t> reached;  // trap id: tick
  std::string error;                             // the scenario does not run
};

Play play(const load::Mission& traps, const Replayer& replayer, const std::string& json,
          const std::string& file) {
  Play out;
  out.run.source = file;
  try {
    runtime::Runner& runner = replayer.start(replayer.scenario(json, file));
    runtime::PropertyMonitor monitor(traps, runner.engine());
    runtime::SelectionObserver selections(runner.engine(), [&](const runtime::Selection& s) {
      std::string name = s.alternative;
      for (const auto& alt : traps.alternatives)
        if (alt.adaptable == s.adaptable && alt.tree_id == s.alternative) name = alt.name;
      monitor.select(s.adaptable, name, s.requirement);
    });
    const runtime::Observing observing_selections(runner.engine(), selections);
    const runtime::Observing observing_monitor(runner.engine(), monitor);
    while (!runner.done() && static_cast<std::int64_t>(runner.ticks()) < runner.max_ticks()) {
      runner.step();
      runner.world().clear_log();
      if (runner.error()) break;
      for (const auto& v : monitor.after_tick(runner.ticks()))
        out.reached.emplace(v.result.id, v.tick);
    }
    out.run.ticks = runner.ticks();
    out.run.verdict = runner.verdict();
    if (runner.error()) out.run.error = runner.error()->message;
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  return out;
}

std::string where(const load::Mission& mission, const SourceLocation& l) {
  return path_prefix_for(mission.dir) + place_text(l);
}

// Why the monitor cannot judge a trap on a trace: "the trace lacks OnMud", else its own words.
std::string lacking(const std::string& reason) {
  const std::string marker = "the trace has no variable '";
  const std::size_t at = reason.find(marker);
  if (at == std::string::npos) return reason;
  const std::size_t begin = at + marker.size();
  return "the trace lacks " + reason.substr(begin, reason.find('\'', begin) - begin);
}

}  // namespace

std::vector<prove::Goal> guarantee_goals(const load::Mission& mission) {
  std::vector<prove::Goal> out;
  for (const auto& p : plan(mission)) out.push_back(p.goal);
  return out;
}

const prove::WorldModel* load_world(const load::Mission& mission,
                                    std::optional<prove::WorldModel>& storage) {
  std::error_code ec;
  if (!std::filesystem::exists(mission.dir / "world.json", ec)) return nullptr;
  return &storage.emplace(prove::mission_world(mission));
}

GuaranteePlan plan_guarantee_targets(const load::Mission& mission, const Replayer& replayer,
                                     const Options& options) {
  GuaranteePlan out;
  out.traps = mission;
  out.traps.properties.clear();
  if (!options.criteria.count(Criterion::guarantee)) return out;
  std::vector<Planned> planned = plan(mission);
  if (planned.empty()) {
    out.notes.push_back(
        "guarantee targets not planned: no guarantee of this mission has a trigger (a mode, an "
        "upon/if/when condition)");
    return out;
  }
  if (options.world == nullptr) {
    out.notes.push_back("guarantee targets not planned: the mission has no world.json");
    return out;
  }
  std::vector<prove::Goal> goals;
  for (const auto& p : planned) goals.push_back(p.goal);
  std::vector<prove::Reach> answers;
  try {
    prove::Options prove_options;
    prove_options.depth = options.prove_depth;
    prove_options.max_states = options.prove_max_states;
    answers = prove::reach(mission, replayer.document(), *options.world, goals, prove_options);
  } catch (const std::exception& e) {
    out.notes.push_back(std::string("guarantee targets not planned: ") + e.what());
    return out;
  }
  for (const auto& g : goals) out.traps.properties.push_back(prove::trap_requirement(g));

  std::vector<std::size_t> reached;  // planned indices whose trap is violated
  for (std::size_t k = 0; k < planned.size(); ++k) {
    Target t = planned[k].target;
    const prove::Reach& a = answers[k];
    const fretish::Requirement& r = *planned[k].goal.scope_of;
    if (a.verdict == prove::Verdict::violated) {
      reached.push_back(k);
    } else {
      t.reachable = false;
      t.undecided = !unreached(a, t.reason);
      if (a.verdict == prove::Verdict::proved)
        t.reason = "no run that world.json allows reaches it (" + r.id + " at " +
                   where(mission, r.location) + ")";
    }
    out.targets.push_back(std::move(t));
    out.covered.push_back(false);
  }

  // Each reached goal's witness, replayed: the goals it reaches, its own at the planned tick.
  struct Candidate {
    std::size_t goal = 0;
    std::string json;
    Play play;
    std::set<std::size_t> reaches;  // planned indices
    std::string problem;
  };
  std::vector<Candidate> candidates;
  for (std::size_t k : reached) {
    Candidate cand;
    cand.goal = k;
    Json j = Json::parse(answers[k].witness->scenario);
    j["description"] = "";
    cand.json = j.dump(2) + "\n";
    cand.play = play(out.traps, replayer, cand.json, "guarantee.json");
    const std::uint64_t tick = answers[k].witness->tick;
    for (std::size_t g = 0; g < goals.size(); ++g) {
      const auto it = cand.play.reached.find(goals[g].id);
      if (it != cand.play.reached.end() && (g != k || it->second == tick)) cand.reaches.insert(g);
    }
    if (!cand.play.error.empty())
      cand.problem = "the scenario does not run: " + cand.play.error;
    else if (!cand.reaches.count(k)) {
      const auto it = cand.play.reached.find(goals[k].id);
      cand.problem =
          "the run does not reach it at tick " + std::to_string(tick) +
          (it == cand.play.reached.end() ? " (nor later)"
                                         : " (it does at tick " + std::to_string(it->second) + ")");
    }
    candidates.push_back(std::move(cand));
  }
  // Greedy set cover: the witness that reaches most goals not yet covered, first found first.
  std::set<std::size_t> open(reached.begin(), reached.end());
  std::vector<std::pair<std::size_t, std::vector<std::size_t>>> chosen;  // candidate, purposes
  while (!open.empty()) {
    std::size_t best = candidates.size(), best_count = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      std::size_t n = 0;
      for (std::size_t g : candidates[i].reaches) n += open.count(g);
      if (n > best_count) {
        best = i;
        best_count = n;
      }
    }
    if (best == candidates.size()) break;
    std::vector<std::size_t> purposes;
    for (std::size_t g : candidates[best].reaches)
      if (open.erase(g)) purposes.push_back(g);
    chosen.emplace_back(best, std::move(purposes));
  }
  // A witness whose replay misses its goal is kept, with its problem: the testbed would too.
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (!candidates[i].problem.empty()) chosen.emplace_back(i, std::vector<std::size_t>{});
  std::map<std::string, std::size_t> per_guarantee, next;
  auto base_of = [&](std::size_t i) {
    return "guarantee-" + planned[candidates[i].goal].goal.scope_of->id;
  };
  for (const auto& [i, purposes] : chosen) ++per_guarantee[base_of(i)];
  for (auto& [i, purposes] : chosen) {
    Candidate& cand = candidates[i];
    Scenario s;
    const std::string base = base_of(i);
    s.name = numbered(base, ++next[base], per_guarantee[base]);
    if (purposes.empty()) purposes.push_back(cand.goal);
    std::sort(purposes.begin(), purposes.end());
    for (std::size_t g : purposes) {
      s.purpose.push_back(g);
      s.description += (s.description.empty() ? "" : "; ") + planned[g].target.text;
      if (cand.problem.empty()) out.covered[g] = true;
    }
    s.description = "Test campaign: " + s.description;
    Json j = Json::parse(cand.json);
    j["description"] = s.description;
    s.json = j.dump(2) + "\n";
    s.run = cand.play.run;
    s.run.source = s.name + ".json";
    if (!cand.problem.empty()) s.problems.push_back(cand.problem);
    out.scenarios.push_back(std::move(s));
  }
  return out;
}

void add_guarantee_targets(const load::Mission& mission, const Replayer& replayer,
                           const Options& options, Campaign& c) {
  GuaranteePlan plan = plan_guarantee_targets(mission, replayer, options);
  const std::size_t first = c.targets.size();
  c.targets.insert(c.targets.end(), plan.targets.begin(), plan.targets.end());
  c.covered.insert(c.covered.end(), plan.covered.begin(), plan.covered.end());
  c.notes.insert(c.notes.end(), plan.notes.begin(), plan.notes.end());
  for (auto& s : plan.scenarios)
    for (auto& t : s.purpose) t += first;
  // Before the behaviour changes' scenarios.
  auto at = std::find_if(c.scenarios.begin(), c.scenarios.end(),
                         [](const Scenario& s) { return !s.change.empty(); });
  c.scenarios.insert(at, std::make_move_iterator(plan.scenarios.begin()),
                     std::make_move_iterator(plan.scenarios.end()));
}

std::set<std::size_t> guarantees_reached(const GuaranteePlan& plan, const Replayer& replayer,
                                         const std::string& json, const std::string& file) {
  std::set<std::size_t> out;
  if (plan.targets.empty()) return out;
  const Play p = play(plan.traps, replayer, json, file);
  for (std::size_t k = 0; k < plan.traps.properties.size(); ++k)
    if (p.reached.count(plan.traps.properties[k].id)) out.insert(k);
  return out;
}

std::set<std::size_t> guarantees_reached(const GuaranteePlan& plan, const std::string& content,
                                         const std::string& file,
                                         std::map<std::size_t, std::string>& not_judged) {
  std::set<std::size_t> out;
  if (plan.targets.empty()) return out;
  std::vector<Finding> findings;  // observe_trace reported them: the trace was read once already
  const auto trace = monitor::read_trace(content, file, findings);
  if (!trace) return out;
  const monitor::TraceReport report =
      monitor::check_trace(plan.traps.properties, plan.traps.domain, *trace, file, findings);
  for (std::size_t k = 0; k < plan.traps.properties.size(); ++k) {
    const monitor::PropertyResult& r = report.properties[k];
    if (r.verdict == monitor::Verdict::violated)
      out.insert(k);
    else if (r.verdict == monitor::Verdict::not_monitored)
      not_judged.emplace(k, lacking(r.reason));
  }
  return out;
}

}  // namespace uabt::campaign
