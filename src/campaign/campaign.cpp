// The campaign: minimised scenarios for the targets, each replayed, and its reports.
#include "campaign/campaign.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "base/number_text.hpp"
#include "base/text.hpp"
#include "campaign/guarantee.hpp"
#include "campaign/node.hpp"
#include "campaign/world_play.hpp"
#include "campaign/world_reach.hpp"
#include "monitor/trace.hpp"
#include "report/coverage_view.hpp"
#include "report/reports.hpp"
#include "runtime/scenario.hpp"

namespace uabt::campaign {

namespace {

using Json = nlohmann::ordered_json;

std::set<std::string> names_of(const State& state) {
  std::set<std::string> out;
  for (const auto& [name, v] : state) out.insert(name);
  return out;
}

void set_missing(State& into, const State& from) {
  for (const auto& [name, v] : from)
    if (find_value(into, name) == nullptr) into.emplace_back(name, v);
}

}  // namespace

std::string Change::text() const {
  auto name = [](const std::string& alternative) {
    return alternative.empty() ? std::string("no alternative") : alternative;
  };
  return "node " + adaptable + " moves from " + name(from) + " to " + name(to);
}

std::vector<Change> behaviour_changes(const verify::Impact& impact) {
  std::vector<Change> out;
  for (const auto& node : impact.nodes)
    for (const auto& change : node.changes)
      if (!change.example.empty())
        out.push_back({node.adaptable, change.from, change.to, change.example});
  return out;
}

std::size_t Campaign::change_scenarios() const {
  std::size_t n = 0;
  for (const auto& s : scenarios) n += !s.change.empty();
  return n;
}

bool Campaign::passed() const {
  for (const auto& s : scenarios)
    if (!s.problems.empty()) return false;
  for (std::size_t k = 0; k < targets.size(); ++k)
    if (targets[k].reachable && !covered[k]) return false;
  return true;
}

namespace {

// A value of each declared variable that no node ranges over, so that a script of the tree
// reading it does not stop the run: the lower bound (else 0), the first literal, false.
State other_variables(const load::Mission& mission, const std::set<std::string>& covered) {
  State out;
  for (const auto& v : mission.domain.variables) {
    if (!v.declared || covered.count(v.name) || !v.invalid.empty()) continue;
    switch (v.type) {
      case fretish::VarType::boolean: out.emplace_back(v.name, Value::of_bool(false)); break;
      case fretish::VarType::enumeration:
        if (!v.enum_values.empty()) out.emplace_back(v.name, Value::of_enum(v.enum_values[0]));
        break;
      case fretish::VarType::integer: {
        std::int64_t x = 0;
        try {
          if (!v.lower.empty()) x = std::max<std::int64_t>(x, std::stoll(v.lower));
          if (!v.upper.empty()) x = std::min<std::int64_t>(x, std::stoll(v.upper));
        } catch (const std::exception&) {
          continue;
        }
        out.emplace_back(v.name, Value::of_int(x));
        break;
      }
      case fretish::VarType::real: {
        double x = 0;
        try {
          if (!v.lower.empty()) x = std::max(x, std::stod(v.lower));
          if (!v.upper.empty()) x = std::min(x, std::stod(v.upper));
        } catch (const std::exception&) {
          continue;
        }
        out.emplace_back(v.name, Value::of_real(x, number_text(x)));
        break;
      }
    }
  }
  return out;
}

// Writes the scenario's file (its description prefixed, `initial` in the domain's order) and
// replays it until every node of `nodes` has selected.
void replay(const load::Mission& mission, const Replayer& replayer, const Options& options,
            State initial, const std::set<std::string>& nodes, Scenario& s) {
  s.description = "Test campaign: " + s.description;
  Json j_scenario = Json::object();
  j_scenario["description"] = s.description;
  j_scenario["max_ticks"] = options.max_ticks;
  // In world.json's world: an initial state it allows, its actions' contracts.
  if (options.world != nullptr)
    initial = world_initial(mission, *options.world, std::move(initial));
  j_scenario["initial"] = state_json(in_domain_order(mission.domain, initial));
  if (options.world != nullptr) j_scenario["actions"] = world_actions(*options.world, initial);
  s.json = j_scenario.dump(2) + "\n";
  try {
    s.run = replayer.run(s.json, s.name + ".json", nodes);
  } catch (const std::exception& e) {
    s.problems.push_back(std::string("the scenario does not run: ") + e.what());
  }
}

// Why a run did not select `want` at `adaptable` ("" when it did; `seen` is then its
// observation).
std::string selection_problem(const RunRecord& run, const std::string& adaptable,
                              const std::string& want, const Observation*& seen) {
  seen = nullptr;
  for (const auto& o : run.observations)
    if (o.adaptable == adaptable) {
      seen = &o;
      break;
    }
  if (seen == nullptr)
    return adaptable + " is not ticked (" + count_text(run.ticks, "tick") + ", verdict " +
           run.verdict + (run.error.empty() ? "" : ": " + run.error) + ")";
  if (seen->alternative != want)
    return adaptable + " selected " + (seen->alternative.empty() ? "nothing" : seen->alternative) +
           " at tick " + std::to_string(seen->tick) + ", expected " +
           (want.empty() ? "nothing" : want);
  return "";
}

// What a scenario does not set: each node's default state, then a value of every other
// declared variable.
State filler_state(const load::Mission& mission, const Model& model) {
  State filler;
  for (std::size_t k = 0; k < model.nodes(); ++k) set_missing(filler, model.default_state(k));
  set_missing(filler, other_variables(mission, names_of(filler)));
  return filler;
}

struct Round {
  std::vector<Scenario> scenarios;
  // (node, state index) of each planned state whose run did not reach its purpose
  std::vector<std::pair<std::size_t, std::uint64_t>> misses;
};

// Scenarios for the picks: nodes over disjoint variables share scenarios (a lane); every
// scenario also gives the other nodes' variables a value of their domain, so that the run
// gets to its node. Each is replayed and checked against its purpose.
Round plan_round(const load::Mission& mission, const Model& model, const Replayer& replayer,
                 const std::vector<Model::Pick>& picks, const std::vector<Target>& targets,
                 const Options& options) {
  Round round;
  const std::size_t n = model.nodes();
  std::vector<State> defaults(n);
  std::vector<std::set<std::string>> variables(n);
  std::vector<std::vector<const Model::Pick*>> by_node(n);
  for (std::size_t k = 0; k < n; ++k) {
    defaults[k] = model.default_state(k);
    variables[k] = names_of(defaults[k]);
  }
  const State filler = filler_state(mission, model);
  for (const auto& p : picks) by_node[p.node].push_back(&p);
  std::vector<std::vector<std::size_t>> lanes;
  std::vector<std::set<std::string>> lane_vars;
  for (std::size_t k = 0; k < n; ++k) {
    if (by_node[k].empty()) continue;
    std::size_t lane = 0;
    for (; lane < lanes.size(); ++lane) {
      bool disjoint = true;
      for (const auto& v : variables[k]) disjoint = disjoint && lane_vars[lane].count(v) == 0;
      if (disjoint) break;
    }
    if (lane == lanes.size()) {
      lanes.emplace_back();
      lane_vars.emplace_back();
    }
    lanes[lane].push_back(k);
    lane_vars[lane].insert(variables[k].begin(), variables[k].end());
  }
  for (const auto& lane : lanes) {
    std::size_t rounds = 0;
    for (std::size_t k : lane) rounds = std::max(rounds, by_node[k].size());
    for (std::size_t j = 0; j < rounds; ++j) {
      Scenario s;
      State initial;
      std::set<std::string> purpose_nodes;
      std::vector<std::pair<std::size_t, const Model::Pick*>> planned;
      for (std::size_t k : lane) {
        if (j >= by_node[k].size()) continue;
        const Model::Pick* p = by_node[k][j];
        if (s.name.empty()) s.name = numbered(model.adaptable(k), j + 1, rounds);
        set_missing(initial, p->state);
        purpose_nodes.insert(model.adaptable(k));
        s.purpose.insert(s.purpose.end(), p->purpose.begin(), p->purpose.end());
        planned.emplace_back(k, p);
      }
      set_missing(initial, filler);
      for (std::size_t t : s.purpose)
        s.description += (s.description.empty() ? "" : "; ") + targets[t].text;
      replay(mission, replayer, options, std::move(initial), purpose_nodes, s);
      for (const auto& [k, p] : planned) {
        const std::string want = model.expected(k, p->state);
        const Observation* seen = nullptr;
        std::string problem = selection_problem(s.run, model.adaptable(k), want, seen);
        if (problem.empty() && model.expected(k, seen->state) != want)
          problem = model.adaptable(k) + " selected in another state than planned";
        if (problem.empty()) continue;
        s.problems.push_back(problem);
        round.misses.emplace_back(k, p->index);
      }
      round.scenarios.push_back(std::move(s));
    }
  }
  return round;
}

}  // namespace

Campaign build_campaign(const load::Mission& mission, const Options& given) {
  Options options = given;
  std::optional<prove::WorldModel> world;
  if (options.world == nullptr) options.world = load_world(mission, world);
  Campaign c;
  c.mission = mission.name;
  Model model(mission, options.criteria, options.solve_every_node);
  c.targets = model.targets();
  c.skipped = model.skipped();
  for (const auto& [node, why] : model.solved())
    c.notes.push_back("targets of " + node + " solved one by one, not enumerated: " + why);
  const Replayer replayer = options.compiled_tree != nullptr && options.trace != nullptr
                                ? Replayer(mission, *options.compiled_tree, *options.trace)
                                : Replayer::compiling(mission, options.compile);
  // A state whose run does not get to its node (the tree takes another branch first) is
  // set aside and the targets planned again, a few times.
  std::vector<std::set<std::uint64_t>> excluded(model.nodes());
  Round round;
  for (int attempt = 0; attempt < 12; ++attempt) {
    round = plan_round(mission, model, replayer, model.minimise(excluded), c.targets, options);
    bool fresh = false;
    for (const auto& [k, index] : round.misses) fresh = excluded[k].insert(index).second || fresh;
    if (!fresh) break;
  }
  // What still misses its purpose is no test: left out.
  for (auto& s : round.scenarios)
    if (s.problems.empty()) c.scenarios.push_back(std::move(s));
  // The targets those runs miss: searched for in the world model prove explores, which says
  // which no run reaches.
  reach_in_world(mission, model, replayer, options, c);
  // Numbered again without the gaps, per node.
  std::map<std::string, std::size_t> per_base;
  for (const auto& s : c.scenarios) ++per_base[s.name.substr(0, s.name.rfind('-'))];
  std::map<std::string, std::size_t> next;
  for (auto& s : c.scenarios) {
    const std::string base = s.name.substr(0, s.name.rfind('-'));
    s.name = numbered(base, ++next[base], per_base[base]);
    s.run.source = s.name + ".json";
  }
  // The behaviour changes of an uplink, one scenario each, kept even when the run does not
  // show the change (its problem says what the testbed will see instead).
  const State filler = filler_state(mission, model);
  std::map<std::string, std::size_t> changes_per_node;
  for (const auto& change : options.changes) ++changes_per_node[change.adaptable];
  std::map<std::string, std::size_t> next_change;
  for (const auto& change : options.changes) {
    Scenario s;
    s.name = numbered(change.adaptable + "-change", ++next_change[change.adaptable],
                      changes_per_node[change.adaptable]);
    s.change = change.text();
    s.description = "behaviour change: " + s.change;
    State initial = change.state;
    set_missing(initial, filler);
    replay(mission, replayer, options, std::move(initial), {change.adaptable}, s);
    const Observation* seen = nullptr;
    const std::string problem = selection_problem(s.run, change.adaptable, change.to, seen);
    if (!problem.empty()) s.problems.push_back(problem);
    c.scenarios.push_back(std::move(s));
  }
  std::vector<RunRecord> runs;
  for (const auto& s : c.scenarios) runs.push_back(s.run);
  c.covered = model.covered(runs);
  add_guarantee_targets(mission, replayer, options, c);
  return c;
}

Campaign build_uplink_campaign(const load::Mission& merged, const verify::Impact& impact,
                               Options options) {
  options.changes = behaviour_changes(impact);
  return build_campaign(merged, options);
}

std::vector<std::pair<std::string, std::string>> campaign_files(const Campaign& campaign) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& s : campaign.scenarios) files.emplace_back(s.name + ".json", s.json);
  files.emplace_back(kSummaryFile, campaign_json(campaign));
  files.emplace_back(kJunitFile, campaign_junit(campaign));
  return files;
}

