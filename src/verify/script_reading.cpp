// BehaviorTree.CPP script conditions back into FRETISH (the inverse of compile's
// atom_to_script): the script is parsed by the one BT.CPP script parser (bt/script), and its
// tree is translated here.
#include "verify/script_reading.hpp"

#include <stdexcept>

#include "bt/script/ast.hpp"

namespace uabt::verify {

using bt::script::CompareOp;
using bt::script::Expr;
using bt::script::Op;
using fretish::ExprKind;
using fretish::ExprPtr;

namespace {

// std::numeric_limits<float>::epsilon() (2^-23), written out exactly.
constexpr const char* kFloatEpsilon = "0.00000011920928955078125";

// The FRETISH relation a script comparison operator means (`==` is `=`).
ExprKind relation_of(CompareOp op) {
  switch (op) {
    case CompareOp::eq: return ExprKind::eq;
    case CompareOp::ne: return ExprKind::ne;
    case CompareOp::lt: return ExprKind::lt;
    case CompareOp::le: return ExprKind::le;
    case CompareOp::gt: return ExprKind::gt;
    case CompareOp::ge: return ExprKind::ge;
  }
  return ExprKind::eq;
}

struct ReadError : std::runtime_error {
  ReadError(const std::string& message, std::size_t column)
      : std::runtime_error(message + " (column " + std::to_string(column) + ")") {}
};

class Translator {
 public:
  Translator(const bt::script::Script& script, const fretish::Domain& domain, ScriptReading& out,
             bool names_as_written = false)
      : script_(script), domain_(domain), out_(out), names_as_written_(names_as_written) {}

  ExprPtr statement() {
    const auto& statements = script_.statements();
    if (statements.empty()) throw ReadError("the code is empty", 1);
    if (statements.size() > 1)
      throw ReadError("';' chains statements: a condition is one expression",
                      script_.nodes()[statements[1]].column);
    return translate(statements.front());
  }

 private:
  bool is_enum_literal(const std::string& text) const {
    for (const auto& v : domain_.variables)
      for (const auto& literal : v.enum_values)
        if (literal == text) return true;
    return false;
  }

  ExprPtr binary(ExprKind kind, const Expr& e) {
    return fretish::make_expr(kind, {translate(e.a), translate(e.b)});
  }

  // Whether BT.CPP computes the operand as a real that is not always whole: a real literal or
  // variable, a quotient, or arithmetic over one. (Every script number is a double; integer
  // values compare and add exactly as FRETISH integers do, below 2^53, where the engine stops.)
  bool real_valued(std::uint32_t index) const {
    const Expr& e = script_.nodes()[index];
    switch (e.op) {
      case Op::literal: return e.literal.kind == bt::script::ScriptValue::Kind::real;
      case Op::name: {
        const fretish::Variable* v = domain_.find(bt::script::entry_key(e.name));
        return v != nullptr && v->type == fretish::VarType::real;
      }
      case Op::negate: return real_valued(e.a);
      case Op::add:
      case Op::sub:
      case Op::mul: return real_valued(e.a) || real_valued(e.b);
      case Op::div: return true;
      case Op::conditional: return real_valued(e.b) || real_valued(e.c);
      default: return false;
    }
  }

  // A script `/` divides doubles: of two integers it is FRETISH's real division, not its
  // truncating one. An integer numeral is written as a real (`x / 2` reads `x / 2.0`), else
  // the dividend is made real (`x / y` reads `x * 1.0 / y`); the divisor keeps its text.
  ExprPtr quotient(const Expr& e) {
    ExprPtr dividend = translate(e.a), divisor = translate(e.b);
    if (!real_valued(e.a) && !real_valued(e.b)) {
      if (divisor->kind == ExprKind::number)
        divisor = fretish::make_number(divisor->text + ".0");
      else if (dividend->kind == ExprKind::number)
        dividend = fretish::make_number(dividend->text + ".0");
      else
        dividend = fretish::make_expr(ExprKind::mul, {dividend, fretish::make_number("1.0")});
    }
    return fretish::make_expr(ExprKind::div, {dividend, divisor});
  }

  // BT.CPP's == and != on numbers hold within float epsilon of equal (IsSame in
  // scripting/operators.hpp): `a == b` with a real operand is `a - b <= eps & b - a <= eps`.
  static ExprPtr relation(CompareOp op, const ExprPtr& lhs, const ExprPtr& rhs, bool reals) {
    if (!reals || (op != CompareOp::eq && op != CompareOp::ne))
      return fretish::make_expr(relation_of(op), {lhs, rhs});
    const ExprPtr epsilon = fretish::make_number(kFloatEpsilon);
    const ExprPtr below = fretish::make_expr(ExprKind::sub, {lhs, rhs});
    const ExprPtr above = fretish::make_expr(ExprKind::sub, {rhs, lhs});
    if (op == CompareOp::eq)
      return fretish::make_expr(ExprKind::logical_and,
                                {fretish::make_expr(ExprKind::le, {below, epsilon}),
                                 fretish::make_expr(ExprKind::le, {above, epsilon})});
    return fretish::make_expr(ExprKind::logical_or,
                              {fretish::make_expr(ExprKind::gt, {below, epsilon}),
                               fretish::make_expr(ExprKind::gt, {above, epsilon})});
  }

