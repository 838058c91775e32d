// The pre-filter that spares the solver: meeting_candidates must keep every pair that
// `disjoint` cannot rule out (a pair it drops is never asked about, so a missed overlap would
// be a wrong verdict), and drop exactly the pairs `disjoint` rules out.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "smt/encoder.hpp"
#include "verify/mission_builder.hpp"
#include "verify/prefilter.hpp"

namespace uabt::testing {
namespace {

const char* kDomain =
    "enum e in {a, b, c, d, f}\n"
    "integer n in [0, 20]\n"
    "real r in [0, 5]\n"
    "boolean p, q\n";

// Literals of every kind a signature captures, and some it does not (!=, disjunctions).
const std::vector<std::string> kLiterals = {
    "e = a",  "e = b",  "e = c",   "e != d",  "n >= 5",        "n < 7", "n = 3",
    "n > 12", "n <= 2", "r > 1.5", "r <= 2",  "r >= 2",        "r < 1", "p",
    "!p",     "!q",     "n != 4",  "(p | q)", "e = f & n > 1", "false", "r = 2.5"};

std::vector<std::vector<std::size_t>> pairwise(
    const std::vector<const verify::detail::Signature*>& s) {
  std::vector<std::vector<std::size_t>> meets(s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = 0; j < s.size(); ++j)
      if (i != j && !verify::detail::disjoint(*s[i], *s[j])) meets[i].push_back(j);
  return meets;
}

// The signatures of the node's guards in priority order (the default's is empty), and
// pointers to them as meeting_candidates takes them.
struct Signatures {
  std::vector<verify::detail::Signature> owned;
  std::vector<const verify::detail::Signature*> pointers;
};

Signatures signatures_of(const load::Mission& m) {
  smt::Encoder encoder(m.domain);
  std::vector<Finding> findings;
  Signatures out;
  for (const auto* r : m.selections_for("node")) {
    if (!r->guard) {
      out.owned.emplace_back();  // the default constrains nothing
      continue;
    }
    EXPECT_TRUE(encoder.lower_condition(*r->guard, r->guard_location, findings));
    out.owned.push_back(verify::detail::signature_of(*r->guard, encoder.typing()));
  }
  for (const auto& s : out.owned) out.pointers.push_back(&s);
  return out;
}

TEST(MeetingCandidates, AgreeWithComparingEveryPair) {
  std::mt19937 random(20261122);
  for (int round = 0; round < 400; ++round) {
    // Bias each round towards one variable so each kind of pivot (values, interval, boolean)
    // gets its turn, with guards that leave it unconstrained mixed in.
    const std::size_t bias = random() % kLiterals.size();
    const std::size_t guards = 2 + random() % 14;
    std::string requirements;
    for (std::size_t g = 0; g < guards; ++g) {
      std::string guard = kLiterals[random() % 3 == 0 ? bias : random() % kLiterals.size()];
      for (std::size_t extra = random() % 3; extra > 0; --extra)
        guard += " & " + kLiterals[random() % kLiterals.size()];
      if (random() % 8 == 0) {
        requirements += "G" + std::to_string(g) +
                        ": In node Mission shall satisfy selected_alt = a" + std::to_string(g) +
                        "\n";
        continue;
      }
      requirements += "G" + std::to_string(g) + ": In node if " + guard +
                      " Mission shall satisfy selected_alt = a" + std::to_string(g) + "\n";
    }
    SCOPED_TRACE(requirements);
    const Signatures signatures = signatures_of(make_mission(requirements, kDomain));
    EXPECT_EQ(verify::detail::meeting_candidates(signatures.pointers),
              pairwise(signatures.pointers));
  }
}

TEST(MeetingCandidates, APartitionOfIntervalsMeetsNothing) {
  std::string requirements;
  for (int k = 0; k < 50; ++k)
    requirements += "I" + std::to_string(k) + ": In node if n >= " + std::to_string(k * 2) +
                    " & n < " + std::to_string(k * 2 + 2) +
                    " Mission shall satisfy selected_alt = a" + std::to_string(k) + "\n";
  const Signatures signatures =
      signatures_of(make_mission(requirements, "integer n in [0, 100]\n"));
  for (const auto& meets : verify::detail::meeting_candidates(signatures.pointers))
    EXPECT_TRUE(meets.empty());
}

}  // namespace
}  // namespace uabt::testing
