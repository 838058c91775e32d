#include "verify/coverage.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <set>
#include <string>

#include "smt/atoms.hpp"
#include "smt/evaluate.hpp"
#include "smt/rational.hpp"
#include "verify/compiled_condition.hpp"

namespace uabt::verify::detail {

using fretish::Expr;
using fretish::ExprKind;

namespace {

constexpr std::uint64_t kMaxCountedStates = std::uint64_t{1} << 24;

// A set of states as one bit per state of the enumerated space.
class Bits {
 public:
  Bits() = default;
  Bits(std::uint64_t size, bool value)
      : size_(size), words_((size + 63) / 64, value ? ~std::uint64_t{0} : 0) {
    clear_tail();
  }
  void set(std::uint64_t i) { words_[i / 64] |= std::uint64_t{1} << (i % 64); }
  std::uint64_t count() const {
    std::uint64_t n = 0;
    for (auto w : words_) n += static_cast<std::uint64_t>(std::popcount(w));
    return n;
  }
  Bits operator&(const Bits& o) const {
    return zip(o, [](auto a, auto b) { return a & b; });
  }
  Bits operator|(const Bits& o) const {
    return zip(o, [](auto a, auto b) { return a | b; });
  }
  Bits operator^(const Bits& o) const {
    return zip(o, [](auto a, auto b) { return a ^ b; });
  }
  Bits operator~() const {
    Bits r = *this;
    for (auto& w : r.words_) w = ~w;
    r.clear_tail();
    return r;
  }

 private:
  std::uint64_t size_ = 0;
  std::vector<std::uint64_t> words_;

  void clear_tail() {
    if (size_ % 64 != 0 && !words_.empty()) words_.back() &= (std::uint64_t{1} << (size_ % 64)) - 1;
  }
  template <typename F>
  Bits zip(const Bits& o, F f) const {
    Bits r = *this;
    for (std::size_t i = 0; i < r.words_.size(); ++i) r.words_[i] = f(r.words_[i], o.words_[i]);
    return r;
  }
};

// A condition over the space: where it holds, and where it has no value (a division by zero
// that reaches it). `holds` is meaningless where `none` is set.
struct Truth {
  Bits holds;
  Bits none;
};

// One enumerated variable: its values are digit 0 … radix-1.
struct Dimension {
  std::string name;
  const fretish::Variable* declaration = nullptr;  // nullptr: implicit boolean
  smt::Sort sort = smt::Sort::boolean;
  std::int64_t lowest = 0;  // integers: the value of digit 0
  std::uint64_t radix = 2;

  // The value as CompiledCondition reads it: 0/1, the literal index, or the integer.
  std::int64_t number(std::uint64_t digit) const {
    return sort == smt::Sort::integer ? lowest + static_cast<std::int64_t>(digit)
                                      : static_cast<std::int64_t>(digit);
  }
};

void variables_of(const Expr& e, const smt::Typing& typing, std::set<std::string>& out) {
  if (e.kind == ExprKind::identifier) {
    if (const smt::TypeInfo* t = typing.find(e); t && (t->variable || t->implicit_boolean))
      out.insert(e.text);
    return;
  }
  for (const auto& arg : e.args) variables_of(*arg, typing, out);
}

std::optional<std::int64_t> integer_end(const std::string& text, bool lower) {
  const auto r = smt::parse_rational(text);
  if (!r || r->numerator.size() > 15 || r->denominator.size() > 16) return std::nullopt;
  const double v = std::strtod(text.c_str(), nullptr);
  return static_cast<std::int64_t>(lower ? std::ceil(v) : std::floor(v));
}

class Counter {
 public:
  Counter(const fretish::Domain& domain, const smt::Typing& typing)
      : domain_(domain), typing_(typing) {}

