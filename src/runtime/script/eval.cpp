// Evaluation of a compiled script, with BT.CPP 4.x's type rules (scripting/operators.hpp):
// booleans are numbers, `+` also joins two strings, `..` joins strings and numbers, a string
// compared with a number is read as a number ('true'/'false' as 1/0), `&&`/`||` evaluate both
// sides. uabt keeps integers exact where BT.CPP uses doubles (+ - * on integers stay
// integers, `/` gives a real); comparisons of reals use BT.CPP's float epsilon for == / !=.
#include <charconv>
#include <cmath>
#include <limits>

#include "runtime/script/program.hpp"

namespace uabt::runtime::script {

namespace {

using Kind = ScriptValue::Kind;

[[noreturn]] void fail(const std::string& message, std::size_t column) {
  throw ScriptError(message, column);
}

// Setters that keep `out.text`'s buffer, so a register allocates at most once.
void set_bool(ScriptValue& out, bool b) {
  out.kind = Kind::boolean;
  out.boolean = b;
}
void set_int(ScriptValue& out, std::int64_t i) {
  out.kind = Kind::integer;
  out.integer = i;
}
void set_real(ScriptValue& out, double r) {
  out.kind = Kind::real;
  out.real = r;
}

bool is_integral(const ScriptValue& v) {
  return v.kind == Kind::integer || v.kind == Kind::boolean;
}
std::int64_t as_int(const ScriptValue& v) {
  return v.kind == Kind::boolean ? (v.boolean ? 1 : 0) : v.integer;
}

const char* op_text(Op op) {
  switch (op) {
    case Op::negate: return "-";
    case Op::logical_not: return "!";
    case Op::complement: return "~";
    case Op::add: return "+";
    case Op::sub: return "-";
    case Op::mul: return "*";
    case Op::div: return "/";
    case Op::concat: return "..";
    case Op::bit_and: return "&";
    case Op::bit_or: return "|";
    case Op::bit_xor: return "^";
    case Op::logic_and: return "&&";
    case Op::logic_or: return "||";
    case Op::assign_create: return ":=";
    case Op::assign: return "=";
    case Op::add_assign: return "+=";
    case Op::sub_assign: return "-=";
    case Op::mul_assign: return "*=";
    case Op::div_assign: return "/=";
    default: return "?";
  }
}

const char* compare_text(CompareOp op) {
  switch (op) {
    case CompareOp::eq: return "==";
    case CompareOp::ne: return "!=";
    case CompareOp::lt: return "<";
    case CompareOp::gt: return ">";
    case CompareOp::le: return "<=";
    case CompareOp::ge: return ">=";
  }
  return "?";
}

std::string operand_types(const ScriptValue& a, const ScriptValue& b) {
  return std::string(kind_name(a.kind)) + " and " + kind_name(b.kind);
}

// BT.CPP's StringToDouble: "true"/"false" are 1/0, otherwise the text must be a number.
double string_to_double(const ScriptValue& v, std::size_t column) {
  if (v.text == "true") return 1.0;
  if (v.text == "false") return 0.0;
  double d = 0.0;
  const char* first = v.text.data();
  const char* last = first + v.text.size();
  const auto [end, ec] = std::from_chars(first, last, d);
  if (v.text.empty() || ec != std::errc() || end != last)
    fail("the string '" + v.text + "' is not a number", column);
  return d;
}

void append_text(std::string& out, const ScriptValue& v) {
  if (v.kind == Kind::string) {
    out += v.text;
  } else {
    out += v.to_string();
  }
}

// `value`'s number written into an entry of `dst`'s type (BT.CPP's Any::copyInto: no lossy
// conversions).
void store_number(ScriptValue& dst, const ScriptValue& value, const std::string& key,
                  std::size_t column) {
  switch (dst.kind) {
    case Kind::real: return set_real(dst, value.as_double());
    case Kind::integer:
      if (is_integral(value)) return set_int(dst, as_int(value));
      if (std::trunc(value.real) == value.real && std::abs(value.real) < 9.2e18)
        return set_int(dst, static_cast<std::int64_t>(value.real));
      break;
    case Kind::boolean: {
      const double d = value.as_double();
      if (d == 0.0 || d == 1.0) return set_bool(dst, d == 1.0);
      break;
    }
    default: break;
  }
  fail("cannot assign " + value.to_string() + " (" + kind_name(value.kind) + ") to '" + key +
           "', which holds a " + kind_name(dst.kind),
       column);
}

}  // namespace

const ScriptValue& Program::run(Blackboard& blackboard) {
  const ScriptValue* last = &empty_;
  for (const std::uint32_t statement : statements_) last = &eval(statement, blackboard);
  return *last;
}

const ScriptValue& Program::eval(std::uint32_t index, Blackboard& bb) {
  const Expr& e = nodes_[index];
  ScriptValue& out = registers_[index];
  switch (e.op) {
    case Op::literal: return e.literal;

    case Op::name: {
      const ScriptValue& v = bb.read(e.slot);
      if (v.empty())
        fail("undefined blackboard key '" + e.name + "' (assign it first, e.g. " + e.name +
                 " := 0, or give it a value in the scenario)",
             e.column);
      if (!copy_reads_) return v;
      out = v;
      return out;
    }

    case Op::negate:
    case Op::logical_not:
    case Op::complement: {
      const ScriptValue& v = eval(e.a, bb);
      if (!v.is_number())
        fail(std::string("operator [") + op_text(e.op) + "] needs a number, not a " +
                 kind_name(v.kind),
             e.column);
      if (e.op == Op::logical_not) {
        set_bool(out, v.as_double() == 0.0);
      } else if (e.op == Op::negate) {
        if (v.kind == Kind::real) {
          set_real(out, -v.real);
        } else if (as_int(v) == std::numeric_limits<std::int64_t>::min()) {
          set_real(out, -static_cast<double>(as_int(v)));
        } else {
          set_int(out, -as_int(v));
        }
      } else {
        if (!is_integral(v) && std::trunc(v.real) != v.real)
          fail("operator [~] needs an integer", e.column);
        set_int(out, ~(is_integral(v) ? as_int(v) : static_cast<std::int64_t>(v.real)));
      }
      return out;
    }

    case Op::add:
    case Op::sub:
    case Op::mul:
    case Op::div: {
      const ScriptValue& l = eval(e.a, bb);
      const ScriptValue& r = eval(e.b, bb);
      if (l.is_number() && r.is_number()) {
        if (e.op != Op::div && is_integral(l) && is_integral(r)) {
          std::int64_t result = 0;
          const std::int64_t a = as_int(l), b = as_int(r);
          const bool overflow = e.op == Op::add   ? __builtin_add_overflow(a, b, &result)
                                : e.op == Op::sub ? __builtin_sub_overflow(a, b, &result)
                                                  : __builtin_mul_overflow(a, b, &result);
          if (!overflow) {
            set_int(out, result);
            return out;
          }
        }
        const double a = l.as_double(), b = r.as_double();
        switch (e.op) {
          case Op::add: set_real(out, a + b); break;
          case Op::sub: set_real(out, a - b); break;
          case Op::mul: set_real(out, a * b); break;
          default: set_real(out, a / b); break;
        }
        return out;
      }
      if (e.op == Op::add && l.is_string() && r.is_string()) {
        if (&out != &l) out.text = l.text;
        out.text += r.text;
        out.kind = Kind::string;
        return out;
      }
      fail(std::string("operator [") + op_text(e.op) + "] cannot combine " + operand_types(l, r),
           e.column);
    }

    case Op::concat: {
      const ScriptValue& l = eval(e.a, bb);
      const ScriptValue& r = eval(e.b, bb);
      if (!(l.is_string() || r.is_string()) || l.empty() || r.empty())
        fail("operator [..] joins strings (and numbers with strings), not " + operand_types(l, r),
             e.column);
      out.text.clear();
      append_text(out.text, l);
      append_text(out.text, r);
      out.kind = Kind::string;
      return out;
    }

    case Op::bit_and:
    case Op::bit_or:
    case Op::bit_xor: {
      const ScriptValue& l = eval(e.a, bb);
      const ScriptValue& r = eval(e.b, bb);
      auto integer = [&](const ScriptValue& v) -> std::int64_t {
        if (is_integral(v)) return as_int(v);
        if (v.kind == Kind::real && std::trunc(v.real) == v.real && std::abs(v.real) < 9.2e18)
          return static_cast<std::int64_t>(v.real);
        fail(std::string("operator [") + op_text(e.op) + "] needs integers, not " +
                 operand_types(l, r),
             e.column);
      };
      const std::int64_t a = integer(l), b = integer(r);
      set_int(out, e.op == Op::bit_and ? (a & b) : e.op == Op::bit_or ? (a | b) : (a ^ b));
      return out;
    }

    case Op::logic_and:
    case Op::logic_or: {
      const ScriptValue& l = eval(e.a, bb);
      const bool lb = l.is_number() && l.as_double() != 0.0;
      const bool l_ok = l.is_number();
      const ScriptValue& r = eval(e.b, bb);
      if (!l_ok || !r.is_number())
        fail(std::string("operator [") + op_text(e.op) + "] needs booleans or numbers, not " +
                 operand_types(l, r),
             e.column);
      const bool rb = r.as_double() != 0.0;
      set_bool(out, e.op == Op::logic_and ? (lb && rb) : (lb || rb));
      return out;
    }

    case Op::compare: return eval_compare(e, bb);

    case Op::conditional: {
      const ScriptValue& c = eval(e.a, bb);
      bool truth = false;
      if (c.is_string()) {
        truth = !c.text.empty();
      } else if (c.is_number()) {
        truth = c.as_double() != 0.0;
      } else {
        fail("the condition of '?:' has no value", e.column);
      }
      return eval(truth ? e.b : e.c, bb);
    }

    case Op::assign_create:
    case Op::assign:
    case Op::add_assign:
    case Op::sub_assign:
    case Op::mul_assign:
    case Op::div_assign: return eval_assign(index, bb);
  }
  return empty_;
}

const ScriptValue& Program::eval_compare(const Expr& e, Blackboard& bb) {
  ScriptValue& out = registers_[static_cast<std::size_t>(&e - nodes_.data())];
  const ScriptValue* lhs = &eval(operands_[e.list_begin], bb);
  for (std::uint32_t i = 0; i + 1 < e.list_size; ++i) {
    // Operands are evaluated left to right and only as far as needed, as in BT.CPP.
    const ScriptValue& rhs = eval(operands_[e.list_begin + i + 1], bb);
    const CompareOp op = compare_ops_[e.ops_begin + i];
    int order = 0;  // <0, 0, >0
    bool equal = false;
    if (lhs->is_string() && rhs.is_string()) {
      const int c = lhs->text.compare(rhs.text);
      order = c < 0 ? -1 : c > 0 ? 1 : 0;
      equal = order == 0;
    } else if (lhs->is_number() || rhs.is_number()) {
      if (is_integral(*lhs) && is_integral(rhs)) {
        const std::int64_t a = as_int(*lhs), b = as_int(rhs);
        order = a < b ? -1 : a > b ? 1 : 0;
        equal = order == 0;
      } else {
        if (lhs->empty() || rhs.empty())
          fail(std::string("cannot compare ") + operand_types(*lhs, rhs), e.column);
        const double a = lhs->is_string() ? string_to_double(*lhs, e.column) : lhs->as_double();
        const double b = rhs.is_string() ? string_to_double(rhs, e.column) : rhs.as_double();
        order = a < b ? -1 : a > b ? 1 : 0;
        equal = std::abs(a - b) <= static_cast<double>(std::numeric_limits<float>::epsilon());
      }
    } else {
      fail(std::string("operator [") + compare_text(op) + "] cannot compare " +
               operand_types(*lhs, rhs),
           e.column);
    }
    bool holds = false;
    switch (op) {
      case CompareOp::eq: holds = equal; break;
      case CompareOp::ne: holds = !equal; break;
      case CompareOp::lt: holds = order < 0; break;
      case CompareOp::gt: holds = order > 0; break;
      case CompareOp::le: holds = order <= 0; break;
      case CompareOp::ge: holds = order >= 0; break;
    }
    if (!holds) {
      set_bool(out, false);
      return out;
    }
    lhs = &rhs;
  }
  set_bool(out, true);
  return out;
}

const ScriptValue& Program::eval_assign(std::uint32_t index, Blackboard& bb) {
  const Expr& e = nodes_[index];
  const Expr& target = nodes_[e.a];
  // Read, not only written: `x = x + 1` reads x, and a pending entry must be resolved first.
  ScriptValue& dst = bb.read_for_update(target.slot);
  const std::string& key = target.name;
  if (dst.empty() && e.op == Op::assign)
    fail("the blackboard entry '" + key +
             "' does not exist yet; use ':=' to create it instead of '='",
         e.column);
  if (dst.empty() && e.op != Op::assign_create)
    fail(std::string("the left operand of [") + op_text(e.op) + "] ('" + key +
             "') is not initialized",
         e.column);
  const ScriptValue& value = eval(e.b, bb);
  if (&value == &dst) return dst;  // x = x

  if (e.op == Op::assign_create || e.op == Op::assign) {
    if (dst.empty() || dst.kind == value.kind) {
      dst = value;  // keeps dst.text's buffer
    } else if (value.is_string()) {
      if (!dst.is_number())
        fail("cannot assign a string to '" + key + "', which holds a " + kind_name(dst.kind),
             e.column);
      ScriptValue number;
      set_real(number, string_to_double(value, e.column));
      store_number(dst, number, key, e.column);
    } else if (dst.is_string()) {
      fail("cannot assign " + value.to_string() + " (" + kind_name(value.kind) + ") to '" + key +
               "', which holds a string",
           e.column);
    } else {
      store_number(dst, value, key, e.column);
    }
    return dst;
  }

  // += -= *= /=
  if (value.is_string()) {
    if (e.op != Op::add_assign || !dst.is_string())
      fail(std::string("operator [") + op_text(e.op) + "] cannot combine " +
               operand_types(dst, value),
           e.column);
    dst.text += value.text;
    return dst;
  }
  if (!dst.is_number() || !value.is_number())
    fail(
        std::string("operator [") + op_text(e.op) + "] cannot combine " + operand_types(dst, value),
        e.column);
  ScriptValue& result = registers_[index];
  std::int64_t exact = 0;
  const bool integral = is_integral(dst) && is_integral(value) && e.op != Op::div_assign;
  bool overflow = true;
  if (integral) {
    const std::int64_t a = as_int(dst), b = as_int(value);
    overflow = e.op == Op::add_assign   ? __builtin_add_overflow(a, b, &exact)
               : e.op == Op::sub_assign ? __builtin_sub_overflow(a, b, &exact)
                                        : __builtin_mul_overflow(a, b, &exact);
  }
  if (integral && !overflow) {
    set_int(result, exact);
  } else {
    const double a = dst.as_double(), b = value.as_double();
    switch (e.op) {
      case Op::add_assign: set_real(result, a + b); break;
      case Op::sub_assign: set_real(result, a - b); break;
      case Op::mul_assign: set_real(result, a * b); break;
      default: set_real(result, a / b); break;
    }
  }
  store_number(dst, result, key, e.column);
  return dst;
}

}  // namespace uabt::runtime::script
