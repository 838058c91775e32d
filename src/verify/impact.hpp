#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"
#include "verify/verify.hpp"

namespace uabt::verify {

// One kind of change an uplink makes at an adaptable node: in some states the node used to
// select `from` and now selects `to` ("" = no alternative: the node fails).
struct SelectionChange {
  std::string from, to;
  std::string from_requirement, to_requirement;  // the requirement that selected it
  std::uint64_t states = 0;                      // how many discrete states (when counted)
  Exact share;                                   // its share of the domain (when measured)
  State example;  // one such state, a full assignment of the new domain
};

struct NodeImpact {
  std::string adaptable;
  std::string status;  // unchanged | changed | added | removed
  // Every variable the guards and assumptions read is discrete: states are counted.
  bool counted = false;
  // The shares are exact: counted, or real variables whose cells are measured (as coverage).
  bool measured = false;
  // Why states are not counted: a real variable (measured), or why nothing is measured.
  std::string not_counted_reason;
  std::uint64_t states = 0;              // states of the new domain (when counted)
  std::uint64_t changed_states = 0;      // states whose selection changes (when counted)
  Exact changed_share;                   // share of the domain that changes (when measured)
  std::vector<SelectionChange> changes;  // every (from, to) pair that occurs, sorted
};

struct Impact {
  std::vector<NodeImpact> nodes;  // adaptable nodes of either version, new mission order first
  std::vector<Finding> findings;  // ill-typed guards, inconclusive solver answers
};

// The semantic impact of an uplink (`uabt diff OLD NEW`): which states change their selected
// alternative. States range over the new version's domain (its declarations, with the old
// version's variables it no longer declares, and its assumptions): the uplinked version is the
// one whose view of the world will fly. Counts and shares come from the space coverage measures
// (verify/space.hpp): discrete states counted, real variables cut into cells and measured.
Impact selection_impact(const load::Mission& before, const load::Mission& after,
                        const Options& options);

}  // namespace uabt::verify
