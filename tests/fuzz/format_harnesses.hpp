#pragma once
// The checks behind fuzz_world, fuzz_uplink, fuzz_scenario, fuzz_scenario_uplink and fuzz_trace,
// shared with test_hardening's replay of their inputs. Each harness writes a small fixed mission
// (the drilling sample: one adaptable node, two alternatives, guarantees, a domain) into a
// temporary directory once, then runs one input through the entry point a command uses and
// returns "" when every invariant holds, otherwise what went wrong.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "base/finding.hpp"
#include "bt/xml_io.hpp"
#include "fretish/durations.hpp"
#include "fretish/parse.hpp"
#include "fuzz/entry_points.hpp"
#include "fuzz/pipeline_harness.hpp"
#include "gate/gate.hpp"
#include "gate/uplink.hpp"
#include "load/mission.hpp"
#include "manager/manager.hpp"
#include "monitor/check_trace.hpp"
#include "monitor/trace.hpp"
#include "prove/prove.hpp"
#include "prove/world_model.hpp"
#include "runtime/runner.hpp"
#include "runtime/scenario.hpp"
#include "runtime/scenario_check.hpp"
#include "runtime/trace.hpp"

namespace uabt::fuzz {

namespace detail {

// The drilling sample (missions/sample_drilling) without its world.json; `requirements`
// replaces its requirements.fret.
inline void write_drilling(const TempMission& m, const std::string& requirements) {
  m.write("mission.xml",
          "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
          "  <BehaviorTree ID=\"MainTree\">\n"
          "    <Repeat num_cycles=\"3\">\n"
          "      <Adaptable ID=\"drilling\"/>\n"
          "    </Repeat>\n"
          "  </BehaviorTree>\n"
          "</root>\n");
  m.write("alternatives/drilling/percussive.xml",
          "<root BTCPP_format=\"4\" main_tree_to_execute=\"percussive\">\n"
          "  <BehaviorTree ID=\"percussive\">\n"
          "    <Sequence>\n"
          "      <Fallback>\n"
          "        <IsBitCool/>\n"
          "        <CoolDown/>\n"
          "      </Fallback>\n"
          "      <Drill name=\"Drill\" mode=\"percussive\"/>\n"
          "    </Sequence>\n"
          "  </BehaviorTree>\n"
          "</root>\n");
  m.write("alternatives/drilling/rotary.xml",
          "<root BTCPP_format=\"4\" main_tree_to_execute=\"rotary\">\n"
          "  <BehaviorTree ID=\"rotary\">\n"
          "    <Sequence>\n"
          "      <Drill name=\"Drill\" mode=\"rotary\"/>\n"
          "    </Sequence>\n"
          "  </BehaviorTree>\n"
          "</root>\n");
  m.write("domain.fret", "boolean HardRock, IsBitCool\n");
  m.write("requirements.fret", requirements);
}

inline const std::string kDrillingRequirements =
    "Hard: In drilling if HardRock Mission shall satisfy selected_alt = percussive\n"
    "Soft: In drilling Mission shall satisfy selected_alt = rotary\n"
    "CoolBit: Mission shall always satisfy Drill.running -> IsBitCool\n"
    "OneTool: Mission shall always satisfy !(Drill.running & CoolDown.running)\n";

// The drilling sample with the guarantees it proves (CoolBit, which rotary breaks, left out),
// on which an uplink can pass the gate; kCoolRequirements is a package's requirements.fret
// that passes it when placed before Soft.
inline void write_uplink_drilling(const TempMission& m) {
  write_drilling(m,
                 "Hard: In drilling if HardRock Mission shall satisfy selected_alt = percussive\n"
                 "Soft: In drilling Mission shall satisfy selected_alt = rotary\n"
                 "OneTool: Mission shall always satisfy !(Drill.running & CoolDown.running)\n");
}

inline const std::string kCoolRequirements =
    "Cool: In drilling if !HardRock & !IsBitCool Mission shall satisfy selected_alt = percussive\n"
    "OneTool: Mission shall always satisfy !(Drill.running & CoolDown.running)\n";

inline std::string located(const SourceLocation& l) {
  return l.file + ":" + std::to_string(l.line) + ":" + std::to_string(l.column);
}

// `message` starts with "file:line:col: " for a line that exists in `text`.
inline std::string check_message_location(const std::string& message, const std::string& file,
                                          std::string_view text) {
  const std::string prefix = file + ":";
  if (message.rfind(prefix, 0) != 0)
    return "error '" + message + "' does not start with '" + prefix + "'";
  int line = 0, column = 0, used = 0;
  if (std::sscanf(message.c_str() + prefix.size(), "%d:%d: %n", &line, &column, &used) < 2 ||
      used == 0)
    return "error '" + message + "' names no line:column of " + file;
  if (line < 1 || line > line_count(text) || column < 1)
    return "error '" + message + "' is at " + std::to_string(line) + ":" + std::to_string(column) +
           " of a text of " + std::to_string(line_count(text)) + " lines";
  return {};
}

// `text` as the scenario `file`, or nothing when parse_scenario refuses it; then `problem` says
// what is wrong with the refusal ("" when it names the file at an existing line:col).
inline std::optional<runtime::Scenario> parse_scenario_located(const std::string& text,
                                                               const char* file,
                                                               std::string& problem) {
  try {
    return runtime::parse_scenario(text, file);
  } catch (const runtime::ScenarioError& e) {
    problem = check_message_location(e.what(), file, text);
    return std::nullopt;
  }
}

// Every finding located in `file` is at a line that exists in `text`, with a column; errors
// there must have a line.
inline std::string check_findings_in(const std::vector<Finding>& findings, const std::string& file,
                                     std::string_view text) {
  for (const Finding& f : findings) {
    if (f.location.file != file) continue;
    const bool needs_line = f.severity == Severity::error;
    if ((needs_line && f.location.line < 1) || f.location.line > line_count(text) ||
        (f.location.line > 0 && f.location.column < 1))
      return "finding '" + f.message + "' [" + f.check + "] is at " + located(f.location) +
             " of a text of " + std::to_string(line_count(text)) + " lines";
  }
  return {};
}

// A gated, compiled mission and its vocabulary: what `uabt prove` and `uabt run` start from.
struct CompiledMission {
  std::unique_ptr<load::Mission> mission;
  std::optional<bt::Document> compiled;
  runtime::ScenarioVocabulary vocabulary;

