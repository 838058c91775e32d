#include "verify/space.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "smt/atoms.hpp"
#include "smt/evaluate.hpp"
#include "smt/rational.hpp"
#include "verify/compiled_condition.hpp"

namespace uabt::verify::detail {

using fretish::Expr;
using fretish::ExprKind;

namespace {

constexpr std::uint64_t kMaxStates = std::uint64_t{1} << 24;
// Most (atom, state) pairs counting evaluates: each distinct atom gets a truth table over the
// whole space. 6,000 atoms over the 400,004 states of an integer in [0, 100000] and two flags
// would take minutes and gigabytes; then the shares are not counted, and the guard checks
// (made by the solver) still are.
constexpr std::uint64_t kMaxAtomStates = std::uint64_t{1} << 27;
// A real variable's breakpoints from one atom that also reads an integer: one per value.
constexpr std::uint64_t kMaxBreaksPerAtom = 4096;

std::optional<std::int64_t> integer_end(const std::string& text, bool lower) {
  const auto r = smt::parse_rational(text);
  if (!r || r->numerator.size() > 15 || r->denominator.size() > 16) return std::nullopt;
  const double v = std::strtod(text.c_str(), nullptr);
  return static_cast<std::int64_t>(lower ? std::ceil(v) : std::floor(v));
}

std::string quoted(const Expr& atom) {
  return "`" + fretish::to_fretish(atom) + "`";
}

}  // namespace

void variables_of(const Expr& e, const smt::Typing& typing, std::set<std::string>& out) {
  if (e.kind == ExprKind::identifier) {
    if (const smt::TypeInfo* t = typing.find(e); t && (t->variable || t->implicit_boolean))
      out.insert(e.text);
    return;
  }
  for (const auto& arg : e.args) variables_of(*arg, typing, out);
}

std::string Space::plan(const std::set<std::string>& names, const std::vector<const Expr*>& atoms) {
  std::set<std::string> remaining = names;
  std::vector<RealAxis> reals;               // declaration order
  for (const auto& v : domain_.variables) {  // declaration order, then implicit booleans
    if (!remaining.erase(v.name)) continue;
    Dimension d;
    d.name = v.name;
    d.declaration = &v;
    switch (v.type) {
      case fretish::VarType::boolean: break;
      case fretish::VarType::real: {
        if (v.lower.empty() || v.upper.empty())
          return "the real variable " + v.name + " has no " +
                 (v.lower.empty() ? "lower" : "upper") + " bound, so its measure is infinite";
        const auto lo = Fraction::parse(v.lower), hi = Fraction::parse(v.upper);
        if (!lo || !hi) return "the bounds of " + v.name + " do not fit in 128 bits";
        RealAxis axis;
        axis.variable = v.name;
        axis.breaks = {*lo};
        if (*hi > *lo) axis.breaks.push_back(*hi);
        if (*hi < *lo) axis.breaks.clear();  // an empty range: the domain has no state
        reals.push_back(std::move(axis));
        continue;
      }
      case fretish::VarType::enumeration:
        d.sort = smt::Sort::enumeration;
        d.radix = v.enum_values.size();
        break;
      case fretish::VarType::integer: {
        d.sort = smt::Sort::integer;
        if (v.lower.empty() || v.upper.empty())
          return "the integer " + v.name + " has no " + (v.lower.empty() ? "lower" : "upper") +
                 " bound";
        const auto lo = integer_end(v.lower, true), hi = integer_end(v.upper, false);
        if (!lo || !hi) return "the bounds of " + v.name + " are too large to enumerate";
        d.lowest = *lo;
        d.radix = *hi < *lo ? 0 : static_cast<std::uint64_t>(*hi - *lo) + 1;
        break;
      }
    }
    dims_.push_back(d);
  }
  for (const auto& name : remaining) dims_.push_back(Dimension{name});

  // Every atom over real variables: a breakpoint, a line, or not measured.
  auto real_of = [&](const std::string& name) -> RealAxis* {
    for (auto& r : reals)
      if (r.variable == name) return &r;
    return nullptr;
  };
  auto dim_of = [&](const std::string& name) -> const Dimension* {
    for (const auto& d : dims_)
      if (d.name == name) return &d;
    return nullptr;
  };
  std::map<std::string, std::set<Fraction>> breaks;
  struct PlannedLine {
    std::string x, y, atom;
    Line line;
  };
  std::vector<PlannedLine> lines;
  for (const Expr* atom : atoms) {
    const std::string key = fretish::to_fretish(*atom);
    if (plans_.count(key)) continue;
    std::set<std::string> vars;
    variables_of(*atom, typing_, vars);
    AtomPlan& plan = plans_[key];
    if (std::none_of(vars.begin(), vars.end(), [&](const auto& n) { return real_of(n); }))
      continue;  // discrete
    plan.linear = linear_atom(*atom, typing_);
    if (!plan.linear) {
      plan.kind = AtomPlan::Kind::unmeasured;
      note_unmeasured("the atom " + quoted(*atom) + " is not linear");
      continue;
    }
    plan.kind = AtomPlan::Kind::linear;
    std::vector<std::pair<std::string, Fraction>> real_terms, discrete_terms;
    for (const auto& [name, c] : plan.linear->coefficients)
      (real_of(name) ? real_terms : discrete_terms).emplace_back(name, c);
    if (real_terms.size() + discrete_terms.size() > 2) {
      plan.kind = AtomPlan::Kind::unmeasured;
      note_unmeasured("the atom " + quoted(*atom) + " relates more than two variables");
      continue;
    }
    const Fraction& c = plan.linear->constant;
    if (real_terms.size() == 1 && discrete_terms.empty()) {
      breaks[real_terms[0].first].insert(-c / real_terms[0].second);
    } else if (real_terms.size() == 1) {
      // a·x + b·d + c: a breakpoint of x for every value of the integer d.
      const Dimension* d = dim_of(discrete_terms[0].first);
      if (d == nullptr || d->sort != smt::Sort::integer || d->radix > kMaxBreaksPerAtom) {
        plan.kind = AtomPlan::Kind::unmeasured;
        note_unmeasured("the atom " + quoted(*atom) + " relates " + real_terms[0].first +
                        " to an integer with too many values");
        continue;
      }
      auto& out = breaks[real_terms[0].first];
      for (std::uint64_t k = 0; k < d->radix; ++k)
        out.insert(-(c + discrete_terms[0].second * Fraction(d->number(k))) / real_terms[0].second);
    } else if (real_terms.size() == 2) {
      // Ordered by declaration: x is the variable declared first.
      std::size_t ix = 0, iy = 0;
      for (std::size_t k = 0; k < reals.size(); ++k) {
        if (reals[k].variable == real_terms[0].first) ix = k;
        if (reals[k].variable == real_terms[1].first) iy = k;
      }
      Fraction a = real_terms[0].second, b = real_terms[1].second;
      if (ix > iy) {
        std::swap(ix, iy);
        std::swap(a, b);
      }
      lines.push_back({reals[ix].variable, reals[iy].variable, key, {Fraction(1), b / a, c / a}});
    }
  }

  // Components: pairs that lines relate. A variable in lines with two different partners would
  // need cells in three dimensions: those lines are not measured.
  std::map<std::string, std::set<std::string>> partners;
  for (const auto& l : lines) {
    partners[l.x].insert(l.y);
    partners[l.y].insert(l.x);
  }
  std::map<std::pair<std::string, std::string>, std::set<Line>> pair_lines;
  for (const auto& l : lines) {
    const RealAxis* rx = real_of(l.x);
    const RealAxis* ry = real_of(l.y);
    if (partners[l.x].size() > 1 || partners[l.y].size() > 1 || rx->breaks.size() < 2 ||
        ry->breaks.size() < 2) {
      plans_[l.atom].kind = AtomPlan::Kind::unmeasured;
      note_unmeasured(partners[l.x].size() > 1 || partners[l.y].size() > 1
                          ? "linear atoms relate " + l.x + " to more than one other variable"
                          : "the atom `" + l.atom + "` reads a variable whose range is a point");
      continue;
    }
    pair_lines[{l.x, l.y}].insert(l.line);
  }
  std::set<std::string> paired;
  for (auto& axis : reals) {
    if (axis.breaks.empty()) {
      size_ = 0;  // an empty range
      return {};
    }
    const Fraction lo = axis.breaks.front(), hi = axis.breaks.back();
    for (const Fraction& b : breaks[axis.variable])
      if (b > lo && b < hi) axis.breaks.push_back(b);
    std::sort(axis.breaks.begin(), axis.breaks.end());
  }
  for (const auto& axis : reals) {
    if (paired.count(axis.variable)) continue;
    RealComponent comp;
    comp.axes.push_back(axis);
    for (const auto& [pair, set] : pair_lines) {
      if (pair.first != axis.variable) continue;
      comp.axes.push_back(*real_of(pair.second));
      comp.lines.assign(set.begin(), set.end());
      paired.insert(pair.second);
    }
    components_.push_back(std::move(comp));
  }

  discrete_size_ = 1;
  size_ = 1;
  for (const auto& d : dims_) {
    if (d.radix == 0) {
      size_ = 0;
      return {};
    }
    if (size_ > kMaxStates / d.radix) return "the guards range over more than 2^24 states";
    size_ *= d.radix;
  }
  discrete_size_ = size_;
  for (std::size_t k = 0; k < components_.size(); ++k) {
    auto& comp = components_[k];
    comp.build();
    Dimension d;
    d.name = comp.axes[0].variable + (comp.axes.size() > 1 ? ", " + comp.axes[1].variable : "");
    d.sort = smt::Sort::real;
    d.radix = comp.cells.size();
    d.component = static_cast<int>(k);
    if (size_ > kMaxStates / d.radix)
      return "the guards cut the space into more than 2^24 states and cells";
    size_ *= d.radix;
    dims_.push_back(d);
  }
  if (plans_.size() > kMaxAtomStates / size_)
    return "the guards' " + std::to_string(plans_.size()) + " atoms over " + std::to_string(size_) +
           " states are more than the 2^27 evaluations uabt counts";
  strides_.assign(dims_.size(), 1);
  for (std::size_t k = 1; k < dims_.size(); ++k) strides_[k] = strides_[k - 1] * dims_[k - 1].radix;
  // The weight of each combination of real cells: the product of the cells' lengths or areas.
  weights_.assign(size_ / discrete_size_, Fraction(1));
  for (std::uint64_t r = 0; r < weights_.size(); ++r) {
    std::uint64_t rest = r;
    for (const auto& d : dims_) {
      if (d.component < 0) continue;
      const auto& cell = components_[static_cast<std::size_t>(d.component)].cells[rest % d.radix];
      rest /= d.radix;
      weights_[r] = weights_[r] * cell.weight;
      if (weights_[r].is_zero()) break;
    }
  }
  return {};
}

std::optional<Fraction> exact_value(const Value& v) {
  if (v.kind == Value::Kind::integer) return Fraction(static_cast<long long>(v.integer));
  const std::string& text = v.text.empty() ? v.to_string() : v.text;
  const auto slash = text.find('/');
  if (slash == std::string::npos) return Fraction::parse(text);
  const auto n = Fraction::parse(text.substr(0, slash)),
             d = Fraction::parse(text.substr(slash + 1));
  if (!n || !d || d->is_zero()) return std::nullopt;
  return *n / *d;
}

std::optional<int> side_of(const Value& v, const Fraction& breakpoint) {
  if (v.kind == Value::Kind::integer) {
    const Fraction x(static_cast<long long>(v.integer));
    return x < breakpoint ? -1 : breakpoint < x ? 1 : 0;
  }
  if (v.kind != Value::Kind::real || std::isnan(v.real)) return std::nullopt;
  const double at = breakpoint.to_double();
  return v.real < at ? -1 : v.real > at ? 1 : 0;
}

std::optional<std::uint64_t> Space::state_of(const State& state) const {
  std::uint64_t index = 0;
  for (std::size_t k = 0; k < dims_.size(); ++k) {
    const Dimension& d = dims_[k];
    std::uint64_t digit = 0;
    if (d.component < 0) {
      const Value* v = find_value(state, d.name);
      if (v == nullptr) return std::nullopt;
      if (d.sort == smt::Sort::integer) {
        if (v->kind != Value::Kind::integer || v->integer < d.lowest) return std::nullopt;
        digit = static_cast<std::uint64_t>(v->integer - d.lowest);
      } else if (d.sort == smt::Sort::enumeration) {
        const auto& values = d.declaration->enum_values;
        const auto it = std::find(values.begin(), values.end(), v->text);
        if (it == values.end()) return std::nullopt;
        digit = static_cast<std::uint64_t>(it - values.begin());
      } else {
        digit = v->boolean ? 1 : 0;
      }
    } else {
      const RealComponent& comp = components_[static_cast<std::size_t>(d.component)];
      std::vector<Fraction> point;
      std::vector<std::size_t> axis_cells;
      for (const RealAxis& axis : comp.axes) {
        const Value* v = find_value(state, axis.variable);
        const auto x = v ? exact_value(*v) : std::nullopt;
        if (!x) return std::nullopt;
        std::optional<std::size_t> found;
        for (std::size_t c = 0; c < axis.cells() && !found; ++c) {
          const auto from = side_of(*v, axis.from(c));
          if (RealAxis::is_point(c) ? from == 0 : (from > 0 && side_of(*v, axis.to(c)) < 0))
            found = c;
        }
        if (!found) return std::nullopt;
        // At a breakpoint the run computed with the breakpoint itself: so do the lines.
        point.push_back(RealAxis::is_point(*found) ? axis.from(*found) : *x);
        axis_cells.push_back(*found);
      }
      std::vector<int> signs;
      for (const Line& l : comp.lines) signs.push_back(l.at(point[0], point[1]).sign());
      bool found = false;
      for (std::size_t c = 0; c < comp.cells.size() && !found; ++c) {
        const RealCell& cell = comp.cells[c];
        if (cell.axis_cell != axis_cells || cell.signs != signs) continue;
        // Two-variable cells with one sign vector in one box: points differ by where they lie.
        if (comp.axes.size() == 2 && cell.shape.size() == 1 && !(cell.point == point)) continue;
        digit = c;
        found = true;
      }
      if (!found) return std::nullopt;
    }
    if (digit >= d.radix) return std::nullopt;
    index += digit * strides_[k];
  }
  return index;
}

Fraction Space::measure(const Bits& set) const {
  // Members only: a guard's set is a few cells of a space of thousands, and it is measured
  // once per guard. Members come in order, so those of one combination of real cells are
  // counted together.
  Fraction sum;
  std::uint64_t cell = 0, members = 0;
  const auto flush = [&] {
    if (members != 0 && !weights_[cell].is_zero())
      sum += weights_[cell] * Fraction(static_cast<long long>(members));
  };
  set.for_each([&](std::uint64_t i) {
    const std::uint64_t r = i / discrete_size_;
    if (r != cell) {
      flush();
      cell = r;
      members = 0;
    }
    ++members;
  });
  flush();
  return sum;
}

Truth Space::truth(const Expr& e) {
  if (smt::is_boolean_structure(e, typing_)) {
    std::vector<Truth> args;
    for (const auto& a : e.args) args.push_back(truth(*a));
    switch (e.kind) {
      case ExprKind::logical_not: return negation(args[0]);
      case ExprKind::logical_and:
      case ExprKind::logical_or: return junction(e.kind == ExprKind::logical_and, args, size_);
      case ExprKind::logical_xor:
      case ExprKind::ne:
      case ExprKind::iff:
      case ExprKind::eq: {
        // a xor b is (a & !b) | (!a & b); a chain folds left.
        const bool is_xor = e.kind == ExprKind::logical_xor || e.kind == ExprKind::ne;
        Truth acc = args[0];
        for (std::size_t k = 1; k < args.size(); ++k) {
          const Truth& b = args[k];
          Truth x = junction(false,
                             {junction(true, {acc, negation(b)}, size_),
                              junction(true, {negation(acc), b}, size_)},
                             size_);
          // Where an operand has no value, so has the result.
          const Bits none = acc.none | b.none;
          x = {x.sure & ~none, x.maybe & ~none, none};
          acc = is_xor ? x : negation(x);
        }
        return acc;
      }
      case ExprKind::implies: {  // a -> (b -> c) is !a | (!b | c)
        Truth acc = args.back();
        for (std::size_t k = args.size() - 1; k-- > 0;)
          acc = junction(false, {negation(args[k]), acc}, size_);
        return acc;
      }
      default: break;
    }
  }
  if (e.kind == ExprKind::bool_literal)
    return Truth::exactly(Bits(size_, e.bool_value), Bits(size_, false));
  return atom(e);
}

// Evaluates the atom once per assignment of its own dimensions, then spreads the table over
// the space with an odometer that tracks the index into the table.
Truth Space::atom(const Expr& e) {
  const std::string key = fretish::to_fretish(e);
  if (auto it = atoms_.find(key); it != atoms_.end()) return it->second;
  std::set<std::string> names;
  variables_of(e, typing_, names);
  const AtomPlan plan = plans_.count(key) ? plans_[key] : AtomPlan{};
  if (plan.kind == AtomPlan::Kind::unmeasured) {
    const Truth t{Bits(size_, false), Bits(size_, true), Bits(size_, false)};
    atoms_.emplace(key, t);
    return t;
  }
  auto reads = [&](const Dimension& d) {
    if (d.component < 0) return names.count(d.name) > 0;
    for (const auto& axis : components_[static_cast<std::size_t>(d.component)].axes)
      if (names.count(axis.variable)) return true;
    return false;
  };
  std::vector<std::size_t> own;  // indices into dims_
  std::vector<std::uint64_t> sub_stride(dims_.size(), 0);
  std::uint64_t table_size = 1;
  for (std::size_t k = 0; k < dims_.size(); ++k) {
    if (!reads(dims_[k])) continue;
    own.push_back(k);
    sub_stride[k] = table_size;
    table_size *= dims_[k].radix;
  }
  std::map<std::string, std::size_t> slot_of;
  for (std::size_t k = 0; k < own.size(); ++k)
    if (dims_[own[k]].component < 0) slot_of[dims_[own[k]].name] = k;
  std::optional<CompiledCondition> condition;
  if (plan.kind == AtomPlan::Kind::discrete) condition.emplace(e, typing_, slot_of);
  std::vector<std::int64_t> assignment(own.size());
  std::vector<std::uint64_t> digits(own.size(), 0);
  std::vector<std::uint8_t> table(table_size);  // 0 false, 1 true, 2 no value
  std::map<std::string, Fraction> values;
  for (std::uint64_t t = 0; t < table_size; ++t) {
    for (std::size_t k = 0; k < own.size(); ++k) {
      const Dimension& d = dims_[own[k]];
      if (d.component < 0) {
        assignment[k] = d.number(digits[k]);
        if (plan.linear) values[d.name] = Fraction(d.number(digits[k]));
        continue;
      }
      const auto& comp = components_[static_cast<std::size_t>(d.component)];
      const auto& cell = comp.cells[digits[k]];
      for (std::size_t a = 0; a < comp.axes.size(); ++a)
        values[comp.axes[a].variable] = cell.point[a];
    }
    if (condition) {
      const auto v = condition->value(assignment.data());
      table[t] = v ? (*v ? 1 : 0) : 2;
    } else {
      table[t] = plan.linear->holds(values) ? 1 : 0;
    }
    for (std::size_t k = 0; k < own.size(); ++k) {  // next assignment, first dimension fastest
      if (++digits[k] < dims_[own[k]].radix) break;
      digits[k] = 0;
    }
  }
  Bits holds(size_, false), none(size_, false);
  std::vector<std::uint64_t> odometer(dims_.size(), 0);
  std::uint64_t index = 0;
  for (std::uint64_t s = 0; s < size_; ++s) {
    if (table[index] == 1)
      holds.set(s);
    else if (table[index] == 2)
      none.set(s);
    for (std::size_t k = 0; k < dims_.size(); ++k) {
      if (++odometer[k] < dims_[k].radix) {
        index += sub_stride[k];
        break;
      }
      odometer[k] = 0;
      index -= (dims_[k].radix - 1) * sub_stride[k];
    }
  }
  const Truth t = Truth::exactly(holds, none);
  atoms_.emplace(key, t);
  return t;
}

}  // namespace uabt::verify::detail
