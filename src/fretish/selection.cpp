// classify_selection: the FRETISH subset that selects an alternative of an adaptable node.
#include "fretish/selection.hpp"

#include <cctype>

namespace uabt::fretish {

namespace {

constexpr const char* kSubset = " is not supported in a selection requirement: ";

SourceLocation at(const Requirement& r, const SourceRange& range) {
  if (range.begin_line == 0) return r.location;
  return {r.location.file, range.begin_line, range.begin_column};
}

bool equals_ignoring_case(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) !=
        std::tolower(static_cast<unsigned char>(b[i])))
      return false;
  return true;
}

std::string scope_text(const Scope& s) {
  std::string out = s.keyword;
  if (!s.mode.empty()) out += " " + s.mode;
  if (s.condition) out += " " + to_fretish(*s.condition);
  return out;
}

std::string timing_text(const Timing& t) {
  std::string out = t.keyword;
  if (!t.duration.empty()) out += " " + t.duration + " " + t.unit;
  if (t.stop_condition) out += " " + to_fretish(*t.stop_condition);
  return out;
}

bool is_selection_scope(const Scope& s) {
  return !s.negated && !s.mode.empty() &&
         (s.keyword == "in" || s.keyword == "during" || s.keyword == "when in" ||
          s.keyword == "if in");
}

bool mentions_selected_alt(const Expr& e) {
  if (e.kind == ExprKind::identifier && e.text == "selected_alt") return true;
  for (const auto& a : e.args)
    if (a && mentions_selected_alt(*a)) return true;
  return false;
}

bool is_mission_property(const Requirement& r) {
  return !r.freeform && r.response && !mentions_selected_alt(*r.response);
}

class Classifier {
 public:
  Classifier(const Requirement& r, std::vector<Finding>& findings) : r_(r), findings_(findings) {}

  // Reports every unsupported field; true when there was none.
  bool check() {
    if (r_.freeform) {
      unsupported("freeform requirement '" + r_.text + "'" + kSubset +
                      "write it as 'In <adaptable> [if <guard>] Mission shall satisfy "
                      "selected_alt = <alternative>'",
                  r_.location);
      return false;
    }
    if (!r_.scope) {
      unsupported(
          "scope missing: a selection requirement needs 'In <adaptable>' (or "
          "'during', 'when in', 'if in')",
          r_.location);
    } else if (!is_selection_scope(*r_.scope)) {
      unsupported("scope '" + scope_text(*r_.scope) + "'" + kSubset +
                      "only 'in', 'during', 'when in' or 'if in' <adaptable>",
                  at(r_, r_.scope->range));
    }
    if (!equals_ignoring_case(r_.component, "Mission")) {
      unsupported("component '" + r_.component + "'" + kSubset + "only 'Mission'",
                  at(r_, r_.component_range));
    }
    if (r_.probability) {
      unsupported("probability 'with probability " + r_.probability->relop + " " +
                      r_.probability->number + "'" + kSubset + "selection is not probabilistic",
                  at(r_, r_.probability->range));
    }
    if (!r_.timing.keyword.empty() && r_.timing.keyword != "immediately") {
      unsupported(
          "timing '" + timing_text(r_.timing) + "'" + kSubset + "only none or 'immediately'",
          at(r_, r_.timing.range));
    }
    if (alternative() == nullptr) {
      const std::string written = r_.response ? to_fretish(*r_.response) : std::string("?");
      unsupported("response '" + written + "'" + kSubset + "only 'selected_alt = <alternative>'",
                  at(r_, r_.response_range));
    }
    return ok_;
  }

  // The alternative's identifier when the response is exactly `selected_alt = <identifier>`.
  const Expr* alternative() const {
    const Expr* e = r_.response.get();
    if (e == nullptr || e->kind != ExprKind::eq || e->args.size() != 2) return nullptr;
    const Expr& lhs = *e->args[0];
    const Expr& rhs = *e->args[1];
    if (lhs.kind != ExprKind::identifier || lhs.text != "selected_alt") return nullptr;
    if (rhs.kind != ExprKind::identifier) return nullptr;
    return &rhs;
  }

 private:
  void unsupported(std::string message, SourceLocation where) {
    Finding f = make_finding("fretish-unsupported", std::move(message), std::move(where));
    f.requirements = {r_.id};
    if (r_.scope && is_selection_scope(*r_.scope)) f.adaptable = r_.scope->mode;
    findings_.push_back(std::move(f));
    ok_ = false;
  }

  const Requirement& r_;
  std::vector<Finding>& findings_;
  bool ok_ = true;
};

}  // namespace

std::vector<SelectionRequirement> classify_selection(const std::vector<Requirement>& requirements,
                                                     std::vector<Finding>& findings) {
  std::vector<SelectionRequirement> selections;
  for (std::size_t i = 0; i < requirements.size(); ++i) {
    const Requirement& r = requirements[i];
    // A requirement that does not choose an alternative is a mission property (DESIGN §10),
    // checked by the monitors and by prove; only its probability has no meaning there.
    if (is_mission_property(r)) {
      if (r.probability) {
        Finding f = make_finding("fretish-unsupported",
                                 "probability 'with probability " + r.probability->relop + " " +
                                     r.probability->number + "': a run has no probability",
                                 at(r, r.probability->range));
        f.requirements = {r.id};
        findings.push_back(std::move(f));
      }
      continue;
    }
    Classifier classifier(r, findings);
    if (!classifier.check()) continue;
    const Expr* alternative = classifier.alternative();
    SelectionRequirement s;
    s.id = r.id;
    s.adaptable = r.scope->mode;
    s.alternative = alternative->text;
    s.guard = r.folded_condition();
    s.location = r.location;
    s.guard_location = r.conditions.empty() ? r.location : at(r, r.conditions.front().range);
    s.alternative_location = at(r, alternative->range);
    s.source_index = static_cast<int>(i);
    selections.push_back(std::move(s));
  }
  return selections;
}

}  // namespace uabt::fretish
