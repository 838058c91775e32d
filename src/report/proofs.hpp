#pragma once
// What a report shows of `uabt prove` (ARCHITECTURE §10): every guarantee with its verdict and, for
// a violated one, its counterexample as a tick-by-tick timeline. Filled by the gate from prove's
// plain result; the report stage only draws it.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "base/location.hpp"
#include "base/value.hpp"

namespace uabt::report {

// One tick of a counterexample's replay.
struct ProofTick {
  std::uint64_t tick = 0;
  std::string root;  // the root's status: RUNNING, SUCCESS, FAILURE
  std::vector<std::pair<std::string, Value>> values;  // what the property reads
  // (action, "started" | "running" | "success" | "failure" | "halted")
  std::vector<std::pair<std::string, std::string>> actions;
};

struct ProofCounterexample {
  std::uint64_t tick = 0;  // the violating tick
  std::vector<ProofTick> ticks;
  std::string scenario;       // the scenario JSON that replays it
  std::string scenario_file;  // where it was written ("" when it was not)
  // About the runs: "action 'Drive' has no world.json entry, so it may run any number of ticks".
  std::vector<std::string> notes;
};

struct ProofAnswer {
  std::string requirement;
  std::string text;
  SourceLocation location;
  std::string verdict;      // proved | violated | bounded | unsupported
  std::string reason;       // why not checked
  std::uint64_t depth = 0;  // violated: the tick; bounded: the depth; symbolic proved: k
  // Explicit engine, for a guarantee with a trigger: the first tick it holds (0: never).
  std::optional<std::uint64_t> first_trigger;
  std::optional<ProofCounterexample> counterexample;
  std::string method;  // symbolic proved: "k-induction" or "IC3/PDR"; else ""
};

// Why no guarantee could be proved: the world model leaves no run, or runs that cannot go on.
struct ProofVacuity {
  std::string message;
  SourceLocation location;
};

struct Proofs {
  std::string engine;                         // explicit | symbolic | none
  std::uint64_t states = 0, transitions = 0;  // explicit engine
  std::uint64_t induction_k = 0;              // symbolic engine: deepest k-induction tried
  std::uint64_t depth = 0;                    // deepest tick explored (symbolic: BMC depth)
  bool complete = false;                      // every reachable state explored
  std::string engine_reason;                  // why `--engine auto` took the symbolic engine
  std::optional<ProofVacuity> vacuity;
  std::vector<ProofAnswer> answers;
  std::vector<std::string> notes;
  // Why prove did not run at all (every answer is then "unsupported" with this reason); "".
  std::string not_run;
  // How to replay a counterexample: `uabt run MISSION RUN_OPTIONS --scenario FILE`, with the
  // mission's path as the user gave it ("" shows MISSION) and e.g. "--selection reactive".
  std::string mission_path;
  std::string run_options;
};

// "proved", "violated at tick 3", "bounded (no violation up to tick 12)", "not checked".
std::string proof_verdict_text(const ProofAnswer& answer);

// A file name for a requirement's counterexample: the id with every character other than
// letters, digits, '-', '_' and '.' replaced by '_', then ".json".
std::string counterexample_file_name(const std::string& requirement);

// What the engine covered: "explicit-state engine: 12 states, 30 transitions, every reachable
// state explored" or "symbolic engine: BMC to depth 6, k-induction up to k = 6".
std::string engine_figures(const Proofs& proofs);

// engine_figures as a sentence, with why the symbolic engine was chosen and why nothing could
// be proved when that is so (or why prove did not run). Every output format says it in these
// words.
std::string proofs_summary(const Proofs& proofs);

// The one JSON shape of the proofs: `uabt prove --format json` (with the tool, mission and
// verdict around it) and the `proofs` member of the gate's findings.json.
nlohmann::ordered_json proofs_json(const Proofs& proofs);

// The report sections (report.html and summary.md); "" when `proofs` has no answer.
std::string proofs_html(const Proofs& proofs);
std::string proofs_markdown(const Proofs& proofs);

// A whole self-contained page of the proofs (`uabt prove --format html`).
std::string proofs_page_html(const Proofs& proofs, const std::string& mission,
                             const std::string& tool_version);

// The command that replays a counterexample scenario: `uabt run MISSION [run_options]
// --scenario FILE`, MISSION as `mission_path` says ("MISSION" when it is not known).
std::string replay_command(const Proofs& proofs, const std::string& scenario_file);

}  // namespace uabt::report
