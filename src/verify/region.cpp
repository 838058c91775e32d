#include "verify/region.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>

#include "base/number_text.hpp"
#include "base/text.hpp"
#include "smt/rational.hpp"
#include "verify/prefilter.hpp"

namespace uabt::verify::detail {

using fretish::Expr;
using fretish::ExprKind;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

ExprKind negated(ExprKind k) {
  switch (k) {
    case ExprKind::eq: return ExprKind::ne;
    case ExprKind::ne: return ExprKind::eq;
    case ExprKind::lt: return ExprKind::ge;
    case ExprKind::le: return ExprKind::gt;
    case ExprKind::gt: return ExprKind::le;
    default: return ExprKind::lt;
  }
}

// An end of an interval with the text that names it.
struct End {
  double value;
  bool strict = false;
  std::string text;
};

struct Interval {
  End lower{-kInf, false, ""};
  End upper{kInf, false, ""};
  bool integer = false;
  std::vector<std::string> excluded;  // x != c literals

  void tighten_lower(End e) {
    if (e.value > lower.value || (e.value == lower.value && e.strict)) lower = std::move(e);
  }
  void tighten_upper(End e) {
    if (e.value < upper.value || (e.value == upper.value && e.strict)) upper = std::move(e);
  }

  std::string render(const std::string& name) const {
    End lo = lower, hi = upper;
    if (integer) {  // whole numbers read better closed: battery in [0, 19]
      if (lo.value > -kInf) {
        const double v = lo.strict ? std::floor(lo.value) + 1 : std::ceil(lo.value);
        lo = {v, false, number_text(v)};
      }
      if (hi.value < kInf) {
        const double v = hi.strict ? std::ceil(hi.value) - 1 : std::floor(hi.value);
        hi = {v, false, number_text(v)};
      }
    }
    std::string out;
    const bool has_lo = lo.value > -kInf, has_hi = hi.value < kInf;
    if (has_lo && has_hi && lo.value == hi.value && !lo.strict && !hi.strict)
      out = name + " = " + lo.text;
    else if (has_lo && has_hi)
      out = name + " in " + (lo.strict ? "(" : "[") + lo.text + ", " + hi.text +
            (hi.strict ? ")" : "]");
    else if (has_lo)
      out = name + (lo.strict ? " > " : " >= ") + lo.text;
    else if (has_hi)
      out = name + (hi.strict ? " < " : " <= ") + hi.text;
    for (const auto& x : excluded) out += (out.empty() ? "" : " & ") + name + " != " + x;
    return out;
  }
};

std::optional<End> domain_end(const std::string& text) {
  if (text.empty() || !smt::parse_rational(text)) return std::nullopt;
  return End{std::strtod(text.c_str(), nullptr), false, text};
}

}  // namespace

std::string render_cube(const std::vector<CubeLiteral>& cube, const fretish::Domain& domain,
                        const smt::Typing& typing) {
  // Pieces in order of first appearance; variables merge into the piece they first made.
  std::vector<std::string> order;
  std::map<std::string, std::string> boolean_piece;
  std::map<std::string, Interval> intervals;
  std::map<std::string, std::pair<const fretish::Variable*, std::vector<bool>>> enums;
  std::vector<std::string> other;
  auto remember = [&](const std::string& key) {
    for (const auto& k : order)
      if (k == key) return;
    order.push_back(key);
  };
  for (const auto& [atom, positive] : cube) {
    const smt::TypeInfo* t = typing.find(*atom);
    if (atom->kind == ExprKind::identifier && t && t->sort == smt::Sort::boolean) {
      remember(atom->text);
      boolean_piece[atom->text] = (positive ? "" : "!") + atom->text;
      continue;
    }
    if ((atom->kind == ExprKind::eq || atom->kind == ExprKind::ne) && atom->args.size() == 2) {
      const smt::TypeInfo* a = typing.find(*atom->args[0]);
      const smt::TypeInfo* b = typing.find(*atom->args[1]);
      if (a && b && a->sort == smt::Sort::enumeration && (a->variable || b->variable) &&
          (a->enum_index >= 0 || b->enum_index >= 0) && (a->enum_type != nullptr)) {
        const smt::TypeInfo* var = a->variable ? a : b;
        const smt::TypeInfo* lit = a->variable ? b : a;
        const std::string name = var->variable->name;
        auto [it, inserted] = enums.try_emplace(
            name, var->enum_type, std::vector<bool>(var->enum_type->enum_values.size(), true));
        const bool is_eq = (atom->kind == ExprKind::eq) == positive;
        auto& allowed = it->second.second;
        for (std::size_t k = 0; k < allowed.size(); ++k)
          if ((static_cast<int>(k) == lit->enum_index) != is_eq) allowed[k] = false;
        remember(name);
        continue;
      }
    }
    if (auto b = bound_of(*atom, typing)) {
      const ExprKind op = positive ? b->op : negated(b->op);
      auto [it, inserted] = intervals.try_emplace(b->variable);
      Interval& iv = it->second;
      if (inserted) {
        iv.integer = b->integer_variable;
        if (const auto* v = smt::find_variable(domain, b->variable)) {
          if (auto lo = domain_end(v->lower)) iv.tighten_lower(*lo);
          if (auto hi = domain_end(v->upper)) iv.tighten_upper(*hi);
        }
      }
      const End end{b->value, op == ExprKind::lt || op == ExprKind::gt, b->text};
      switch (op) {
        case ExprKind::eq:
          iv.tighten_lower(end);
          iv.tighten_upper(end);
          break;
        case ExprKind::ne: iv.excluded.push_back(b->text); break;
        case ExprKind::lt:
        case ExprKind::le: iv.tighten_upper(end); break;
        default: iv.tighten_lower(end); break;
      }
      remember(b->variable);
      continue;
    }
    const std::string text = fretish::to_fretish(*atom);
    const std::string piece = positive ? text : "!(" + text + ")";
    remember("\x01" + piece);
    other.push_back(piece);
  }
  std::string out;
  for (const auto& key : order) {
    std::string piece;
    if (key[0] == '\x01') {
      piece = key.substr(1);
    } else if (auto it = boolean_piece.find(key); it != boolean_piece.end()) {
      piece = it->second;
    } else if (auto iv = intervals.find(key); iv != intervals.end()) {
      piece = iv->second.render(key);
    } else if (auto en = enums.find(key); en != enums.end()) {
      const auto& [type, allowed] = en->second;
      std::vector<std::string> names;
      for (std::size_t k = 0; k < allowed.size(); ++k)
        if (allowed[k]) names.push_back(type->enum_values[k]);
      piece = names.size() == 1 ? key + " = " + names[0] : key + " in {" + join(names, ", ") + "}";
    }
    if (piece.empty()) continue;
    out += (out.empty() ? "" : " & ") + piece;
  }
  return out.empty() ? "every state of the domain" : out;
}

}  // namespace uabt::verify::detail
