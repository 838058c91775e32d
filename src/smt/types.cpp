#include "smt/types.hpp"

#include <stdexcept>

#include "smt/rational.hpp"

namespace uabt::smt {

using fretish::Expr;
using fretish::ExprKind;
using fretish::Variable;
using fretish::VarType;

const char* sort_name(Sort s) {
  switch (s) {
    case Sort::boolean: return "boolean";
    case Sort::integer: return "integer";
    case Sort::real: return "real";
    case Sort::enumeration: return "enum";
    case Sort::invalid: return "ill-typed";
  }
  return "ill-typed";
}

const TypeInfo* Typing::find(const Expr& e) const {
  const auto it = types_.find(&e);
  return it == types_.end() ? nullptr : &it->second;
}

const TypeInfo& Typing::at(const Expr& e) const {
  const TypeInfo* info = find(e);
  if (info == nullptr) throw std::out_of_range("expression was not type checked");
  return *info;
}

const Variable* find_variable(const fretish::Domain& domain, const std::string& name) {
  return domain.find(name);
}

int enum_literal_index(const Variable& enum_variable, const std::string& literal) {
  for (std::size_t i = 0; i < enum_variable.enum_values.size(); ++i)
    if (enum_variable.enum_values[i] == literal) return static_cast<int>(i);
  return -1;
}

bool is_known_function(const std::string& name, std::size_t& arity) {
  if (name == "absInt" || name == "absReal") {
    arity = 1;
    return true;
  }
  if (name == "minInt" || name == "maxInt" || name == "minReal" || name == "maxReal") {
    arity = 2;
    return true;
  }
  if (name == "ite") {
    arity = 3;
    return true;
  }
  return false;
}

namespace {

bool is_numeric(Sort s) {
  return s == Sort::integer || s == Sort::real;
}

bool same_enum(const Variable* a, const Variable* b) {
  return a == b || (a != nullptr && b != nullptr && a->enum_values == b->enum_values);
}

std::string quoted(const Expr& e) {
  return "'" + fretish::to_fretish(e) + "'";
}

std::string enum_values_text(const Variable& v) {
  std::string out = "{";
  for (std::size_t i = 0; i < v.enum_values.size(); ++i) out += (i ? ", " : "") + v.enum_values[i];
  return out + "}";
}

// What the parent needs from a child; steers how a bare identifier resolves.
struct Expect {
  enum Kind { any, boolean, numeric, enumeration } kind = any;
  const Variable* enum_type = nullptr;
};

Expect expect_like(const TypeInfo& t) {
  switch (t.sort) {
    case Sort::boolean: return {Expect::boolean, nullptr};
    case Sort::integer:
    case Sort::real: return {Expect::numeric, nullptr};
    case Sort::enumeration: return {Expect::enumeration, t.enum_type};
    case Sort::invalid: break;
  }
  return {};
}

std::string describe(const TypeInfo& t) {
  if (t.sort == Sort::enumeration && t.enum_type != nullptr)
    return t.enum_index >= 0
               ? "a literal of enum " + t.enum_type->name + " " + enum_values_text(*t.enum_type)
               : "an enum " + enum_values_text(*t.enum_type);
  if (t.sort == Sort::integer) return "an integer";
  return std::string("a ") + sort_name(t.sort);
}

class Checker {
 public:
  Checker(const fretish::Domain& domain, const SourceLocation& where, Typing& typing,
          std::vector<Finding>& findings)
      : domain_(domain), where_(where), typing_(typing), findings_(findings) {}

  bool ok() const { return errors_ == 0; }

  TypeInfo infer(const Expr& e, Expect expect) {
    TypeInfo t = infer_node(e, expect);
    typing_.set(e, t);
    return t;
  }

  void require_boolean_root(const Expr& e) {
    const TypeInfo t = infer(e, {Expect::boolean, nullptr});
    if (t.sort != Sort::boolean && t.sort != Sort::invalid)
      report(e, "the condition " + quoted(e) + " is " + describe(t) +
                    ", not true/false; compare it with something");
  }

 private:
  const fretish::Domain& domain_;
  const SourceLocation& where_;
  Typing& typing_;
  std::vector<Finding>& findings_;
  int errors_ = 0;