  explicit CompiledMission(const std::filesystem::path& dir) {
    std::string error;
    auto loaded = load::load_mission(dir, {}, error);
    if (!loaded) return;
    mission = std::make_unique<load::Mission>(*loaded);
    vocabulary.add(*mission);
    gate::Outcome outcome = gate::check_mission(std::move(*loaded), {}, "fuzz");
    std::vector<Finding> findings;
    if (!outcome.compiled_xml.empty())
      compiled = bt::parse_document(outcome.compiled_xml, "compiled.xml", findings);
  }
  bool ready() const { return mission && compiled; }
};

}  // namespace detail

// world.json for the drilling sample: parse_world against the mission (as `uabt prove` and the
// gate's proof step read it). A refused file throws WorldError at an existing line:col of
// world.json, never anything else. An accepted one is written back as JSON and read again to
// the same model, and a bounded proof in it gives counterexamples whose scenarios fit the
// mission.
class WorldHarness {
 public:
  WorldHarness() {
    detail::write_drilling(dir_, detail::kDrillingRequirements);
    compiled_ = std::make_unique<detail::CompiledMission>(dir_.dir());
  }
  const std::filesystem::path& dir() const { return dir_.dir(); }

  std::string check(std::string_view data, std::size_t max_states = 4000) const {
    if (!compiled_->ready()) return "the fixed mission does not compile";
    const load::Mission& mission = *compiled_->mission;
    const std::string text(data);
    prove::WorldModel world;
    try {
      world = prove::parse_world(text, "world.json", &mission);
    } catch (const prove::WorldError& e) {
      if (e.location.file != "world.json")
        return "world error '" + std::string(e.what()) + "' names '" + e.location.file + "'";
      return detail::check_message_location(e.what(), "world.json", text);
    }
    // Written back and read again: the same model.
    const std::string written = write(world);
    try {
      const prove::WorldModel again = prove::parse_world(written, "world.json", &mission);
      if (write(again) != written)
        return "world.json written back reads as another model:\n" + written + "\nthen\n" +
               write(again);
    } catch (const prove::WorldError& e) {
      return "world.json written back is refused: " + std::string(e.what()) + "\n" + written;
    }
    prove::Options options;
    options.engine = "explicit";
    options.max_states = max_states;
    prove::Result result;
    try {
      result = prove::prove(mission, *compiled_->compiled, world, options);
    } catch (const prove::WorldError& e) {
      if (std::string p = detail::check_message_location(e.what(), "world.json", text); !p.empty())
        return "during the proof: " + p;
      return {};
    } catch (const std::exception& e) {
      // A world prove cannot model is refused in words (the gate and `uabt prove` report it);
      // a counterexample its replay disagrees with is uabt's fault.
      if (std::string_view(e.what()).find("internal error") != std::string_view::npos)
        return std::string("prove: ") + e.what();
      return {};
    }
    for (const prove::Answer& a : result.answers) {
      if (a.verdict == prove::Verdict::violated && !a.counterexample)
        return "guarantee " + a.requirement + " violated without a counterexample";
      if (!a.counterexample) continue;
      try {
        const runtime::Scenario s =
            runtime::parse_scenario(a.counterexample->scenario, "counterexample.json");
        const auto misfits = runtime::check_scenario(s, compiled_->vocabulary);
        if (!misfits.empty())
          return "the counterexample of " + a.requirement +
                 " does not fit the mission: " + misfits.front();
      } catch (const runtime::ScenarioError& e) {
        return "the counterexample of " + a.requirement + " is no scenario: " + e.what();
      }
    }
    return {};
  }

