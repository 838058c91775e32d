// One meaning of "the value of an expression in a state" (ARCHITECTURE §14): the witness checker
// (smt::evaluate), the monitor's compiled expression and verify's compiled condition give every
// expression the same value, or all say it has none.
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <random>
#include <string>

#include "monitor/expression.hpp"
#include "smt/evaluate.hpp"
#include "smt/types.hpp"
#include "verify/compiled_condition.hpp"

#include "../smt/expr_support.hpp"

namespace uabt::testing {
namespace {

const fretish::Domain kDomain = domain(
    "boolean A, B\ninteger x in [-6, 6]\ninteger y in [-6, 6]\n"
    "integer big in [-9223372036854775807, 9223372036854775807]\n"
    "enum terrain in {dust, rocks, sand}\n");

const std::vector<std::string> kTerrain = {"dust", "rocks", "sand"};

struct Point {
  bool a = false, b = false;
  std::int64_t x = 0, y = 0, big = 0;
  int terrain = 0;

  State state() const {
    return {{"A", Value::of_bool(a)},    {"B", Value::of_bool(b)},
            {"x", Value::of_int(x)},     {"y", Value::of_int(y)},
            {"big", Value::of_int(big)}, {"terrain", Value::of_enum(kTerrain[terrain])}};
  }
  std::string text() const {
    return "A=" + std::to_string(a) + " B=" + std::to_string(b) + " x=" + std::to_string(x) +
           " y=" + std::to_string(y) + " big=" + std::to_string(big) +
           " terrain=" + kTerrain[terrain];
  }
};

// The answers for one condition in one state; `on_demand`: the monitor's, reaching each
// variable before it reads it (a model checker's environment, chosen when first read).
struct Answers {
  std::optional<bool> witness_checker, monitor, coverage, on_demand;
  std::vector<std::string> reached;  // by the on-demand evaluation, in order
  bool agree() const {
    return witness_checker == monitor && monitor == coverage && monitor == on_demand;
  }
  std::string text() const {
    auto one = [](const std::optional<bool>& v) -> std::string {
      return v ? (*v ? "true" : "false") : "no value";
    };
    return "smt::evaluate " + one(witness_checker) + ", monitor " + one(monitor) +
           ", CompiledCondition " + one(coverage) + ", monitor on demand " + one(on_demand);
  }
};

// Gives a variable its value in the frame when the evaluation reaches it.
class OnDemand : public monitor::Reader {
 public:
  OnDemand(const std::vector<monitor::Val>& values, std::vector<monitor::Val>& frame,
           const monitor::Variables& names, std::vector<std::string>& reached)
      : values_(values), frame_(frame), names_(names), reached_(reached) {}
  void reach(int slot) override {
    const auto s = static_cast<std::size_t>(slot);
    if (frame_[s].kind != monitor::Val::Kind::missing) return;
    frame_[s] = values_[s];
    reached_.push_back(names_.name(slot));
  }
  bool boolean(int slot) const override {
    return values_[static_cast<std::size_t>(slot)].kind == monitor::Val::Kind::boolean;
  }

 private:
  const std::vector<monitor::Val>& values_;
  std::vector<monitor::Val>& frame_;
  const monitor::Variables& names_;
  std::vector<std::string>& reached_;
};

class Evaluators {
 public:
  explicit Evaluators(const std::string& text) : expr_(expr(text)) {
    std::vector<Finding> findings;
    typed_ = smt::check_condition(*expr_, kDomain, {"requirements.fret", 1, 1}, typing_, findings);
    if (!typed_) return;
    for (const char* v : {"A", "B", "x", "y", "big", "terrain"}) slots_[v] = variables_.id(v);
    monitor::Resolver resolve = [&](const std::string& name) {
      if (const auto id = variables_.find(name))
        return monitor::Resolved{monitor::Resolved::Kind::variable, *id};
      for (const auto& l : kTerrain)
        if (l == name)
          return monitor::Resolved{monitor::Resolved::Kind::literal, symbols_.id(name)};
      return monitor::Resolved{};
    };
    std::string error;
    monitor_ = monitor::CompiledExpression::compile(*expr_, resolve, error);
    EXPECT_TRUE(monitor_.has_value()) << text << ": " << error;
    try {
      coverage_.emplace(*expr_, typing_, slots_);
    } catch (const smt::EvaluationError& e) {
      ADD_FAILURE() << text << ": " << e.what();
    }
  }
  bool typed() const { return typed_; }

