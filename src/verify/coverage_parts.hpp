#pragma once
// The pieces of count_coverage that work on the enumerated space: regions and the map.
#include <vector>

#include "fretish/selection.hpp"
#include "verify/space.hpp"
#include "verify/verify.hpp"

namespace uabt::verify::detail {

// Where each guard holds (in the domain) and where two or more hold, over one node's space.
struct NodeTruths {
  Truth domain;
  std::vector<Truth> enabled;  // per requirement, priority order
  Truth gap;
  Truth overlap;
};

Exact exact_of(const Fraction& f);

// The gap and every overlapping pair as a few boxes each (greedy maximal boxes).
// Grown first from the witnesses of the gap and overlap `findings`.
void fill_regions(const Space& space,
                  const std::vector<const fretish::SelectionRequirement*>& requirements,
                  const NodeTruths& truths, const std::vector<Finding>& findings,
                  Coverage& coverage);

// The map over the two most telling variables, one panel per value of a third.
void fill_map(const Space& space, const fretish::Domain& domain, const NodeTruths& truths,
              std::size_t alternatives, Coverage& coverage);

// Text of one cell (or range of cells) of a dimension, "" when it covers the whole range.
RegionConstraint describe_range(const Space& space, std::size_t dim, std::uint64_t lo,
                                std::uint64_t hi, const fretish::Domain& domain);

}  // namespace uabt::verify::detail