  // The model as world.json (the scripts as written, the initial expression printed).
  static std::string write(const prove::WorldModel& w) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    if (w.initial) j["initial"] = fretish::to_fretish(*w.initial);
    nlohmann::ordered_json actions = nlohmann::ordered_json::object();
    for (const auto& [name, c] : w.actions) {
      nlohmann::ordered_json a;
      a["ticks"] = {c.min_ticks, c.max_ticks};
      nlohmann::ordered_json results = nlohmann::ordered_json::array();
      for (const auto r : c.results)
        results.push_back(r == runtime::NodeStatus::success ? "success" : "failure");
      a["results"] = results;
      if (!c.on_success.empty()) a["on_success"] = c.on_success;
      if (!c.on_failure.empty()) a["on_failure"] = c.on_failure;
      actions[name] = a;
    }
    j["actions"] = actions;
    return j.dump(1) + "\n";
  }

 private:
  detail::TempMission dir_{"drilling"};
  std::unique_ptr<detail::CompiledMission> compiled_;
};

// uplink.json inside a package (uplinks/fuzz/, with a fixed requirements.fret) on a drilling
// mission that passes the gate: load_mission merges it as `gate --uplink` does, then
// run_uplink_gate (the gate, its proof step, the guarantees as the mission's contract).
// Findings about uplink.json are at an existing line:col; a mistake in it never lets the gate
// pass; a placement or removal that was accepted shows in the merged order; loading twice
// merges the same way.
class UplinkHarness {
 public:
  static constexpr const char* kFile = "uplinks/fuzz/uplink.json";

  UplinkHarness() {
    detail::write_uplink_drilling(dir_);
    dir_.write("uplinks/fuzz/requirements.fret", detail::kCoolRequirements);
    std::string error;
    if (auto m = load::load_mission(dir_.dir(), {}, error))
      running_ = std::make_unique<load::Mission>(std::move(*m));
  }
  const std::filesystem::path& dir() const { return dir_.dir(); }

