#pragma once
#include <cstdint>
#include <string>

#include "monitor/formula.hpp"

namespace uabt::monitor {

// FRET's classification of a requirement (its semantics key "scope,condition,timing").
enum class ScopeKind { null, in, notin, only_in, after, before, only_after, only_before };
enum class ConditionKind { null, regular, holding };
enum class TimingKind {
  immediately,
  next,
  eventually,
  finally,
  always,
  never,
  within,
  for_ticks,
  after,
  until,
  before
};

struct Shape {
  ScopeKind scope = ScopeKind::null;
  ConditionKind condition = ConditionKind::null;
  TimingKind timing = TimingKind::eventually;
  std::uint64_t duration = 0;  // ticks, for within / for / after
  // A trap of the test campaign (fretish::Requirement::judged): instead of the requirement,
  // "never the `judged` input at a tick where this timing judges the response" (see
  // build_requirement_formula). Only for the timings that judge the response after the
  // trigger: next, eventually, within, for, after, until, before.
  bool judged = false;
};

// Whether the timing judges the response at ticks other than the trigger's own (then a
// response's atoms decide it there, and the test campaign's traps follow it).
bool judges_later(TimingKind t);

// FRET's names, as in its semantics keys: "in", "onlyAfter", "regular", "for", ...
const char* scope_key(ScopeKind s);
const char* condition_key(ConditionKind c);
const char* timing_key(TimingKind t);

// Input slots of the formula: the scope's mode, the (folded) condition, the response and the
// stop condition of until/before. Unused ones are ignored. With `nodes`, the four are nodes
// already in the formula (a part that is itself a formula over other inputs).
struct Slots {
  int mode = 0, condition = 1, response = 2, stop = 3, judged = 4;
  bool nodes = false;
  int at(Formula& f, int slot) const { return nodes ? slot : f.input(slot); }
};

// Builds the requirement's meaning at every tick: true at tick t exactly when the trace up to
// t, read as a whole finite trace, satisfies the requirement under FRET's past-time
// formalization. Returns the root node.
//
// With shape.judged, the meaning of a test campaign's trap instead: false from the first tick
// t' at which input `judged` holds and the response is judged, in the scope's interval, where
// (T: the trigger as FRET counts it, the rising edge of a regular condition, each tick of a
// holding one, the interval's first point without a condition; P: the response; S: the stop
// condition; the trigger is the latest one before t', in the same interval):
//  - next: t' = T + 1;
//  - eventually: P first holds at t' since T (a run that never satisfies P is judged only when
//    it ends: no tick);
//  - within N: P first holds at t' <= T + N, or t' = T + N and P never held from T (FRET's
//    violation tick: the earliest trigger still waiting);
//  - for N: P first fails at t' <= T + N, or t' = T + N and P held from T;
//  - after N: P first holds at t' <= T + N (too early), or t' = T + N + 1 with P false from T;
//  - until S: T <= t', no S in [T, t'], P held in [T, t' - 1] (each tick P is due, until the
//    first that fails);
//  - before S: P first holds at t' with no S in [T, t'], or S at t' != T and P never held
//    in [T, t' - 1] (FRET's violation).
int build_requirement_formula(Formula& f, const Shape& shape, const Slots& slots);

// FRET's $Left$ for the scope: true at the scope's left end point, from which the temporal
// functions persisted/occurred/prevOcc of the condition, response and stop count (semantics.json,
// endpoints.SMVptExtleft). Reads the mode from input `mode_slot`. Returns the node.
int build_scope_start_formula(Formula& f, ScopeKind scope, int mode_slot);
// The same, reading the mode from the formula's node `mode`.
int build_scope_start_at(Formula& f, ScopeKind scope, int mode);

// An obligation still open at tick t: true at t when the trace so far holds the requirement
// only because it ends before a deadline (a `within`, `for`, `after` or `next` whose trigger
// was recent). FRET's finite-trace meaning counts such a trace as held; reports say it is
// pending. Returns the node, or -1 for a shape with no such obligation (the "only" scopes,
// untimed requirements).
int build_pending_formula(Formula& f, const Shape& shape, const Slots& slots);

// True when the verdict can only go from held to violated, never back (a safety property):
// then a violation is final at the tick it appears. Otherwise (eventually, finally, …) the
// verdict of a finite trace is its value at the last tick.
bool verdict_is_final_once_violated(const Shape& shape);

}  // namespace uabt::monitor
