#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fretish/evaluate.hpp"
#include "fretish/expr.hpp"
#include "smt/types.hpp"

namespace uabt::verify::detail {

// A type-checked condition over discrete variables, compiled to a postfix program for fast
// repeated evaluation during coverage counting (millions of assignments). Its operators are
// fretish::apply, the meaning every evaluator shares (ARCHITECTURE §14): "no value" (a
// division by zero, an overflow) matters only where it reaches the result, so
// `x = 0 | 10 / x > 1` has a value in every state. holds() throws smt::EvaluationError when the
// result itself has no value.
class CompiledCondition {
 public:
  // `slot_of` gives each variable's position in the assignments passed to holds().
  CompiledCondition(const fretish::Expr& condition, const smt::Typing& typing,
                    const std::map<std::string, std::size_t>& slot_of);

  // `assignment[k]`: 0/1 for a boolean, the literal index for an enum, the value of an integer.
  bool holds(const std::int64_t* assignment) const;
  // Like holds(), but nullopt where the condition has no value.
  std::optional<bool> value(const std::int64_t* assignment) const;

 private:
  enum class Load : std::uint8_t { constant, boolean, integer, symbol, apply };
  struct Instruction {
    Load load = Load::constant;
    fretish::Op op = fretish::Op::unknown;  // apply
    std::uint32_t arity = 0;                // operands popped
    std::size_t slot = 0;                   // boolean, integer, symbol
    fretish::Val constant;
  };
  std::vector<Instruction> program_;
  mutable std::vector<fretish::Val> stack_;

  void compile(const fretish::Expr& e, const smt::Typing& typing,
               const std::map<std::string, std::size_t>& slot_of);
};

}  // namespace uabt::verify::detail