  ExprPtr literal(const Expr& e) {
    const bt::script::ScriptValue& v = e.literal;
    switch (v.kind) {
      case bt::script::ScriptValue::Kind::boolean: return fretish::make_bool(v.boolean);
      case bt::script::ScriptValue::Kind::integer:
        return fretish::make_number(std::to_string(v.integer));  // 0x10 reads as 16
      case bt::script::ScriptValue::Kind::real: return fretish::make_number(e.spelling);
      case bt::script::ScriptValue::Kind::string:
        if (!is_enum_literal(v.text))
          throw ReadError("the string '" + v.text + "' is not a value of any enum of the domain",
                          e.column);
        if (domain_.find(v.text) != nullptr)
          throw ReadError(
              "the string '" + v.text + "' is both an enum value and a variable of the domain",
              e.column);
        return fretish::make_identifier(v.text);
      case bt::script::ScriptValue::Kind::empty: break;
    }
    throw ReadError("an empty literal", e.column);
  }

  ExprPtr name(const Expr& e) {
    const bool root = e.name.starts_with('@');
    const std::string key = bt::script::entry_key(e.name);
    if (domain_.find(key) == nullptr && is_enum_literal(key))
      throw ReadError("'" + key +
                          "' is read as a blackboard entry, not as the enum value; write '" + key +
                          "' in quotes",
                      e.column);
    if (!root) out_.local_reads.push_back(key);
    return fretish::make_identifier(names_as_written_ ? e.name : key);
  }

  // A chain a < b <= c holds when every adjacent pair does.
  ExprPtr chain(const Expr& e) {
    const auto& operands = script_.compare_operands();
    const auto& ops = script_.compare_ops();
    std::vector<ExprPtr> links;
    ExprPtr lhs = translate(operands[e.list_begin]);
    for (std::uint32_t i = 0; i + 1 < e.list_size; ++i) {
      const std::uint32_t left = operands[e.list_begin + i], right = operands[e.list_begin + i + 1];
      ExprPtr rhs = translate(right);
      links.push_back(
          relation(ops[e.ops_begin + i], lhs, rhs, real_valued(left) || real_valued(right)));
      lhs = rhs;
    }
    if (links.size() == 1) return links.front();
    return fretish::make_expr(ExprKind::logical_and, std::move(links));
  }

  [[noreturn]] static void assignment(const char* op, const Expr& e) {
    throw ReadError(std::string("'") + op + "' assigns to the blackboard: a condition must not",
                    e.column);
  }

 public:
  ExprPtr translate(std::uint32_t index) {
    const Expr& e = script_.nodes()[index];
    switch (e.op) {
      case Op::literal: return literal(e);
      case Op::name: return name(e);
      case Op::negate: return fretish::make_expr(ExprKind::negate, {translate(e.a)});
      case Op::logical_not: return fretish::make_expr(ExprKind::logical_not, {translate(e.a)});
      case Op::add: return binary(ExprKind::add, e);
      case Op::sub: return binary(ExprKind::sub, e);
      case Op::mul: return binary(ExprKind::mul, e);
      case Op::div: return quotient(e);
      case Op::logic_and: return binary(ExprKind::logical_and, e);
      case Op::logic_or: return binary(ExprKind::logical_or, e);
      case Op::compare: return chain(e);
      case Op::conditional: {
        auto ite = std::make_shared<fretish::Expr>();
        ite->kind = ExprKind::call;
        ite->text = "ite";
        ite->args = {translate(e.a), translate(e.b), translate(e.c)};
        return ite;
      }
      case Op::concat:
        throw ReadError("the string operator '..' is not a condition operator", e.column);
      case Op::complement:
      case Op::bit_and:
      case Op::bit_or:
      case Op::bit_xor:
        throw ReadError("the bitwise operators & | ^ ~ are not condition operators", e.column);
      case Op::assign_create: assignment(":=", e);
      case Op::assign: assignment("=", e);
      case Op::add_assign: assignment("+=", e);
      case Op::sub_assign: assignment("-=", e);
      case Op::mul_assign: assignment("*=", e);
      case Op::div_assign: assignment("/=", e);
    }
    throw ReadError("an unknown operator", e.column);
  }

 private:
  const bt::script::Script& script_;
  const fretish::Domain& domain_;
  ScriptReading& out_;
  bool names_as_written_;
};

}  // namespace

ScriptReading parse_script_condition(const std::string& code, const fretish::Domain& domain) {
  ScriptReading reading;
  try {
    const bt::script::Script script = bt::script::Script::parse(code);
    reading.expr = Translator(script, domain, reading).statement();
  } catch (const bt::script::ScriptError& e) {
    reading.error = std::string(e.what()) + " (column " + std::to_string(e.column()) + ")";
  } catch (const ReadError& e) {
    reading.error = e.what();
  }
  if (!reading.expr) reading.local_reads.clear();
  return reading;
}

ScriptReading read_script_expression(const bt::script::Script& script, std::uint32_t index,
                                     const fretish::Domain& domain, bool names_as_written) {
  ScriptReading reading;
  try {
    reading.expr = Translator(script, domain, reading, names_as_written).translate(index);
  } catch (const ReadError& e) {
    reading.error = e.what();
  }
  if (!reading.expr) reading.local_reads.clear();
  return reading;
}

}  // namespace uabt::verify
