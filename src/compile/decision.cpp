// Builds the decision structure of --selection optimized over a SelectionSpace.
#include "compile/decision.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace uabt::compile {

namespace {

// Literals one enum test may name (BT.CPP parses `a == 'x' || a == 'y' || …` recursively).
constexpr std::size_t kMaxLiterals = 32;

double xlogx(double x) {
  return x > 0 ? x * std::log(x) : 0;
}

// Label distribution of a set of cells, by measure and by count.
struct Distribution {
  std::map<int, std::pair<double, double>> by_label;  // label -> (weight, count)
  double weight = 0, count = 0;

  void add(int label, double w, double c) {
    auto& e = by_label[label];
    e.first += w;
    e.second += c;
    weight += w;
    count += c;
  }
  void add(const Distribution& other) {
    for (const auto& [l, e] : other.by_label) add(l, e.first, e.second);
  }
  // Weighted entropy times total (sum over labels of -x log(x/total)).
  std::pair<double, double> spread() const {
    double sw = 0, sc = 0;
    for (const auto& [l, e] : by_label) {
      sw += xlogx(e.first);
      sc += xlogx(e.second);
    }
    return {xlogx(weight) - sw, xlogx(count) - sc};
  }
};

class Greedy {
 public:
  explicit Greedy(const SelectionSpace& space) : space_(space) {}

  Decision run() {
    std::vector<std::size_t> all(space_.cells());
    for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
    decision_.root = build(all);
    return std::move(decision_);
  }

 private:
  struct Candidate {
    DecisionTest test;
    double gain_weight = 0, gain_count = 0, balance = 0;
  };

  int leaf(int label) {
    Decision::Node n;
    n.label = label;
    decision_.nodes.push_back(n);
    return static_cast<int>(decision_.nodes.size()) - 1;
  }

  void score(Candidate& cand, const Distribution& parent,
             const std::vector<Distribution>& per_piece) const {
    Distribution yes, no;
    for (std::size_t p = 0; p < per_piece.size(); ++p)
      (cand.test.holds[p] ? yes : no).add(per_piece[p]);
    const auto [pw, pc] = parent.spread();
    const auto [yw, yc] = yes.spread();
    const auto [nw, nc] = no.spread();
    cand.gain_weight = parent.weight > 0 ? (pw - yw - nw) / parent.weight : 0;
    cand.gain_count = (pc - yc - nc) / parent.count;
    cand.balance = std::min(yes.count, no.count);
  }

  static bool better(const Candidate& a, const Candidate& b) {
    constexpr double eps = 1e-12;
    if (std::abs(a.gain_weight - b.gain_weight) > eps) return a.gain_weight > b.gain_weight;
    if (std::abs(a.gain_count - b.gain_count) > eps) return a.gain_count > b.gain_count;
    return a.balance > b.balance;
  }