namespace {

struct Counts {
  std::size_t targets = 0, reachable = 0, covered = 0, undecided = 0;
  std::size_t unreachable() const { return targets - reachable - undecided; }
  // "2 unreachable, 1 not decided": targets no state reaches, and those not decided either way.
  std::string unreached_text() const {
    return std::to_string(unreachable()) + " unreachable" +
           (undecided == 0 ? "" : ", " + std::to_string(undecided) + " not decided");
  }
  std::map<std::string, std::size_t> by_criterion;
};

// The line of a target no run can reach: unreachable, or not decided either way, and why.
std::string unreached_line(const Target& t) {
  return (t.undecided ? "not decided: " : "unreachable: ") + t.text + ": " + t.reason + "\n";
}

Counts count(const std::vector<Target>& targets, const std::vector<bool>& covered) {
  Counts c;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    ++c.targets;
    ++c.by_criterion[criterion_name(targets[k].criterion)];
    c.undecided += targets[k].undecided;
    if (!targets[k].reachable) continue;
    ++c.reachable;
    if (covered[k]) ++c.covered;
  }
  return c;
}

std::string criteria_text(const Counts& c) {
  std::string out;
  for (const char* name : {"decision", "mcdc", "boundary", "guarantee"}) {
    auto it = c.by_criterion.find(name);
    if (it == c.by_criterion.end()) continue;
    out += (out.empty() ? "" : ", ") + std::string(name == std::string("mcdc") ? "MC/DC" : name) +
           " " + std::to_string(it->second);
  }
  return out;
}