  Answers answers(const Point& p) {
    Answers out;
    out.witness_checker = smt::try_evaluate(*expr_, kDomain, p.state());
    std::vector<monitor::Val> frame(variables_.size());
    frame[slots_["A"]] = monitor::Val::of_bool(p.a);
    frame[slots_["B"]] = monitor::Val::of_bool(p.b);
    frame[slots_["x"]] = monitor::Val::of_whole(p.x);
    frame[slots_["y"]] = monitor::Val::of_whole(p.y);
    frame[slots_["big"]] = monitor::Val::of_whole(p.big);
    frame[slots_["terrain"]] = monitor::Val::of_symbol(symbols_.id(kTerrain[p.terrain]));
    if (monitor_) {
      std::string error;
      const bool v = monitor_->evaluate_bool(frame, error);
      if (error.empty()) out.monitor = v;
      std::vector<monitor::Val> pending(frame.size());
      OnDemand reader(frame, pending, variables_, out.reached);
      error.clear();
      const bool lazy = monitor_->evaluate_bool(pending, error, &reader);
      if (error.empty()) out.on_demand = lazy;
    }
    if (coverage_) {
      std::vector<std::int64_t> assignment(variables_.size());
      assignment[slots_["A"]] = p.a;
      assignment[slots_["B"]] = p.b;
      assignment[slots_["x"]] = p.x;
      assignment[slots_["y"]] = p.y;
      assignment[slots_["big"]] = p.big;
      assignment[slots_["terrain"]] = p.terrain;
      out.coverage = coverage_->value(assignment.data());
    }
    return out;
  }

 private:
  fretish::ExprPtr expr_;
  smt::Typing typing_;
  bool typed_ = false;
  monitor::Variables variables_;
  monitor::Symbols symbols_;
  std::map<std::string, std::size_t> slots_;
  std::optional<monitor::CompiledExpression> monitor_;
  std::optional<verify::detail::CompiledCondition> coverage_;
};

Answers answers(const std::string& text, const Point& p) {
  Evaluators e(text);
  EXPECT_TRUE(e.typed()) << text;
  return e.answers(p);
}

// Random well-typed conditions over the domain above.
class Generator {
 public:
  explicit Generator(unsigned seed) : random_(seed) {}

  std::string condition(int depth) {
    const int pick = below(depth <= 0 ? 3 : 10);
    switch (pick) {
      case 0: return below(2) ? "A" : "B";
      case 1: return "terrain " + std::string(below(2) ? "=" : "!=") + " " + terrain();
      case 2:
      case 3:
      case 4: {
        static const char* relations[] = {"<", "<=", ">", ">=", "=", "!="};
        return number(depth - 1) + " " + relations[below(6)] + " " + number(depth - 1);
      }
      case 5: return "!(" + condition(depth - 1) + ")";
      case 6: {
        static const char* connectives[] = {"&", "|", "xor", "->", "<->"};
        return "(" + condition(depth - 1) + " " + connectives[below(5)] + " " +
               condition(depth - 1) + ")";
      }
      case 7:
        return "(" + condition(depth - 1) + " & " + condition(depth - 1) + " & " +
               condition(depth - 1) + ")";
      case 8:
        return "(" + condition(depth - 1) + " -> " + condition(depth - 1) + " -> " +
               condition(depth - 1) + ")";
      default:
        return "ite(" + condition(depth - 1) + ", " + condition(depth - 1) + ", " +
               condition(depth - 1) + ")";
    }
  }