  std::string check(std::string_view data, unsigned timeout_ms = 500) const {
    if (!running_ || has_errors(running_->findings)) return "the fixed mission does not load";
    const std::string text(data);
    dir_.write(kFile, text);
    load::LoadOptions options;
    options.uplinks.push_back(dir_.dir() / "uplinks" / "fuzz");
    std::string error;
    auto merged = load::load_mission(dir_.dir(), options, error);
    if (!merged) return "the mission did not load: " + error;
    if (std::string p = detail::check_findings_in(merged->findings, kFile, text); !p.empty())
      return p;
    bool uplink_errors = false;
    for (const Finding& f : merged->findings) {
      if (f.check != "uplink-invalid") continue;
      if (f.location.file.rfind("uplinks/fuzz/", 0) != 0)
        return "uplink finding '" + f.message + "' names '" + f.location.file + "'";
      uplink_errors |= f.severity == Severity::error;
    }
    if (std::string p = check_merges(*merged); !p.empty()) return p;
    // Loading the same package again merges it the same way.
    auto again = load::load_mission(dir_.dir(), options, error);
    if (!again) return "the mission did not load a second time: " + error;
    if (ids(*again) != ids(*merged) || again->findings.size() != merged->findings.size())
      return "loading the same uplink twice merged it differently";

    // The gate depends only on the merged mission: one that was gated already (many inputs
    // merge the same way) is not gated again, which keeps the target fast.
    const std::string key = merged_state(*merged);
    if (const auto seen = gated_.find(key); seen != gated_.end()) return seen->second;
    gate::Options gate_options;
    gate_options.verify.timeout_ms = timeout_ms;
    gate_options.verify.threads = 1;
    gate_options.conform.timeout_ms = timeout_ms;
    gate_options.prove.max_states = 20000;
    const bool load_errors = has_errors(merged->findings);
    const gate::Outcome outcome =
        gate::run_uplink_gate(*running_, std::move(*merged), gate_options, "fuzz");
    std::string problem = check_gate(outcome, uplink_errors, load_errors);
    if (gated_.size() < 100000) gated_.emplace(key, problem);
    return problem;
  }

 private:
  static std::vector<std::string> ids(const load::Mission& m) {
    std::vector<std::string> out;
    for (const auto& r : m.requirements) out.push_back(r.id);
    return out;
  }

  static std::string check_gate(const gate::Outcome& outcome, bool uplink_errors,
                                bool load_errors) {
    if (outcome.passed() && uplink_errors)
      return "the uplink gate passed although uplink.json has an error";
    if (std::string p = PipelineHarness::check_outcome(outcome, load_errors); !p.empty()) return p;
    for (const Finding& f : outcome.report.findings) {
      if (f.severity == Severity::error && f.location.file.empty())
        return "error finding '" + f.message + "' [" + f.check + "] names no file";
    }
    return {};
  }

  // What the gate sees of a merge: requirements in order, merge records, consents, findings.
  static std::string merged_state(const load::Mission& m) {
    std::string out;
    for (const auto& r : m.requirements) out += r.id + "\n" + r.text + "\n";
    for (const auto& merge : m.merges)
      out += "merge " + merge.requirement + " " + merge.rule + " " + merge.relation + " " +
             merge.anchor + "\n";
    for (const auto& c : m.consents)
      out += "consent " + c.kind + " " + c.requirement + (c.reason.empty() ? "" : " why") + "\n";
    // Findings by check and severity only: the loader's words (a misspelt id, a place in the
    // file) change nothing the gate decides.
    std::set<std::string> kinds;
    for (const Finding& f : m.findings)
      kinds.insert(f.check + (f.severity == Severity::error ? " error" : ""));
    for (const std::string& k : kinds) out += "finding " + k + "\n";
    return out;
  }

  // Each accepted "placed" record stands before/after its anchor; a removed id is gone.
  static std::string check_merges(const load::Mission& m) {
    if (has_errors(m.findings)) return {};
    const std::vector<std::string> order = ids(m);
    auto index = [&](const std::string& id) {
      return std::find(order.begin(), order.end(), id) - order.begin();
    };
    const auto end = static_cast<std::ptrdiff_t>(order.size());
    for (const load::UplinkMerge& merge : m.merges) {
      if (merge.rule == "removed" && index(merge.requirement) != end)
        return "requirement " + merge.requirement + " was removed but is still there";
      if (merge.rule != "placed") continue;
      const auto at = index(merge.requirement), anchor = index(merge.anchor);
      if (at == end || anchor == end)
        return "requirement " + merge.requirement + " was placed " + merge.relation + " " +
               merge.anchor + " but one of them is missing";
      if ((merge.relation == "before") != (at < anchor))
        return "requirement " + merge.requirement + " was placed " + merge.relation + " " +
               merge.anchor + " but stands at " + std::to_string(at) + ", the anchor at " +
               std::to_string(anchor);
    }
    return {};
  }

  detail::TempMission dir_{"drilling"};
  std::unique_ptr<load::Mission> running_;
  mutable std::map<std::string, std::string> gated_;  // merged state -> the gate's problem
};

