#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"
#include "report/proofs.hpp"
#include "verify/impact.hpp"
#include "verify/verify.hpp"

namespace uabt::report {

// What `gate --uplink` adds to a report (ARCHITECTURE §11): the package, where the merge put each
// requirement, and the behaviour change from the running version to the merged one.
// A guarantee whose statement an uplink changes (ARCHITECTURE §11: the guarantees are the mission's
// contract), with its status on the version on board and on the merged mission.
struct ContractChange {
  std::string requirement;
  // added | restated (the merged mission still satisfies the old text) | weakened (restated,
  // and it does not) | removed
  std::string change;
  std::string before_text, after_text;  // "" where it is not stated
  std::string before;     // the old text on the version on board ("proved", "violated at tick 3")
  std::string old_after;  // the old text on the merged mission
  std::string after;      // the new text on the merged mission ("" when removed)
  std::string consent;    // "retire" | "weaken" when uplink.json allows it, else ""
  std::string consent_reason;
  bool old_holds = false;  // the merged mission satisfies the old text (proved)
  // Weakened or removed: the old text, as proved on the merged mission, with the run that
  // breaks it (its counterexample) when prove found one.
  std::optional<ProofAnswer> old_on_merged;
};

struct UplinkChange {
  std::string package;  // as given on the command line
  std::vector<load::UplinkMerge> merges;
  verify::Impact impact;
  std::vector<ContractChange> contract;  // added, restated, weakened, removed, in that order
};

// What the gate says about the test campaign it wrote beside the reports (ARCHITECTURE §13):
// information for the testbed, never part of the verdict.
struct TestCampaign {
  std::string directory;  // where the scenarios are, relative to the report ("tests/")
  std::size_t targets = 0, reachable = 0, covered = 0, scenarios = 0, change_scenarios = 0;
  std::vector<std::pair<std::string, std::string>> unreachable;  // target, reason
  std::vector<std::pair<std::string, std::string>> undecided;    // not decided: target, reason
  std::vector<std::string> notes;  // "guarantee targets not planned: the mission has no world.json"
  std::vector<std::pair<std::string, std::string>> skipped;  // adaptable node, reason
  std::vector<std::string> problems;  // "scenario.json: why it did not reach its purpose"
  std::string not_built;              // why there is no campaign ("" when there is one)
  // "tests/: 12 scenarios (1 for a behaviour change) cover 30 of 30 reachable targets; 32
  // targets, 2 unreachable", or why there is none: the first line of every format's section.
  std::string headline() const;
  // The items under it: "unreachable: TEXT: REASON", "not decided: TEXT: REASON", "no targets
  // for NODE: REASON", the notes, "not reached: SCENARIO: WHY".
  std::vector<std::string> details() const;
};

// Everything a report shows about one mission, gathered by the gate (or by `verify`).
struct ReportInput {
  std::string tool_version;
  std::string mission_name;             // the mission directory's name
  std::vector<std::string> adaptables;  // adaptable node ids, mission order
  std::vector<Finding> findings;        // every stage's findings, sorted
  std::vector<verify::Coverage> coverage;
  // Stages that ran ("load", "verify", "compile", "conform"): JUnit marks the checks of a stage
  // that did not run as skipped rather than passed, and the summary lists them. Empty: unknown,
  // every check counts as run.
  std::vector<std::string> stages;
  // Files of the mission whose lines SARIF and the HTML report point into (displayed paths).
  std::string compiled_tree_file;  // "" when no compiled tree was written
  // The mission directory's path from the repository root, with a trailing '/'
  // ("missions/msl_curiosity/"): prefixed to SARIF artifact URIs so that code scanning
  // annotates the right file. "" when the mission directory is the root.
  std::string uri_prefix;
  // The loaded mission (requirements, domain, guards), for pictures and requirement text.
  // May be null when the mission could not be loaded at all.
  const load::Mission* mission = nullptr;
  std::optional<UplinkChange> uplink;    // set by `gate --uplink`
  std::optional<Proofs> proofs;          // set when the mission states guarantees
  std::optional<TestCampaign> campaign;  // set by `gate` when it writes the test campaign

  // What a report of `mission` starts from: its adaptable nodes in mission order and the
  // findings loading it gave; each stage that runs adds its findings and its name.
  static ReportInput of(const load::Mission& mission, std::string tool_version,
                        std::vector<std::string> stages);

  bool passed() const { return !has_errors(findings); }
  // "pass", "fail", or "pass with 1 guarantee retired" (and/or weakened) when an uplink gives
  // up guarantees with uplink.json's consent: every format's banner says it in these words.
  std::string verdict_text() const;
  // verdict_text with its first word in capitals, for banners: "PASS with 1 guarantee retired".
  std::string banner() const;
};

}  // namespace uabt::report