  // Sets up the space; returns the reason when it cannot be enumerated.
  std::string plan(const std::set<std::string>& names) {
    std::set<std::string> remaining = names;
    for (const auto& v : domain_.variables) {  // declaration order, then implicit booleans
      if (!remaining.erase(v.name)) continue;
      Dimension d;
      d.name = v.name;
      d.declaration = &v;
      switch (v.type) {
        case fretish::VarType::boolean: break;
        case fretish::VarType::real: return "the guards range over the real variable " + v.name;
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
    size_ = 1;
    for (const auto& d : dims_) {
      if (d.radix == 0) {
        size_ = 0;
        break;
      }
      if (size_ > kMaxCountedStates / d.radix) return "the guards range over more than 2^24 states";
      size_ *= d.radix;
    }
    return {};
  }

  std::uint64_t size() const { return size_; }
  const std::vector<Dimension>& dimensions() const { return dims_; }

  // Where a condition holds and where it has no value. A definite false decides a
  // conjunction (and a definite true a disjunction) even where another operand has no value,
  // as in `battery != 0 & 10 / battery > 2`.
  Truth truth(const Expr& e) {
    if (smt::is_boolean_structure(e, typing_)) {
      std::vector<Truth> args;
      for (const auto& a : e.args) args.push_back(truth(*a));
      Bits any_none(size_, false);
      for (const auto& a : args) any_none = any_none | a.none;
      switch (e.kind) {
        case ExprKind::logical_not: return {~args[0].holds, args[0].none};
        case ExprKind::logical_and:
        case ExprKind::logical_or: return junction(e.kind == ExprKind::logical_and, args);
        case ExprKind::logical_xor:
        case ExprKind::ne:
        case ExprKind::iff:
        case ExprKind::eq: {
          const bool is_xor = e.kind == ExprKind::logical_xor || e.kind == ExprKind::ne;
          Bits acc = args[0].holds;
          for (std::size_t k = 1; k < args.size(); ++k)
            acc = is_xor ? acc ^ args[k].holds : ~(acc ^ args[k].holds);
          return {acc, any_none};
        }
        case ExprKind::implies: {  // a -> (b -> c) is !a | (!b | c)
          Truth acc = args.back();
          for (std::size_t k = args.size() - 1; k-- > 0;)
            acc = junction(false, {Truth{~args[k].holds, args[k].none}, acc});
          return acc;
        }
        default: break;
      }
    }
    if (e.kind == ExprKind::bool_literal) return {Bits(size_, e.bool_value), Bits(size_, false)};
    return atom(e);
  }

 private:
  const fretish::Domain& domain_;
  const smt::Typing& typing_;
  std::vector<Dimension> dims_;
  std::uint64_t size_ = 0;
  std::map<std::string, Truth> atoms_;  // by FRETISH text: repeated atoms are evaluated once

  Truth junction(bool is_and, const std::vector<Truth>& args) const {
    // Where some operand is definitely false (and) / true (or), the result is decided.
    Bits decided(size_, false), any_none(size_, false);
    for (const auto& a : args) {
      decided = decided | ((is_and ? ~a.holds : a.holds) & ~a.none);
      any_none = any_none | a.none;
    }
    return {is_and ? ~decided : decided, any_none & ~decided};
  }

  // Evaluates the atom once per assignment of its own variables, then spreads the table over
  // the space with an odometer that tracks the index into the table.
  Truth atom(const Expr& e) {
    const std::string key = fretish::to_fretish(e);
    if (auto it = atoms_.find(key); it != atoms_.end()) return it->second;
    std::set<std::string> names;
    variables_of(e, typing_, names);
    std::vector<std::size_t> own;  // indices into dims_
    std::vector<std::uint64_t> sub_stride(dims_.size(), 0);
    std::uint64_t table_size = 1;
    for (std::size_t k = 0; k < dims_.size(); ++k) {
      if (!names.count(dims_[k].name)) continue;
      own.push_back(k);
      sub_stride[k] = table_size;
      table_size *= dims_[k].radix;
    }
    std::map<std::string, std::size_t> slot_of;
    std::vector<std::int64_t> assignment(own.size());
    for (std::size_t k = 0; k < own.size(); ++k) {
      slot_of[dims_[own[k]].name] = k;
      assignment[k] = dims_[own[k]].number(0);
    }
    const CompiledCondition condition(e, typing_, slot_of);
    std::vector<std::uint64_t> digits(own.size(), 0);
    std::vector<std::uint8_t> table(table_size);  // 0 false, 1 true, 2 no value
    for (std::uint64_t t = 0; t < table_size; ++t) {
      const auto v = condition.value(assignment.data());
      table[t] = v ? (*v ? 1 : 0) : 2;
      for (std::size_t k = 0; k < own.size(); ++k) {  // next assignment, first variable fastest
        if (++digits[k] < dims_[own[k]].radix) {
          assignment[k] = dims_[own[k]].number(digits[k]);
          break;
        }
        digits[k] = 0;
        assignment[k] = dims_[own[k]].number(0);
      }
    }
    Truth bits{Bits(size_, false), Bits(size_, false)};
    std::vector<std::uint64_t> odometer(dims_.size(), 0);
    std::uint64_t index = 0;
    for (std::uint64_t s = 0; s < size_; ++s) {
      if (table[index] == 1)
        bits.holds.set(s);
      else if (table[index] == 2)
        bits.none.set(s);
      for (std::size_t k = 0; k < dims_.size(); ++k) {
        if (++odometer[k] < dims_[k].radix) {
          index += sub_stride[k];
          break;
        }
        odometer[k] = 0;
        index -= (dims_[k].radix - 1) * sub_stride[k];
      }
    }
    atoms_.emplace(key, bits);
    return bits;
  }
};

}  // namespace

Coverage count_coverage(const std::string& adaptable,
                        const std::vector<const fretish::SelectionRequirement*>& requirements,
                        const std::vector<const Expr*>& assumptions, const fretish::Domain& domain,
                        const smt::Typing& typing) {
  Coverage cov;
  cov.adaptable = adaptable;
  for (const auto* r : requirements) {
    AlternativeCoverage a;
    a.name = r->alternative;
    a.requirement = r->id;
    cov.alternatives.push_back(a);
  }
  // The guards' variables, closed under "an assumption links them": other assumptions only
  // constrain other variables and, the domain being consistent, do not change the counts.
  std::set<std::string> names;
  for (const auto* r : requirements)
    if (r->guard) variables_of(*r->guard, typing, names);
  std::vector<const Expr*> linked;
  std::vector<bool> used(assumptions.size(), false);
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t k = 0; k < assumptions.size(); ++k) {
      if (used[k]) continue;
      std::set<std::string> own;
      variables_of(*assumptions[k], typing, own);
      bool touches = own.empty();
      for (const auto& n : own) touches = touches || names.count(n) > 0;
      if (!touches) continue;
      used[k] = grew = true;
      linked.push_back(assumptions[k]);
      names.insert(own.begin(), own.end());
    }
  }
  Counter counter(domain, typing);
  const std::string reason = counter.plan(names);
  for (const auto& d : counter.dimensions()) cov.variables.push_back(d.name);
  if (!reason.empty()) {
    cov.not_counted_reason = reason;
    return cov;
  }
  try {
    // Enum membership and ranges are built into the enumeration; assumptions are filtered.
    Bits in_domain(counter.size(), true);
    for (const Expr* a : linked) {
      const Truth t = counter.truth(*a);
      if ((in_domain & t.none).count() > 0)
        throw smt::EvaluationError("an assumption has no value in some state (division by zero)");
      in_domain = in_domain & t.holds;
    }
    Bits any(counter.size(), false), two_or_more(counter.size(), false);
    Bits claimed(counter.size(), false);  // an earlier guard (or the default) holds
    for (std::size_t k = 0; k < requirements.size(); ++k) {
      const auto* r = requirements[k];
      Bits enabled = in_domain;
      if (r->guard) {
        const Truth t = counter.truth(*r->guard);
        if ((in_domain & t.none).count() > 0)
          throw smt::EvaluationError("the guard of " + r->id +
                                     " has no value in some state (division by zero)");
        enabled = t.holds & in_domain;
      }
      cov.alternatives[k].enabled_states = enabled.count();
      cov.alternatives[k].states = (enabled & ~claimed).count();
      claimed = claimed | enabled;
      if (r->guard) {
        two_or_more = two_or_more | (any & enabled);
        any = any | enabled;
      }
    }
    cov.states = in_domain.count();
    cov.gap_states = (in_domain & ~claimed).count();
    cov.overlap_states = two_or_more.count();
    cov.counted = true;
  } catch (const smt::EvaluationError& e) {
    for (auto& a : cov.alternatives) a.states = a.enabled_states = 0;
    cov.not_counted_reason = e.what();
  }
  return cov;
}

}  // namespace uabt::verify::detail
