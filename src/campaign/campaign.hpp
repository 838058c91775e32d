#pragma once
// The test campaign of a mission (ARCHITECTURE §13): the targets a testbed run should exercise
// (decision, MC/DC, boundary, guarantee), scenarios in the `uabt run` format that reach them, each
// replayed on the runtime, and what a set of runs covered.
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/value.hpp"
#include "compile/compile.hpp"
#include "load/mission.hpp"
#include "prove/world_model.hpp"
#include "runtime/runner.hpp"
#include "runtime/scenario.hpp"
#include "verify/impact.hpp"
#include "verify/verify.hpp"

namespace uabt::campaign {

enum class Criterion { decision, mcdc, boundary, guarantee };
const char* criterion_name(Criterion c);

// One thing a campaign must exercise.
struct Target {
  std::string id;  // stable, unique in the mission: "navigation/mcdc/Req1/OnDust"
  std::string adaptable;
  Criterion criterion = Criterion::decision;
  std::string text;  // "navigation selects on_dust (Req1)"
  // false: no state of the domain reaches it; `reason` says why.
  bool reachable = true;
  std::string reason;
  // Not decided: neither reached nor proved unreachable within the depth explored (`reason`
  // says how deep); `reachable` is false and it is not counted as unreachable.
  bool undecided = false;
  // A state that reaches it (two for an MC/DC pair), as scenario values; empty when
  // unreachable.
  std::vector<State> witness;
  // A guarantee target's: the campaign's scenario (JSON) that reaches it; "" when none.
  std::string scenario;
};

// What one run did at an adaptable node: the alternative it selected and the values of the
// node's variables at that moment.
struct Observation {
  std::string adaptable;
  std::string alternative;  // "" when the run does not say (a monitor trace without .selected)
  State state;
  std::uint64_t tick = 0;
};

struct RunRecord {
  std::string source;   // the scenario or trace, as displayed
  std::string verdict;  // the run's verdict so far (runs stop once their purpose is reached)
  std::string error;    // the tick error that stopped the run, if any
  std::uint64_t ticks = 0;
  std::vector<Observation> observations;
};

// A share of a node's domain (the states that satisfy its assumptions), as the coverage stage
// measures it: states counted, real variables measured (length, area), exact.
struct Share {
  std::string exact = "0";  // "1/404"
  double value = 0;
};

// A set of a node's cells the runs visited: how many, the share of the domain they hold, and
// those of measure zero (a point or line on a boundary) counted apart.
struct Visited {
  std::uint64_t cells = 0;     // boundary cells included
  std::uint64_t boundary = 0;  // cells of measure zero
  Share share;
  std::string boundary_kind;  // "a boundary point", "a boundary line", "boundary points and lines"
};

// What runs visited of one adaptable node's space, and of each of its targets' states.
struct NodeVisit {
  std::string adaptable;
  bool counted = true;      // every variable discrete: a cell is a state
  std::uint64_t cells = 0;  // cells of the domain
  Visited visited;
  // A node whose space is not enumerated: why, and no share is measured ("" otherwise).
  std::string share_not_computed;
  struct TargetShare {
    std::size_t target = 0;  // into Model::targets()
    Share share;             // what its states hold of the domain
    Visited visited;         // of its states, those the runs visited
  };
  std::vector<TargetShare> targets;  // every target reached by single states (not MC/DC pairs)
  // The visited cells placed on the node's coverage map (one mark per cell of the map, with the
  // runs that visited it, in the order of the first state visited); `no_map` says why the node
  // has no map ("" when it has one).
  std::vector<verify::MapMark> marks;
  std::string no_map;
};

// Targets and their witnesses for every adaptable node, enumerated exactly over the cells of
// the coverage stage (verify/space.hpp). A node whose space cannot be enumerated (too many
// states, conditions the cells cannot decide) has each target solved with Z3 instead: the same
// targets, witnesses from the solver, no share. Nodes whose guards do not type-check are listed
// in `skipped` with the reason, and get no targets.
class Model {
 public:
  // `solve_every_node`: solve every node's targets with Z3, as for a space too large to
  // enumerate (tests compare the two).
  Model(const load::Mission& mission, const std::set<Criterion>& criteria,
        bool solve_every_node = false);
  ~Model();
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const std::vector<Target>& targets() const { return targets_; }
  const std::vector<std::pair<std::string, std::string>>& skipped() const { return skipped_; }
  // The nodes whose targets were solved rather than enumerated: adaptable, why.
  std::vector<std::pair<std::string, std::string>> solved() const;

