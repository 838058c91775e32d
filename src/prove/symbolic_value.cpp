#include "prove/symbolic_value.hpp"

#include <charconv>
#include <cmath>

#include "base/number_text.hpp"
#include "smt/assign.hpp"
#include "smt/division.hpp"
#include "smt/rational.hpp"
#include "verify/script_reading.hpp"

namespace uabt::prove {

using runtime::ScriptValue;
using runtime::script::Op;

int SymbolCodes::code(const std::string& name) {
  const auto [it, added] = codes_.emplace(name, static_cast<int>(names_.size()));
  if (added) names_.push_back(name);
  return it->second;
}

z3::expr real_literal(z3::context& ctx, double value) {
  char buffer[64];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  if (ec != std::errc() || !std::isfinite(value))
    throw SymbolicUnsupported("the real " + number_text(value) + " has no exact value");
  return ctx.real_val(std::string(buffer, end).c_str());
}

z3::expr constant_of(z3::context& ctx, const ScriptValue& v, SymType type, SymbolCodes& codes) {
  switch (type) {
    case SymType::boolean: return ctx.bool_val(v.kind == ScriptValue::Kind::boolean && v.boolean);
    case SymType::integer:
      return ctx.int_val(
          static_cast<int64_t>(v.kind == ScriptValue::Kind::integer ? v.integer : 0));
    case SymType::real: return real_literal(ctx, v.kind == ScriptValue::Kind::real ? v.real : 0.0);
    case SymType::symbol:
      return ctx.int_val(v.kind == ScriptValue::Kind::string ? codes.code(v.text) : -1);
  }
  return ctx.bool_val(false);
}

namespace {

bool integral(SymType t) {
  return t == SymType::boolean || t == SymType::integer;
}
bool numeric(SymType t) {
  return t != SymType::symbol;
}
z3::expr as_int(const SymValue& v) {
  if (v.type == SymType::boolean) return z3::ite(v.e, v.e.ctx().int_val(1), v.e.ctx().int_val(0));
  return v.e;
}
z3::expr as_real(const SymValue& v) {
  if (v.type == SymType::real) return v.e;
  return z3::to_real(as_int(v));
}
z3::expr truth(const SymValue& v) {
  if (v.type == SymType::boolean) return v.e;
  if (v.type == SymType::integer) return v.e != 0;
  return v.e != v.e.ctx().real_val(0);
}

class ScriptEncoder {
 public:
  ScriptEncoder(z3::context& ctx, const runtime::script::Program& p, const ScriptScope& scope,
                std::vector<z3::expr>& values, const z3::expr& guard, const std::string& where)
      : ctx_(ctx), p_(p), scope_(scope), values_(values), guard_(guard), where_(where) {}

  std::optional<SymValue> run() {
    std::optional<SymValue> last;
    for (std::uint32_t s : p_.statements()) last = statement(s);
    return last;
  }

 private:
  [[noreturn]] void refuse(const std::string& why) const {
    throw SymbolicUnsupported(where_ + ": `" + p_.code() + "`: " + why);
  }

  int var(const runtime::script::Expr& e) const {
    const int v = scope_.var_of(e.name);
    if (v < 0) refuse("'" + e.name + "' is neither a domain variable nor a condition");
    return v;
  }

  SymValue read(int v) const {
    const SymType t = (*scope_.types)[static_cast<std::size_t>(v)];
    SymValue out{t, values_[static_cast<std::size_t>(v)], {}};
    if (t == SymType::symbol) out.codes = (*scope_.domains)[static_cast<std::size_t>(v)];
    return out;
  }

  SymValue statement(std::uint32_t index) {
    const runtime::script::Expr& e = p_.nodes()[index];
    switch (e.op) {
      case Op::assign_create:
      case Op::assign:
      case Op::add_assign:
      case Op::sub_assign:
      case Op::mul_assign: return assign(e);
      case Op::div_assign: refuse("'/=' is not modelled");
      default: return eval(index);
    }
  }

