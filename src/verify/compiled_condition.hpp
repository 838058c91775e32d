#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fretish/expr.hpp"
#include "smt/types.hpp"

namespace uabt::verify::detail {

// A type-checked condition over discrete variables, compiled to a postfix program for fast
// repeated evaluation during coverage counting (millions of assignments). Same semantics as
// smt::evaluate (integer division and mod truncated toward zero; real sub-terms in double), except
// that a division by zero or an overflow is "no value" that only matters where it reaches the
// result: `x = 0 | 10 / x > 1` has a value in every state. holds() throws
// smt::EvaluationError when the result itself has no value.
class CompiledCondition {
 public:
  // `slot_of` gives each variable's position in the assignments passed to holds().
  CompiledCondition(const fretish::Expr& condition, const smt::Typing& typing,
                    const std::map<std::string, std::size_t>& slot_of);

  // `assignment[k]`: 0/1 for a boolean, the literal index for an enum, the value of an integer.
  bool holds(const std::int64_t* assignment) const;
  // Like holds(), but nullopt where the condition has no value.
  std::optional<bool> value(const std::int64_t* assignment) const;

  enum class Op : std::uint8_t;

 private:
  struct Instruction {
    Op op;
    std::uint32_t arity = 0;  // operands popped
    std::int64_t integer = 0;
    double real = 0.0;
  };
  struct Val {
    std::int64_t i = 0;
    double r = 0.0;
    bool none = false;  // no value (division by zero, overflow)
  };
  std::vector<Instruction> program_;
  std::size_t max_depth_ = 0;
  mutable std::vector<Val> stack_;

  void compile(const fretish::Expr& e, const smt::Typing& typing,
               const std::map<std::string, std::size_t>& slot_of, bool want_real);
  void emit(Op op, std::uint32_t arity, std::int64_t integer = 0, double real = 0.0);
};

}  // namespace uabt::verify::detail
