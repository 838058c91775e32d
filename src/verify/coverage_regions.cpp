#include <algorithm>
#include <map>

#include "base/number_text.hpp"
#include "base/text.hpp"
#include "verify/coverage_parts.hpp"

namespace uabt::verify::detail {

namespace {

// How many rows a region list shows before it says how many more there are.
constexpr std::size_t kMaxRegions = 10;
constexpr std::size_t kMaxCounted = 1000;
// States visited while growing boxes, per list: beyond it the boxes stop growing (they stay
// correct, only more of them).
constexpr std::uint64_t kGrowthBudget = std::uint64_t{1} << 22;

// One dimension of a box: a set of values (booleans, enums), a range of digits (integers,
// cells of one real variable), or a range of cells on each axis with the side of every line
// (two real variables).
struct Selector {
  std::vector<bool> values;
  std::uint64_t lo = 0, hi = 0;  // digits; x cells for two variables
  std::uint64_t ylo = 0, yhi = 0;
  std::vector<int> signs;
};

bool categorical(const Dimension& d) {
  return d.component < 0 && d.sort != smt::Sort::integer;
}

// A boolean or an enum variable as a constraint on the values `taken`: "!flag", "mode = a",
// "mode in {a, b}"; no text when it may take every value.
RegionConstraint values_constraint(const Dimension& d, const std::vector<bool>& taken) {
  RegionConstraint c;
  c.kind = RegionConstraint::Kind::values;
  c.variable = d.name;
  const bool enumeration = d.sort == smt::Sort::enumeration;
  for (std::uint64_t v = 0; v < d.radix; ++v)
    if (taken[v])
      c.values.push_back(enumeration ? d.declaration->enum_values[v] : (v ? "true" : "false"));
  if (c.values.size() == d.radix) return c;
  if (!enumeration)
    c.text = (c.values[0] == "true" ? "" : "!") + d.name;
  else if (c.values.size() == 1)
    c.text = d.name + " = " + c.values[0];
  else
    c.text = d.name + " in {" + join(c.values, ", ") + "}";
  return c;
}

class BoxCover {
 public:
  BoxCover(const Space& space, const Bits& set, const Bits& dont_care)
      : space_(space), set_(set), dont_care_(dont_care), covered_(set.size(), false) {}

  // States to grow boxes from before all others (the verifier's witnesses).
  void prefer(std::vector<std::uint64_t> states) { preferred_ = std::move(states); }

  // The next box, grown from a preferred state, else the first state not yet covered; false
  // when all are covered.
  bool next(std::vector<Selector>& box) {
    std::uint64_t seed = set_.size();
    while (!preferred_.empty() && seed == set_.size()) {
      const std::uint64_t s = preferred_.front();
      preferred_.erase(preferred_.begin());
      if (s < set_.size() && set_.test(s) && !covered_.test(s)) seed = s;
    }
    if (seed == set_.size()) {
      while (seed_ < set_.size() && (!set_.test(seed_) || covered_.test(seed_))) ++seed_;
      if (seed_ >= set_.size()) return false;
      seed = seed_;
    }
    const auto& dims = space_.dimensions();
    box.assign(dims.size(), {});
    for (std::size_t d = 0; d < dims.size(); ++d) {
      const std::uint64_t digit = space_.digit(seed, d);
      Selector& s = box[d];
      if (categorical(dims[d])) {
        s.values.assign(dims[d].radix, false);
        s.values[digit] = true;
      } else if (dims[d].component >= 0 && two_d(d)) {
        const auto& cell = component(d).cells[digit];
        s.lo = s.hi = cell.axis_cell[0];
        s.ylo = s.yhi = cell.axis_cell[1];
        s.signs = cell.signs;
      } else {
        s.lo = s.hi = digit;
      }
    }
    for (std::size_t d = 0; d < dims.size(); ++d) grow(box, d);
    for_each(box, [&](std::uint64_t s) {
      if (set_.test(s)) covered_.set(s);
      return true;
    });
    return true;
  }

  // The members of the set inside the box.
  Bits members(const std::vector<Selector>& box) const {
    Bits out(set_.size(), false);
    for_each(box, [&](std::uint64_t s) {
      if (set_.test(s)) out.set(s);
      return true;
    });
    return out;
  }

 private:
  const Space& space_;
  const Bits& set_;
  const Bits& dont_care_;
  Bits covered_;
  std::uint64_t seed_ = 0;
  std::uint64_t visited_ = 0;
  std::vector<std::uint64_t> preferred_;

