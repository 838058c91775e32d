// Algorithm 1 of the paper: a guard becomes a condition-checking subtree.
#include <stdexcept>

#include "bt/node_kinds.hpp"
#include "compile/compile.hpp"
#include "compile/guard_rewrite.hpp"

namespace uabt::compile {

using fretish::Expr;
using fretish::ExprKind;

namespace {

bt::Node leaf(std::string tag) {
  bt::Node n;
  n.tag = std::move(tag);
  return n;
}

const char* script_operator(ExprKind kind) {
  switch (kind) {
    case ExprKind::eq: return "==";
    case ExprKind::ne: return "!=";
    case ExprKind::lt: return "<";
    case ExprKind::le: return "<=";
    case ExprKind::gt: return ">";
    case ExprKind::ge: return ">=";
    case ExprKind::add: return "+";
    case ExprKind::sub: return "-";
    case ExprKind::mul: return "*";
    case ExprKind::div: return "/";
    default: return nullptr;
  }
}

int script_precedence(ExprKind kind) {
  switch (kind) {
    case ExprKind::eq:
    case ExprKind::ne:
    case ExprKind::lt:
    case ExprKind::le:
    case ExprKind::gt:
    case ExprKind::ge: return 1;
    case ExprKind::add:
    case ExprKind::sub: return 2;
    case ExprKind::mul:
    case ExprKind::div: return 3;
    case ExprKind::negate: return 4;
    default: return 5;
  }
}

std::string script_of(const Expr& e, const fretish::Domain& domain, int parent_precedence,
                      bool right_operand) {
  switch (e.kind) {
    case ExprKind::number: return e.text;
    case ExprKind::bool_literal: return e.bool_value ? "true" : "false";
    case ExprKind::identifier:
      // An enum literal is a string in BT.CPP scripts; a variable is a blackboard entry.
      if (domain.find(e.text) == nullptr && domain.enum_owning(e.text) != nullptr)
        return "'" + e.text + "'";
      return e.text;
    case ExprKind::negate: {
      std::string inner = script_of(*e.args.at(0), domain, script_precedence(e.kind), false);
      return parent_precedence > script_precedence(e.kind) ? "(-" + inner + ")" : "-" + inner;
    }
    default: break;
  }
  const char* op = script_operator(e.kind);
  if (op == nullptr || e.args.size() != 2)
    throw UnsupportedGuard("'" + fretish::to_fretish(e) +
                           "' has no BehaviorTree.CPP script equivalent (scripts know + - * / "
                           "and comparisons)");
  if (e.kind == ExprKind::div && !is_real_valued(e, domain))
    throw UnsupportedGuard("'" + fretish::to_fretish(e) +
                           "' divides integers, which FRETISH truncates (7 / 2 is 3) and a "
                           "BehaviorTree.CPP script divides as doubles (7 / 2 is 3.5); write the "
                           "guard without the division (x / 2 > 1 is x > 3 for x >= 0) or "
                           "divide a real");
  const int prec = script_precedence(e.kind);
  std::string text = script_of(*e.args[0], domain, prec, false) + " " + op + " " +
                     script_of(*e.args[1], domain, prec, true);
  // Left-associative operators: a right operand of equal precedence needs parentheses.
  const bool parens = prec < parent_precedence || (right_operand && prec == parent_precedence);
  return parens ? "(" + text + ")" : text;
}

bt::Node build(const Expr& e, const fretish::Domain& domain) {
  using K = bt::NodeKind;
  switch (e.kind) {
    case ExprKind::bool_literal:
      return leaf(bt::kind_name(e.bool_value ? K::always_success : K::always_failure));
    case ExprKind::identifier: return leaf(e.text);
    case ExprKind::logical_not: {
      bt::Node n = leaf(bt::kind_name(K::inverter));
      n.children.push_back(build(*e.args.at(0), domain));
      return n;
    }
    case ExprKind::logical_and:
    case ExprKind::logical_or: {
      bt::Node n = leaf(bt::kind_name(e.kind == ExprKind::logical_and ? K::sequence : K::fallback));
      for (const auto& arg : e.args) {
        bt::Node child = build(*arg, domain);
        // Nested nodes of one kind are flattened: (a & b) & c is one Sequence.
        if (child.tag == n.tag && child.attributes.empty()) {
          for (auto& grandchild : child.children) n.children.push_back(std::move(grandchild));
        } else {
          n.children.push_back(std::move(child));
        }
      }
      return n;
    }
    default: break;
  }
  bt::Node n = leaf(bt::kind_name(K::script_condition));
  n.set_attribute("code", atom_to_script(e, domain));
  return n;
}

}  // namespace

std::string atom_to_script(const Expr& atom, const fretish::Domain& domain) {
  return script_of(atom, domain, 0, false);
}

bt::Node guard_to_tree(const Expr& guard, const fretish::Domain& domain, SelectionStyle) {
  // Guards are synchronous conditions: inside them plain Sequence/Fallback already re-check
  // every time they are ticked, so the reactive style only changes the selector around them.
  fretish::ExprPtr normal = to_and_or_not(guard, domain);
  return build(*normal, domain);
}

}  // namespace uabt::compile
