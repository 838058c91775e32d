#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "load/mission.hpp"

namespace uabt::verify {

// An exact non-negative quantity (a measure or a share): the rational as text ("3/8") and a
// double for pictures and JSON numbers.
struct Exact {
  std::string text = "0";
  double value = 0.0;
};

// One conjunct of a region: an interval or a set of values of one variable, or a linear
// constraint over two.
struct RegionConstraint {
  enum class Kind { interval, values, linear } kind = Kind::interval;
  std::string variable;  // interval, values
  std::string text;      // "wind in [0, 15)", "terrain = slope", "wind + slope > 60"
  // interval: its ends, exact text and as doubles
  std::string lower, upper;
  double lower_value = 0, upper_value = 0;
  bool lower_closed = true, upper_closed = true;
  std::vector<std::string> values;  // values: enum literals or "true"/"false"
};

// A box (or a box cut by linear constraints) of the state space: one row of a DMN-style
// decision table, with the requirements whose guards make it a gap or an overlap.
struct Region {
  std::vector<RegionConstraint> constraints;  // a conjunction; empty: the whole domain
  std::vector<std::string> requirements;
  Exact measure, share;  // of the region inside the domain (0 for a boundary)
  // false: an atom inside it could not be measured, so only part of the region may belong.
  bool exact = true;
  bool measured = true;      // false: listed from the solver's answers, not measured
  std::string text() const;  // "wind in [0, 15) & terrain = slope"
};

// The selected alternative drawn over at most two variables, one panel per value of a third
// (ARCHITECTURE §5 coverage picture). Coordinates are the variables' own values; categorical axes
// put value k at [k, k+1].
struct MapShape {
  std::vector<std::pair<double, double>> points;  // polygon (>= 3), segment (2) or point (1)
  std::vector<int> outcomes;                      // alternatives selected in it; -1: gap
  bool overlap = false;                           // two or more guards hold in some state of it
  bool uncertain = false;                         // an unmeasured atom makes its outcome uncertain
  Exact gap_share;    // the share of the node's space that is gap inside it
  std::string where;  // "wind in (0, 15) & battery = 10"
};
struct MapAxis {
  std::string variable;
  bool categorical = false;
  double lower = 0, upper = 1;
  std::vector<std::pair<double, std::string>> ticks;  // position, label
};
struct MapPanel {
  std::string label;  // "terrain = slope"; "" when there is one panel
  std::vector<MapShape> shapes;
};
// A cell of the map that runs visited (`uabt coverage --format html`), drawn over the map: the
// cell a state lies in, over the map's variables (a state's other variables are off the map).
struct MapMark {
  std::size_t panel = 0;                          // index into CoverageMap::panels
  std::vector<std::pair<double, double>> points;  // as MapShape: polygon, segment or point
  std::string where;                              // "wind in (0, 15) & battery = 50"
  std::vector<std::string> runs;                  // the runs that visited it, as displayed
};
struct CoverageMap {
  MapAxis x;
  std::optional<MapAxis> y;  // none: a strip over x alone
  std::string panel_variable;
  std::vector<MapPanel> panels;
  bool other_variables = false;  // variables off the map: a shape may hold several outcomes
};

// Terrain coverage of one adaptable node (ARCHITECTURE §5): how the domain's state space is split
// among the alternatives. `counted`: a discrete space, counted exactly (states). `measured`:
// the measure of every part is exact (counted, or real variables measured exactly); otherwise
// `not_measured_reason` says why, and `bounded` tells whether the *_lower/_upper shares give
// certified bounds.
struct AlternativeCoverage {
  std::string name;                  // alternative
  std::string requirement;           // requirement id
  std::uint64_t states = 0;          // states in which this alternative is the one selected
  std::uint64_t enabled_states = 0;  // states in which its guard holds
  bool reachable = true;  // some state selects it (decided by the solver, also when uncounted)
  Exact measure, share;   // where it is the one selected
  Exact enabled_share;    // where its guard holds
  Exact share_lower, share_upper;
  // The guard as a row of a decision table: per variable a cell ("< 15", "in [0, 19]",
  // "= sand", "true"), in the order of `Coverage::variables`; what relates several variables
  // goes to `other_condition`. No cell for a variable: any value.
  std::vector<std::pair<std::string, std::string>> cells;
  std::string other_condition;
};

struct Coverage {
  std::string adaptable;
  bool counted = false;
  std::string not_counted_reason;
  std::uint64_t states = 0;                       // size of the domain (states satisfying D)
  std::vector<AlternativeCoverage> alternatives;  // priority order, default last
  std::uint64_t gap_states = 0;                   // no guard holds
  std::uint64_t overlap_states = 0;               // two or more non-default guards hold
  std::vector<std::string> gap_region;            // the uncovered region as a few readable cubes
  std::vector<std::string> variables;             // the variables the guards range over

  bool measured = false;
  bool bounded = false;
  std::string not_measured_reason;
  Exact measure;  // of the whole domain
  Exact gap_measure, gap_share, overlap_measure, overlap_share;
  Exact gap_share_lower, gap_share_upper, overlap_share_lower, overlap_share_upper;
  // The gap and every overlap as regions; a list stops after a few rows (omitted: how many
  // more there are).
  std::vector<Region> gap_regions, overlap_regions;
  std::size_t gap_regions_omitted = 0, overlap_regions_omitted = 0;
  std::optional<CoverageMap> map;
};

struct Options {
  bool allow_overlap = false;   // guard-overlap becomes a warning
  unsigned timeout_ms = 10000;  // per solver query; unknown → verification-inconclusive
  unsigned threads = 0;         // 0: one per core
};

struct Statistics {
  std::uint64_t solver_queries = 0;
  std::uint64_t prefiltered = 0;  // questions answered without the solver
};

struct Result {
  std::vector<Finding> findings;   // verify-stage findings only (not the loader's)
  std::vector<Coverage> coverage;  // one per adaptable node, mission order
  Statistics statistics;
};

// Guard verification of every adaptable node of a loaded mission (ARCHITECTURE §5).
Result verify_mission(const load::Mission& mission, const Options& options);

}  // namespace uabt::verify