std::string witness_text(const Target& t) {
  std::string out;
  for (const auto& w : t.witness) out += (out.empty() ? "" : " and ") + state_json(w).dump();
  return out;
}

// A guarantee target's scenario on one line, without its description (which names the targets).
std::string scenario_text(const Target& t) {
  Json j = Json::parse(t.scenario);
  j.erase("description");
  return j.dump();
}

Json target_json(const Target& t, bool covered) {
  Json j = Json::object();
  j["id"] = t.id;
  j["adaptable"] = t.adaptable;
  j["criterion"] = criterion_name(t.criterion);
  j["text"] = t.text;
  j["reachable"] = t.reachable;
  if (t.undecided) j["undecided"] = true;
  if (!t.reachable) j["reason"] = t.reason;
  j["covered"] = covered;
  return j;
}

// The visited cells of a node or a target: how many, their exact share, those of measure zero.
void visited_json(Json& out, const Visited& v) {
  out["visited_cells"] = v.cells;
  out["visited_share"] = number_json(v.share.value);
  out["visited_share_exact"] = v.share.exact;
  out["visited_boundary_cells"] = v.boundary;
  if (v.boundary > 0) out["visited_boundary"] = v.boundary_kind;
}

Json skipped_json(const std::vector<std::pair<std::string, std::string>>& skipped) {
  Json j = Json::array();
  for (const auto& [node, reason] : skipped) j.push_back({{"adaptable", node}, {"reason", reason}});
  return j;
}

}  // namespace