  SymValue assign(const runtime::script::Expr& e) {
    const int v = var(p_.nodes()[e.a]);
    const SymValue value = eval(e.b);
    const SymValue dst = read(v);
    z3::expr next = dst.e;
    if (e.op == Op::assign || e.op == Op::assign_create) {
      switch (dst.type) {
        case SymType::boolean:
          if (value.type != SymType::boolean) refuse("assigns a non-boolean to a boolean");
          next = value.e;
          break;
        case SymType::integer:
          if (!integral(value.type)) refuse("assigns a non-integer to an integer");
          smt::assign(next, as_int(value));
          break;
        case SymType::real:
          if (!numeric(value.type)) refuse("assigns a name to a real");
          smt::assign(next, as_real(value));
          break;
        case SymType::symbol:
          if (value.type != SymType::symbol) refuse("assigns a number to an enumeration");
          for (int c : value.codes)
            if (!dst.codes.contains(c))
              refuse("assigns '" + scope_.codes->name(c) + "', which is not a value of '" +
                     p_.nodes()[e.a].name + "'");
          next = value.e;
          break;
      }
    } else {
      if (!numeric(value.type) || dst.type == SymType::symbol || dst.type == SymType::boolean)
        refuse("compound assignment on non-numbers");
      if (dst.type == SymType::integer) {
        if (!integral(value.type)) refuse("compound assignment of a real to an integer");
        const z3::expr a = dst.e, b = as_int(value);
        smt::assign(next, e.op == Op::add_assign ? a + b : e.op == Op::sub_assign ? a - b : a * b);
      } else {
        const z3::expr a = dst.e, b = as_real(value);
        smt::assign(next, e.op == Op::add_assign ? a + b : e.op == Op::sub_assign ? a - b : a * b);
      }
    }
    z3::expr& slot = values_[static_cast<std::size_t>(v)];
    smt::assign(slot, guard_.is_true() ? next : z3::ite(guard_, next, slot));
    SymValue out = dst;
    out.e = next;
    return out;
  }

  // An expression of the script, read as FRETISH (with BT.CPP's `/` and `==`) and encoded.
  SymValue eval(std::uint32_t index) {
    const verify::ScriptReading reading =
        verify::read_script_expression(p_.script(), index, *scope_.domain, true);
    if (!reading.expr) refuse(reading.error);
    const auto resolve = [this](const std::string& name) {
      // The reading gives a quoted value as its name, and refuses an unquoted one.
      if (scope_.domain->find(name) == nullptr && scope_.domain->enum_owning(name) != nullptr) {
        const int c = scope_.codes->code(name);
        return SymValue{SymType::symbol, ctx_.int_val(c), {c}};
      }
      if (const int v = scope_.var_of(name); v >= 0) return read(v);
      refuse("'" + name + "' is neither a domain variable nor a condition");
    };
    return fretish_value(ctx_, *reading.expr, resolve, where_ + ": `" + p_.code() + "`");
  }

  z3::context& ctx_;
  const runtime::script::Program& p_;
  const ScriptScope& scope_;
  std::vector<z3::expr>& values_;
  z3::expr guard_;
  std::string where_;
};

}  // namespace

std::optional<SymValue> run_script(z3::context& ctx, const runtime::script::Program& program,
                                   const ScriptScope& scope, std::vector<z3::expr>& values,
                                   const z3::expr& guard, const std::string& where) {
  return ScriptEncoder(ctx, program, scope, values, guard, where).run();
}

z3::expr script_truth(const SymValue& v, const std::string& where) {
  if (!numeric(v.type)) throw SymbolicUnsupported(where + ": a script whose result is a name");
  if (v.type == SymType::integer)  // the engine (as BT.CPP) takes only 0 and 1 as a truth
    throw SymbolicUnsupported(where + ": a script whose result is an integer");
  return truth(v);
}

namespace {

using K = fretish::ExprKind;

class FretishEncoder {
 public:
  FretishEncoder(z3::context& ctx, const std::function<SymValue(const std::string&)>& resolve,
                 const std::string& where)
      : ctx_(ctx), resolve_(resolve), where_(where) {}