  std::string number(int depth) {
    const int pick = below(depth <= 0 ? 3 : 12);
    switch (pick) {
      case 0: {
        static const char* names[] = {"x", "y", "big"};
        return names[below(3)];
      }
      case 1: {
        static const char* literals[] = {
            "0", "1", "2", "3", "7", "0.5", "1.5", "2.0", "9223372036854775807"};
        return literals[below(9)];
      }
      case 2: return below(2) ? "x" : "y";
      case 3:
      case 4:
      case 5: {
        static const char* ops[] = {"+", "-", "*", "/", "mod"};
        const char* op = ops[below(5)];
        return "(" + (std::string(op) == "mod" ? integer(depth - 1) : number(depth - 1)) + " " +
               op + " " + (std::string(op) == "mod" ? integer(depth - 1) : number(depth - 1)) + ")";
      }
      case 6: return "-" + number(depth - 1);
      case 7: {
        static const char* exponents[] = {"0", "1", "2", "3", "x", "y", "0.5", "64"};
        return "(" + number(depth - 1) + " ^ " + exponents[below(8)] + ")";
      }
      case 8: return "absReal(" + number(depth - 1) + ")";
      case 9: {
        static const char* f[] = {"minReal", "maxReal"};
        return std::string(f[below(2)]) + "(" + number(depth - 1) + ", " + number(depth - 1) + ")";
      }
      case 10:
        return "ite(" + condition(depth - 1) + ", " + number(depth - 1) + ", " + number(depth - 1) +
               ")";
      default: return integer(depth);
    }
  }

  std::string integer(int depth) {
    const int pick = below(depth <= 0 ? 2 : 7);
    switch (pick) {
      case 0: return below(2) ? "x" : "y";
      case 1: {
        static const char* literals[] = {"0", "1", "2", "3", "-4", "big"};
        return literals[below(6)];
      }
      case 2: {
        static const char* ops[] = {"+", "-", "*", "/", "mod"};
        return "(" + integer(depth - 1) + " " + ops[below(5)] + " " + integer(depth - 1) + ")";
      }
      case 3: return "absInt(" + integer(depth - 1) + ")";
      case 4: {
        static const char* f[] = {"minInt", "maxInt"};
        return std::string(f[below(2)]) + "(" + integer(depth - 1) + ", " + integer(depth - 1) +
               ")";
      }
      case 5: return "(" + integer(depth - 1) + " ^ " + std::to_string(below(4)) + ")";
      default:
        return "ite(" + condition(depth - 1) + ", " + integer(depth - 1) + ", " +
               integer(depth - 1) + ")";
    }
  }

  Point point() {
    Point p;
    p.a = below(2);
    p.b = below(2);
    p.x = below(13) - 6;
    p.y = below(13) - 6;
    static const std::int64_t bigs[] = {
        0, 1, -1, 3037000500, -3037000500, 9223372036854775807, -9223372036854775807};
    p.big = bigs[below(7)];
    p.terrain = below(3);
    return p;
  }