// A scenario (scenarios/*.json) for the drilling sample: parse_scenario, check_scenario
// against the mission (as `uabt run` checks it), then a run of at most 40 ticks on the compiled
// tree. Every error names scenarios/fuzz.json at an existing line:col; a run ends with a known
// verdict within its bound, and running it twice gives the same run.
class ScenarioHarness {
 public:
  static constexpr const char* kFile = "scenarios/fuzz.json";
  static constexpr std::int64_t kMaxTicks = 40;

  ScenarioHarness() {
    detail::write_drilling(dir_, detail::kDrillingRequirements);
    compiled_ = std::make_unique<detail::CompiledMission>(dir_.dir());
  }

  std::string check(std::string_view data) const {
    if (!compiled_->ready()) return "the fixed mission does not compile";
    const std::string text(data);
    std::string refused;
    const auto parsed = detail::parse_scenario_located(text, kFile, refused);
    if (!parsed) return refused;
    const runtime::Scenario& scenario = *parsed;
    for (const std::string& misfit : runtime::check_scenario(scenario, compiled_->vocabulary))
      if (std::string p = detail::check_message_location(misfit, kFile, text); !p.empty()) return p;
    if (!runtime::check_scenario(scenario, compiled_->vocabulary).empty()) return {};
    runtime::RunOptions options;
    options.max_ticks = std::min(scenario.max_ticks, kMaxTicks);
    const runtime::RunResult first = run(scenario, options);
    const runtime::RunResult second = run(scenario, options);
    static const std::vector<std::string> verdicts = {"success", "failure", "skipped", "timeout",
                                                      "error"};
    if (std::find(verdicts.begin(), verdicts.end(), first.verdict) == verdicts.end())
      return "the run ended with the verdict '" + first.verdict + "'";
    if (first.ticks > static_cast<std::uint64_t>(options.max_ticks))
      return "the run took " + std::to_string(first.ticks) + " ticks, more than its bound " +
             std::to_string(options.max_ticks);
    if (first.verdict == "error" && !first.error) return "an error verdict without its error";
    if (first.verdict != second.verdict || first.ticks != second.ticks ||
        first.log.size() != second.log.size())
      return "the same scenario ran twice differently: " + first.verdict + " after " +
             std::to_string(first.ticks) + " ticks, then " + second.verdict + " after " +
             std::to_string(second.ticks);
    return {};
  }

 private:
  runtime::RunResult run(const runtime::Scenario& scenario,
                         const runtime::RunOptions& options) const {
    runtime::Runner runner(*compiled_->compiled, scenario, options);
    return runner.run();
  }

  detail::TempMission dir_{"drilling"};
  std::unique_ptr<detail::CompiledMission> compiled_;
};

// A scenario with uplink events for the drilling sample, run as `uabt run` runs it: the Behavior
// Tree Manager admits the mission, checks the scenario against it and every package it names,
// and takes each due uplink through the gate mid-run (at most 40 ticks). Three fixed packages:
// uplinks/cool adds a requirement and passes, uplinks/overlap adds one that overlaps Hard and
// fails, uplinks/rotary_v2 is a new version of an alternative and passes. Every error names
// scenarios/fuzz.json at an existing line:col; a run ends with a known verdict within its
// bound; the due uplink events are traced in order, each at its tick, accepted without findings
// or rejected with located errors; the first one is decided as `uabt gate --uplink` decides its
// package on the starting mission, and uplinks/overlap is never accepted; the accepted ones are
// the run's accepted uplinks, and a property an uplink added is monitored from an accepted
// uplink's tick; the same scenario runs twice to the same trace and property verdicts.
class ScenarioUplinkHarness {
 public:
  static constexpr const char* kFile = "scenarios/fuzz.json";
  static constexpr std::int64_t kMaxTicks = 40;