std::string campaign_text(const Campaign& campaign) {
  const Counts c = count(campaign.targets, campaign.covered);
  std::string out = campaign.mission + ": " + std::to_string(c.targets) + " targets" +
                    (c.targets == 0 ? "" : " (" + criteria_text(c) + ")") + ", " +
                    c.unreached_text() + "; " + std::to_string(campaign.scenarios.size()) +
                    " scenarios cover " + std::to_string(c.covered) + " of " +
                    std::to_string(c.reachable) + " reachable targets\n";
  for (const auto& s : campaign.scenarios) {
    out += "  " + s.name + ".json: " +
           (s.change.empty() ? std::to_string(s.purpose.size()) +
                                   (s.purpose.size() == 1 ? " target, " : " targets, ")
                             : "behaviour change: " + s.change + ", ") +
           (s.problems.empty() ? "reached at tick " + std::to_string(s.run.ticks) : "not reached") +
           "\n";
    for (const auto& p : s.problems) out += "    " + p + "\n";
  }
  for (std::size_t k = 0; k < campaign.targets.size(); ++k) {
    const Target& t = campaign.targets[k];
    if (!t.reachable)
      out += unreached_line(t);
    else if (!campaign.covered[k])
      out += "not covered: " + t.text + "\n";
  }
  for (const auto& [node, reason] : campaign.skipped)
    out += "no targets for " + node + ": " + reason + "\n";
  for (const auto& note : campaign.notes) out += note + "\n";
  return out;
}

