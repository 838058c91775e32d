// bb-read-before-write: a must-write analysis over one pass of BT.CPP's tick order from a fresh
// blackboard. Later ticks only add entries (nothing here unsets one), so a read that the first
// pass can reach unwritten is the first place BT.CPP fails.
#include <algorithm>
#include <cstdint>
#include <map>
#include <set>

#include "verify/tree/blackboard_checks.hpp"

namespace uabt::verify::tree {

namespace {

constexpr std::uint32_t kNone = UINT32_MAX;

using Bits = std::vector<std::uint64_t>;

bool has(const Bits& b, std::uint32_t e) {
  return (b[e / 64] >> (e % 64)) & 1U;
}

std::string step_text(const FlowGraph& g, std::uint32_t v) {
  const Vertex& x = g.vertices[v];
  const std::string& label = g.nodes[x.node].label;
  switch (x.step) {
    case Step::enter: return "ticks " + label;
    case Step::run: return label + " runs";
    case Step::success: return label + " succeeds";
    case Step::failure: return label + " fails";
    case Step::skipped: return label + " is skipped";
  }
  return label;
}

// For every vertex, the one before it on a shortest path of ticks from the root on which no
// vertex writes `entry` (kNone: none, or the root).
std::vector<std::uint32_t> shortest_unwritten(const FlowGraph& g, std::uint32_t entry) {
  const std::size_t n = g.vertices.size();
  std::vector<std::uint32_t> dist(n, kNone), parent(n, kNone);
  dist[0] = 0;
  for (std::uint32_t v = 1; v < n; ++v) {
    for (const std::uint32_t p : g.vertices[v].preds) {
      if (dist[p] == kNone) continue;
      const auto& w = g.vertices[p].writes;
      if (std::find(w.begin(), w.end(), entry) != w.end()) continue;
      const auto& r = g.vertices[p].reads;
      if (std::any_of(r.begin(), r.end(), [&](const Read& x) { return x.entry == entry; }))
        continue;  // a read there would have failed first
      if (dist[p] + 1 < dist[v]) dist[v] = dist[p] + 1, parent[v] = p;
    }
  }
  return parent;
}

// The witness: that path to `target`, as the ticks and the results nodes decided themselves.
std::vector<std::uint32_t> witness(const FlowGraph& g, const std::vector<std::uint32_t>& parent,
                                   std::uint32_t target) {
  std::vector<std::uint32_t> path;
  for (std::uint32_t v = target; v != kNone; v = parent[v]) path.push_back(v);
  std::reverse(path.begin(), path.end());
  // A node's return counts when the node decided it itself (a leaf, a pre-condition); the
  // returns that only pass a child's result up are implied by the path.
  std::vector<std::uint32_t> shown;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Vertex& x = g.vertices[path[i]];
    if (x.step == Step::enter) {
      shown.push_back(path[i]);
      continue;
    }
    if (x.step == Step::run) continue;
    const Vertex& before = g.vertices[path[i - 1]];
    if (before.node == x.node && (before.step == Step::enter || before.step == Step::run))
      shown.push_back(path[i]);
  }
  return shown;
}

}  // namespace

std::vector<Finding> check_read_before_write(const FlowGraph& g) {
  std::vector<Finding> out;
  const std::size_t vertices = g.vertices.size();
  if (vertices == 0) return out;
  const std::size_t words = (g.entry_keys.size() + 63) / 64;
  // Entries surely written when each vertex is left, kept only until its last successor read
  // them: memory follows the width of the tree, not its size.
  std::vector<std::uint32_t> pending(vertices, 0);
  for (const Vertex& v : g.vertices)
    for (const std::uint32_t p : v.preds) ++pending[p];
  std::vector<Bits> out_bits(vertices);
  std::vector<char> reached(vertices, 0);
  std::vector<std::pair<std::uint32_t, const Read*>> unwritten;  // (vertex, read)

  Bits robot(words, 0);
  for (std::uint32_t e = 0; e < g.robot.size(); ++e)
    if (g.robot[e]) robot[e / 64] |= std::uint64_t{1} << (e % 64);

  for (std::uint32_t v = 0; v < vertices; ++v) {
    const Vertex& x = g.vertices[v];
    Bits in;
    if (v == 0) {
      in = robot;
      reached[v] = 1;
    } else {
      for (const std::uint32_t p : x.preds) {
        if (!reached[p]) continue;
        if (!reached[v]) {
          in = out_bits[p];
          reached[v] = 1;
        } else {
          for (std::size_t w = 0; w < words; ++w) in[w] &= out_bits[p][w];
        }
      }
      for (const std::uint32_t p : x.preds)
        if (--pending[p] == 0) Bits().swap(out_bits[p]);
    }
    if (!reached[v]) continue;
    for (const Read& r : x.reads) {
      if (!has(in, r.entry)) unwritten.emplace_back(v, &r);
      // Past a read the entry is there, or BT.CPP has already failed: one finding per defect.
      in[r.entry / 64] |= std::uint64_t{1} << (r.entry % 64);
    }
    for (const std::uint32_t e : x.writes) in[e / 64] |= std::uint64_t{1} << (e % 64);
    if (pending[v] != 0) out_bits[v] = std::move(in);
  }

  std::set<std::tuple<std::string, int, int, std::uint32_t>> reported;
  std::map<std::uint32_t, std::vector<std::uint32_t>> parents;  // one search per entry
  for (const auto& [v, read] : unwritten) {
    const TickNode& node = g.nodes[g.vertices[v].node];
    if (!reported
             .insert({node.location.file, node.location.line, node.location.column, read->entry})
             .second)
      continue;
    auto it = parents.find(read->entry);
    if (it == parents.end())
      it = parents.emplace(read->entry, shortest_unwritten(g, read->entry)).first;
    const std::vector<std::uint32_t> path = witness(g, it->second, v);
    const std::string name = g.entry_name(read->entry);
    const bool script = read->what.rfind("the script", 0) == 0;
    Finding f = make_finding(
        "bb-read-before-write",
        "blackboard entry " + name + " is read by " + read->what +
            " before anything writes it, on a path of " + std::to_string(path.size()) +
            " ticks from the root: BehaviorTree.CPP " +
            (script ? "throws there (\"Variable not found: " + g.entry_keys[read->entry] +
                          "\", or \"… is not initialized\" when a port declared the entry)"
                    : "finds no entry there and the node's getInput() fails"),
        node.location);
    for (const std::uint32_t step : path)
      f.related.push_back({g.nodes[g.vertices[step].node].location, step_text(g, step)});
    f.notes.push_back(
        "write it on every path before this read (an output port, a Script with `" +
        g.entry_keys[read->entry] +
        " := …`, a SubTree port), or, when the robot publishes it, declare it in domain.fret");
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace uabt::verify::tree