  ScenarioUplinkHarness() {
    detail::write_uplink_drilling(dir_);
    dir_.write("uplinks/cool/requirements.fret", detail::kCoolRequirements);
    dir_.write("uplinks/cool/uplink.json", "{\"place\": {\"Cool\": {\"before\": \"Soft\"}}}\n");
    dir_.write("uplinks/overlap/requirements.fret",
               "Rock: In drilling if HardRock Mission shall satisfy selected_alt = rotary\n");
    dir_.write("uplinks/rotary_v2/alternatives/drilling/rotary.xml",
               "<root BTCPP_format=\"4\" main_tree_to_execute=\"rotary\">\n"
               "  <BehaviorTree ID=\"rotary\">\n"
               "    <Sequence>\n"
               "      <Fallback>\n"
               "        <IsBitCool/>\n"
               "        <CoolDown/>\n"
               "      </Fallback>\n"
               "      <Drill name=\"Drill\" mode=\"rotary\"/>\n"
               "    </Sequence>\n"
               "  </BehaviorTree>\n"
               "</root>\n");
    // What `uabt gate MISSION --uplink DIR` decides for each package on the starting mission.
    std::string error;
    const auto running = load::load_mission(dir_.dir(), {}, error);
    if (!running) return;
    for (const std::string package : {"uplinks/cool", "uplinks/overlap", "uplinks/rotary_v2"}) {
      load::LoadOptions with;
      with.uplinks.push_back(dir_.dir() / package);
      if (auto merged = load::load_mission(dir_.dir(), with, error))
        alone_[package] =
            gate::run_uplink_gate(*running, std::move(*merged), gate_options(), "fuzz").passed();
    }
  }
  const std::filesystem::path& dir() const { return dir_.dir(); }
  // The gate's verdict on `package` alone on the starting mission (false when unknown).
  bool passes_alone(const std::string& package) const {
    const auto it = alone_.find(package);
    return it != alone_.end() && it->second;
  }

  std::string check(std::string_view data) const {
    if (alone_.size() != 3) return "the fixed mission or its packages do not load";
    const std::string text(data);
    std::string refused;
    const auto parsed = detail::parse_scenario_located(text, kFile, refused);
    if (!parsed) return refused;
    const runtime::Scenario& scenario = *parsed;
    manager::ManagerOptions options;
    options.gate = gate_options();
    options.max_ticks = std::min(scenario.max_ticks, kMaxTicks);
    manager::ManagerRun first;
    try {
      first = manager::BehaviorTreeManager(dir_.dir(), scenario, options).run();
    } catch (const runtime::ScenarioError& e) {
      // One "file:line:col: error: …" line per misfit.
      const std::string what = e.what();
      for (std::size_t at = 0; at < what.size();) {
        const std::size_t end = std::min(what.find('\n', at), what.size());
        if (std::string p = detail::check_message_location(what.substr(at, end - at), kFile, text);
            !p.empty())
          return p;
        at = end + 1;
      }
      return {};
    } catch (const manager::NotAdmitted& e) {
      return "the mission was not admitted: " + detail::first_error(e.findings);
    }
    if (std::string p = check_run(scenario, first, options.max_ticks); !p.empty()) return p;
    const manager::ManagerRun second =
        manager::BehaviorTreeManager(dir_.dir(), scenario, options).run();
    if (summary(first) != summary(second))
      return "the same scenario ran twice differently:\n" + summary(first) + "then\n" +
             summary(second);
    return {};
  }

 private:
  static gate::Options gate_options() {
    gate::Options options;
    options.verify.threads = 1;
    options.prove.max_states = 20000;
    return options;
  }

  static std::string summary(const manager::ManagerRun& run) {
    return manager::trace_summary(run) + manager::property_summary(run) +
           "verdict: " + run.verdict + "\n";
  }