std::string campaign_json(const Campaign& campaign) {
  const Counts c = count(campaign.targets, campaign.covered);
  Json j = Json::object();
  j["mission"] = campaign.mission;
  j["passed"] = campaign.passed();
  j["summary"] = {{"targets", c.targets},
                  {"reachable", c.reachable},
                  {"unreachable", c.unreachable()},
                  {"undecided", c.undecided},
                  {"covered", c.covered},
                  {"scenarios", campaign.scenarios.size()},
                  {"behaviour_change_scenarios", campaign.change_scenarios()}};
  std::vector<Json> by(campaign.targets.size(), Json::array());
  for (const auto& s : campaign.scenarios)
    for (std::size_t t : s.purpose) by[t].push_back(s.name + ".json");
  Json targets = Json::array();
  for (std::size_t k = 0; k < campaign.targets.size(); ++k) {
    Json t = target_json(campaign.targets[k], campaign.covered[k]);
    t["scenarios"] = std::move(by[k]);
    targets.push_back(std::move(t));
  }
  j["targets"] = targets;
  Json scenarios = Json::array();
  for (const auto& s : campaign.scenarios) {
    Json e = Json::object();
    e["file"] = s.name + ".json";
    Json purpose = Json::array();
    for (std::size_t t : s.purpose) purpose.push_back(campaign.targets[t].id);
    e["purpose"] = purpose;
    if (!s.change.empty()) e["behaviour_change"] = s.change;
    e["reached"] = s.problems.empty();
    e["ticks"] = s.run.ticks;
    e["problems"] = s.problems;
    scenarios.push_back(std::move(e));
  }
  j["scenarios"] = scenarios;
  j["skipped"] = skipped_json(campaign.skipped);
  j["notes"] = campaign.notes;
  return j.dump(2) + "\n";
}

std::string campaign_junit(const Campaign& campaign) {
  report::JunitSuite suite{campaign.mission + ".tests", {}};
  for (const auto& s : campaign.scenarios) {
    report::JunitCase t;
    t.name = s.name;
    if (!s.problems.empty()) {
      t.failure = s.problems.front();
      t.failure_type = "purpose-not-reached";
      for (const auto& p : s.problems) t.failure_text += p + "\n";
    }
    t.system_out = s.description + "\nreplayed: " + count_text(s.run.ticks, "tick") + ", " +
                   (s.run.verdict.empty() ? "not run" : s.run.verdict + " so far") + "\n";
    suite.cases.push_back(std::move(t));
  }
  return report::junit_xml({suite});
}

std::string coverage_headline(const CoverageReport& report) {
  const Counts c = count(report.targets, report.covered);
  return report.mission + ": " + std::to_string(report.runs.size()) +
         (report.runs.size() == 1 ? " run covers " : " runs cover ") + std::to_string(c.covered) +
         " of " + std::to_string(c.reachable) + " reachable targets (" +
         (c.targets == 0 ? "" : criteria_text(c) + "; ") + c.unreached_text() +
         (report.not_judged.empty()
              ? ""
              : ", " + std::to_string(report.not_judged.size()) + " not judged") +
         ")";
}

std::string covering_text(const Target& t) {
  return t.scenario.empty() ? "initial " + witness_text(t) : "the scenario " + scenario_text(t);
}

std::string coverage_text(const CoverageReport& report) {
  std::string out = coverage_headline(report) + "\n";
  for (const auto& r : report.runs) {
    out += "  " + r.source + ": " + std::to_string(r.observations.size()) +
           (r.observations.size() == 1 ? " observation in " : " observations in ") +
           count_text(r.ticks, "tick") + (r.error.empty() ? "" : ", stopped: " + r.error) + "\n";
  }
  for (const auto& v : report.visits)
    out += "  " + v.adaptable + ": " +
           (v.share_not_computed.empty()
                ? std::to_string(v.visited.cells) + " of " + std::to_string(v.cells) +
                      (v.counted ? " states" : " cells") + " visited, " + visited_text(v.visited)
                : std::to_string(v.visited.cells) +
                      " states visited, share not computed: " + v.share_not_computed) +
           "\n";
  for (const auto& v : report.visits)
    for (const auto& t : v.targets) {
      const Target& target = report.targets[t.target];
      if (target.criterion == Criterion::boundary && t.visited.cells > 0)
        out += "visited: " + target.text + ": " + visited_text(t.visited) + "\n";
    }
  for (std::size_t k = 0; k < report.targets.size(); ++k) {
    const Target& t = report.targets[k];
    if (!t.reachable || report.covered[k] || report.not_judged.count(k)) continue;
    out += "missed: " + t.text + "; covered by " + covering_text(t) + "\n";
  }
  for (const auto& [k, why] : report.not_judged)
    out += "not judged: " + report.targets[k].text + ": " + why + "\n";
  for (const auto& t : report.targets)
    if (!t.reachable) out += unreached_line(t);
  for (const auto& [node, reason] : report.skipped)
    out += "no targets for " + node + ": " + reason + "\n";
  for (const auto& note : report.notes) out += note + "\n";
  return out;
}

