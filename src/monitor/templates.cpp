// The meaning of each FRET scope × condition × timing, built as a past-time formula.
//
// FRET formalizes a requirement in two layers, and so does this file:
//  - a base formula over the whole trace for the condition and timing (FRET's null scope), or
//    its dual for the "only" scopes, where the response is required NOT to behave as the
//    timing says (FRET: "only in M, P" means "outside M, not P");
//  - a scope wrapper. Multi-interval scopes (in, not in, only in) check the base relativized
//    to each interval: "historically" becomes "since the interval's first point", "once"
//    likewise, the first tick becomes the interval's first point, and a closed interval is
//    checked at the point after its end (FRET's Lin). `after` and `only before` relativize to
//    their single interval that runs to the end of the trace; `before` and `only after` check
//    the unrelativized base on the prefix that ends before their end point.
//
// FRET writes "within N" as H(O[=N] A -> O[<N] B), which would need the last N ticks. Under the
// H, it is equivalent to H(!(!B S[>=N] A)): no A at distance >= N with B absent ever since,
// which is one counter (`deadline` below). FRET's "only … after N" with a condition asks
// whether the trigger was exactly N+1 ticks ago while triggers may come at any tick; that is
// the one place a ring of N+1 bits is needed.
#include "monitor/templates.hpp"

namespace uabt::monitor {

const char* scope_key(ScopeKind s) {
  switch (s) {
    case ScopeKind::null: return "null";
    case ScopeKind::in: return "in";
    case ScopeKind::notin: return "notin";
    case ScopeKind::only_in: return "onlyIn";
    case ScopeKind::after: return "after";
    case ScopeKind::before: return "before";
    case ScopeKind::only_after: return "onlyAfter";
    case ScopeKind::only_before: return "onlyBefore";
  }
  return "null";
}

const char* condition_key(ConditionKind c) {
  switch (c) {
    case ConditionKind::null: return "null";
    case ConditionKind::regular: return "regular";
    case ConditionKind::holding: return "holding";
  }
  return "null";
}

const char* timing_key(TimingKind t) {
  switch (t) {
    case TimingKind::immediately: return "immediately";
    case TimingKind::next: return "next";
    case TimingKind::eventually: return "eventually";
    case TimingKind::finally: return "finally";
    case TimingKind::always: return "always";
    case TimingKind::never: return "never";
    case TimingKind::within: return "within";
    case TimingKind::for_ticks: return "for";
    case TimingKind::after: return "after";
    case TimingKind::until: return "until";
    case TimingKind::before: return "before";
  }
  return "eventually";
}

namespace {

// The temporal operators of a base formula, relativized to an interval whose first point is
// `start` (or to the whole trace when start < 0).
struct Context {
  Formula& f;
  int start = -1;

