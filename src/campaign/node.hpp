#pragma once
// One adaptable node of a campaign model: its enumerated space (the coverage stage's cells),
// where each guard holds, what each state selects, and its targets as sets of states.
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "campaign/campaign.hpp"
#include "fretish/selection.hpp"
#include "smt/evaluate.hpp"
#include "verify/bits.hpp"
#include "verify/space.hpp"

namespace uabt::campaign {

struct Model::Node {
  std::string adaptable;
  std::vector<const fretish::SelectionRequirement*> reqs;  // priority order
  smt::Typing typing;
  std::unique_ptr<verify::detail::Space> space;
  verify::detail::Bits domain;                 // states that satisfy the assumptions
  std::vector<verify::detail::Bits> enabled;   // per requirement: its guard holds (in domain)
  std::vector<verify::detail::Bits> selected;  // per requirement: it is the one selected
  std::vector<std::string> atom_text;          // distinct atoms of the guards, by FRETISH text
  std::vector<const fretish::Expr*> atom_expr;
  std::vector<std::vector<std::size_t>> req_atoms;  // per requirement: its atoms
  // An atom and one that holds exactly where it does (or where it does not: `wind >= 15` and
  // `wind < 15`) are one condition: one column of the signature, with a polarity.
  std::vector<std::size_t> column;
  std::vector<bool> inverted;
  std::size_t words = 1;            // 64-bit words of a signature
  std::vector<std::uint64_t> sigs;  // per state: the columns' values, `words` words
  std::vector<int> sel;             // per state: requirement selected, -1 gap, -2 outside

  // A target of this node: the states that reach it, or (MC/DC) the pairs that do.
  struct Local {
    std::size_t target = 0;  // index into the model's targets
    verify::detail::Bits states;
    bool pair = false;    // MC/DC: reached by a pair of states, `pairs`
    bool select = false;  // reached by a run that selects the alternative of `req`
    std::size_t req = 0, atom = 0;
    std::vector<std::pair<std::uint64_t, std::uint64_t>> pairs;
  };
  std::vector<Local> locals;

  bool build(const load::Mission& mission, std::string& reason);
  void decision_targets(std::vector<Target>& all);
  void mcdc_targets(std::vector<Target>& all);
  void boundary_targets(std::vector<Target>& all);
  void add(std::vector<Target>& all, Target t, verify::detail::Bits states);

  bool atom_holds(std::uint64_t state, std::size_t atom) const;
  // The state's signature as bytes, for hashing (bit c of the bytes is column c).
  std::string key(std::uint64_t state) const;
  State state_values(std::uint64_t state) const;
  // `state`, or when it is excluded another state of the domain where every atom has the
  // same value (nullopt: none is left).
  std::optional<std::uint64_t> substitute(std::uint64_t state,
                                          const std::set<std::uint64_t>& excluded) const;
  // The state (in the domain) an assignment lies in.
  std::optional<std::uint64_t> state_index(const State& state) const;
};

}  // namespace uabt::campaign