  std::string check_run(const runtime::Scenario& scenario, const manager::ManagerRun& run,
                        std::int64_t max_ticks) const {
    static const std::vector<std::string> verdicts = {"success", "failure", "skipped", "timeout",
                                                      "error"};
    if (std::find(verdicts.begin(), verdicts.end(), run.verdict) == verdicts.end())
      return "the run ended with the verdict '" + run.verdict + "'";
    if (run.ticks > static_cast<std::uint64_t>(max_ticks))
      return "the run took " + std::to_string(run.ticks) + " ticks, more than its bound " +
             std::to_string(max_ticks);
    if ((run.verdict == "error") != run.error.has_value())
      return "the verdict '" + run.verdict + "' and the run's error disagree";
    std::vector<const runtime::ScenarioEvent*> due;
    for (const runtime::ScenarioEvent& e : scenario.events)
      if (!e.uplink.empty()) due.push_back(&e);
    std::vector<std::string> accepted;
    std::set<std::uint64_t> accepted_ticks;
    std::size_t n = 0;
    for (const runtime::TraceEvent& e : run.trace) {
      if (e.event != "uplink") continue;
      if (n == due.size()) return "an uplink event no scenario event asked for: " + e.uplink;
      const runtime::ScenarioEvent& asked = *due[n];
      const auto at = static_cast<std::uint64_t>(std::max<std::int64_t>(asked.at, 1));
      if (e.uplink != asked.uplink || e.tick != at)
        return "uplink event " + std::to_string(n) + " is " + e.uplink + " at tick " +
               std::to_string(e.tick) + ", the scenario asked for " + asked.uplink + " at " +
               std::to_string(at);
      if (e.verdict == "accepted") {
        if (!e.findings.empty()) return "uplink " + e.uplink + " accepted with findings";
        if (e.uplink == "uplinks/overlap") return "uplinks/overlap was accepted";
        accepted.push_back(e.uplink);
        accepted_ticks.insert(e.tick);
      } else if (e.verdict == "rejected") {
        if (e.findings.empty()) return "uplink " + e.uplink + " rejected without a finding";
        for (const Finding& f : e.findings)
          if (f.severity != Severity::error || f.location.file.empty() || f.location.line < 0)
            return "uplink " + e.uplink + " rejected with '" + f.message + "' [" + f.check +
                   "] at '" + detail::located(f.location) + "'";
      } else {
        return "uplink " + e.uplink + " has the verdict '" + e.verdict + "'";
      }
      if (n == 0 && alone_.count(e.uplink) && (e.verdict == "accepted") != passes_alone(e.uplink))
        return "the first uplink, " + e.uplink + ", was " + e.verdict + " mid-run but the gate " +
               (passes_alone(e.uplink) ? "passes" : "rejects") + " it on the starting mission";
      ++n;
    }
    for (std::size_t i = n; i < due.size(); ++i)
      if (due[i]->at <= static_cast<std::int64_t>(run.ticks))
        return "the uplink " + due[i]->uplink + " due at tick " + std::to_string(due[i]->at) +
               " of a run of " + std::to_string(run.ticks) + " ticks was not taken";
    if (run.accepted_uplinks != accepted)
      return "the run's accepted uplinks are not those its trace accepts";
    for (const monitor::PropertyResult& p : run.properties)
      if (p.monitored_from && accepted_ticks.count(*p.monitored_from) == 0)
        return "property " + p.id + " is monitored from tick " + std::to_string(*p.monitored_from) +
               ", when no uplink was accepted";
    return {};
  }

  detail::TempMission dir_{"drilling"};
  std::map<std::string, bool> alone_;  // package -> passes the gate on the starting mission
};

// A monitor trace (JSON lines, `uabt monitor` and `run --monitor-trace`): read_trace, then
// check_trace on fixed requirements and a fixed domain, as `uabt monitor` does. Every finding
// in the trace is at an existing line; a refused trace has an error; an accepted one, written
// back line by line, reads again to the same ticks and the same verdicts, and the JSON report
// parses.
class TraceHarness {
 public:
  static constexpr const char* kFile = "trace.jsonl";
  static constexpr const char* kRequirements =
      "CoolBit: Mission shall always satisfy Drill.running -> IsBitCool\n"
      "Cools: Mission shall always satisfy !IsBitCool -> CoolDown.running\n"
      "Within: Mission shall within 3 ticks satisfy depth > 2\n"
      "Until: Mission shall until HardRock satisfy tool = rotary\n"
      "After: after HardRock Mission shall immediately satisfy tool = percussive\n"
      "Eventually: Mission shall eventually satisfy depth >= 10 & temperature < 40.5\n";
  static constexpr const char* kDomain =
      "boolean HardRock, IsBitCool\n"
      "integer depth in [0, 20]\n"
      "real temperature\n"
      "enum tool in {rotary, percussive}\n"
      "assume Depth: depth <= 20\n";

  TraceHarness() {
    fretish::ParseResult parsed =
        fretish::parse_requirements_file(kRequirements, "requirements.fret");
    requirements_ = std::move(parsed.requirements);
    std::vector<Finding> findings;
    domain_ = fretish::parse_domain_file(kDomain, "domain.fret", findings);
    fretish::lower_durations(requirements_, domain_.tick_seconds, findings);
    findings.insert(findings.end(), parsed.findings.begin(), parsed.findings.end());
    if (has_errors(findings)) setup_error_ = detail::first_error(findings);
  }