  int first() const { return start >= 0 ? start : f.first_tick(); }
  int H(int x) const {
    return start >= 0 ? f.since(x, f.conjunction(x, start)) : f.historically(x);
  }
  int O(int x) const {
    if (start < 0) return f.once(x);
    const int nx = f.negation(x);
    return f.negation(f.since(nx, f.conjunction(nx, start)));
  }
  int Y(int x) const {
    return start >= 0 ? f.conjunction(f.negation(start), f.yesterday(x)) : f.yesterday(x);
  }
  int Z(int x) const {
    return start >= 0 ? f.disjunction(start, f.yesterday(x)) : f.weak_yesterday(x);
  }
  // H(O[=k] a -> O[<k] b), with b including the interval's first point.
  int deadline(int a, int b, std::uint64_t k) const {
    return H(f.negation(f.since_at_least(f.negation(b), a, k)));
  }
  int NOT(int x) const { return f.negation(x); }
  int AND(int x, int y) const { return f.conjunction(x, y); }
  int OR(int x, int y) const { return f.disjunction(x, y); }
  int IMP(int x, int y) const { return f.implication(x, y); }
};

struct Inputs {
  int C, P, S;
  int J = -1;  // a trap's condition (Shape::judged)
};

// The ticks at which the timing judges the response (templates.hpp, build_requirement_formula).
int judged_tick(const Context& c, const Shape& shape, const Inputs& in) {
  Formula& f = c.f;
  const int st = c.first();
  const int P = in.P, nP = c.NOT(P), nS = c.NOT(in.S);
  const std::uint64_t d = shape.duration;
  const int T = shape.condition == ConditionKind::null      ? st
                : shape.condition == ConditionKind::regular ? c.AND(in.C, c.Z(c.NOT(in.C)))
                                                            : in.C;
  // a S b inside the interval: the chain does not cross its first point.
  const auto since = [&](int a, int b) { return f.since(c.AND(a, c.NOT(st)), b); };
  // g held at every tick from the latest trigger up to now.
  const auto held = [&](int g) { return since(g, c.AND(T, g)); };
  const int near = f.once_within(T, d);                        // the latest trigger <= d ago
  const int exactly = c.AND(near, c.NOT(f.once_below(T, d)));  // exactly d ago
  // g fails now for the first time since the latest trigger, at most d ticks after it.
  const auto first_fail = [&](int g) {
    return c.AND(c.NOT(g), c.OR(T, c.AND(c.Y(held(g)), near)));
  };
  switch (shape.timing) {
    case TimingKind::next: return c.Y(T);
    case TimingKind::eventually: return c.AND(P, c.OR(T, c.Y(held(nP))));
    case TimingKind::within: {
      // FRET's violation: a trigger d ticks ago or more, P false ever since; its first tick.
      const int late = f.since_at_least(c.AND(nP, c.NOT(st)), c.AND(T, nP), d);
      return c.OR(first_fail(nP), c.AND(late, c.NOT(c.Y(late))));
    }
    case TimingKind::for_ticks: return c.OR(first_fail(P), c.AND(held(P), exactly));
    case TimingKind::after: return c.OR(first_fail(nP), c.Y(c.AND(held(nP), exactly)));
    case TimingKind::until:
      return c.AND(nS, c.OR(T, c.Y(since(c.AND(P, nS), c.AND(c.AND(T, P), nS)))));
    case TimingKind::before: {
      const int open = c.Y(since(c.AND(nP, nS), c.AND(c.AND(T, nP), nS)));
      return c.OR(c.AND(c.AND(P, nS), c.OR(T, open)), c.AND(c.AND(in.S, c.NOT(T)), open));
    }
    default: return T;
  }
}

// FRET's null-scope formula for one condition kind and timing; `dual` for the only scopes.
int base(const Context& c, const Shape& shape, const Inputs& in, bool dual) {
  Formula& f = c.f;
  const int P = in.P, S = in.S, C = in.C;
  const int nP = c.NOT(P);
  const std::uint64_t d = shape.duration;
  const int ftp = c.first();
  if (shape.judged) return c.H(c.NOT(c.AND(judged_tick(c, shape, in), in.J)));
  if (shape.condition == ConditionKind::null) {
    if (!dual) {
      switch (shape.timing) {
        case TimingKind::immediately: return c.H(c.IMP(ftp, P));
        case TimingKind::next: return c.H(c.IMP(c.Y(ftp), P));
        case TimingKind::eventually: return c.O(P);
        case TimingKind::finally: return P;
        case TimingKind::always: return c.H(P);
        case TimingKind::never: return c.H(nP);
        case TimingKind::within: return c.H(c.IMP(c.H(nP), f.once_below(ftp, d)));
        case TimingKind::for_ticks: return c.H(c.IMP(f.once_within(ftp, d), P));
        case TimingKind::after:
          return c.AND(c.H(c.IMP(f.once_within(ftp, d), nP)),
                       c.H(c.IMP(c.H(nP), f.once_below(ftp, d + 1))));
        case TimingKind::until: return c.H(c.IMP(c.H(c.NOT(S)), P));
        case TimingKind::before: return c.H(c.IMP(S, c.Y(c.O(P))));
      }
    } else {
      switch (shape.timing) {
        case TimingKind::immediately: return c.H(c.IMP(ftp, nP));
        case TimingKind::next: return c.H(c.IMP(c.Y(ftp), nP));
        case TimingKind::eventually: return c.H(nP);
        case TimingKind::finally: return nP;
        case TimingKind::always: return c.NOT(c.H(P));
        case TimingKind::never: return c.O(P);
        case TimingKind::within: return c.H(c.IMP(f.once_within(ftp, d), nP));
        case TimingKind::for_ticks: return c.H(c.IMP(c.H(P), f.once_below(ftp, d)));
        case TimingKind::after: {
          // The first point was exactly d+1 ticks ago (a later first point makes the
          // implication hold anyway, through O[<=d]).
          const int at_d1 = c.AND(f.once_within(ftp, d + 1), c.NOT(f.once_within(ftp, d)));
          return c.H(c.IMP(at_d1, c.OR(c.OR(f.once_within(ftp, d), nP), c.Y(c.O(P)))));
        }
        case TimingKind::until: return c.H(c.IMP(S, c.Y(c.NOT(c.H(P)))));
        case TimingKind::before: return c.H(c.IMP(c.H(c.NOT(S)), nP));
      }
    }
    return f.constant(true);
  }
  const bool regular = shape.condition == ConditionKind::regular;
  const int T = regular ? c.AND(C, c.Z(c.NOT(C))) : C;  // the trigger
  const int never = c.H(c.NOT(C));                      // no trigger yet
  if (!dual) {
    switch (shape.timing) {
      case TimingKind::immediately: return c.H(c.IMP(T, P));
      case TimingKind::next: return c.H(c.IMP(c.Y(T), c.OR(P, ftp)));
      case TimingKind::eventually: return c.OR(never, c.NOT(f.since(nP, c.AND(nP, T))));
      case TimingKind::finally: return c.OR(never, P);
      case TimingKind::always: return c.H(c.OR(never, P));
      case TimingKind::never: return c.H(c.OR(never, nP));
      case TimingKind::within: return c.deadline(c.AND(T, nP), c.OR(ftp, P), d);
      case TimingKind::for_ticks: return c.H(c.IMP(f.once_within(T, d), c.OR(never, P)));
      case TimingKind::after:
        return c.AND(c.H(c.IMP(f.once_within(T, d), c.OR(never, nP))),
                     c.deadline(c.AND(T, nP), c.OR(ftp, P), d + 1));
      case TimingKind::until: {
        const int nS = c.NOT(S);
        return c.H(c.OR(never, c.IMP(f.since(nS, c.AND(nS, T)), P)));
      }
      case TimingKind::before: {
        const int earlier =
            c.AND(c.AND(c.Y(f.constant(true)), c.NOT(T)), c.Y(c.NOT(f.since(nP, c.AND(nP, T)))));
        return c.H(c.IMP(S, c.OR(never, earlier)));
      }
    }
  } else {
    switch (shape.timing) {
      case TimingKind::immediately: return c.H(c.IMP(T, nP));
      case TimingKind::next: return c.H(c.IMP(c.Y(T), c.OR(nP, ftp)));
      case TimingKind::eventually: return c.H(c.OR(never, nP));
      case TimingKind::finally: return c.OR(never, nP);
      case TimingKind::always: return c.OR(never, c.NOT(f.since(P, c.AND(P, T))));
      case TimingKind::never: return c.OR(never, c.NOT(f.since(nP, c.AND(nP, T))));
      case TimingKind::within: return c.H(c.IMP(f.once_within(T, d), c.OR(never, nP)));
      case TimingKind::for_ticks: return c.deadline(c.AND(T, P), c.OR(ftp, nP), d);
      case TimingKind::after:
        return c.H(c.IMP(f.exactly_ago(T, d + 1),
                         c.OR(c.OR(f.once_within(ftp, d), nP), c.Y(f.once_within(P, d)))));
      case TimingKind::until: {
        const int earlier =
            c.AND(c.AND(c.Y(f.constant(true)), c.NOT(T)), c.Y(c.NOT(f.since(P, c.AND(P, T)))));
        return c.H(c.IMP(S, c.OR(never, earlier)));
      }
      case TimingKind::before: {
        const int nS = c.NOT(S);
        return c.H(c.OR(never, c.IMP(f.since(nS, c.AND(nS, T)), nP)));
      }
    }
  }
  return f.constant(true);
}

bool is_dual(ScopeKind s) {
  return s == ScopeKind::only_in || s == ScopeKind::only_after || s == ScopeKind::only_before;
}

}  // namespace

int build_requirement_formula(Formula& f, const Shape& shape, const Slots& slots) {
  const Inputs in{slots.at(f, slots.condition), slots.at(f, slots.response),
                  slots.at(f, slots.stop), shape.judged ? slots.at(f, slots.judged) : -1};
  const int M = slots.at(f, slots.mode);
  const int nM = f.negation(M);
  const bool dual = is_dual(shape.scope);
  // First and one-past-last points of the intervals where `m` holds.
  const auto first_of = [&](int m) { return f.conjunction(m, f.weak_yesterday(f.negation(m))); };
  const auto past_end_of = [&](int m) { return f.conjunction(f.negation(m), f.yesterday(m)); };
  const auto first_time = [&](int x) {
    return f.conjunction(x, f.yesterday(f.historically(f.negation(x))));
  };
  // FRET's FFin: the first point where M holds; FLin: the first point after the first M interval.
  const int first_mode = f.conjunction(first_of(M), f.weak_yesterday(f.historically(nM)));
  const int after_first_interval = first_time(past_end_of(M));

  switch (shape.scope) {
    case ScopeKind::null: return base(Context{f}, shape, in, false);
    case ScopeKind::in:
    case ScopeKind::notin:
    case ScopeKind::only_in: {
      const int m = shape.scope == ScopeKind::in ? M : nM;
      const int start = first_of(m);
      const int past_end = past_end_of(m);
      const int inside = base(Context{f, start}, shape, in, dual);
      const int closed = f.historically(f.implication(past_end, f.yesterday(inside)));
      const int open_now =
          f.since(f.negation(past_end), f.conjunction(f.negation(past_end), start));
      return f.conjunction(closed, f.implication(open_now, inside));
    }
    case ScopeKind::after:
    case ScopeKind::only_before: {
      const int start = shape.scope == ScopeKind::after ? after_first_interval : first_mode;
      return f.implication(f.once(start), base(Context{f, start}, shape, in, dual));
    }
    case ScopeKind::before:
    case ScopeKind::only_after: {
      const int whole = base(Context{f}, shape, in, dual);
      int end = shape.scope == ScopeKind::before ? first_mode : after_first_interval;
      if (shape.scope == ScopeKind::before) end = f.conjunction(end, f.yesterday(f.constant(true)));
      const int ended = f.historically(f.implication(end, f.yesterday(whole)));
      const int not_yet = f.historically(
          f.negation(shape.scope == ScopeKind::before ? first_mode : after_first_interval));
      return f.conjunction(ended, f.implication(not_yet, whole));
    }
  }
  return f.constant(true);
}

int build_scope_start_formula(Formula& f, ScopeKind scope, int mode_slot) {
  return build_scope_start_at(f, scope, f.input(mode_slot));
}

int build_scope_start_at(Formula& f, ScopeKind scope, int M) {
  const int nM = f.negation(M);
  const int ftp = f.first_tick();
  // First point of an interval where m holds: m & (FTP | Y !m).
  const auto first_of = [&](int m, int not_m) {
    return f.conjunction(m, f.disjunction(ftp, f.yesterday(not_m)));
  };
  switch (scope) {
    case ScopeKind::null:
    case ScopeKind::before:
    case ScopeKind::only_after: return ftp;
    case ScopeKind::in: return first_of(M, nM);
    case ScopeKind::notin:
    case ScopeKind::only_in: return first_of(nM, M);
    case ScopeKind::after: {
      // FLin: the first point after the end of the first interval of m.
      const int past_end = f.conjunction(nM, f.yesterday(M));
      return f.conjunction(past_end, f.yesterday(f.historically(f.negation(past_end))));
    }
    case ScopeKind::only_before:
      // FFin: the first point where m holds.
      return f.conjunction(first_of(M, nM), f.disjunction(f.yesterday(f.historically(nM)), ftp));
  }
  return ftp;
}

namespace {

// An open obligation of the null-scope formula (not dual) in context `c`, or -1.
int pending_base(const Context& c, const Shape& shape, const Inputs& in) {
  Formula& f = c.f;
  const int nP = c.NOT(in.P);
  const std::uint64_t d = shape.duration;
  const int ftp = c.first();
  if (shape.condition == ConditionKind::null) {
    switch (shape.timing) {
      case TimingKind::next: return ftp;
      case TimingKind::within:
      case TimingKind::after: return c.H(nP);
      case TimingKind::for_ticks: return f.once_below(ftp, d);
      default: return -1;
    }
  }
  const bool regular = shape.condition == ConditionKind::regular;
  const int T = regular ? c.AND(in.C, c.Z(c.NOT(in.C))) : in.C;
  const int undischarged = f.since(nP, c.AND(T, nP));  // a trigger, no response since
  switch (shape.timing) {
    case TimingKind::next: return T;
    case TimingKind::within: return undischarged;
    case TimingKind::for_ticks: return f.once_below(T, d);
    case TimingKind::after: return c.OR(undischarged, f.once_within(T, d));
    default: return -1;
  }
}

}  // namespace

int build_pending_formula(Formula& f, const Shape& shape, const Slots& slots) {
  if (is_dual(shape.scope) || shape.judged) return -1;
  const Inputs in{slots.at(f, slots.condition), slots.at(f, slots.response),
                  slots.at(f, slots.stop)};
  const int M = slots.at(f, slots.mode);
  const auto first_of = [&](int m) { return f.conjunction(m, f.weak_yesterday(f.negation(m))); };
  const auto and_if = [&](int open, int now) { return open < 0 ? -1 : f.conjunction(open, now); };
  switch (shape.scope) {
    case ScopeKind::null: return pending_base(Context{f}, shape, in);
    case ScopeKind::in:
    case ScopeKind::notin: {
      // Open only while the interval is: one that closed was checked when it closed.
      const int m = shape.scope == ScopeKind::in ? M : f.negation(M);
      return and_if(pending_base(Context{f, first_of(m)}, shape, in), m);
    }
    case ScopeKind::after: {
      const int past_end = f.conjunction(f.negation(M), f.yesterday(M));
      const int start = f.conjunction(past_end, f.yesterday(f.historically(f.negation(past_end))));
      return and_if(pending_base(Context{f, start}, shape, in), f.once(start));
    }
    case ScopeKind::before: {
      const int first_mode =
          f.conjunction(first_of(M), f.weak_yesterday(f.historically(f.negation(M))));
      return and_if(pending_base(Context{f}, shape, in), f.historically(f.negation(first_mode)));
    }
    default: return -1;
  }
}

bool judges_later(TimingKind t) {
  switch (t) {
    case TimingKind::next:
    case TimingKind::eventually:
    case TimingKind::within:
    case TimingKind::for_ticks:
    case TimingKind::after:
    case TimingKind::until:
    case TimingKind::before: return true;
    default: return false;
  }
}

bool verdict_is_final_once_violated(const Shape& shape) {
  if (shape.judged) return true;
  const TimingKind t = shape.timing;
  if (is_dual(shape.scope))
    return t != TimingKind::always && t != TimingKind::never && t != TimingKind::finally;
  return t != TimingKind::eventually && t != TimingKind::finally;
}

}  // namespace uabt::monitor
