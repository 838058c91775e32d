#pragma once
#include <memory>
#include <string>

#include "compile/compile.hpp"
#include "conform/conform.hpp"
#include "load/mission.hpp"
#include "report/model.hpp"
#include "verify/verify.hpp"

namespace uabt::gate {

struct Options {
  verify::Options verify;
  compile::Options compile;
  conform::Options conform;
};

// The outcome of the pre-uplink gate on one mission: load → verify guards → compile →
// conform the compiled tree. It passes only when no stage reported an error; anything
// inconclusive is an error (fail closed).
struct Outcome {
  std::unique_ptr<load::Mission> mission;  // owned here: `report.mission` points into it
  verify::Result verification;
  compile::Result compiled;
  std::string compiled_xml;  // "" when the mission did not compile
  conform::Result conformance;
  report::ReportInput report;

  bool passed() const { return report.passed(); }
};

// Runs every stage on a loaded mission. Stages that cannot run (nothing compiled) are left
// out of `report.stages`; their absence is itself a failure because the load errors that
// stopped them are in the findings.
Outcome run_gate(load::Mission mission, const Options& options, const std::string& tool_version);

}  // namespace uabt::gate
