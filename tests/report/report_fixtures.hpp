#pragma once
// Hand-built report inputs: what the gate would gather for a failing and a passing mission.
#include <string>
#include <utility>
#include <vector>

#include "report/model.hpp"

namespace uabt::testing {

inline Finding finding(std::string check, Severity severity, std::string message,
                       SourceLocation location, std::string adaptable = {}) {
  Finding f;
  f.check = std::move(check);
  f.severity = severity;
  f.message = std::move(message);
  f.location = std::move(location);
  f.adaptable = std::move(adaptable);
  return f;
}

// One alternative's coverage as the verifier fills it for a counted space: the states and the
// exact shares they give.
inline verify::AlternativeCoverage alternative(std::string name, std::string requirement,
                                               std::uint64_t states, std::uint64_t enabled,
                                               bool reachable) {
  verify::AlternativeCoverage a;
  a.name = std::move(name);
  a.requirement = std::move(requirement);
  a.states = states;
  a.enabled_states = enabled;
  a.reachable = reachable;
  return a;
}

// A region over booleans, as the verifier lists it: `OnDust = value & OnRocks = value`.
inline verify::Region boolean_region(bool dust, bool rocks, std::vector<std::string> requirements,
                                     verify::Exact share) {
  verify::Region r;
  for (const auto& [name, value] : {std::pair{"OnDust", dust}, std::pair{"OnRocks", rocks}}) {
    verify::RegionConstraint c;
    c.kind = verify::RegionConstraint::Kind::values;
    c.variable = name;
    c.values = {value ? "true" : "false"};
    c.text = (value ? "" : "!") + std::string(name);
    r.constraints.push_back(c);
  }
  r.requirements = std::move(requirements);
  r.measure = {"1", 1};
  r.share = std::move(share);
  return r;
}

// The paper's MSL mission without domain or default (ARCHITECTURE §9): overlap and gap on
// `navigation`, an uncounted node `arm` over a real variable, a syntax error and a warning.
inline report::ReportInput failing_input() {
  report::ReportInput input;
  input.tool_version = "0.1.0";
  input.mission_name = "msl_curiosity_paper";
  input.adaptables = {"navigation", "arm"};
  input.stages = {"load", "verify", "compile", "conform"};
  input.uri_prefix = "missions/msl_curiosity_paper/";

  Finding gap = finding("guard-gap", Severity::error,
                        "no requirement of 'navigation' holds in some state: the node fails there",
                        {"requirements.fret", 1, 1}, "navigation");
  gap.requirements = {"Req1", "Req2"};
  gap.witness = {{"OnDust", Value::of_bool(false)}, {"OnRocks", Value::of_bool(false)}};
  gap.notes = {"uncovered: !OnDust & !OnRocks"};

  Finding overlap = finding("guard-overlap", Severity::error,
                            "the guards of Req1 and Req2 both hold in some state",
                            {"requirements.fret", 2, 1}, "navigation");
  overlap.requirements = {"Req1", "Req2"};
  overlap.alternatives = {"on_dust", "on_rocks"};
  overlap.witness = {{"OnDust", Value::of_bool(true)}, {"OnRocks", Value::of_bool(true)}};

  Finding arm_overlap = finding("guard-overlap", Severity::error,
                                "the guards of Arm1 and Arm2 both hold in some state",
                                {"requirements.fret", 4, 1}, "arm");
  arm_overlap.requirements = {"Arm1", "Arm2"};
  arm_overlap.alternatives = {"reach", "retract"};
  arm_overlap.witness = {{"battery", Value::of_int(20)},
                         {"slope", Value::of_real(1.0 / 3.0, "1/3")},
                         {"speed", Value::of_real(0.5, "0.5")},
                         {"load", Value::of_real(0.25, "1/4")},
                         {"terrain", Value::of_enum("rocks")}};

  Finding syntax =
      finding("fretish-syntax", Severity::error, "expected 'shall' after <Adaptable> | here",
              {"requirements.fret", 5, 10});

  Finding orphan = finding("ref-orphan-alternative", Severity::warning,
                           "alternative 'spare' of 'navigation' is named by no requirement",
                           {"alternatives/navigation/spare.xml", 0, 0}, "navigation");
  orphan.node_path = "spare/Sequence[0]";

  input.findings = {gap, overlap, arm_overlap, syntax, orphan};
  sort_findings(input.findings);

  verify::Coverage navigation;
  navigation.adaptable = "navigation";
  navigation.counted = true;
  navigation.states = 4;
  navigation.alternatives = {alternative("on_dust", "Req1", 2, 2, true),
                             alternative("on_rocks", "Req2", 1, 2, true)};
  navigation.gap_states = 1;
  navigation.overlap_states = 1;
  navigation.gap_region = {"!OnDust & !OnRocks"};
  navigation.variables = {"OnDust", "OnRocks"};
  // A counted space is measured too: the shares are the counts over the states.
  navigation.measured = true;
  navigation.measure = {"4", 4};
  navigation.alternatives[0].measure = {"2", 2};
  navigation.alternatives[0].share = navigation.alternatives[0].share_lower =
      navigation.alternatives[0].share_upper = {"1/2", 0.5};
  navigation.alternatives[0].cells = {{"OnDust", "true"}};
  navigation.alternatives[1].measure = {"1", 1};
  navigation.alternatives[1].share = navigation.alternatives[1].share_lower =
      navigation.alternatives[1].share_upper = {"1/4", 0.25};
  navigation.alternatives[1].cells = {{"OnRocks", "true"}};
  navigation.gap_measure = navigation.overlap_measure = {"1", 1};
  navigation.gap_share = navigation.overlap_share = {"1/4", 0.25};
  navigation.gap_regions = {boolean_region(false, false, {"Req1", "Req2"}, {"1/4", 0.25})};
  navigation.overlap_regions = {boolean_region(true, true, {"Req1", "Req2"}, {"1/4", 0.25})};

  verify::Coverage arm;
  arm.adaptable = "arm";
  arm.counted = false;
  arm.not_counted_reason = "slope is a real variable";
  arm.alternatives = {alternative("reach", "Arm1", 0, 0, true),
                      alternative("retract", "Arm2", 0, 0, false)};
  arm.variables = {"battery", "slope"};

  input.coverage = {navigation, arm};
  return input;
}

// The same mission with a domain and a default: nothing but a note.
inline report::ReportInput passing_input() {
  report::ReportInput input;
  input.tool_version = "0.1.0";
  input.mission_name = "msl_curiosity";
  input.adaptables = {"navigation"};
  input.stages = {"load", "verify", "compile", "conform"};

  verify::Coverage navigation;
  navigation.adaptable = "navigation";
  navigation.counted = true;
  navigation.states = 3;
  navigation.alternatives = {alternative("on_dust", "Req1", 1, 1, true),
                             alternative("on_rocks", "Req2", 1, 1, true),
                             alternative("hold_position", "Safe", 1, 3, true)};
  navigation.variables = {"OnDust", "OnRocks"};
  input.coverage = {navigation};
  return input;
}

}  // namespace uabt::testing
