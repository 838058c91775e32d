#pragma once
// The pieces of count_coverage that work on the enumerated space: regions and the map.
#include <optional>
#include <string>
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
// part / whole; 0 when the whole is empty.
Fraction ratio(const Fraction& part, const Fraction& whole);

// The gap and every overlapping pair as a few boxes each (greedy maximal boxes).
// Grown first from the witnesses of the gap and overlap `findings`.
void fill_regions(const Space& space,
                  const std::vector<const fretish::SelectionRequirement*>& requirements,
                  const NodeTruths& truths, const std::vector<Finding>& findings,
                  Coverage& coverage);

// Where a variable of the map lives in the space: a discrete dimension, or one axis of a real
// component.
struct MapPlace {
  std::size_t dim = 0;
  int axis = -1;  // within a real component: 0 or 1; -1 for a discrete dimension
};
// The map's axes and panels, chosen from the space alone: real variables first (a related pair
// together), then integers, then the rest; one panel per value of the next small enumerated or
// boolean variable.
struct MapLayout {
  MapPlace x;
  std::optional<MapPlace> y;
  std::optional<std::size_t> panel;  // the dimension drawn as one panel per value
  bool joint = false;                // both axes from one two-variable component
};
// The layout of a node's map, or nullopt with `why` it has none (no state, too many cells to
// draw, no variable that varies).
std::optional<MapLayout> map_layout(const Space& space, std::size_t alternatives, std::string& why);
// The cell of the map that a state of the space lies in: its panel, its shape in the map's
// coordinates and where it is, as fill_map draws one cell.
MapMark map_mark(const Space& space, const fretish::Domain& domain, const MapLayout& layout,
                 std::uint64_t state);

// The map over the two most telling variables, one panel per value of a third.
void fill_map(const Space& space, const fretish::Domain& domain, const NodeTruths& truths,
              std::size_t alternatives, Coverage& coverage);

// Text of one cell (or range of cells) of a dimension, "" when it covers the whole range.
RegionConstraint describe_range(const Space& space, std::size_t dim, std::uint64_t lo,
                                std::uint64_t hi, const fretish::Domain& domain);

}  // namespace uabt::verify::detail
