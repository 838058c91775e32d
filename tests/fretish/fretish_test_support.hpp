#pragma once
// Helpers shared by the FRETISH tests.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fretish/parse.hpp"

namespace uabt::testing {

inline fretish::TextOrigin test_origin(int line = 1, int column = 1) {
  return {"test.fret", line, column};
}

// Parses an expression that must be valid (no error-severity finding).
inline fretish::ExprPtr expr(const std::string& text) {
  std::vector<Finding> findings;
  fretish::ExprPtr e = fretish::parse_expression(text, test_origin(), findings);
  EXPECT_FALSE(has_errors(findings))
      << text << ": " << (findings.empty() ? "" : findings.front().message);
  EXPECT_NE(e, nullptr) << text;
  return e;
}

// Fully parenthesized rendering: shows exactly how the tree groups.
inline std::string grouped(const fretish::Expr& e) {
  using fretish::ExprKind;
  auto op = [](ExprKind k) -> std::string {
    switch (k) {
      case ExprKind::iff: return "<->";
      case ExprKind::implies: return "->";
      case ExprKind::logical_xor: return "xor";
      case ExprKind::logical_or: return "|";
      case ExprKind::logical_and: return "&";
      case ExprKind::eq: return "=";
      case ExprKind::ne: return "!=";
      case ExprKind::lt: return "<";
      case ExprKind::le: return "<=";
      case ExprKind::gt: return ">";
      case ExprKind::ge: return ">=";
      case ExprKind::add: return "+";
      case ExprKind::sub: return "-";
      case ExprKind::mul: return "*";
      case ExprKind::div: return "/";
      case ExprKind::mod: return "mod";
      case ExprKind::pow: return "^";
      default: return "?";
    }
  };
  switch (e.kind) {
    case ExprKind::bool_literal: return e.bool_value ? "true" : "false";
    case ExprKind::number:
    case ExprKind::identifier: return e.text;
    case ExprKind::logical_not: return "(!" + grouped(*e.args[0]) + ")";
    case ExprKind::negate: return "(-" + grouped(*e.args[0]) + ")";
    case ExprKind::call: {
      std::string out = e.text + "(";
      for (std::size_t i = 0; i < e.args.size(); ++i) out += (i ? ", " : "") + grouped(*e.args[i]);
      return out + ")";
    }
    default: {
      std::string out = "(";
      for (std::size_t i = 0; i < e.args.size(); ++i)
        out += (i ? " " + op(e.kind) + " " : "") + grouped(*e.args[i]);
      return out + ")";
    }
  }
}

inline std::string grouped(const std::string& text) {
  fretish::ExprPtr e = expr(text);
  return e ? grouped(*e) : "<error>";
}

inline std::vector<Finding> findings_of(const std::vector<Finding>& all, const std::string& check) {
  std::vector<Finding> out;
  for (const Finding& f : all)
    if (f.check == check) out.push_back(f);
  return out;
}

}  // namespace uabt::testing
