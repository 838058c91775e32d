#include <iostream>

#include "base/diagnostics.hpp"
#include "base/files.hpp"
#include "cli/commands.hpp"
#include "cli/common.hpp"
#include "cli/findings_output.hpp"
#include "gate/gate.hpp"
#include "gate/proof_report.hpp"
#include "gate/proofs.hpp"
#include "report/text.hpp"

namespace uabt::cli {

namespace {

std::string summary_line(const prove::Result& r, const report::Proofs& proofs) {
  int counts[5] = {0, 0, 0, 0, 0};
  for (const auto& a : r.answers) ++counts[static_cast<int>(a.verdict)];
  std::string line = "prove: " + std::to_string(r.answers.size()) + " guarantee" +
                     (r.answers.size() == 1 ? "" : "s") + ": " + std::to_string(counts[0]) +
                     " proved, " + std::to_string(counts[1]) + " violated, " +
                     std::to_string(counts[2]) + " bounded";
  if (counts[3]) line += ", " + std::to_string(counts[3]) + " vacuous";
  if (counts[4]) line += ", " + std::to_string(counts[4]) + " not checked";
  return line + " (" + report::engine_figures(proofs) + ")";
}

// What a proof covered: the reachable runs' size, and when the guarantee first asks something.
std::string proof_extent(const prove::Result& r, const prove::Answer& a) {
  std::string out =
      r.engine == "symbolic"
          ? (a.by_pdr ? "IC3/PDR, Z3's Spacer" : "k-induction with k = " + std::to_string(a.depth))
          : "over " + std::to_string(r.states) + " reachable states and " +
                std::to_string(r.transitions) + " transitions";
  if (a.has_trigger && a.trigger_decided)
    out += a.first_trigger == 0
               ? "; its trigger never holds"
               : "; its trigger first holds at tick " + std::to_string(a.first_trigger);
  return out;
}

}  // namespace

// Model checking (ARCHITECTURE §10): every guarantee over every run of the compiled mission in the
// world model. Exit 0 when every guarantee is proved, 1 otherwise (violated, bounded, not
// checked, or the mission does not load or compile), 2 on a bad command line or world.json.
void register_prove(CLI::App& app, int& exit_code) {
  struct Args {
    std::string mission, format = "text", output, counterexamples, selection, engine = "auto";
    std::uint64_t depth = 0;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "prove", "Prove the mission's guarantees on every run its world model allows");
  add_mission_argument(*cmd, args->mission);
  add_number_option(
      *cmd, "--depth", 1, kMaxProveDepth,
      "explore runs of up to this many ticks (default: until every reachable state is seen; "
      "the symbolic engine: 40)",
      [args](std::int64_t ticks) { args->depth = static_cast<std::uint64_t>(ticks); });
  cmd->add_option("--engine", args->engine,
                  "auto | explicit (state enumeration) | symbolic (Z3: BMC and k-induction)")
      ->check(CLI::IsMember({"auto", "explicit", "symbolic"}));
  cmd->add_option("--selection", args->selection, kSelectionHelp)
      ->check(CLI::IsMember({"sequence", "reactive", "optimized"}));
  cmd->add_option("--counterexamples", args->counterexamples,
                  "write each counterexample as DIR/<requirement>.json (a runtime scenario)");
  cmd->add_option("--format", args->format,
                  "text | json | sarif | html (a page with each counterexample's timeline)")
      ->check(CLI::IsMember({"text", "json", "sarif", "html"}));
  cmd->add_option("-o,--output", args->output, "write the output to FILE");
  cmd->callback([args, &exit_code] {
    if (!args->counterexamples.empty())
      check_output_directory(args->counterexamples, "--counterexamples");
    auto mission = load_without_errors(args->mission, {}, exit_code);
    if (!mission) return;
    gate::Options gate_options;
    apply_selection(args->selection, gate_options.compile);
    gate::Outcome outcome = gate::check_mission(std::move(*mission), gate_options, tool_version());
    if (outcome.compiled_xml.empty()) {
      std::cerr << "uabt: the mission does not compile; nothing to prove\n"
                << format_text(outcome.report.findings);
      exit_code = kExitFail;
      return;
    }
    // Nothing to explore: say so rather than report an engine's figures over no property
    // (SARIF and HTML are simply empty then).
    if (!prove::has_guarantees(*outcome.mission) &&
        (args->format == "text" || args->format == "json")) {
      exit_code = kExitPass;
      prove::Result none;
      none.engine = "none";
      none.complete = true;
      emit(args->output,
           args->format == "json"
               ? gate::result_json(none, gate::report_proofs(none), outcome.mission->name,
                                   tool_version())
               : "prove: " + outcome.mission->name +
                     " states no guarantees (requirements that choose no alternative and are "
                     "not about the Environment): nothing to prove\n");
      return;
    }
    // Every message names the lines the user wrote: a node of the compiled tree (which prove
    // holds in memory and never writes) by the place it comes from (prove_checked), and, in
    // text, every file as opened from the current directory, as `uabt verify` names them.
    const std::string prefix = path_prefix_for(outcome.mission->dir);
    prove::Options options;
    options.depth = args->depth;
    options.engine = args->engine;
    std::vector<Finding> warnings;
    const auto warn = [&] {
      TextOptions text;
      text.path_prefix = prefix;
      std::cerr << format_text(warnings, text);
    };
    prove::Result result;
    try {
      result = gate::prove_checked(outcome, *outcome.mission, options, &warnings);
      warn();
    } catch (const prove::WorldError& e) {
      warn();
      // world.json named as opened from the current directory, like every other finding.
      std::cerr << prefix << e.what() << (e.check == "load-file" ? "" : " [" + e.check + "]")
                << "\n";
      exit_code = kExitUsage;
      return;
    } catch (const std::exception& e) {
      warn();
      std::cerr << "uabt: prove: " << with_user_path(e.what(), prefix) << "\n";
      // A counterexample its replay disagrees with is uabt's fault, not the mission's.
      const bool internal = std::string_view(e.what()).find("internal error") != std::string::npos;
      exit_code = internal ? kExitUsage : kExitFail;
      return;
    }
    std::map<std::string, std::string> written;
    if (!args->counterexamples.empty()) {
      make_output_directory(args->counterexamples, "--counterexamples");
      for (const auto& a : result.answers) {
        if (!a.counterexample) continue;
        const auto path = std::filesystem::path(args->counterexamples) /
                          report::counterexample_file_name(a.requirement);
        write_file_atomically(path, a.counterexample->scenario);
        written[a.requirement] = path.generic_string();
      }
    }
    exit_code = result.passed() ? kExitPass : kExitFail;
    // Every format draws from the one model of the proofs (the gate's reports too).
    report::Proofs proofs = gate::report_proofs(result, written);
    proofs.mission_path = args->mission;
    if (!args->selection.empty()) proofs.run_options = "--selection " + args->selection;
    if (args->format == "json") {
      emit(args->output, gate::result_json(result, proofs, outcome.mission->name, tool_version()));
      return;
    }
    if (args->format == "html") {
      emit(args->output, report::proofs_page_html(proofs, outcome.mission->name, tool_version()));
      return;
    }
    report::ReportInput input =
        report::ReportInput::of(*outcome.mission, tool_version(), {"prove"});
    input.findings = gate::findings_of(result, written, proofs);
    input.uri_prefix = sarif_uri_prefix(args->mission, "");
    if (args->format == "sarif") {
      write_findings(input, "sarif", args->output);
      return;
    }
    // Files named as opened from the current directory, as the gate names them.
    TextOptions text_options;
    text_options.path_prefix = prefix;
    for (Finding& f : input.findings) {
      f.message = with_user_path(f.message, prefix);
      for (std::string& note : f.notes) note = with_user_path(note, prefix);
    }
    std::string text = format_text(input.findings, text_options);
    for (const auto& a : result.answers)
      if (a.verdict == prove::Verdict::proved)
        text += text_options.path_prefix + place_text(a.location) + ": note: guarantee '" +
                a.requirement + "' is proved: " + a.text + " (" + proof_extent(result, a) + ")\n";
    if (!result.engine_reason.empty())
      text +=
          "note: the symbolic engine was chosen: " + with_user_path(result.engine_reason, prefix) +
          "\n";
    for (const auto& n : result.notes) text += "note: " + with_user_path(n, prefix) + "\n";
    text += summary_line(result, proofs) + "\n";
    emit(args->output, text);
  });
}

}  // namespace uabt::cli