  std::string check(std::string_view data) const {
    if (!setup_error_.empty()) return "the fixed requirements do not parse: " + setup_error_;
    const std::string text(data);
    std::vector<Finding> findings;
    const std::optional<monitor::Trace> trace = monitor::read_trace(text, kFile, findings);
    if (std::string p = detail::check_findings_in(findings, kFile, text); !p.empty()) return p;
    if (!trace) return has_errors(findings) ? "" : "a trace refused without an error";
    if (has_errors(findings)) return "a trace with an error was accepted";
    const monitor::TraceReport report =
        monitor::check_trace(requirements_, domain_, *trace, kFile, findings);
    if (std::string p = detail::check_findings_in(findings, kFile, text); !p.empty()) return p;
    if (!nlohmann::json::accept(monitor::trace_report_json(report)))
      return "the JSON report does not parse";
    // Written back in the canonical form: the same ticks, the same verdicts.
    const std::string written = write(*trace);
    std::vector<Finding> again_findings;
    const auto again = monitor::read_trace(written, kFile, again_findings);
    if (!again) return "the trace written back is refused:\n" + written;
    if (write(*again) != written) return "the trace written back reads differently";
    const monitor::TraceReport again_report =
        monitor::check_trace(requirements_, domain_, *again, kFile, again_findings);
    if (monitor::trace_report_text(again_report) != monitor::trace_report_text(report))
      return "the trace written back has other verdicts:\n" + monitor::trace_report_text(report) +
             "then\n" + monitor::trace_report_text(again_report);
    return {};
  }

  static nlohmann::ordered_json values(
      const std::vector<std::pair<std::string, monitor::TraceValue>>& list) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const auto& [name, v] : list) {
      switch (v.kind) {
        case monitor::TraceValue::Kind::boolean: out[name] = v.boolean; break;
        case monitor::TraceValue::Kind::text: out[name] = v.text; break;
        case monitor::TraceValue::Kind::none: out[name] = nullptr; break;  // no value
        case monitor::TraceValue::Kind::number:
          // Integers as integers (a double holds those the reader gave exactly).
          if (v.integer && v.number >= 0 && v.number < 1.8e19)
            out[name] = static_cast<std::uint64_t>(v.number);
          else if (v.integer && v.number < 0 && v.number >= -9.2e18)
            out[name] = static_cast<std::int64_t>(v.number);
          else
            out[name] = v.number;
          break;
      }
    }
    return out;
  }

  static std::string write(const monitor::Trace& trace) {
    using Json = nlohmann::ordered_json;
    std::string out;
    for (const monitor::TraceTick& t : trace.ticks) {
      if (!t.adaptables.empty()) {
        Json nodes = Json::object();
        for (const auto& a : t.adaptables)
          nodes[a.id] = {{"alternatives", a.alternatives}, {"requirements", a.requirements}};
        out += Json{{"selection", nodes}}.dump() + "\n";
      }
      Json line;
      line["tick"] = t.tick;
      line["state"] = values(t.state);
      if (!t.selections.empty()) {
        Json select = Json::object();
        for (const auto& s : t.selections) {
          Json one = {{"alternative", s.alternative}, {"read", values(s.read)}};
          if (!s.after.empty()) one["after"] = s.after;
          if (!select.contains(s.adaptable)) select[s.adaptable] = Json::array();
          select[s.adaptable].push_back(one);
        }
        line["select"] = select;
      }
      out += line.dump() + "\n";
    }
    return out;
  }

 private:
  std::vector<fretish::Requirement> requirements_;
  fretish::Domain domain_;
  std::string setup_error_;
};

// The body of a libFuzzer target over `Harness`: a broken invariant aborts with its message.
template <class Harness>
int run_target(const char* name, const std::uint8_t* data, std::size_t size) {
  static const Harness harness;  // the fixed mission, written once
  const std::string problem =
      harness.check(std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "%s: invariant violated: %s\n", name, problem.c_str());
    std::abort();
  }
  return 0;
}

}  // namespace uabt::fuzz
