#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/value.hpp"
#include "fretish/domain.hpp"
#include "fretish/requirement.hpp"
#include "monitor/expression.hpp"
#include "monitor/formula.hpp"
#include "monitor/templates.hpp"

namespace uabt::monitor {

// A requirement's FRET classification, or why it has none on a trace.
struct Classified {
  std::optional<Shape> shape;
  std::string reason;  // when !shape: what has no meaning here, naming the field
};

// FRET's scope, condition kind and timing of a lowered requirement: its duration is the
// ticks its lowering gave (fretish/durations.hpp); one that could not be converted has no
// shape, with the lowering's reason.
Classified classify(const fretish::Requirement& r);

// One requirement compiled into a synchronous monitor: step() once per tick, constant time.
class RequirementMonitor {
 public:
  // nullopt with `reason` when the requirement cannot be monitored on this vocabulary.
  static std::unique_ptr<RequirementMonitor> compile(const fretish::Requirement& r,
                                                     const Resolver& resolve, std::string& reason);

  // The verdict of the trace so far, read as a whole finite trace (FRET's formula at this
  // tick). After an evaluation error the monitor stops (error() says why).
  bool step(const std::vector<Val>& frame);

  const std::string& id() const { return id_; }
  const Shape& shape() const { return shape_; }
  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }
  bool holds() const { return holds_; }  // the value at the last tick
  // The tick from which the verdict has been false without a break (set while !holds()).
  std::uint64_t violated_since() const { return violated_since_; }
  // True once the verdict turned false for good (safety properties: at once).
  bool final_violation() const { return !holds_ && verdict_is_final_once_violated(shape_); }
  // Slots of the variables the requirement reads, in first-use order, and their values at
  // violated_since().
  const std::vector<int>& variables() const { return variables_; }
  // While the verdict holds only because the trace ends before a deadline (FRET's
  // finite-trace meaning): the tick the open obligation was triggered, else nullopt.
  std::optional<std::uint64_t> pending_since() const {
    return holds_ && pending_ ? std::optional<std::uint64_t>(pending_since_) : std::nullopt;
  }
  // What stays due while pending: "stopped within 2 ticks".
  const std::string& obligation() const { return obligation_; }
  const std::vector<Val>& violation_values() const { return violation_values_; }

 private:
  std::string id_;
  Shape shape_;
  std::vector<std::optional<CompiledExpression>> parts_;  // mode, condition, response, stop, trap
  Formula formula_;
  std::optional<FormulaMonitor> run_;
  Formula start_formula_;  // FRET's $Left$, when a part has temporal functions
  std::optional<FormulaMonitor> start_;
  std::vector<int> variables_;
  std::vector<Val> violation_values_;
  std::string error_;
  int pending_node_ = -1;
  bool pending_ = false;
  std::uint64_t pending_since_ = 0;
  std::string obligation_;
  bool holds_ = true;
  std::uint64_t tick_ = 0;
  std::uint64_t violated_since_ = 0;
};

// A value for reports, typed: true/false, a number (number_text, number_json), a symbol's name;
// a value the trace did not give is the name "?".
Value value_of(const Val& v, const Symbols& symbols);
}  // namespace uabt::monitor