std::string coverage_json(const CoverageReport& report) {
  const Counts c = count(report.targets, report.covered);
  Json j = Json::object();
  j["mission"] = report.mission;
  j["summary"] = {{"targets", c.targets},           {"reachable", c.reachable},
                  {"unreachable", c.unreachable()}, {"undecided", c.undecided},
                  {"covered", c.covered},           {"not_judged", report.not_judged.size()},
                  {"runs", report.runs.size()}};
  Json runs = Json::array();
  for (const auto& r : report.runs) {
    Json e = Json::object();
    e["source"] = r.source;
    e["ticks"] = r.ticks;
    e["observations"] = r.observations.size();
    if (!r.error.empty()) e["error"] = r.error;
    runs.push_back(std::move(e));
  }
  j["runs"] = runs;
  Json targets = Json::array();
  for (std::size_t k = 0; k < report.targets.size(); ++k) {
    const Target& t = report.targets[k];
    Json e = target_json(t, report.covered[k]);
    if (const auto why = report.not_judged.find(k); why != report.not_judged.end())
      e["not_judged"] = why->second;
    else if (t.reachable && !report.covered[k] && !t.scenario.empty())
      e["scenario"] = Json::parse(t.scenario);
    else if (t.reachable && !report.covered[k]) {
      Json w = Json::array();
      for (const auto& s : t.witness) w.push_back(state_json(s));
      e["scenario_initial"] = w;
    }
    targets.push_back(std::move(e));
  }
  for (const auto& v : report.visits)
    for (const auto& t : v.targets) {
      Json& e = targets[t.target];
      e["share"] = number_json(t.share.value);
      e["share_exact"] = t.share.exact;
      visited_json(e, t.visited);
    }
  j["targets"] = targets;
  Json visits = Json::array();
  for (const auto& v : report.visits) {
    Json e = Json::object();
    e["adaptable"] = v.adaptable;
    if (!v.share_not_computed.empty()) {
      e["visited_states"] = v.visited.cells;
      e["share_not_computed"] = v.share_not_computed;
      visits.push_back(std::move(e));
      continue;
    }
    e["counted"] = v.counted;
    e["cells"] = v.cells;
    visited_json(e, v.visited);
    visits.push_back(std::move(e));
  }
  j["visits"] = visits;
  j["skipped"] = skipped_json(report.skipped);
  j["notes"] = report.notes;
  return j.dump(2) + "\n";
}

std::string visited_text(const Visited& v) {
  const std::string zero = "0% of the space (" + v.boundary_kind + ")";
  if (v.cells == v.boundary) return v.boundary == 0 ? "0% of the space" : zero;
  std::string out = report::detail::share_text({v.share.value, v.share.exact}) + " of the space";
  if (v.boundary > 0)
    out += "; " + std::to_string(v.boundary) + " of the cells on a boundary: " + zero;
  return out;
}

RunRecord observe_trace(const load::Mission& mission, const std::string& content,
                        const std::string& file, std::vector<Finding>& findings) {
  RunRecord record;
  record.source = file;
  auto trace = monitor::read_trace(content, file, findings);
  if (!trace) return record;
  std::set<std::string> adaptables;
  for (const auto& site : mission.adaptables) adaptables.insert(site.id);
  State now;
  for (const auto& tick : trace->ticks) {
    for (const auto& [name, v] : tick.state) {
      if (v.kind == monitor::TraceValue::Kind::none) {  // no value at this tick
        // An init-capture: clang before 16 cannot capture a structured binding.
        std::erase_if(now, [&key = name](const auto& entry) { return entry.first == key; });
        continue;
      }
      Value value;
      if (v.kind == monitor::TraceValue::Kind::boolean)
        value = Value::of_bool(v.boolean);
      else if (v.kind == monitor::TraceValue::Kind::text)
        value = Value::of_enum(v.text);
      else if (fretish::number_is_integer(mission.domain.find(name), v.number, v.integer))
        value = Value::of_int(static_cast<std::int64_t>(v.number));
      else
        value = Value::of_real(v.number, number_text(v.number));
      bool replaced = false;
      for (auto& [n, old] : now)
        if (n == name) {
          old = value;
          replaced = true;
        }
      if (!replaced) now.emplace_back(name, value);
    }
    record.ticks = tick.tick;
    for (const auto& node : adaptables) {
      Observation o;
      o.adaptable = node;
      o.tick = tick.tick;
      o.state = now;
      if (const Value* sel = find_value(now, node + ".selected")) o.alternative = sel->text;
      record.observations.push_back(std::move(o));
    }
  }
  return record;
}

}  // namespace uabt::campaign
