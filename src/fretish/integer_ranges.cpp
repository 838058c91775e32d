#include "fretish/integer_ranges.hpp"

#include <algorithm>

#include "fretish/relation.hpp"

namespace uabt::fretish {

std::vector<IntegerRange> ranges_of(ExprKind op, __int128 c) {
  switch (op) {
    case ExprKind::eq: return {{c, c}};
    case ExprKind::ne: return {{std::nullopt, c - 1}, {c + 1, std::nullopt}};
    case ExprKind::lt: return {{std::nullopt, c - 1}};
    case ExprKind::le: return {{std::nullopt, c}};
    case ExprKind::gt: return {{c + 1, std::nullopt}};
    case ExprKind::ge: return {{c, std::nullopt}};
    default: return {};
  }
}

std::vector<IntegerRange> merged(std::vector<IntegerRange> ranges) {
  std::sort(ranges.begin(), ranges.end(), [](const IntegerRange& a, const IntegerRange& b) {
    if (!a.lo || !b.lo) return !a.lo && b.lo;
    return *a.lo < *b.lo;
  });
  std::vector<IntegerRange> out;
  for (const IntegerRange& r : ranges) {
    IntegerRange* last = out.empty() ? nullptr : &out.back();
    if (last && (!last->hi || !r.lo || *r.lo <= *last->hi + 1)) {
      if (last->hi && (!r.hi || *r.hi > *last->hi)) last->hi = r.hi;
      continue;
    }
    out.push_back(r);
  }
  return out;
}

std::optional<__int128> integer_numeral(const Expr& e) {
  if (e.kind == ExprKind::negate && e.args.size() == 1) {
    const auto x = integer_numeral(*e.args[0]);
    return x ? std::optional<__int128>(-*x) : std::nullopt;
  }
  if (e.kind != ExprKind::number || e.text.empty() || e.text.size() > 18 ||
      !std::all_of(e.text.begin(), e.text.end(), [](char ch) { return ch >= '0' && ch <= '9'; }))
    return std::nullopt;
  __int128 value = 0;
  for (const char ch : e.text) value = value * 10 + (ch - '0');
  return value;
}

std::optional<IntegerComparison> integer_comparison(const Expr& e) {
  if (!is_relation(e.kind) || e.args.size() != 2) return std::nullopt;
  const Expr* variable = e.args[0].get();
  const Expr* numeral = e.args[1].get();
  ExprKind op = e.kind;
  if (variable->kind != ExprKind::identifier) {
    std::swap(variable, numeral);
    op = mirrored_relation(op);
  }
  if (variable->kind != ExprKind::identifier) return std::nullopt;
  const auto c = integer_numeral(*numeral);
  if (!c) return std::nullopt;
  return IntegerComparison{variable, ranges_of(op, *c)};
}

IntegerRuns integer_runs(
    const Expr& disjunction,
    const std::function<bool(const Expr& argument, const IntegerComparison& comparison)>& merge) {
  IntegerRuns out;
  for (const auto& arg : disjunction.args) {
    const auto c = integer_comparison(*arg);
    if (c && merge(*arg, *c)) {
      auto& mine = out.ranges[c->variable->text];
      mine.insert(mine.end(), c->ranges.begin(), c->ranges.end());
    } else {
      out.rest.push_back(arg.get());
    }
  }
  return out;
}

}  // namespace uabt::fretish
