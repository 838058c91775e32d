#include <iostream>
#include <nlohmann/json.hpp>

#include "base/diagnostics.hpp"
#include "base/files.hpp"
#include "base/number_text.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "cli/findings_output.hpp"
#include "realize/realize.hpp"
#include "report/proofs.hpp"

namespace uabt::cli {

namespace {

using Json = nlohmann::ordered_json;

Json values_json(const std::vector<Value>& values) {
  Json out = Json::array();
  for (const Value& v : values) out.push_back(value_json(v));
  return out;
}

Json defeat_json(const std::vector<realize::Choice>& choices) {
  Json ticks = Json::array();
  for (const auto& c : choices) {
    ticks.push_back({{"tick", c.tick}, {"inputs", state_json(c.inputs)}});
  }
  return ticks;
}

Json decided_json(const std::optional<bool>& b) {
  return b ? Json(*b) : Json(nullptr);
}

std::vector<std::string> sorted(std::vector<std::string> ids) {
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::string json_of(const realize::Result& r) {
  Json j;
  j["realizable"] = decided_json(r.realizable);
  Json components = Json::array(), conflicts = Json::array();
  std::vector<std::vector<std::string>> all;
  Json counterexample = nullptr;
  for (const auto& c : r.components) {
    Json jc;
    jc["requirements"] = c.requirements;
    jc["realizable"] = decided_json(c.realizable);
    if (!c.realizable) jc["reason"] = c.reason;
    jc["states"] = c.states;
    if (c.realizable == false) {
      Json mine = Json::array();
      for (const auto& conflict : c.conflicts) {
        mine.push_back(sorted(conflict));
        all.push_back(sorted(conflict));
      }
      jc["conflicts"] = mine;
      jc["conflicts_complete"] = c.conflicts_complete;
      if (!c.defeating_inputs.empty()) {
        jc["defeating_inputs"] = defeat_json(c.defeating_inputs);
        if (counterexample.is_null())
          counterexample = {{"requirements", sorted(c.requirements)},
                            {"ticks", defeat_json(c.defeating_inputs)}};
      }
    }
    components.push_back(jc);
  }
  std::sort(all.begin(), all.end());
  for (const auto& conflict : all) conflicts.push_back(conflict);
  j["components"] = components;
  j["conflicts"] = conflicts;
  j["counterexample"] = counterexample;
  Json inputs = Json::array(), outputs = Json::array();
  for (const auto& s : r.signals)
    (s.role == realize::Role::input ? inputs : outputs)
        .push_back({{"name", s.name}, {"values", values_json(s.values)}, {"why", s.why}});
  j["inputs"] = inputs;
  j["outputs"] = outputs;
  j["notes"] = r.notes;
  return j.dump(2) + "\n";
}

std::string text_of(const load::Mission& m, const realize::Result& r,
                    const std::vector<std::string>& written) {
  TextOptions options;
  options.path_prefix = path_prefix_for(m.dir);
  std::string out = format_text(realize::findings_of(m, r), options);
  std::size_t unrealizable = 0, undecided = 0, conflicts = 0;
  for (const auto& c : r.components) {
    unrealizable += c.realizable == false ? 1 : 0;
    undecided += c.realizable ? 0 : 1;
    conflicts += c.conflicts.size();
  }
  for (const auto& note : r.notes) out += "note: " + note + "\n";
  for (const auto& note : written) out += "note: " + note + "\n";
  out += "realizable: " +
         std::string(r.realizable == true    ? "yes"
                     : r.realizable == false ? "no"
                                             : "not decided") +
         " (" + std::to_string(r.components.size()) + " component" +
         (r.components.size() == 1 ? "" : "s");
  if (unrealizable)
    out += ", " + std::to_string(unrealizable) + " unrealizable with " + std::to_string(conflicts) +
           " minimal conflict" + (conflicts == 1 ? "" : "s");
  if (undecided) out += ", " + std::to_string(undecided) + " not decided";
  return out + ")\n";
}

}  // namespace

// Realizability (ARCHITECTURE §15): whether any tree can meet the mission's guarantees in every
// world its assumptions allow. Exit 0 when realizable; 1 when not, or not decided (fail
// closed); 2 when the mission cannot be read.
void register_realizable(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, format = "text", output, source_root, scenarios;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "realizable",
      "Whether any behavior tree can meet the mission's guarantees in every world its "
      "assumptions allow; the minimal conflicts and the inputs that defeat every tree when not");
  add_mission_argument(*cmd, args->mission);
  cmd->add_option("--format", args->format,
                  "text | json (the verdict, conflicts and defeating inputs as data) | sarif | "
                  "junit (the findings, for code scanning and CI) | html (a page with the "
                  "conflicts as a matrix of requirements)")
      ->check(CLI::IsMember({"text", "json", "sarif", "junit", "html"}));
  add_source_root_option(*cmd, args->source_root);
  cmd->add_option("-o,--output", args->output, "write the output to FILE");
  cmd->add_option("--scenarios", args->scenarios,
                  "write each unrealizable component's defeating inputs as DIR/<requirement>.json "
                  "(a runtime scenario, named by the first requirement of its first conflict)");
  cmd->callback([args, &exit_code] {
    if (!args->scenarios.empty()) check_output_directory(args->scenarios, "--scenarios");
    auto mission = load_without_errors(args->mission, {}, exit_code);
    if (!mission) {
      if (exit_code != kExitUsage) exit_code = kExitUsage;
      return;
    }
    std::optional<prove::WorldModel> world;
    try {
      world = prove::mission_world(*mission);
    } catch (const prove::WorldError& e) {
      std::cerr << e.what() << '\n';
      exit_code = kExitUsage;
      return;
    }
    const realize::Result result = realize::check_realizability(*mission, *world);
    std::vector<std::string> written;  // what --scenarios wrote, as notes of the text output
    if (!args->scenarios.empty()) {
      make_output_directory(args->scenarios, "--scenarios");
      for (const auto& c : result.components) {
        const std::optional<std::string> scenario = realize::defeat_scenario(result, c);
        if (!scenario) continue;
        const std::string id = c.conflicts.front().front();
        const auto path =
            std::filesystem::path(args->scenarios) / report::counterexample_file_name(id);
        write_file_atomically(path, *scenario);
        written.push_back("the inputs that defeat every tree meeting " + id + "'s conflict: " +
                          path.generic_string() + " (replay them with `uabt run " + args->mission +
                          " --scenario " + path.generic_string() + "`)");
      }
    }
    if (args->format == "sarif" || args->format == "junit" || args->format == "html") {
      report::ReportInput input =
          report::ReportInput::of(*mission, tool_version(), {"load", "realize"});
      const std::vector<Finding> found = realize::findings_of(*mission, result);
      input.findings.insert(input.findings.end(), found.begin(), found.end());
      sort_findings(input.findings);
      input.uri_prefix = sarif_uri_prefix(args->mission, args->source_root);
      write_findings(input, args->format, args->output);
    } else {
      emit(args->output,
           args->format == "json" ? json_of(result) : text_of(*mission, result, written));
    }
    exit_code = result.realizable == true ? kExitPass : kExitFail;
  });
}

}  // namespace uabt::cli
