#pragma once
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "fretish/domain.hpp"
#include "fretish/requirement.hpp"
#include "monitor/property_set.hpp"
#include "monitor/trace.hpp"

namespace uabt::monitor {

struct TraceReport {
  bool pass = true;     // no guarantee violated, everything monitored
  bool failed = false;  // a guarantee violated, or the trace does not fit the domain
  // "pass", "fail", or "inconclusive": nothing failed, but some requirement is not monitored.
  const char* verdict() const { return pass ? "pass" : failed ? "fail" : "inconclusive"; }
  std::uint64_t ticks = 0;
  std::vector<PropertyResult> properties;
};

// Checks every requirement (and domain assumption) on a recorded trace. A variable the domain
// declares must carry values of its type (a `trace-invalid` finding otherwise).
TraceReport check_trace(const std::vector<fretish::Requirement>& requirements,
                        const fretish::Domain& domain, const Trace& trace,
                        const std::string& trace_file, std::vector<Finding>& findings);

// ARCHITECTURE §10's JSON and a text summary.
std::string trace_report_json(const TraceReport& report);
std::string trace_report_text(const TraceReport& report);

}  // namespace uabt::monitor