  SourceLocation at(const Expr& e) const { return start_of(e.range, where_); }

  void report(const Expr& e, std::string message) {
    ++errors_;
    findings_.push_back(make_finding("ref-type-mismatch", std::move(message), at(e)));
  }

  TypeInfo invalid() const { return TypeInfo{}; }

  TypeInfo infer_node(const Expr& e, Expect expect) {
    switch (e.kind) {
      case ExprKind::bool_literal: return TypeInfo{Sort::boolean};
      case ExprKind::number: return number(e);
      case ExprKind::identifier: return identifier(e, expect);
      case ExprKind::call: return call(e, expect);
      case ExprKind::logical_not:
      case ExprKind::logical_and:
      case ExprKind::logical_or:
      case ExprKind::logical_xor:
      case ExprKind::implies:
      case ExprKind::iff: return connective(e);
      case ExprKind::eq:
      case ExprKind::ne: return equality(e);
      case ExprKind::lt:
      case ExprKind::le:
      case ExprKind::gt:
      case ExprKind::ge: return ordering(e);
      case ExprKind::add:
      case ExprKind::sub:
      case ExprKind::mul:
      case ExprKind::div:
      case ExprKind::mod:
      case ExprKind::pow:
      case ExprKind::negate: return arithmetic(e);
    }
    return invalid();
  }

  TypeInfo number(const Expr& e) {
    if (!parse_rational(e.text)) {
      report(e, quoted(e) + " is not a number uabt can read exactly");
      return invalid();
    }
    return TypeInfo{is_integer_literal(e.text) ? Sort::integer : Sort::real};
  }

  TypeInfo literal_of(const Variable& enum_type, int index) const {
    TypeInfo t{Sort::enumeration};
    t.enum_type = &enum_type;
    t.enum_index = index;
    return t;
  }

  TypeInfo identifier(const Expr& e, Expect expect) {
    const std::string& name = e.text;
    if (expect.kind == Expect::enumeration && expect.enum_type != nullptr) {
      const int index = enum_literal_index(*expect.enum_type, name);
      if (index >= 0) return literal_of(*expect.enum_type, index);
    }
    if (const Variable* v = find_variable(domain_, name)) {
      TypeInfo t;
      t.variable = v;
      switch (v->type) {
        case VarType::boolean: t.sort = Sort::boolean; break;
        case VarType::integer: t.sort = Sort::integer; break;
        case VarType::real: t.sort = Sort::real; break;
        case VarType::enumeration:
          t.sort = Sort::enumeration;
          t.enum_type = v;
          break;
      }
      return t;
    }
    std::vector<const Variable*> owners;
    for (const auto& v : domain_.variables)
      if (v.type == VarType::enumeration && enum_literal_index(v, name) >= 0) owners.push_back(&v);
    if (owners.size() == 1) return literal_of(*owners[0], enum_literal_index(*owners[0], name));
    if (owners.size() > 1) {
      report(e, "'" + name + "' is a literal of enums " + owners[0]->name + " and " +
                    owners[1]->name + "; compare it with one of them to say which");
      return invalid();
    }
    if (expect.kind == Expect::boolean) {  // ARCHITECTURE §3: an undeclared condition is a boolean
      TypeInfo t{Sort::boolean};
      t.implicit_boolean = true;
      return t;
    }
    if (expect.kind == Expect::any) {  // compared with something whose type it would take
      report(e, "'" + name + "' is compared but not declared; declare it in domain.fret (e.g. " +
                    "'enum " + name + " in {…}' or 'boolean " + name + "')");
      return invalid();
    }
    if (expect.kind == Expect::enumeration && expect.enum_type != nullptr) {
      report(e, "'" + name + "' is not a literal of enum " + expect.enum_type->name + " " +
                    enum_values_text(*expect.enum_type));
      return invalid();
    }
    report(e, "'" + name + "' is used as a number but is not declared; declare it in " +
                  "domain.fret (e.g. 'integer " + name + " in [0, 100]' or 'real " + name + "')");
    return invalid();
  }