  SymValue value(const fretish::Expr& e) {
    switch (e.kind) {
      case K::bool_literal: return {SymType::boolean, ctx_.bool_val(e.bool_value), {}};
      case K::number: {
        const auto r = smt::parse_rational(e.text);
        if (!r) refuse("the number " + e.text);
        if (smt::is_integer_literal(e.text))
          return {SymType::integer, ctx_.int_val(r->text().c_str()), {}};
        return {SymType::real, ctx_.real_val(r->text().c_str()), {}};
      }
      case K::identifier: return resolve_(e.text);
      case K::logical_not: return {SymType::boolean, !boolean(*e.args[0]), {}};
      case K::logical_and:
      case K::logical_or: {
        z3::expr acc = ctx_.bool_val(e.kind == K::logical_and);
        for (const auto& a : e.args)
          smt::assign(acc, e.kind == K::logical_and ? acc && boolean(*a) : acc || boolean(*a));
        return {SymType::boolean, acc, {}};
      }
      case K::logical_xor:
        return {SymType::boolean, boolean(*e.args[0]) != boolean(*e.args[1]), {}};
      case K::implies:
        return {SymType::boolean, z3::implies(boolean(*e.args[0]), boolean(*e.args[1])), {}};
      case K::iff: return {SymType::boolean, boolean(*e.args[0]) == boolean(*e.args[1]), {}};
      case K::eq:
      case K::ne: {
        const SymValue a = value(*e.args[0]), b = value(*e.args[1]);
        z3::expr same = ctx_.bool_val(false);
        if (a.type == SymType::boolean && b.type == SymType::boolean) {
          smt::assign(same, a.e == b.e);
        } else if (a.type == SymType::symbol && b.type == SymType::symbol) {
          smt::assign(same, a.e == b.e);
        } else if (number_kind(a) && number_kind(b)) {
          smt::assign(same, both_int(a, b) ? a.e == b.e : as_real(a) == as_real(b));
        } else {
          refuse("'" + fretish::to_fretish(e) + "' compares values of different kinds");
        }
        return {SymType::boolean, e.kind == K::eq ? same : !same, {}};
      }
      case K::lt:
      case K::le:
      case K::gt:
      case K::ge: {
        const SymValue a = number(*e.args[0]), b = number(*e.args[1]);
        const z3::expr x = both_int(a, b) ? a.e : as_real(a), y = both_int(a, b) ? b.e : as_real(b);
        const z3::expr r = e.kind == K::lt   ? x < y
                           : e.kind == K::le ? x <= y
                           : e.kind == K::gt ? x > y
                                             : x >= y;
        return {SymType::boolean, r, {}};
      }
      case K::add:
      case K::sub:
      case K::mul: {
        const SymValue a = number(*e.args[0]), b = number(*e.args[1]);
        const bool ints = both_int(a, b);
        const z3::expr x = ints ? a.e : as_real(a), y = ints ? b.e : as_real(b);
        const z3::expr r = e.kind == K::add ? x + y : e.kind == K::sub ? x - y : x * y;
        return {ints ? SymType::integer : SymType::real, r, {}};
      }
      case K::negate: {
        const SymValue a = number(*e.args[0]);
        return {a.type, -a.e, {}};
      }
      case K::div:
      case K::mod: {
        // By a non-zero numeral only, which keeps the term linear: integers by the truncated
        // quotient and its remainder (smt/division.hpp), anything else by real division.
        if (!nonzero_numeral(*e.args[1])) break;
        const SymValue a = number(*e.args[0]);
        SymValue b = number(*e.args[1]);
        smt::assign(b.e, b.e.simplify());  // `-8` as the numeral -8
        if (both_int(a, b))
          return {SymType::integer,
                  e.kind == K::div ? smt::truncated_quotient(a.e, b.e)
                                   : smt::truncated_remainder(a.e, b.e),
                  {}};
        if (e.kind == K::mod) refuse("'" + fretish::to_fretish(e) + "': mod of a real");
        return {SymType::real, as_real(a) / as_real(b), {}};
      }
      case K::call: return call(e);
      default: break;
    }
    refuse("'" + fretish::to_fretish(e) + "' (division, modulo and powers are not modelled)");
  }

