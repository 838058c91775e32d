#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/location.hpp"
#include "fretish/expr.hpp"

namespace uabt::fretish {

// The full AST of one FRETISH requirement (FRET's Requirement.g4), every field kept with
// its source range so that diagnostics point at what the engineer wrote.
struct Scope {
  // "in", "during", "when in", "if in", "when not in", "if not in", "unless in", "while",
  // "after", "before", "only in", "only during", "only when in", "only if in", "only while",
  // "only after", "only before", "except in", "except during", "except when in",
  // "except if in", "except while", "not in" — the words as written, lower case, one space.
  std::string keyword;
  std::string mode;      // the mode name for mode scopes
  ExprPtr condition;     // for while / after B / before B
  bool negated = false;  // an odd number of not/unless/except
  SourceRange range;
};

struct Condition {
  std::string qualifier;   // upon whenever when unless where if (lower case)
  std::string connective;  // "", "and" or "or": how it joins the previous condition
  ExprPtr expr;
  bool is_true_suffix = false;   // "is true" written
  bool is_false_suffix = false;  // "is false" written
  SourceRange range;
};

struct Probability {
  std::string relop;  // < <= = != > >=
  std::string number;
  SourceRange range;
};

struct Timing {
  // "" (none: FRET's eventually), immediately, initially, "at the first timepoint",
  // "at the same timepoint", "at the next timepoint", "at the last timepoint", within, for,
  // after, until, before, eventually, finally, always, never
  std::string keyword;
  std::string duration;        // number for within/for/after, as written
  std::string unit;            // ticks, seconds, ... as written (lower case)
  SourceRange duration_range;  // the number
  // The duration in whole ticks, set once where the requirement is lowered
  // (fretish/durations.hpp, with the domain's tick period). Every command reads it, never
  // `duration` and `unit`. Unset when there is no duration or it cannot be converted; then
  // `unconverted` says why, as the lowering reported it.
  std::optional<std::uint64_t> ticks;
  std::string unconverted;
  ExprPtr stop_condition;  // until B / before B
  SourceRange range;
};

struct Requirement {
  std::string id;           // label, FRET reqid, or R<line>
  std::string text;         // the sentence as written (without label)
  SourceLocation location;  // where the sentence starts
  bool freeform = false;    // a quoted freeform sentence: stored, not formalized

  std::optional<Scope> scope;
  std::vector<Condition> conditions;
  std::string component;
  SourceRange component_range;
  bool component_before_shall = true;
  std::optional<Probability> probability;
  Timing timing;
  ExprPtr response;  // the expression after "satisfy"
  SourceRange response_range;
  // Never written in FRETISH: set only on the traps of uabt's test campaign (prove/reach.hpp),
  // which then mean "never `judged` at a tick where this requirement's timing judges its
  // response" (monitor/templates.hpp, Shape::judged).
  ExprPtr judged;

  // The guard these conditions mean, folded left to right: "or" → |, "and"/nothing → &,
  // unless C and "C is false" → !C. nullptr when there is no condition.
  ExprPtr folded_condition() const;
};

// Component `Environment` (any case) marks an assumption about the world; any other component a
// guarantee of the mission (ARCHITECTURE §10).
bool is_assumption(const Requirement& r);

}  // namespace uabt::fretish