  TypeInfo connective(const Expr& e) {
    bool ok = true;
    for (const auto& arg : e.args) {
      const TypeInfo t = infer(*arg, {Expect::boolean, nullptr});
      if (t.sort == Sort::invalid) {
        ok = false;
      } else if (t.sort != Sort::boolean) {
        report(*arg, quoted(*arg) + " is " + describe(t) + ", but " +
                         (e.kind == ExprKind::logical_not ? "'!'" : "a logical operator") +
                         " needs a condition");
        ok = false;
      }
    }
    return ok ? TypeInfo{Sort::boolean} : invalid();
  }

  // A name that means the same whatever it is compared with.
  bool resolves_alone(const Expr& e) const {
    return e.kind != ExprKind::identifier || find_variable(domain_, e.text) != nullptr;
  }

  TypeInfo equality(const Expr& e) {
    if (e.args.size() != 2) return invalid();
    const bool lhs_first = resolves_alone(*e.args[0]) || !resolves_alone(*e.args[1]);
    const Expr& first = lhs_first ? *e.args[0] : *e.args[1];
    const Expr& second = lhs_first ? *e.args[1] : *e.args[0];
    const TypeInfo t1 = infer(first, {});
    if (t1.sort == Sort::invalid) {
      // Still report errors inside the other side, but not a second "undeclared" for a name
      // whose meaning would have come from the first.
      if (second.kind != ExprKind::identifier) infer(second, {});
      return invalid();
    }
    const TypeInfo t2 = infer(second, expect_like(t1));
    if (t2.sort == Sort::invalid) return invalid();
    const bool compatible = (t1.sort == Sort::boolean && t2.sort == Sort::boolean) ||
                            (is_numeric(t1.sort) && is_numeric(t2.sort)) ||
                            (t1.sort == Sort::enumeration && t2.sort == Sort::enumeration &&
                             same_enum(t1.enum_type, t2.enum_type));
    if (!compatible && t1.sort == Sort::enumeration && t2.sort == Sort::enumeration &&
        t2.enum_index >= 0) {
      report(second, quoted(second) + " is a literal of enum " + t2.enum_type->name + ", not of " +
                         describe(t1));
      return invalid();
    }
    if (!compatible) {
      report(e, "cannot compare " + quoted(first) + " (" + describe(t1) + ") with " +
                    quoted(second) + " (" + describe(t2) + ")");
      return invalid();
    }
    return TypeInfo{Sort::boolean};
  }

  // Types the operands of a numeric operator; reports the first non-numeric one (once per
  // operator, so `A < B` gives one finding, not two).
  bool numeric_operands(const Expr& e, const char* op, bool& all_integer) {
    bool ok = !e.args.empty();
    bool reported = false;
    all_integer = true;
    for (const auto& arg : e.args) {
      const TypeInfo t = infer(*arg, {Expect::numeric, nullptr});
      all_integer = all_integer && t.sort == Sort::integer;
      if (t.sort == Sort::invalid) {
        ok = false;
      } else if (!is_numeric(t.sort)) {
        ok = false;
        if (!reported && t.variable != nullptr && !t.variable->declared)
          report(*arg, "'" + arg->text + "' is used as a number but is not declared; declare " +
                           "it in domain.fret (e.g. 'integer " + arg->text +
                           " in [0, 100]' or 'real " + arg->text + "')");
        else if (!reported)
          report(*arg,
                 std::string("'") + op + "' needs numbers; " + quoted(*arg) + " is " + describe(t));
        reported = true;
      }
    }
    return ok;
  }

  TypeInfo ordering(const Expr& e) {
    static const char* const names[] = {"<", "<=", ">", ">="};
    const char* op = names[static_cast<int>(e.kind) - static_cast<int>(ExprKind::lt)];
    bool all_integer = true;
    const bool ok = numeric_operands(e, op, all_integer) && e.args.size() == 2;
    return ok ? TypeInfo{Sort::boolean} : invalid();
  }

