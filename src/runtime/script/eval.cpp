// Evaluation of a compiled script, with BT.CPP 4.10's type rules (scripting/operators.hpp,
// utils/convert_impl.hpp): booleans are numbers, every operator computes on doubles and gives
// a double (the literals true/false are 1.0/0.0 too; only integer literals and entries keep
// their integer type), an integer beyond 2^53 that an operator would round is an error, `&&`
// and `||` accept an integer only when it is 0 or 1, `+` also joins two strings, `..` joins
// strings and numbers, a string compared with a number is read as a number ('true'/'false'
// as 1/0), `&&`/`||` evaluate both sides, == and != use BT.CPP's float epsilon. A value
// written into an existing entry takes the entry's type (Any::copyInto): no lossy
// conversions, and an integer written into a boolean entry is kept as that integer.
#include <charconv>
#include <cmath>
#include <limits>

#include "runtime/script/program.hpp"

namespace uabt::runtime::script {

namespace {

using Kind = ScriptValue::Kind;

// The largest integer a double holds exactly: BT.CPP refuses to round one beyond it.
constexpr std::int64_t kMaxExactInteger = (std::int64_t{1} << 53) - 1;

[[noreturn]] void fail(const std::string& message, std::size_t column) {
  throw ScriptError(message, column);
}

// Setters that keep `out.text`'s buffer, so a register allocates at most once.
void set_bool(ScriptValue& out, bool b) {
  out.kind = Kind::boolean;
  out.boolean = b;
  out.bool_entry = false;
}
void set_int(ScriptValue& out, std::int64_t i) {
  out.kind = Kind::integer;
  out.integer = i;
  out.bool_entry = false;
}
void set_real(ScriptValue& out, double r) {
  out.kind = Kind::real;
  out.real = r;
  out.bool_entry = false;
}

bool is_integral(const ScriptValue& v) {
  return v.kind == Kind::integer || v.kind == Kind::boolean;
}
std::int64_t as_int(const ScriptValue& v) {
  return v.kind == Kind::boolean ? (v.boolean ? 1 : 0) : v.integer;
}

// A number as the double BT.CPP computes with (Any::cast<double>).
double number(const ScriptValue& v, std::size_t column) {
  if (v.kind == Kind::integer && (v.integer > kMaxExactInteger || v.integer < -kMaxExactInteger))
    fail("the integer " + std::to_string(v.integer) +
             " has no exact double value (beyond 2^53), so no operator can use it",
         column);
  return v.as_double();
}

// A number as the 64-bit integer BT.CPP casts to (Any::cast<int64_t>): a real must be whole
// and in range. False when it is not.
bool whole(const ScriptValue& v, std::int64_t& out) {
  if (is_integral(v)) {
    out = as_int(v);
    return true;
  }
  // In range first (this also refuses NaN), then whole: the cast back must give it again.
  if (v.kind != Kind::real || !(v.real < 0x1p63 && v.real >= -0x1p63)) return false;
  out = static_cast<std::int64_t>(v.real);
  return static_cast<double>(out) == v.real;
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

// An operand of && or || as BT.CPP's Any::cast<bool>: a real is true when not zero, an
// integer must be 0 or 1.
bool truth_of(const ScriptValue& v, Op op, std::size_t column) {
  if (v.kind == Kind::integer && v.integer != 0 && v.integer != 1)
    fail(std::string("operator [") + op_text(op) +
             "] takes an integer only when it is 0 or 1, not " + std::to_string(v.integer) +
             " (compare it, e.g. x != 0)",
         column);
  return v.as_double() != 0.0;
}

void append_text(std::string& out, const ScriptValue& v) {
  if (v.kind == Kind::string) {
    out += v.text;
  } else {
    out += v.to_string();
  }
}

// The type BT.CPP gives the entry that holds `v`.
const char* entry_type(const ScriptValue& v) {
  return v.bool_entry ? kind_name(Kind::boolean) : kind_name(v.kind);
}

[[noreturn]] void fail_store(const ScriptValue& dst, const ScriptValue& value,
                             const std::string& key, std::size_t column) {
  fail("cannot assign " + value.to_string() + " (" + kind_name(value.kind) + ") to '" + key +
           "', which holds a " + entry_type(dst),
       column);
}

// `value`'s number written into an entry of `dst`'s type (BT.CPP's Any::copyInto: no lossy
// conversions). A boolean entry stays boolean: BT.CPP's Any keeps bools and integers as int64,
// so copyInto stores the raw integer (a whole real converted to one) under the type bool; the
// entry then holds that integer, which a later boolean read refuses, and a later 0, 1, true or
// false makes it a boolean again.
void store_number(ScriptValue& dst, const ScriptValue& value, const std::string& key,
                  std::size_t column) {
  std::int64_t i = 0;
  if (dst.kind == Kind::boolean || dst.bool_entry) {
    if (value.kind == Kind::boolean) return set_bool(dst, value.boolean);
    if (!whole(value, i)) fail_store(dst, value, key, column);
    if (i == 0 || i == 1) return set_bool(dst, i == 1);
    set_int(dst, i);
    dst.bool_entry = true;
    return;
  }
  switch (dst.kind) {
    case Kind::real: return set_real(dst, number(value, column));
    case Kind::integer:
      if (whole(value, i)) return set_int(dst, i);
      break;
    default: break;
  }
  fail_store(dst, value, key, column);
}

double arithmetic(Op op, double a, double b) {
  switch (op) {
    case Op::add:
    case Op::add_assign: return a + b;
    case Op::sub:
    case Op::sub_assign: return a - b;
    case Op::mul:
    case Op::mul_assign: return a * b;
    default: return a / b;
  }
}

}  // namespace

const ScriptValue& Program::run(Blackboard& blackboard) {
  const ScriptValue* last = &empty_;
  for (const std::uint32_t statement : script_.statements()) last = &eval(statement, blackboard);
  return *last;
}

const ScriptValue& Program::eval(std::uint32_t index, Blackboard& bb) {
  const Expr& e = script_.nodes()[index];
  ScriptValue& out = registers_[index];
  switch (e.op) {
    case Op::literal:
      // true/false are the doubles 1.0/0.0 (set once by parse()).
      return e.literal.kind == Kind::boolean ? out : e.literal;

    case Op::name: {
      const ScriptValue& v = bb.read(e.slot);
      if (v.empty())
        fail("undefined blackboard key '" + e.name + "' (assign it first, e.g. " + e.name +
                 " := 0, or give it a value in the scenario)",
             e.column);
      if (!script_.nested_assignment()) return v;
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
      const double d = number(v, e.column);
      if (e.op == Op::logical_not) {
        set_real(out, d == 0.0 ? 1.0 : 0.0);
      } else if (e.op == Op::negate) {
        set_real(out, -d);
      } else {
        if (!(d < 0x1p63 && d >= -0x1p63))
          fail("operator [~] needs a number within the 64-bit integers", e.column);
        set_real(out, static_cast<double>(~static_cast<std::int64_t>(d)));
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
        const double a = number(l, e.column);
        set_real(out, arithmetic(e.op, a, number(r, e.column)));
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
      std::int64_t a = 0, b = 0;
      if (!l.is_number() || !r.is_number() || !whole(l, a) || !whole(r, b))
        fail(std::string("operator [") + op_text(e.op) + "] needs integers, not " +
                 operand_types(l, r),
             e.column);
      set_real(out, static_cast<double>(e.op == Op::bit_and  ? (a & b)
                                        : e.op == Op::bit_or ? (a | b)
                                                             : (a ^ b)));
      return out;
    }

    case Op::logic_and:
    case Op::logic_or: {
      const ScriptValue& l = eval(e.a, bb);
      const bool l_ok = l.is_number();
      const bool lb = l_ok && truth_of(l, e.op, e.column);
      const ScriptValue& r = eval(e.b, bb);
      if (!l_ok || !r.is_number())
        fail(std::string("operator [") + op_text(e.op) + "] needs booleans or numbers, not " +
                 operand_types(l, r),
             e.column);
      const bool rb = truth_of(r, e.op, e.column);
      set_real(out, (e.op == Op::logic_and ? (lb && rb) : (lb || rb)) ? 1.0 : 0.0);
      return out;
    }

    case Op::compare: return eval_compare(e, bb);

    case Op::conditional: {
      const ScriptValue& c = eval(e.a, bb);
      bool truth = false;
      if (c.is_string()) {
        truth = !c.text.empty();
      } else if (c.is_number()) {
        truth = number(c, e.column) != 0.0;
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
  ScriptValue& out = registers_[static_cast<std::size_t>(&e - script_.nodes().data())];
  const ScriptValue* lhs = &eval(script_.compare_operands()[e.list_begin], bb);
  for (std::uint32_t i = 0; i + 1 < e.list_size; ++i) {
    // Operands are evaluated left to right and only as far as needed, as in BT.CPP.
    const ScriptValue& rhs = eval(script_.compare_operands()[e.list_begin + i + 1], bb);
    const CompareOp op = script_.compare_ops()[e.ops_begin + i];
    int order = 0;  // <0, 0, >0
    bool equal = false;
    if (lhs->is_string() && rhs.is_string()) {
      const int c = lhs->text.compare(rhs.text);
      order = c < 0 ? -1 : c > 0 ? 1 : 0;
      equal = order == 0;
    } else if ((lhs->is_number() || lhs->is_string()) && (rhs.is_number() || rhs.is_string())) {
      const double a = lhs->is_string() ? string_to_double(*lhs, e.column) : number(*lhs, e.column);
      const double b = rhs.is_string() ? string_to_double(rhs, e.column) : number(rhs, e.column);
      order = a < b ? -1 : a > b ? 1 : 0;
      equal = std::abs(a - b) <= static_cast<double>(std::numeric_limits<float>::epsilon());
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
      set_real(out, 0.0);
      return out;
    }
    lhs = &rhs;
  }
  set_real(out, 1.0);
  return out;
}

const ScriptValue& Program::eval_assign(std::uint32_t index, Blackboard& bb) {
  const Expr& e = script_.nodes()[index];
  const Expr& target = script_.nodes()[e.a];
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
    if (dst.empty() || (dst.kind == value.kind && dst.bool_entry == value.bool_entry)) {
      dst = value;  // keeps dst.text's buffer
    } else if (value.is_string()) {
      if (!dst.is_number())
        fail("cannot assign a string to '" + key + "', which holds a " + kind_name(dst.kind),
             e.column);
      ScriptValue parsed;
      set_real(parsed, string_to_double(value, e.column));
      store_number(dst, parsed, key, e.column);
    } else if (dst.is_string()) {
      fail_store(dst, value, key, e.column);
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
  const double a = number(dst, e.column);
  set_real(result, arithmetic(e.op, a, number(value, e.column)));
  store_number(dst, result, key, e.column);
  return dst;
}

}  // namespace uabt::runtime::script