 private:
  std::mt19937 random_;
  int below(int n) { return std::uniform_int_distribution<int>(0, n - 1)(random_); }
  std::string terrain() { return kTerrain[static_cast<std::size_t>(below(3))]; }
};

// An operand with no value does not matter where another decides: a definite false decides an
// `&`, a definite true an `|`, either order.
TEST(EvaluatorAgreement, DivisionByZeroInAnOperandThatDoesNotDecide) {
  Point zero;
  for (const char* text : {"x = 0 | 10 / x > 1", "10 / x > 1 | x = 0", "x != 0 -> 10 / x > 1",
                           "10 / x > 1 -> x = 0", "!(10 / x > 1 & x != 0)"}) {
    const Answers a = answers(text, zero);
    EXPECT_TRUE(a.agree()) << text << ": " << a.text();
    EXPECT_EQ(a.witness_checker, std::optional<bool>(true)) << text << ": " << a.text();
  }
  const Answers none = answers("10 / x > 1 | x = 1", zero);
  EXPECT_TRUE(none.agree()) << none.text();
  EXPECT_EQ(none.witness_checker, std::nullopt) << none.text();
}

// Reading on demand, `&`, `|`, `->` and ite read their operands left to right and stop where
// the value is decided: the variables after that are never reached.
TEST(EvaluatorAgreement, OnDemandReadsStopWhereTheValueIsDecided) {
  Point p;  // A, B false; x, y 0
  p.y = 2;
  const std::map<std::string, std::vector<std::string>> reached = {
      {"A & B & x > 0", {"A"}},
      {"B | A | x = 0 | y = 1", {"B", "A", "x"}},
      {"A -> B", {"A"}},
      {"A -> x > 0", {"A"}},
      {"x = 0 -> A", {"x", "A"}},
      {"ite(A, x, y) > 1", {"A", "y", "x"}},  // an integer branch is real where the other is
      {"ite(A, B, y > 1)", {"A", "y"}},
      {"x != 0 -> 10 / x > 1", {"x"}},
      {"A xor B", {"A", "B"}}};
  for (const auto& [text, names] : reached) {
    const Answers a = answers(text, p);
    EXPECT_TRUE(a.agree()) << text << ": " << a.text();
    EXPECT_EQ(a.reached, names) << text;
  }
}

// minReal, maxReal and absReal are reals, whatever their arguments: a quotient of one divides
// exactly.
TEST(EvaluatorAgreement, RealFunctionsOfIntegersDivideExactly) {
  Point p;
  p.x = 3;
  p.y = 5;
  for (const char* text :
       {"minReal(x, y) / 2 = 1.5", "absReal(x) / 2 = 1.5", "ite(!A, x, 0.5) / 2 = 1.5"}) {
    const Answers a = answers(text, p);
    EXPECT_TRUE(a.agree()) << text << ": " << a.text();
    EXPECT_EQ(a.witness_checker, std::optional<bool>(true)) << text << ": " << a.text();
  }
}

// An integer too large for 64 bits has no value: no evaluator wraps it or rounds it.
TEST(EvaluatorAgreement, IntegerOverflowHasNoValue) {
  Point p;
  p.big = 9223372036854775807;
  for (const char* text :
       {"big + 1 > 0", "big * 2 > 0", "-(big + 1) < 0", "big ^ 2 > 0", "big + 1 > big"}) {
    const Answers a = answers(text, p);
    EXPECT_TRUE(a.agree()) << text << ": " << a.text();
    EXPECT_EQ(a.witness_checker, std::nullopt) << text << ": " << a.text();
  }
  const Answers exact = answers("big - 1 < big", p);
  EXPECT_TRUE(exact.agree()) << exact.text();
  EXPECT_EQ(exact.witness_checker, std::optional<bool>(true)) << exact.text();
}

// `x ^ y` is a real power (its type is real unless the exponent is a whole number written
// out): its quotient is exact, and a negative exponent gives a fraction.
TEST(EvaluatorAgreement, PowerWithAVariableExponentIsReal) {
  Point p;
  p.x = 3;
  p.y = 1;
  for (const char* text : {"x ^ y / 2 = 1.5", "(x ^ 2) / 2 = 4"}) {
    const Answers a = answers(text, p);
    EXPECT_TRUE(a.agree()) << text << ": " << a.text();
    EXPECT_EQ(a.witness_checker, std::optional<bool>(true)) << text << ": " << a.text();
  }
  p.x = 2;
  p.y = -1;
  const Answers a = answers("x ^ y = 0.5", p);
  EXPECT_TRUE(a.agree()) << a.text();
  EXPECT_EQ(a.witness_checker, std::optional<bool>(true)) << a.text();
}

TEST(EvaluatorAgreement, RandomConditionsInRandomStates) {
  Generator g(20261202);
  int compared = 0, disagreements = 0;
  for (int n = 0; n < 3000 && disagreements < 5; ++n) {
    const std::string text = g.condition(4);
    Evaluators e(text);
    if (!e.typed()) continue;
    for (int s = 0; s < 20; ++s) {
      const Point p = g.point();
      const Answers a = e.answers(p);
      ++compared;
      if (!a.agree()) {
        ++disagreements;
        ADD_FAILURE() << text << " at " << p.text() << ": " << a.text();
        break;
      }
    }
  }
  EXPECT_GT(compared, 20000);
}

}  // namespace
}  // namespace uabt::testing