  TypeInfo arithmetic(const Expr& e) {
    const char* op = "+";
    switch (e.kind) {
      case ExprKind::sub: op = "-"; break;
      case ExprKind::mul: op = "*"; break;
      case ExprKind::div: op = "/"; break;
      case ExprKind::mod: op = "mod"; break;
      case ExprKind::pow: op = "^"; break;
      case ExprKind::negate: op = "-"; break;
      default: break;
    }
    bool all_integer = true;
    if (!numeric_operands(e, op, all_integer)) return invalid();
    if (e.kind == ExprKind::mod && !all_integer) {
      report(e, "'mod' needs integers; " + quoted(e) + " has a real operand");
      return invalid();
    }
    if ((e.kind == ExprKind::div || e.kind == ExprKind::mod) && e.args.size() == 2 &&
        is_literal_zero(*e.args[1])) {
      findings_.push_back(make_finding(
          "arith-division-by-zero",
          quoted(e) + " divides by zero; the solver treats its value as unknown, so any "
                      "number may stand for it",
          at(e)));
    }
    if (e.kind == ExprKind::pow)
      return TypeInfo{all_integer && fretish::is_natural_numeral(*e.args[1]) ? Sort::integer
                                                                             : Sort::real};
    return TypeInfo{all_integer ? Sort::integer : Sort::real};
  }

  TypeInfo call(const Expr& e, Expect expect) {
    std::size_t arity = 0;
    if (!is_known_function(e.text, arity)) {
      for (const auto& arg : e.args) infer(*arg, {});
      report(e, "'" + e.text + "' is not a function a guard can use (absInt, absReal, minInt, " +
                    "maxInt, minReal, maxReal, ite)");
      return invalid();
    }
    if (e.args.size() != arity) {
      report(e, "'" + e.text + "' takes " + std::to_string(arity) + " argument" +
                    (arity == 1 ? "" : "s") + ", not " + std::to_string(e.args.size()));
      return invalid();
    }
    if (e.text == "ite") return ite(e, expect);
    bool all_integer = true;
    if (!numeric_operands(e, e.text.c_str(), all_integer)) return invalid();
    const bool integer_function = e.text.ends_with("Int");
    if (integer_function && !all_integer) {
      report(e, "'" + e.text + "' needs integers; use " + e.text.substr(0, 3) +
                    "Real for real arguments");
      return invalid();
    }
    return TypeInfo{integer_function ? Sort::integer : Sort::real};
  }

  TypeInfo ite(const Expr& e, Expect expect) {
    const TypeInfo c = infer(*e.args[0], {Expect::boolean, nullptr});
    bool ok = c.sort != Sort::invalid;
    if (ok && c.sort != Sort::boolean) {
      report(*e.args[0], "the condition of ite " + quoted(*e.args[0]) + " is " + describe(c));
      ok = false;
    }
    const bool then_first = resolves_alone(*e.args[1]) || !resolves_alone(*e.args[2]);
    const Expr& first = then_first ? *e.args[1] : *e.args[2];
    const Expr& second = then_first ? *e.args[2] : *e.args[1];
    const TypeInfo t1 = infer(first, expect);
    if (t1.sort == Sort::invalid) {
      infer(second, expect);
      return invalid();
    }
    const TypeInfo t2 = infer(second, expect_like(t1));
    if (t2.sort == Sort::invalid || !ok) return invalid();
    if (t1.sort == Sort::boolean && t2.sort == Sort::boolean) return TypeInfo{Sort::boolean};
    if (is_numeric(t1.sort) && is_numeric(t2.sort))
      return TypeInfo{t1.sort == Sort::integer && t2.sort == Sort::integer ? Sort::integer
                                                                           : Sort::real};
    if (t1.sort == Sort::enumeration && t2.sort == Sort::enumeration &&
        same_enum(t1.enum_type, t2.enum_type)) {
      TypeInfo t{Sort::enumeration};
      t.enum_type = t1.enum_type;
      return t;
    }
    report(e, "the branches of " + quoted(e) + " differ: " + describe(t1) + " and " + describe(t2));
    return invalid();
  }
};

}  // namespace

bool is_literal_zero(const Expr& e) {
  if (e.kind == ExprKind::negate && e.args.size() == 1 && e.args[0])
    return is_literal_zero(*e.args[0]);
  if (e.kind != ExprKind::number) return false;
  const auto r = parse_rational(e.text);
  return r && r->is_zero();
}

bool check_condition(const Expr& condition, const fretish::Domain& domain,
                     const SourceLocation& where, Typing& typing, std::vector<Finding>& findings) {
  Checker checker(domain, where, typing, findings);
  checker.require_boolean_root(condition);
  return checker.ok();
}

}  // namespace uabt::smt