  // The targets a set of runs covered (indices into targets()).
  std::vector<bool> covered(const std::vector<RunRecord>& runs) const;
  // What a set of runs visited of each node's space, measured exactly (visits.cpp).
  std::vector<NodeVisit> visits(const std::vector<RunRecord>& runs) const;

  // Minimised: per adaptable node the states (as scenario values) that together reach every
  // reachable target of it, fewest first found by greedy set cover, with the targets each
  // was chosen for.
  struct Pick {
    std::size_t node = 0;
    std::uint64_t index = 0;  // the state's index in the node's space
    State state;
    std::vector<std::size_t> purpose;  // targets this state is needed for
  };
  // States in `excluded` (per node, by index) are not used: runs showed they do not reach
  // the node.
  std::vector<Pick> minimise(const std::vector<std::set<std::uint64_t>>& excluded = {}) const;
  // Per node: its adaptable id, the variables it ranges over, and a state of its domain
  // (empty when the domain has none).
  std::size_t nodes() const;
  const std::string& adaptable(std::size_t node) const;
  State default_state(std::size_t node) const;
  // The alternative a state selects at a node ("" outside its space or in a gap).
  std::string expected(std::size_t node, const State& state) const;
  // The variables a node's targets are about: its guards', and those assumptions link to them.
  const std::set<std::string>& variables(std::size_t node) const;

  // What a run must show at a node to reach a target, for the world model's search
  // (world_reach.hpp): FRETISH conditions of one tick on the node's variables. A single-state
  // target has one (`single`); an MC/DC pair target one per state of each of its pairs.
  // `complete`: every way to reach the target is among them, so that the world model ruling
  // each out proves the target unreachable.
  struct ReachCondition {
    std::size_t node = 0;
    std::string single;
    std::vector<std::pair<std::string, std::string>> pairs;
    bool complete = true;
  };
  // nullopt for a target of no node (a guarantee target). One no state of the domain reaches
  // has a condition no state satisfies, or no pair.
  std::optional<ReachCondition> reach_condition(std::size_t target) const;

  struct Node;

 private:
  const load::Mission& mission_;
  std::vector<std::unique_ptr<Node>> nodes_;
  std::vector<Target> targets_;
  std::vector<std::pair<std::string, std::string>> skipped_;  // adaptable, reason
};

// Runs scenarios on the compiled mission (the runtime `uabt run` uses, without the gate).
class Replayer {
 public:
  // Runs `compiled_tree`, the mission's compiled tree as read back (compile::read_back), whose
  // nodes come from where `trace` says.
  Replayer(const load::Mission& mission, bt::Document compiled_tree,
           std::vector<compile::TraceEntry> trace);
  // Compiles the mission and reads it back first. Throws std::runtime_error when it does not
  // compile or read back.
  static Replayer compiling(const load::Mission& mission, const compile::Options& options);
  Replayer(Replayer&&) noexcept;
  ~Replayer();
  // Runs a scenario (JSON text) until every adaptable node of `stop_after` has selected, the
  // root completes, a tick throws or max_ticks is reached; every selection is observed.
  // Throws runtime::ScenarioError when the scenario does not parse. Each run is on the same
  // tree, reset to exactly its fresh state: a Replayer runs one scenario at a time.
  RunRecord run(const std::string& json, const std::string& file,
                const std::set<std::string>& stop_after = {}) const;
  // A scenario (JSON text) parsed, its numbers typed by the mission's declarations
  // (runtime::type_numbers). Throws runtime::ScenarioError when it does not parse.
  runtime::Scenario scenario(const std::string& json, const std::string& file) const;
  // The one tree, reset to exactly its fresh state in `scenario` (built at the first call),
  // with no observer but those a caller adds and removes; valid until the next call.
  runtime::Runner& start(runtime::Scenario scenario) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;

