#include "monitor/property_check.hpp"

#include <algorithm>

#include "base/suggest.hpp"
#include "monitor/expression.hpp"
#include "monitor/monitor.hpp"

namespace uabt::monitor {

namespace {

using fretish::Expr;
using fretish::ExprKind;
using Type = Observables::Type;

const char* type_name(Type t) {
  switch (t) {
    case Type::boolean: return "a boolean";
    case Type::number: return "a number";
    case Type::name: return "a name";
  }
  return "a boolean";
}

class PartChecker {
 public:
  PartChecker(const fretish::Requirement& r, const Observables& o, std::optional<NameIndex>& names,
              std::vector<Finding>& findings)
      : r_(r), o_(o), names_(names), findings_(findings) {}

  void part(const Expr& e, const char* what) {
    ok_ = true;
    const auto t = type_of(e);
    if (ok_ && t && *t != Type::boolean)
      report("property-type",
             std::string("the ") + what + " '" + fretish::to_fretish(e) + "' is " + type_name(*t) +
                 ", not a boolean",
             e);
  }

 private:
  SourceLocation at(const Expr& e) const { return start_of(e.range, r_.location); }
  void report(const std::string& check, std::string message, const Expr& e,
              std::vector<std::string> notes = {}) {
    if (!ok_) return;  // one finding per part
    Finding f = make_finding(check, std::move(message), at(e));
    f.requirements = {r_.id};
    f.notes = std::move(notes);
    findings_.push_back(std::move(f));
    ok_ = false;
  }
  // nullopt: unknown (already reported)
  std::optional<Type> type_of(const Expr& e) {
    switch (e.kind) {
      case ExprKind::bool_literal: return Type::boolean;
      case ExprKind::number: return Type::number;
      case ExprKind::identifier: {
        if (const auto it = o_.variables.find(e.text); it != o_.variables.end()) return it->second;
        if (o_.literals.count(e.text) != 0) return Type::name;
        if (e.text == "FTP") return Type::boolean;  // FRET's first time point
        if (const auto gone = o_.not_observable.find(e.text); gone != o_.not_observable.end()) {
          report("property-reference",
                 "'" + e.text + "' is not an observable of the run: " + gone->second, e);
          return std::nullopt;
        }
        std::vector<std::string> notes;
        if (!names_) {
          std::vector<std::string> observables;
          for (const auto& [name, type] : o_.variables) observables.push_back(name);
          names_.emplace(observables);
        }
        if (std::string hint = names_->did_you_mean(e.text); !hint.empty())
          notes.push_back(std::move(hint));
        report("property-reference",
               "'" + e.text +
                   "' is not an observable of the run: not a domain variable, condition, "
                   "<node>.success/.failure/.running, <adaptable> or <adaptable>.selected",
               e, std::move(notes));
        return std::nullopt;
      }
      case ExprKind::call: {
        const std::string why = unmonitored_temporal(e.text, e.args.size());
        if (!is_monitored_function(e.text) || !why.empty()) {
          report("property-reference",
                 why.empty() ? "function '" + e.text + "' is not monitored on a run" : why, e);
          return std::nullopt;
        }
        std::optional<Type> result = Type::number;
        const bool temporal = is_temporal_function(e.text);
        for (std::size_t i = 0; i < e.args.size(); ++i) {
          const Expr& a = *e.args[i];
          const auto t = type_of(a);
          if (!t) return std::nullopt;
          if (e.text.rfind("pre", 0) == 0 || e.text == "ite") result = t;
          // persisted(n, p), occurred(n, p), prevOcc(p, q): p and q are conditions.
          if (temporal && *t != Type::boolean && (e.text == "prevOcc" || i == 1)) {
            report("property-type",
                   "'" + fretish::to_fretish(a) + "' is " + type_name(*t) + ", but " + e.text +
                       " needs a boolean there",
                   a);
            return std::nullopt;
          }
        }
        if (e.text == "preBool" || is_temporal_function(e.text)) return Type::boolean;
        return result;
      }
      case ExprKind::logical_not:
      case ExprKind::logical_and:
      case ExprKind::logical_or:
      case ExprKind::logical_xor:
      case ExprKind::implies:
      case ExprKind::iff:
        for (const auto& a : e.args) {
          const auto t = type_of(*a);
          if (!t) return std::nullopt;
          if (*t != Type::boolean) {
            report("property-type",
                   "'" + fretish::to_fretish(*a) + "' is " + type_name(*t) +
                       ", but a boolean operator needs booleans",
                   *a);
            return std::nullopt;
          }
        }
        return Type::boolean;
      default: break;
    }
    // Relations and arithmetic.
    std::vector<Type> types;
    for (const auto& a : e.args) {
      const auto t = type_of(*a);
      if (!t) return std::nullopt;
      types.push_back(*t);
    }
    const bool equality = e.kind == ExprKind::eq || e.kind == ExprKind::ne;
    for (std::size_t i = 0; i < types.size(); ++i) {
      const bool fits = equality ? types[i] == types[0] : types[i] == Type::number;
      if (!fits) {
        report("property-type",
               "'" + fretish::to_fretish(e) + "' " +
                   (equality ? "compares " + std::string(type_name(types[0])) + " with " +
                                   type_name(types[i])
                             : "needs numbers, got " + std::string(type_name(types[i]))),
               e);
        return std::nullopt;
      }
    }
    return fretish::is_relation(e.kind) ? Type::boolean : Type::number;
  }

  const fretish::Requirement& r_;
  const Observables& o_;
  std::optional<NameIndex>& names_;  // o_'s variables, indexed at the first unknown name
  std::vector<Finding>& findings_;
  bool ok_ = true;
};

}  // namespace

std::vector<Finding> check_properties(const std::vector<fretish::Requirement>& properties,
                                      const Observables& observables) {
  std::vector<Finding> findings;
  std::optional<NameIndex> names;  // built when a name is not an observable
  for (const fretish::Requirement& r : properties) {
    const Classified c = classify(r);
    // A duration that could not be converted is the lowering's error, reported there.
    if (!c.shape && r.timing.unconverted.empty()) {
      Finding f = make_finding("property-timing", r.id + ": " + c.reason, r.location);
      f.requirements = {r.id};
      findings.push_back(std::move(f));
    }
    PartChecker check(r, observables, names, findings);
    if (r.scope) {
      if (r.scope->condition) {
        check.part(*r.scope->condition, "scope");
      } else if (!r.scope->mode.empty()) {
        check.part(*fretish::make_identifier(r.scope->mode, {r.scope->range.begin_line,
                                                             r.scope->range.begin_column, 0, 0}),
                   "scope");
      }
    }
    for (const auto& cond : r.conditions)
      if (cond.expr) check.part(*cond.expr, "condition");
    if (r.response) check.part(*r.response, "response");
    if (r.timing.stop_condition) check.part(*r.timing.stop_condition, "stop condition");
  }
  return findings;
}

}  // namespace uabt::monitor