  const RealComponent& component(std::size_t d) const {
    return space_.components()[static_cast<std::size_t>(space_.dimensions()[d].component)];
  }
  bool two_d(std::size_t d) const { return component(d).axes.size() == 2; }

  std::vector<std::uint64_t> digits(const std::vector<Selector>& box, std::size_t d) const {
    const Dimension& dim = space_.dimensions()[d];
    const Selector& s = box[d];
    std::vector<std::uint64_t> out;
    if (categorical(dim)) {
      for (std::uint64_t v = 0; v < dim.radix; ++v)
        if (s.values[v]) out.push_back(v);
    } else if (dim.component >= 0 && two_d(d)) {
      const auto& cells = component(d).cells;
      for (std::uint64_t c = 0; c < cells.size(); ++c) {
        const auto& cell = cells[c];
        if (cell.axis_cell[0] >= s.lo && cell.axis_cell[0] <= s.hi && cell.axis_cell[1] >= s.ylo &&
            cell.axis_cell[1] <= s.yhi && cell.signs == s.signs)
          out.push_back(c);
      }
    } else {
      for (std::uint64_t v = s.lo; v <= s.hi; ++v) out.push_back(v);
    }
    return out;
  }

  // Calls f on every state of the box until it returns false; false then.
  template <typename F>
  bool for_each(const std::vector<Selector>& box, F f) const {
    const auto& dims = space_.dimensions();
    std::vector<std::vector<std::uint64_t>> lists;
    for (std::size_t d = 0; d < dims.size(); ++d) {
      lists.push_back(digits(box, d));
      if (lists.back().empty()) return true;
    }
    std::vector<std::size_t> at(dims.size(), 0);
    for (;;) {
      std::uint64_t s = 0;
      for (std::size_t d = 0; d < dims.size(); ++d) s += lists[d][at[d]] * space_.stride(d);
      if (!f(s)) return false;
      std::size_t d = 0;
      for (; d < dims.size(); ++d) {
        if (++at[d] < lists[d].size()) break;
        at[d] = 0;
      }
      if (d == dims.size()) return true;
    }
  }

  bool inside(const std::vector<Selector>& box) {
    return for_each(box, [&](std::uint64_t s) {
      ++visited_;
      return set_.test(s) || dont_care_.test(s);
    });
  }

  // Grows one side of one dimension of the box as far as it stays inside the set.
  void grow(std::vector<Selector>& box, std::size_t d) {
    const Dimension& dim = space_.dimensions()[d];
    auto try_with = [&](auto change) {
      if (visited_ > kGrowthBudget) return false;
      std::vector<Selector> wider = box;
      if (!change(wider[d])) return false;
      // Only the added slab needs checking: the rest of the box is inside already.
      std::vector<Selector> slab = wider;
      if (!change_to_slab(box[d], slab[d], dim)) return false;
      if (!inside(slab)) return false;
      box = std::move(wider);
      return true;
    };
    if (categorical(dim)) {
      for (std::uint64_t v = 0; v < dim.radix; ++v)
        if (!box[d].values[v])
          try_with([v](Selector& s) {
            s.values[v] = true;
            return true;
          });
      return;
    }
    const std::uint64_t x_cells = dim.component >= 0 ? component(d).axes[0].cells() : dim.radix;
    while (box[d].hi + 1 < x_cells && try_with([](Selector& s) { return ++s.hi, true; })) {
    }
    while (box[d].lo > 0 && try_with([](Selector& s) { return --s.lo, true; })) {
    }
    if (dim.component >= 0 && two_d(d)) {
      const std::uint64_t y_cells = component(d).axes[1].cells();
      while (box[d].yhi + 1 < y_cells && try_with([](Selector& s) { return ++s.yhi, true; })) {
      }
      while (box[d].ylo > 0 && try_with([](Selector& s) { return --s.ylo, true; })) {
      }
    }
  }

