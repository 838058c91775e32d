// Nodes are verified in parallel, each in a Z3 context of its own: the report must not depend
// on the number of threads, and a query that runs too long is stopped by the watchdog.
#include <gtest/gtest.h>

#include <string>

#include "base/diagnostics.hpp"
#include "verify/mission_builder.hpp"

namespace uabt::testing {
namespace {

// Everything a user sees of a result: every finding as the text report prints it (witness and
// notes included) and every coverage count.
std::string rendered(const verify::Result& r) {
  std::string out = format_text(r.findings);
  for (const auto& c : r.coverage) {
    out += c.adaptable + (c.counted ? " counted " : " not counted ") + c.not_counted_reason +
           " states=" + std::to_string(c.states) + " gap=" + std::to_string(c.gap_states) +
           " overlap=" + std::to_string(c.overlap_states) + "\n";
    for (const auto& a : c.alternatives)
      out += "  " + a.name + " " + std::to_string(a.states) + "/" +
             std::to_string(a.enabled_states) + (a.reachable ? " reachable" : " unreachable") +
             "\n";
    for (const auto& cube : c.gap_region) out += "  gap: " + cube + "\n";
  }
  return out;
}

const char* kRequirements =
    "A1: In drive if terrain = sand | terrain = mud Mission shall satisfy selected_alt = slow\n"
    "A2: In drive if terrain = mud & speed > 3 Mission shall satisfy selected_alt = stop\n"
    "A3: In drive if terrain = rock Mission shall satisfy selected_alt = careful\n"
    "B1: In arm if battery >= 20 & battery < 60 Mission shall satisfy selected_alt = low\n"
    "B2: In arm if battery >= 50 Mission shall satisfy selected_alt = high\n"
    "C1: In camera if dusty & (tau > 1.5 | night) Mission shall satisfy selected_alt = wait\n"
    "C2: In camera if tau > 2 & dusty Mission shall satisfy selected_alt = hide\n"
    "C3: In camera Mission shall satisfy selected_alt = shoot\n"
    "D1: In comms if speed > 5 & speed > 2 Mission shall satisfy selected_alt = relay\n"
    "D2: In comms if speed <= 5 Mission shall satisfy selected_alt = direct\n"
    "E1: In sample if battery > 10 Mission shall satisfy selected_alt = drill\n"
    "E2: In sample if battery > 30 & terrain = rock Mission shall satisfy selected_alt = scoop\n"
    "E3: In sample Mission shall satisfy selected_alt = skip\n";

const char* kDomain =
    "enum terrain in {sand, mud, rock, flat}\n"
    "integer speed in [0, 10]\n"
    "integer battery in [0, 100]\n"
    "real tau in [0, 5]\n"
    "boolean dusty, night\n";

TEST(Parallel, TheReportIsTheSameWhateverTheNumberOfThreads) {
  const load::Mission m = make_mission(kRequirements, kDomain);
  verify::Options one;
  one.threads = 1;
  const verify::Result reference = verify_checked(m, one);
  // The mission has something of every kind to report, so the comparison means something.
  for (const char* check : {"guard-overlap", "guard-gap", "guard-shadowed", "guard-vacuous-atom"})
    EXPECT_FALSE(findings_of(reference, check).empty()) << check;
  for (unsigned threads : {2u, 3u, 8u}) {
    verify::Options options;
    options.threads = threads;
    EXPECT_EQ(rendered(verify_checked(m, options)), rendered(reference)) << threads << " threads";
  }
}

}  // namespace
}  // namespace uabt::testing
