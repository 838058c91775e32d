#pragma once
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/finding.hpp"
#include "fretish/parse.hpp"
#include "fretish/selection.hpp"
#include "load/mission.hpp"
#include "load/references.hpp"
#include "smt/evaluate.hpp"
#include "smt/expr_support.hpp"
#include "verify/verify.hpp"

namespace uabt::testing {

// A mission held in memory: requirements.fret and domain.fret text, no files and no trees.
// The adaptable nodes are those the selection requirements name, in first-use order.
inline load::Mission make_mission(const std::string& requirements,
                                  const std::string& domain_text = "") {
  load::Mission m;
  m.name = "test";
  m.layout = "uabt";
  m.requirements_file = "requirements.fret";
  fretish::ParseResult parsed = fretish::parse_requirements_file(requirements, "requirements.fret");
  if (has_errors(parsed.findings))
    throw std::runtime_error("test requirements do not parse: " + parsed.findings.front().message);
  m.requirements = std::move(parsed.requirements);
  std::vector<Finding> findings;
  m.selections = fretish::classify_selection(m.requirements, findings);
  if (has_errors(findings))
    throw std::runtime_error("test requirements are not selections: " + findings.front().message);
  if (!domain_text.empty()) m.domain = domain(domain_text);
  std::set<std::string> seen;
  for (const auto& s : m.selections) {
    if (!seen.insert(s.adaptable).second) continue;
    load::AdaptableSite site;
    site.id = s.adaptable;
    site.tree_id = "MainTree";
    m.adaptables.push_back(site);
  }
  load::infer_condition_variables(m);
  return m;
}

inline std::vector<const Finding*> findings_of(const verify::Result& r, const std::string& check) {
  std::vector<const Finding*> out;
  for (const auto& f : r.findings)
    if (f.check == check) out.push_back(&f);
  return out;
}

inline const fretish::SelectionRequirement* requirement(const load::Mission& m,
                                                        const std::string& id) {
  for (const auto& s : m.selections)
    if (s.id == id) return &s;
  return nullptr;
}

inline bool guard_holds(const load::Mission& m, const fretish::SelectionRequirement& s,
                        const State& state) {
  if (!s.guard) return true;
  return smt::evaluate(*s.guard, m.domain, state);
}

// Checks every witness of a result with the independent evaluator: it satisfies D, and it
// makes the finding true (both guards for an overlap, none for a gap, the shadowed guard and
// one of its hiders for shadowing).
inline void expect_witnesses_valid(const load::Mission& m, const verify::Result& r) {
  for (const auto& f : r.findings) {
    if (f.check == "guard-overlap" || f.check == "guard-gap" || f.check == "guard-shadowed") {
      ASSERT_FALSE(f.witness.empty()) << f.check << ": " << f.message;
    }
    if (f.witness.empty()) continue;
    SCOPED_TRACE(f.check + ": " + f.message);
    EXPECT_TRUE(smt::satisfies_domain(m.domain, f.witness));
    if (f.check == "guard-overlap") {
      ASSERT_EQ(f.requirements.size(), 2u);
      for (const auto& id : f.requirements)
        EXPECT_TRUE(guard_holds(m, *requirement(m, id), f.witness)) << id;
    } else if (f.check == "guard-gap") {
      for (const auto* s : m.selections_for(f.adaptable))
        EXPECT_FALSE(guard_holds(m, *s, f.witness)) << s->id;
    } else if (f.check == "guard-shadowed") {
      EXPECT_TRUE(guard_holds(m, *requirement(m, f.requirements[0]), f.witness));
      bool some_hider = false;
      for (std::size_t k = 1; k < f.requirements.size(); ++k)
        some_hider = some_hider || guard_holds(m, *requirement(m, f.requirements[k]), f.witness);
      EXPECT_TRUE(some_hider);
    }
  }
}

// verify_mission plus the witness checks every test wants.
inline verify::Result verify_checked(const load::Mission& m, verify::Options options = {}) {
  verify::Result r = verify::verify_mission(m, options);
  expect_witnesses_valid(m, r);
  return r;
}

}  // namespace uabt::testing