  // Turns the widened selector into the part that the widening added.
  static bool change_to_slab(const Selector& before, Selector& after, const Dimension& dim) {
    if (categorical(dim)) {
      for (std::size_t v = 0; v < after.values.size(); ++v)
        after.values[v] = after.values[v] && !before.values[v];
      return true;
    }
    if (after.hi != before.hi)
      after.lo = after.hi;
    else if (after.lo != before.lo)
      after.hi = after.lo;
    else if (after.yhi != before.yhi)
      after.ylo = after.yhi;
    else if (after.ylo != before.ylo)
      after.yhi = after.ylo;
    else
      return false;
    return true;
  }
};

std::string number_text(const Fraction& f) {
  return f.decimal();
}

// "x + 2*y" with the relation and the right-hand side.
std::string line_text(const RealComponent& comp, const Line& l, int sign) {
  auto term = [](const Fraction& c, const std::string& v, bool first) {
    std::string out;
    const bool negative = c.sign() < 0;
    const Fraction m = negative ? -c : c;
    out += first ? (negative ? "-" : "") : (negative ? " - " : " + ");
    if (!(m == Fraction(1))) out += number_text(m) + "*";
    return out + v;
  };
  return term(l.a, comp.axes[0].variable, true) + term(l.b, comp.axes[1].variable, false) +
         (sign < 0   ? " < "
          : sign > 0 ? " > "
                     : " = ") +
         number_text(-l.c);
}

RegionConstraint axis_range(const RealAxis& axis, std::uint64_t lo, std::uint64_t hi) {
  RegionConstraint c;
  c.kind = RegionConstraint::Kind::interval;
  c.variable = axis.variable;
  if (axis.breaks.size() < 2 || (lo == 0 && hi + 1 == axis.cells())) return c;  // whole range
  const Fraction& from = axis.from(lo);
  const Fraction& to = axis.to(hi);
  c.lower = number_text(from);
  c.upper = number_text(to);
  c.lower_value = from.to_double();
  c.upper_value = to.to_double();
  c.lower_closed = RealAxis::is_point(lo);
  c.upper_closed = RealAxis::is_point(hi);
  if (lo == hi && RealAxis::is_point(lo))
    c.text = axis.variable + " = " + c.lower;
  else
    c.text = axis.variable + " in " + (c.lower_closed ? "[" : "(") + c.lower + ", " + c.upper +
             (c.upper_closed ? "]" : ")");
  return c;
}

}  // namespace

RegionConstraint describe_range(const Space& space, std::size_t dim, std::uint64_t lo,
                                std::uint64_t hi, const fretish::Domain&) {
  const Dimension& d = space.dimensions()[dim];
  RegionConstraint c;
  c.variable = d.name;
  if (d.component >= 0) return axis_range(space.components()[d.component].axes[0], lo, hi);
  if (d.sort == smt::Sort::integer) {
    c.kind = RegionConstraint::Kind::interval;
    if (lo == 0 && hi + 1 == d.radix) return c;
    c.lower = number_text(d.number(lo));
    c.upper = number_text(d.number(hi));
    c.lower_value = static_cast<double>(d.number(lo));
    c.upper_value = static_cast<double>(d.number(hi));
    c.text =
        lo == hi ? d.name + " = " + c.lower : d.name + " in [" + c.lower + ", " + c.upper + "]";
    return c;
  }
  std::vector<bool> taken(d.radix, false);
  for (std::uint64_t v = lo; v <= hi; ++v) taken[v] = true;
  return values_constraint(d, taken);
}

namespace {

std::vector<RegionConstraint> render(const Space& space, const std::vector<Selector>& box,
                                     const fretish::Domain& domain) {
  std::vector<RegionConstraint> out;
  const auto& dims = space.dimensions();
  auto keep = [&](RegionConstraint c) {
    if (!c.text.empty()) out.push_back(std::move(c));
  };
  // Variables in declaration order: discrete ones first in the space, then reals; a reader
  // wants the domain's order.
  std::vector<std::pair<std::size_t, RegionConstraint>> ordered;
  for (std::size_t d = 0; d < dims.size(); ++d) {
    const Dimension& dim = dims[d];
    const Selector& s = box[d];
    if (categorical(dim)) {
      ordered.emplace_back(d, values_constraint(dim, s.values));
      continue;
    }
    if (dim.component < 0 || space.components()[dim.component].axes.size() == 1) {
      ordered.emplace_back(d, describe_range(space, d, s.lo, s.hi, domain));
      continue;
    }
    const RealComponent& comp = space.components()[dim.component];
    ordered.emplace_back(d, axis_range(comp.axes[0], s.lo, s.hi));
    ordered.emplace_back(d, axis_range(comp.axes[1], s.ylo, s.yhi));
    // A line is a constraint of the region when the region lies on it or it cuts the box.
    const Fraction x0 = comp.axes[0].from(s.lo), x1 = comp.axes[0].to(s.hi);
    const Fraction y0 = comp.axes[1].from(s.ylo), y1 = comp.axes[1].to(s.yhi);
    for (std::size_t k = 0; k < comp.lines.size(); ++k) {
      const Line& l = comp.lines[k];
      bool below = false, above = false;
      for (const auto& x : {x0, x1})
        for (const auto& y : {y0, y1}) {
          const int sg = l.at(x, y).sign();
          below = below || sg < 0;
          above = above || sg > 0;
        }
      if (s.signs[k] != 0 && !(below && above)) continue;
      RegionConstraint c;
      c.kind = RegionConstraint::Kind::linear;
      c.text = line_text(comp, l, s.signs[k]);
      ordered.emplace_back(d, c);
    }
  }
  // Declaration order of the variables.
  auto rank = [&](const RegionConstraint& c) {
    for (std::size_t k = 0; k < domain.variables.size(); ++k)
      if (domain.variables[k].name == c.variable) return k;
    return c.kind == RegionConstraint::Kind::linear ? domain.variables.size() + 1
                                                    : domain.variables.size();
  };
  std::stable_sort(ordered.begin(), ordered.end(),
                   [&](const auto& a, const auto& b) { return rank(a.second) < rank(b.second); });
  for (auto& [d, c] : ordered) keep(std::move(c));
  return out;
}

void cover(const Space& space, const Bits& may, const Bits& sure, const Bits& dont_care,
           const std::vector<std::string>& requirements, const fretish::Domain& domain,
           const Fraction& total, const std::vector<std::uint64_t>& witnesses,
           std::vector<Region>& out, std::size_t& omitted) {
  BoxCover boxes(space, may, dont_care);
  boxes.prefer(witnesses);
  std::vector<Selector> box;
  while (boxes.next(box)) {
    if (out.size() >= kMaxRegions) {
      // Only counted; a fragmented set stops being counted at some point (then "… and more").
      if (++omitted >= kMaxCounted) break;
      continue;
    }
    Region r;
    r.constraints = render(space, box, domain);
    r.requirements = requirements;
    const Bits inside = boxes.members(box);
    const Fraction m = space.measure(inside & sure);
    r.measure = exact_of(m);
    r.share = exact_of(ratio(m, total));
    r.exact = (inside & ~sure).count() == 0;
    out.push_back(std::move(r));
  }
}

}  // namespace

void fill_regions(const Space& space,
                  const std::vector<const fretish::SelectionRequirement*>& requirements,
                  const NodeTruths& truths, const std::vector<Finding>& findings,
                  Coverage& coverage) {
  // The witnesses of this node's findings, by check and requirements, in finding order: one
  // pass, so that a node with thousands of overlaps does not scan every finding per pair.
  std::map<std::vector<std::string>, std::vector<std::uint64_t>> overlap_witnesses;
  std::vector<std::uint64_t> gap_witnesses;
  for (const auto& f : findings) {
    if (f.adaptable != coverage.adaptable) continue;
    if (f.check != "guard-gap" && f.check != "guard-overlap") continue;
    const auto s = space.state_of(f.witness);
    if (!s) continue;
    if (f.check == "guard-gap")
      gap_witnesses.push_back(*s);
    else
      overlap_witnesses[f.requirements].push_back(*s);
  }
  auto witnesses = [&](const std::vector<std::string>& ids) {
    const auto it = overlap_witnesses.find(ids);
    return it == overlap_witnesses.end() ? std::vector<std::uint64_t>{} : it->second;
  };
  const fretish::Domain& domain = space.domain();
  const Fraction total = space.measure(truths.domain.sure);
  const Bits outside = ~truths.domain.maybe;
  if (truths.gap.maybe.any()) {
    std::vector<std::string> ids;
    for (const auto* r : requirements) ids.push_back(r->id);
    cover(space, truths.gap.maybe, truths.gap.sure, outside, ids, domain, total, gap_witnesses,
          coverage.gap_regions, coverage.gap_regions_omitted);
  }
  if (!truths.overlap.maybe.any()) return;
  for (std::size_t i = 0; i < requirements.size(); ++i) {
    if (!requirements[i]->guard) continue;
    for (std::size_t j = i + 1; j < requirements.size(); ++j) {
      if (!requirements[j]->guard) continue;
      if (!truths.enabled[i].maybe.intersects(truths.enabled[j].maybe)) continue;
      const Bits both = truths.enabled[i].maybe & truths.enabled[j].maybe;
      const std::vector<std::string> ids{requirements[i]->id, requirements[j]->id};
      cover(space, both, truths.enabled[i].sure & truths.enabled[j].sure, outside, ids, domain,
            total, witnesses(ids), coverage.overlap_regions, coverage.overlap_regions_omitted);
    }
  }
}

}  // namespace uabt::verify::detail

namespace uabt::verify {

std::string Region::text() const {
  std::string out;
  for (const auto& c : constraints) out += (out.empty() ? "" : " & ") + c.text;
  return out.empty() ? "every state of the domain" : out;
}

}  // namespace uabt::verify
