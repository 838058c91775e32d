#include "prove/cells.hpp"

#include <optional>

#include "fretish/integer_ranges.hpp"
#include "verify/linear.hpp"
#include "verify/real_cells.hpp"
#include "verify/script_reading.hpp"

namespace uabt::prove {

using fretish::Expr;
using fretish::ExprKind;
using runtime::ScriptValue;
using verify::detail::Affine;
using verify::detail::Fraction;
namespace script = runtime::script;

// `lhs op rhs` as an atom over one variable x of the cut, the others (if any) of the mission's
// state: x's coefficient and the rest (Σ a_m·m + b), so that the breakpoint is -rest / a.
struct detail::Atom {
  std::string variable;
  Fraction a;
  Affine rest;
};

namespace {

using detail::Atom;

std::optional<Atom> atom_of(const std::optional<Affine>& l, const std::optional<Affine>& r,
                            const std::set<std::string, std::less<>>& numeric) {
  if (!l || !r) return std::nullopt;
  const Affine d = l->plus(*r, -1);
  Atom out;
  out.rest.constant = d.constant;
  for (const auto& [name, a] : d.terms) {
    if (numeric.contains(name)) {
      if (!out.variable.empty()) return std::nullopt;  // two variables of the cut
      out.variable = name;
      out.a = a;
    } else {
      out.rest.terms[name] = a;
    }
  }
  if (out.variable.empty()) return std::nullopt;
  return out;
}

// Whether `e` has FRETISH's integer type (its numbers and variables are integers).
bool integral(const Expr& e, const std::set<std::string, std::less<>>& integers) {
  switch (e.kind) {
    case ExprKind::number: return fretish::is_integer_literal(e.text);
    case ExprKind::identifier: return integers.contains(e.text);
    case ExprKind::negate:
    case ExprKind::add:
    case ExprKind::sub:
    case ExprKind::mul:
    case ExprKind::div:
    case ExprKind::mod:
      for (const auto& a : e.args)
        if (!a || !integral(*a, integers)) return false;
      return true;
    default: return false;
  }
}

// `e` as an affine form over the cut's variables and the mission's state; a division of
// integers truncates toward zero, a step function, so it has none.
std::optional<Affine> affine_of(const Expr& e, const std::set<std::string, std::less<>>& numeric,
                                const std::set<std::string, std::less<>>& mission,
                                const std::set<std::string, std::less<>>& integers) {
  const verify::detail::AffineReading reading{
      [&](const Expr& x) { return numeric.contains(x.text) || mission.contains(x.text); },
      [&](const Expr& d) {
        return integral(*d.args[0], integers) && integral(*d.args[1], integers);
      }};
  try {
    return verify::detail::affine_form(e, reading);
  } catch (const verify::detail::FractionOverflow&) {
    return std::nullopt;
  }
}

}  // namespace

void Cuts::add(const Expr& e, const std::string& where, bool at_tick_start) {
  walk(e, where, nullptr, at_tick_start);
}

bool Cuts::cut(const std::optional<Atom>& atom, const std::string& where, bool at_tick_start) {
  if (!atom) return false;
  try {
    if (atom->rest.terms.empty()) {
      breaks_[atom->variable].insert(-atom->rest.constant / atom->a);
      return true;
    }
    MixedAtom mixed;
    for (const auto& [name, a] : atom->rest.terms) mixed.terms.emplace_back(name, a / atom->a);
    mixed.b = atom->rest.constant / atom->a;
    mixed.at_tick_start = at_tick_start;
    mixed.where = where;
    mixed_[atom->variable].push_back(std::move(mixed));
    return true;
  } catch (const verify::detail::FractionOverflow&) {
    return false;
  }
}

bool Cuts::name_value(const std::string& variable, const std::string& value) {
  const auto it = enums_.find(variable);
  if (it == enums_.end() || !it->second.contains(value)) return false;
  named_[variable].insert(value);
  return true;
}

void Cuts::cut_at_range_ends(std::map<std::string, std::vector<fretish::IntegerRange>>& ranges) {
  for (auto& [variable, allowed] : ranges)
    for (const fretish::IntegerRange& r : fretish::merged(std::move(allowed))) {
      if (r.lo) breaks_[variable].insert(Fraction(static_cast<long long>(*r.lo)));
      if (r.hi) breaks_[variable].insert(Fraction(static_cast<long long>(*r.hi)));
    }
}

void Cuts::walk(const Expr& e, const std::string& where, const Expr* atom, bool at_tick_start) {
  if (e.kind == ExprKind::logical_or && e.args.size() >= fretish::kMinRangeRun) {
    // As a whole, a long run of an integer's comparisons with numerals only changes truth at the
    // ends of the union of their ranges (integer_ranges.hpp): cutting there, not at every
    // numeral, keeps 60,000 `depth = k` disjuncts a handful of cells.
    auto [ranges, rest] =
        fretish::integer_runs(e, [&](const Expr&, const fretish::IntegerComparison& c) {
          return numeric_.contains(c.variable->text) && integers_.contains(c.variable->text);
        });
    for (const Expr* arg : rest) walk(*arg, where, atom, at_tick_start);
    cut_at_range_ends(ranges);
    return;
  }
  if ((e.kind == ExprKind::eq || e.kind == ExprKind::ne) && e.args.size() == 2 &&
      e.args[0]->kind == ExprKind::identifier && e.args[1]->kind == ExprKind::identifier &&
      (name_value(e.args[0]->text, e.args[1]->text) ||
       name_value(e.args[1]->text, e.args[0]->text)))
    return;
  if (fretish::is_relation(e.kind) && e.args.size() == 2) {
    std::optional<Atom> a;
    try {
      a = atom_of(affine_of(*e.args[0], numeric_, mission_, integers_),
                  affine_of(*e.args[1], numeric_, mission_, integers_), numeric_);
    } catch (const verify::detail::FractionOverflow&) {
    }
    if (cut(a, "the atom `" + fretish::to_fretish(e) + "` (" + where + ")", at_tick_start)) return;
    atom = &e;
  }
  if (e.kind == ExprKind::identifier && enums_.contains(e.text)) {
    add_uncut(e.text, "`" + e.text +
                          "` is read outside an atom that compares it with one of its "
                          "values (" +
                          where + ")");
    return;
  }
  if (e.kind == ExprKind::identifier && numeric_.contains(e.text)) {
    add_uncut(e.text, atom ? "the atom `" + fretish::to_fretish(*atom) + "` (" + where +
                                 ") does not compare it with a constant or with the mission's "
                                 "own state"
                           : "`" + e.text +
                                 "` is read outside an atom that compares it with a "
                                 "constant (" +
                                 where + ")");
    return;
  }
  for (const auto& a : e.args)
    if (a) walk(*a, where, atom, at_tick_start);
}

void Cuts::add(const script::Program& program, const fretish::Domain& domain,
               const std::string& where) {
  const std::string what = "script `" + program.code() + "` in " + where;
  const auto& nodes = program.nodes();
  for (const std::uint32_t statement : program.statements()) {
    const script::Expr& e = nodes[statement];
    const bool assigns = bt::script::is_assignment(e.op);
    if (assigns) {
      const std::string target = bt::script::entry_key(nodes[e.a].name);
      if (numeric_.contains(target) || enums_.contains(target))
        add_uncut(target, "the " + what + " assigns it");
    }
    // The one reading of the script language: its atoms are cut as a requirement's are.
    const verify::ScriptReading reading =
        verify::read_script_expression(program.script(), assigns ? e.b : statement, domain);
    if (reading.expr) {
      walk(*reading.expr, what, nullptr, false);
      continue;
    }
    for (const std::string& name : program.names())
      if (numeric_.contains(bt::script::entry_key(name)) ||
          enums_.contains(bt::script::entry_key(name)))
        add_uncut(bt::script::entry_key(name),
                  "the " + what + " reads it in a way that has no FRETISH reading (" +
                      reading.error + ")");
  }
}

void Cuts::add_any_of(const std::vector<const script::Program*>& programs,
                      const fretish::Domain& domain, const std::string& where) {
  // Read as one disjunction, so that a long run of an integer's comparisons is cut as a
  // requirement's run is (walk).
  std::vector<fretish::ExprPtr> readings;
  for (const script::Program* program : programs) {
    if (program->statements().size() == 1 &&
        !bt::script::is_assignment(program->nodes()[program->statements().front()].op)) {
      verify::ScriptReading reading =
          verify::read_script_expression(program->script(), program->statements().front(), domain);
      if (reading.expr) {
        readings.push_back(std::move(reading.expr));
        continue;
      }
    }
    add(*program, domain, where);
  }
  if (readings.empty()) return;
  const auto any =
      readings.size() == 1 ? readings.front() : fretish::make_expr(ExprKind::logical_or, readings);
  walk(*any, "the conditions of " + where, nullptr, false);
}

void Cuts::add_truth_read(const std::string& variable, const std::string& where) {
  if (numeric_.contains(variable)) breaks_[variable].insert(Fraction(0));
  if (enums_.contains(variable)) add_uncut(variable, where + " reads it as a truth value");
}

void Cuts::add_uncut(const std::string& variable, const std::string& why) {
  if (!uncut_.contains(variable)) uncut_[variable] = why;
}

const std::set<Fraction>& Cuts::breaks(const std::string& variable) const {
  static const std::set<Fraction> kNone;
  const auto it = breaks_.find(variable);
  return it == breaks_.end() ? kNone : it->second;
}

const std::vector<MixedAtom>& Cuts::mixed(const std::string& variable) const {
  static const std::vector<MixedAtom> kNone;
  const auto it = mixed_.find(variable);
  return it == mixed_.end() ? kNone : it->second;
}

const std::set<std::string, std::less<>>& Cuts::named(const std::string& variable) const {
  static const std::set<std::string, std::less<>> kNone;
  const auto it = named_.find(variable);
  return it == named_.end() ? kNone : it->second;
}

std::string Cuts::uncut(const std::string& variable) const {
  const auto it = uncut_.find(variable);
  return it == uncut_.end() ? std::string() : it->second;
}

namespace {

// The integer inside the open interval (lo, hi) nearest to its middle, if there is one.
std::optional<__int128> integer_inside(const std::optional<Fraction>& lo,
                                       const std::optional<Fraction>& hi) {
  if (!lo && !hi) return 0;
  // The integers strictly inside: from floor(lo) + 1 to the last one below hi.
  const __int128 last = hi ? (hi->denominator() == 1 ? hi->floor() - 1 : hi->floor()) : 0;
  if (!lo) return last;
  const __int128 first = lo->floor() + 1;
  if (!hi) return first;
  if (first > last) return std::nullopt;
  const __int128 middle = ((*lo + *hi) / Fraction(2)).floor();
  return middle < first ? first : middle > last ? last : middle;
}

ScriptValue number_value(const Fraction& f, bool integer) {
  if (integer) return ScriptValue::of_int(static_cast<std::int64_t>(f.numerator()));
  return ScriptValue::of_real(f.to_double());
}

}  // namespace

std::vector<ScriptValue> cell_values(const fretish::Variable& v, const std::set<Fraction>& breaks) {
  const bool integer = v.type == fretish::VarType::integer;
  std::optional<Fraction> lo, hi;
  if (!v.lower.empty()) lo = Fraction::parse(v.lower);
  if (!v.upper.empty()) hi = Fraction::parse(v.upper);
  if (integer) {  // the integers of the range: [ceil(lo), floor(hi)]
    if (lo) lo = Fraction(static_cast<long long>(-(-*lo).floor()));
    if (hi) hi = Fraction(static_cast<long long>(hi->floor()));
  }
  std::vector<Fraction> points;  // sorted: bounds and the breakpoints inside them
  if (lo) points.push_back(*lo);
  for (const Fraction& b : breaks)
    if ((!lo || b > *lo) && (!hi || b < *hi)) points.push_back(b);
  if (hi && (!lo || *hi > *lo)) points.push_back(*hi);
  if (lo && hi && *hi < *lo) return {};  // an empty range
  std::vector<ScriptValue> out;
  auto interval = [&](const std::optional<Fraction>& from, const std::optional<Fraction>& to) {
    if (const auto k = integer_inside(from, to)) {
      out.push_back(integer ? ScriptValue::of_int(static_cast<std::int64_t>(*k))
                            : ScriptValue::of_real(static_cast<double>(*k)));
    } else if (!integer && from && to) {
      out.push_back(ScriptValue::of_real(((*from + *to) / Fraction(2)).to_double()));
    }
  };
  if (!lo) interval(std::nullopt, points.empty() ? std::optional<Fraction>() : points.front());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!integer || points[i].denominator() == 1) out.push_back(number_value(points[i], integer));
    if (i + 1 < points.size()) interval(points[i], points[i + 1]);
  }
  if (!hi && !points.empty()) interval(points.back(), std::nullopt);
  return out;
}

std::vector<ScriptValue> enum_cell_values(const fretish::Variable& v,
                                          const std::set<std::string, std::less<>>& named) {
  std::vector<ScriptValue> out;
  bool unnamed_kept = false;
  for (const std::string& value : v.enum_values) {
    const bool is_named = named.contains(value);
    if (!is_named && unnamed_kept) continue;
    unnamed_kept = unnamed_kept || !is_named;
    out.push_back(ScriptValue::of_string(value));
  }
  return out;
}

}  // namespace uabt::prove
