#include "monitor/monitor.hpp"

#include "base/number_text.hpp"

#include <cstdio>
#include <iterator>

#include "fretish/durations.hpp"
#include "fretish/expr.hpp"

namespace uabt::monitor {

namespace {

// A requirement's parts, in the order the monitor compiles them and reads their inputs.
constexpr const char* kPartNames[] = {"scope", "condition", "response", "stop condition", "trap"};
constexpr std::size_t kParts = std::size(kPartNames);

bool contains(const std::string& text, const char* word) {
  return text.find(word) != std::string::npos;
}

std::optional<ScopeKind> scope_kind(const fretish::Scope& s) {
  const bool only = s.keyword.rfind("only", 0) == 0;
  if (contains(s.keyword, "after")) return only ? ScopeKind::only_after : ScopeKind::after;
  if (contains(s.keyword, "before")) return only ? ScopeKind::only_before : ScopeKind::before;
  if (s.negated) return only ? std::nullopt : std::optional(ScopeKind::notin);
  return only ? ScopeKind::only_in : ScopeKind::in;
}

std::optional<TimingKind> timing_kind(const std::string& k) {
  if (k.empty() || k == "eventually") return TimingKind::eventually;
  if (k == "immediately" || k == "initially" || k == "at the first timepoint" ||
      k == "at the same timepoint")
    return TimingKind::immediately;
  if (k == "at the next timepoint" || k == "next") return TimingKind::next;
  if (k == "finally" || k == "at the last timepoint") return TimingKind::finally;
  if (k == "always") return TimingKind::always;
  if (k == "never") return TimingKind::never;
  if (k == "within") return TimingKind::within;
  if (k == "for") return TimingKind::for_ticks;
  if (k == "after") return TimingKind::after;
  if (k == "until") return TimingKind::until;
  if (k == "before") return TimingKind::before;
  return std::nullopt;
}

// A ring of N+1 bits is the one state that grows with N; refuse absurd sizes.
constexpr std::uint64_t kMaxRingTicks = std::uint64_t{1} << 26;

}  // namespace

Classified classify(const fretish::Requirement& r) {
  Classified c;
  if (r.freeform) {
    c.reason = "freeform requirement: FRET does not formalize it";
    return c;
  }
  if (r.probability) {
    c.reason = "probability 'with probability " + r.probability->relop + " " +
               r.probability->number + "': a run has no probability";
    return c;
  }
  Shape s;
  if (r.scope) {
    const auto kind = scope_kind(*r.scope);
    if (!kind) {
      c.reason = "scope '" + r.scope->keyword + "': FRET gives 'only' with a negation no meaning";
      return c;
    }
    s.scope = *kind;
  }
  if (!r.conditions.empty()) {
    bool all_whenever = true;
    for (const auto& cond : r.conditions)
      all_whenever = all_whenever && cond.qualifier == "whenever";
    s.condition = all_whenever ? ConditionKind::holding : ConditionKind::regular;
  }
  const auto timing = timing_kind(r.timing.keyword);
  if (!timing) {
    c.reason = "timing '" + r.timing.keyword + "' is not one of FRET's";
    return c;
  }
  s.timing = *timing;
  if (!r.timing.duration.empty()) {
    if (!r.timing.ticks) {
      c.reason = !r.timing.unconverted.empty()
                     ? r.timing.unconverted
                     : "timing '" + fretish::timing_text(r.timing) + "' was not lowered to ticks";
      return c;
    }
    s.duration = *r.timing.ticks;
  }
  const bool ring = (s.scope == ScopeKind::only_in || s.scope == ScopeKind::only_after ||
                     s.scope == ScopeKind::only_before) &&
                    s.timing == TimingKind::after && s.condition != ConditionKind::null;
  if (ring && s.duration >= kMaxRingTicks) {
    c.reason = "timing 'after " + std::to_string(s.duration) +
               " ticks' in an 'only' scope with a condition needs the last N ticks; N is too large";
    return c;
  }
  if (r.judged) {
    if (!judges_later(s.timing)) {
      c.reason = "a trap judged by timing '" + r.timing.keyword + "': it judges only the trigger";
      return c;
    }
    s.judged = true;
  }
  c.shape = s;
  return c;
}

std::unique_ptr<RequirementMonitor> RequirementMonitor::compile(const fretish::Requirement& r,
                                                                const Resolver& resolve,
                                                                std::string& reason) {
  const Classified c = classify(r);
  if (!c.shape) {
    reason = c.reason;
    return nullptr;
  }
  auto m = std::make_unique<RequirementMonitor>();
  m->id_ = r.id;
  m->shape_ = *c.shape;
  fretish::ExprPtr mode;
  if (r.scope)
    mode = r.scope->condition ? r.scope->condition : fretish::make_identifier(r.scope->mode);
  const fretish::ExprPtr parts[] = {mode, r.folded_condition(), r.response, r.timing.stop_condition,
                                    r.judged};
  static_assert(std::size(parts) == kParts);
  for (std::size_t i = 0; i < kParts; ++i) {
    if (!parts[i]) {
      m->parts_.emplace_back();
      continue;
    }
    std::string error;
    auto compiled =
        CompiledExpression::compile(*parts[i], resolve, error, i == 0 ? Field::mode : Field::other);
    if (!compiled) {
      reason = std::string(kPartNames[i]) + ": " + error;
      return nullptr;
    }
    for (int v : compiled->variables()) {
      bool known = false;
      for (int w : m->variables_) known = known || v == w;
      if (!known) m->variables_.push_back(v);
    }
    m->parts_.push_back(std::move(compiled));
  }
  bool temporal = false;
  for (std::size_t i = 1; i < kParts; ++i)
    temporal = temporal || (m->parts_[i] && m->parts_[i]->has_temporal_functions());
  if (temporal)
    m->start_.emplace(m->start_formula_,
                      build_scope_start_formula(m->start_formula_, m->shape_.scope, 0));
  const int root = build_requirement_formula(m->formula_, m->shape_, Slots{});
  m->pending_node_ = r.response ? build_pending_formula(m->formula_, m->shape_, Slots{}) : -1;
  if (m->pending_node_ >= 0) {
    const std::string& unit = m->shape_.duration == 1 ? "tick" : "ticks";
    const std::string n = std::to_string(m->shape_.duration) + " " + unit;
    const std::string response = fretish::to_fretish(*r.response);
    switch (m->shape_.timing) {
      case TimingKind::next: m->obligation_ = response + " at the next tick"; break;
      case TimingKind::within: m->obligation_ = response + " within " + n; break;
      case TimingKind::for_ticks: m->obligation_ = response + " for " + n; break;
      case TimingKind::after: m->obligation_ = response + " after " + n; break;
      default: m->pending_node_ = -1; break;
    }
  }
  m->run_.emplace(m->formula_, root);
  return m;
}

bool RequirementMonitor::step(const std::vector<Val>& frame) {
  if (failed()) return holds_;
  bool inputs[kParts] = {};
  for (std::size_t i = 0; i < kParts; ++i) {
    if (i == 1 && start_) {
      const bool left = start_->step(inputs);  // reads the mode, input 0
      for (std::size_t j = 1; j < kParts; ++j)
        if (parts_[j]) parts_[j]->set_scope_start(left);
    }
    if (!parts_[i]) continue;
    std::string error;
    inputs[i] = parts_[i]->evaluate_bool(frame, error);
    if (!error.empty()) {
      error_ = "at tick " + std::to_string(tick_) + ", the " + kPartNames[i] + ": " + error;
      return holds_;
    }
  }
  const bool now = run_->step(inputs);
  const bool pending = pending_node_ >= 0 && run_->value(pending_node_);
  if (pending && !pending_) pending_since_ = tick_;
  pending_ = pending;
  if (!now && (holds_ || tick_ == 0)) {
    violated_since_ = tick_;
    violation_values_.clear();
    for (int slot : variables_) violation_values_.push_back(frame[static_cast<std::size_t>(slot)]);
  }
  holds_ = now;
  ++tick_;
  return now;
}

Value value_of(const Val& v, const Symbols& symbols) {
  switch (v.kind) {
    case Val::Kind::missing: return Value::of_enum("?");
    case Val::Kind::boolean: return Value::of_bool(v.number != 0);
    case Val::Kind::symbol: return Value::of_enum(symbols.name(v.symbol));
    case Val::Kind::number: return number_value(v.number);
  }
  return Value::of_enum("?");
}

}  // namespace uabt::monitor