 public:
  // The compiled tree it runs, as `uabt run` reads it back.
  const bt::Document& document() const;
};

// A state in which an uplink changes what a node selects: the campaign runs one scenario for
// each, beside its targets, so that a testbed runs exactly what the uplink changes.
struct Change {
  std::string adaptable;
  std::string from, to;      // alternatives before and after the uplink; "" = none (the node fails)
  State state;               // a state in which the node moves
  std::string text() const;  // "node navigation moves from on_dust to on_mud"
};
// One change per (node, from, to) of an uplink's impact that has an example state.
std::vector<Change> behaviour_changes(const verify::Impact& impact);

struct Options {
  std::set<Criterion> criteria{Criterion::decision, Criterion::mcdc, Criterion::boundary,
                               Criterion::guarantee};
  std::vector<Change> changes;
  compile::Options compile;
  std::int64_t max_ticks = 100;
  // The world scenarios play in and guarantee targets are solved over; nullptr: the mission's
  // world.json, when it has one.
  const prove::WorldModel* world = nullptr;
  // The mission's compiled tree as read back and where its nodes come from, when the caller
  // has them (the gate); nullptr: compiled and read back here with `compile`.
  const bt::Document* compiled_tree = nullptr;
  const std::vector<compile::TraceEntry>* trace = nullptr;
  // Guarantee targets: how deep and how many states the prove engines explore (0: every tick).
  std::uint64_t prove_depth = 0;
  std::size_t prove_max_states = 2'000'000;
  // Solve every node's targets with Z3, even where its space can be enumerated (tests).
  bool solve_every_node = false;
};

struct Scenario {
  std::string name;  // file name without ".json": "navigation-01"
  std::string description;
  std::string json;                   // the file
  std::vector<std::size_t> purpose;   // targets it was written for
  std::string change;                 // the behaviour change it shows (Change::text), or ""
  RunRecord run;                      // its replay
  std::vector<std::string> problems;  // purposes the replay did not reach, and why
};

struct Campaign {
  std::string mission;
  std::vector<Target> targets;
  std::vector<bool> covered;        // per target, by the replays
  std::vector<Scenario> scenarios;  // the targets' scenarios, then the behaviour changes'
  std::vector<std::pair<std::string, std::string>> skipped;  // adaptable, reason
  std::vector<std::string> notes;  // "guarantee targets not planned: the mission has no world.json"
  std::size_t change_scenarios() const;
  bool passed() const;  // every scenario reached its purpose, every reachable target covered
};

// Plans, writes (in memory) and replays the campaign.
Campaign build_campaign(const load::Mission& mission, const Options& options);
// The campaign of a mission an uplink was merged into: its targets' scenarios, then one per
// behaviour change of the uplink (`impact`, the diff of the mission before and after it), so
// that a testbed runs exactly what the uplink changes. `uabt tests --uplink` and `uabt gate
// --uplink` both build theirs here.
Campaign build_uplink_campaign(const load::Mission& merged, const verify::Impact& impact,
                               Options options);

// The campaign's summary and its JUnit run, written beside the scenarios.
inline constexpr const char* kSummaryFile = "campaign.json";
inline constexpr const char* kJunitFile = "junit.xml";

// The files of a campaign: <name>.json per scenario, campaign.json, junit.xml.
std::vector<std::pair<std::string, std::string>> campaign_files(const Campaign& campaign);
std::string campaign_text(const Campaign& campaign);
std::string campaign_json(const Campaign& campaign);
std::string campaign_junit(const Campaign& campaign);

// `uabt coverage`: what runs covered and what they missed, with a scenario for each miss.
struct CoverageReport {
  std::string mission;
  std::vector<Target> targets;
  std::vector<bool> covered;
  std::vector<RunRecord> runs;
  std::vector<std::pair<std::string, std::string>> skipped;
  std::vector<NodeVisit> visits;  // per node: the cells the runs visited (Model::visits)
  // Targets no run could judge (a monitor trace without the values its trap reads), with
  // "<trace>: the trace lacks X": not counted as missed.
  std::map<std::size_t, std::string> not_judged;
  std::vector<std::string> notes;  // "guarantee targets not planned: …"
};
std::string coverage_text(const CoverageReport& report);
std::string coverage_json(const CoverageReport& report);
// One self-contained HTML page (inline CSS and SVG, no script): per adaptable node the cells the
// runs visited drawn over its coverage map (`maps`: verify's coverage of the mission, one per
// node) and its targets, covered or missed, each miss with what covers it; then the guarantee
// targets, the runs and the notes. The same facts as coverage_text.
std::string coverage_html(const CoverageReport& report, const load::Mission& mission,
                          const std::vector<verify::Coverage>& maps,
                          const std::string& tool_version);
// The first line of coverage_text: "msl_curiosity: 1 run covers 8 of 19 reachable targets (…)".
std::string coverage_headline(const CoverageReport& report);
// What covers a missed target: "initial {…}" (" and {…}" for a pair), or for a guarantee target
// "the scenario {…}", the campaign's, on one line without its description.
std::string covering_text(const Target& t);
// "25% (1/4) of the space", "0% of the space (a boundary point)", both when both are there.
std::string visited_text(const Visited& visited);

// A monitor trace as observations: every tick whose state holds all of a node's variables.
RunRecord observe_trace(const load::Mission& mission, const std::string& content,
                        const std::string& file, std::vector<Finding>& findings);

}  // namespace uabt::campaign