  z3::expr boolean(const fretish::Expr& e) {
    const SymValue v = value(e);
    if (v.type != SymType::boolean) refuse("'" + fretish::to_fretish(e) + "' is not a boolean");
    return v.e;
  }

 private:
  [[noreturn]] void refuse(const std::string& why) const {
    throw SymbolicUnsupported(where_ + ": " + why);
  }
  static bool number_kind(const SymValue& v) {
    return v.type == SymType::integer || v.type == SymType::real;
  }
  // A number written out (`8`, `0.5`, `-8`) that is not zero.
  static bool nonzero_numeral(const fretish::Expr& e) {
    if (e.kind == K::negate && e.args.size() == 1 && e.args[0]) return nonzero_numeral(*e.args[0]);
    return e.kind == K::number && e.text.find_first_not_of("0.") != std::string::npos;
  }
  static bool both_int(const SymValue& a, const SymValue& b) {
    return a.type == SymType::integer && b.type == SymType::integer;
  }
  SymValue number(const fretish::Expr& e) {
    const SymValue v = value(e);
    if (!number_kind(v)) refuse("'" + fretish::to_fretish(e) + "' is not a number");
    return v;
  }
  SymValue call(const fretish::Expr& e) {
    const std::string& f = e.text;
    if ((f == "absReal" || f == "absInt") && e.args.size() == 1) {
      const SymValue a = number(*e.args[0]);
      return {a.type, z3::ite(a.e >= 0, a.e, -a.e), {}};
    }
    if ((f == "minReal" || f == "maxReal" || f == "minInt" || f == "maxInt") &&
        e.args.size() == 2) {
      const SymValue a = number(*e.args[0]), b = number(*e.args[1]);
      const bool ints = both_int(a, b);
      const z3::expr x = ints ? a.e : as_real(a), y = ints ? b.e : as_real(b);
      const bool min = f.rfind("min", 0) == 0;
      return {ints ? SymType::integer : SymType::real, z3::ite(min ? x <= y : x >= y, x, y), {}};
    }
    if (f == "ite" && e.args.size() == 3) {
      const z3::expr c = boolean(*e.args[0]);
      const SymValue a = value(*e.args[1]), b = value(*e.args[2]);
      if (number_kind(a) && number_kind(b) && a.type != b.type)  // an ite with a real branch
        return {SymType::real, z3::ite(c, as_real(a), as_real(b)), {}};
      if (a.type != b.type) refuse("the branches of ite have different kinds");
      SymValue out{a.type, z3::ite(c, a.e, b.e), a.codes};
      out.codes.insert(b.codes.begin(), b.codes.end());
      return out;
    }
    refuse("function '" + f + "' is not modelled");
  }

  z3::context& ctx_;
  const std::function<SymValue(const std::string&)>& resolve_;
  std::string where_;
};

}  // namespace

z3::expr fretish_bool(z3::context& ctx, const fretish::Expr& e,
                      const std::function<SymValue(const std::string&)>& resolve,
                      const std::string& where) {
  return FretishEncoder(ctx, resolve, where).boolean(e);
}

SymValue fretish_value(z3::context& ctx, const fretish::Expr& e,
                       const std::function<SymValue(const std::string&)>& resolve,
                       const std::string& where) {
  return FretishEncoder(ctx, resolve, where).value(e);
}

}  // namespace uabt::prove