  void candidates_for(std::size_t d, const std::vector<Distribution>& per_piece,
                      std::vector<Candidate>& out) const {
    const Dimension& dim = space_.dimensions[d];
    std::vector<std::size_t> present;
    for (std::size_t p = 0; p < per_piece.size(); ++p)
      if (per_piece[p].count > 0) present.push_back(p);
    if (present.size() < 2) return;
    auto add = [&](std::vector<bool> holds) {
      Candidate c;
      c.test.dimension = d;
      c.test.holds = std::move(holds);
      out.push_back(std::move(c));
    };
    const std::size_t n = dim.pieces.size();
    switch (dim.kind) {
      case Dimension::Kind::boolean:
      case Dimension::Kind::opaque: add({false, true}); return;
      case Dimension::Kind::ordered:
        for (std::size_t i = 0; i + 1 < present.size(); ++i) {
          std::vector<bool> holds(n, false);
          for (std::size_t p = 0; p <= present[i]; ++p) holds[p] = true;
          add(std::move(holds));
        }
        return;
      case Dimension::Kind::enumeration: {
        // One literal; the literals whose cells all select one requirement; and a split of the
        // literals into two halves of equal measure (a binary search over the enum).
        std::map<int, std::vector<bool>> by_label;
        std::vector<std::size_t> order = present;
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
          return per_piece[a].weight + per_piece[a].count * 1e-9 >
                 per_piece[b].weight + per_piece[b].count * 1e-9;
        });
        // A test names at most kMaxLiterals literals (one ScriptCondition): on a larger enum
        // the "half" is the heaviest kMaxLiterals.
        const bool halves = present.size() <= 2 * kMaxLiterals;
        std::vector<bool> half(n, false);
        double yes = 0, no = 0;
        std::size_t taken = 0;
        for (std::size_t p : order) {
          const double w = per_piece[p].weight + per_piece[p].count * 1e-9;
          if (halves ? yes <= no : taken++ < kMaxLiterals) {
            half[p] = true;
            yes += w;
          } else {
            no += w;
          }
          std::vector<bool> one(n, false);
          one[p] = true;
          add(std::move(one));
          if (per_piece[p].by_label.size() == 1) {
            auto& group = by_label[per_piece[p].by_label.begin()->first];
            group.resize(n, false);
            group[p] = true;
          }
        }
        add(std::move(half));
        for (auto& [label, group] : by_label) {
          const auto members =
              static_cast<std::size_t>(std::count(group.begin(), group.end(), true));
          if (members > 1 && members < present.size() &&
              std::min(members, present.size() - members) <= kMaxLiterals)
            add(std::move(group));
        }
        return;
      }
    }
  }

  int build(const std::vector<std::size_t>& cells) {
    Distribution parent;
    for (std::size_t c : cells) parent.add(space_.label[c], space_.weight[c], 1);
    if (parent.by_label.size() == 1) return leaf(parent.by_label.begin()->first);

    std::optional<Candidate> best;
    for (std::size_t d = 0; d < space_.dimensions.size(); ++d) {
      std::vector<Distribution> per_piece(space_.dimensions[d].pieces.size());
      for (std::size_t c : cells)
        per_piece[space_.piece(c, d)].add(space_.label[c], space_.weight[c], 1);
      std::vector<Candidate> cands;
      candidates_for(d, per_piece, cands);
      for (auto& cand : cands) {
        score(cand, parent, per_piece);
        if (!best || better(cand, *best)) best = std::move(cand);
      }
    }
    // Cells with different labels differ in some piece, so some test splits them.
    const DecisionTest& test = best->test;
    std::vector<std::size_t> yes, no;
    for (std::size_t c : cells)
      (test.holds[space_.piece(c, test.dimension)] ? yes : no).push_back(c);
    decision_.tests.push_back(test);
    const int test_index = static_cast<int>(decision_.tests.size()) - 1;
    const int yes_node = build(yes);
    const int no_node = build(no);
    Decision::Node n;
    n.test = test_index;
    n.yes = yes_node;
    n.no = no_node;
    decision_.nodes.push_back(n);
    return static_cast<int>(decision_.nodes.size()) - 1;
  }

  const SelectionSpace& space_;
  Decision decision_;
};

template <typename PerCell>
SelectionCost summarize(const SelectionSpace& space, PerCell cost_of) {
  SelectionCost cost;
  double total = 0, weighted = 0, plain = 0;
  for (std::size_t c = 0; c < space.cells(); ++c) {
    const int n = cost_of(c);
    cost.worst = std::max(cost.worst, n);
    total += space.weight[c];
    weighted += space.weight[c] * n;
    plain += n;
  }
  if (total > 0)
    cost.average = weighted / total;
  else if (space.cells() > 0)
    cost.average = plain / static_cast<double>(space.cells());
  return cost;
}

}  // namespace

Decision build_decision(const SelectionSpace& space) {
  return Greedy(space).run();
}

SelectionCost decision_cost(const SelectionSpace& space, const Decision& decision) {
  return summarize(space, [&](std::size_t c) {
    int n = 0;
    int at = decision.root;
    while (decision.nodes[at].test >= 0) {
      const DecisionTest& t = decision.tests[decision.nodes[at].test];
      ++n;
      at = t.holds[space.piece(c, t.dimension)] ? decision.nodes[at].yes : decision.nodes[at].no;
    }
    return n;
  });
}

SelectionCost algorithm1_cost(const SelectionSpace& space) {
  return summarize(space, [&](std::size_t c) {
    int n = 0;
    for (const auto& g : space.guards)
      if (evaluate_on_cell(space, g, c, &n)) break;
    return n;
  });
}

}  // namespace uabt::compile
