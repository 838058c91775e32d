// What a set of runs visited of each node's space: the cells, and the exact share of the
// domain they hold, measured as the coverage stage measures shares (ARCHITECTURE §5).
#include <algorithm>
#include <map>
#include <set>

#include "base/number_text.hpp"
#include "campaign/campaign.hpp"
#include "campaign/node.hpp"
#include "verify/coverage_parts.hpp"

namespace uabt::campaign {

namespace {

using verify::detail::Bits;
using verify::detail::Fraction;
using verify::detail::RealAxis;

// The dimension of a state's cell: 0 for a point, 1 for a line, ... over its real variables.
std::size_t real_dimension(const verify::detail::Space& space, std::uint64_t state) {
  std::size_t out = 0;
  const auto& dims = space.dimensions();
  for (std::size_t d = 0; d < dims.size(); ++d) {
    if (dims[d].component < 0) continue;
    const auto& comp = space.components()[static_cast<std::size_t>(dims[d].component)];
    const auto& cell = comp.cells[space.digit(state, d)];
    if (comp.axes.size() == 1)
      out += RealAxis::is_point(cell.axis_cell[0]) ? 0 : 1;
    else
      out += cell.shape.size() >= 3 ? 2 : cell.shape.size() - 1;
  }
  return out;
}

Share share_of(const Fraction& part, const Fraction& whole) {
  const Fraction f = whole.is_zero() ? Fraction(0) : part / whole;
  return {f.text(), f.to_double()};
}

Visited measure(const Model::Node& n, const std::set<std::uint64_t>& states, const Bits* within,
                const Fraction& whole) {
  Visited v;
  Bits set(n.space->size(), false);
  std::set<std::string> kinds;
  for (std::uint64_t s : states) {
    if (within != nullptr && !within->test(s)) continue;
    set.set(s);
    ++v.cells;
    if (!n.space->weight(s).is_zero()) continue;
    ++v.boundary;
    kinds.insert(real_dimension(*n.space, s) == 0 ? "a boundary point" : "a boundary line");
  }
  v.share = share_of(n.space->measure(set), whole);
  if (kinds.size() == 1) v.boundary_kind = *kinds.begin();
  if (kinds.size() > 1) v.boundary_kind = "boundary points and lines";
  return v;
}

// The visited states on the node's coverage map: one mark per cell of the map (the states that
// differ only off the map share one), with the runs that visited it.
void place_on_map(const Model::Node& n,
                  const std::map<std::uint64_t, std::vector<std::string>>& runs, NodeVisit& visit) {
  const auto layout = verify::detail::map_layout(*n.space, n.reqs.size(), visit.no_map);
  if (!layout) return;
  std::map<std::pair<std::size_t, std::string>, std::size_t> at;  // panel, where → mark
  for (const auto& [state, sources] : runs) {
    verify::MapMark mark = verify::detail::map_mark(*n.space, n.space->domain(), *layout, state);
    const auto [it, fresh] = at.emplace(std::make_pair(mark.panel, mark.where), visit.marks.size());
    if (fresh) visit.marks.push_back(std::move(mark));
    auto& named = visit.marks[it->second].runs;
    for (const auto& source : sources)
      if (std::find(named.begin(), named.end(), source) == named.end()) named.push_back(source);
  }
}

}  // namespace

std::vector<NodeVisit> Model::visits(const std::vector<RunRecord>& runs) const {
  std::map<std::string, std::vector<std::pair<const Observation*, const RunRecord*>>> by_node;
  for (const auto& run : runs)
    for (const auto& o : run.observations) by_node[o.adaptable].emplace_back(&o, &run);
  std::vector<NodeVisit> out;
  for (const auto& node : nodes_) {
    const Node& n = *node;
    NodeVisit visit;
    visit.adaptable = n.adaptable;
    if (n.solved) {
      // No enumeration, no measure: the distinct states the runs visited, counted.
      std::set<std::string> seen;
      for (const auto& [o, run] : by_node[n.adaptable])
        if (const auto s = n.solved_state(o->state)) seen.insert(state_json(*s).dump());
      visit.visited.cells = seen.size();
      visit.share_not_computed = n.solved->why;
      visit.no_map = n.solved->why;
      out.push_back(std::move(visit));
      continue;
    }
    visit.counted = !n.space->has_reals();
    visit.cells = n.domain.count();
    std::set<std::uint64_t> states;
    std::map<std::uint64_t, std::vector<std::string>> sources;  // state → the runs, in order
    for (const auto& [seen, run] : by_node[n.adaptable])
      if (const auto s = n.state_index(seen->state)) {
        states.insert(*s);
        auto& named = sources[*s];
        if (named.empty() || named.back() != run->source) named.push_back(run->source);
      }
    const Fraction whole = n.space->measure(n.domain);
    visit.visited = measure(n, states, nullptr, whole);
    for (const auto& local : n.locals) {
      if (local.pair) continue;
      NodeVisit::TargetShare t;
      t.target = local.target;
      t.share = share_of(n.space->measure(local.states), whole);
      t.visited = measure(n, states, &local.states, whole);
      visit.targets.push_back(std::move(t));
    }
    place_on_map(n, sources, visit);
    out.push_back(std::move(visit));
  }
  return out;
}

}  // namespace uabt::campaign
