// classify_selection: the FRETISH subset that selects an alternative of an adaptable node.
#include "fretish/selection.hpp"

#include <cctype>

#include "fretish/durations.hpp"

namespace uabt::fretish {

namespace {

constexpr const char* kSubset = " is not supported in a selection requirement: ";

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

bool is_selection_scope(const Scope& s) {
  return !s.negated && !s.mode.empty() &&
         (s.keyword == "in" || s.keyword == "during" || s.keyword == "when in" ||
          s.keyword == "if in");
}

class Classifier {
 public:
  Classifier(const Requirement& r, std::vector<Finding>& findings) : r_(r), findings_(findings) {}

  // Reports every unsupported field; true when there was none.
  bool check() {
    if (r_.freeform) {
      unsupported("freeform requirement '" + r_.text +
                      "' has no formal meaning: FRET does not formalize it; write it in "
                      "FRETISH, e.g. 'In <adaptable> [if <guard>] Mission shall satisfy "
                      "selected_alt = <alternative>' or a mission property",
                  r_.location);
      return false;
    }
    if (r_.probability) {
      unsupported("probability 'with probability " + r_.probability->relop + " " +
                      r_.probability->number +
                      "' has no meaning here: a selection is not probabilistic and a run has no "
                      "probability",
                  start_of(r_.probability->range, r_.location));
    }
    // Not meant as a selection requirement: a mission property (ARCHITECTURE §10).
    if (!mentions_selected_alt()) return false;
    if (!r_.scope) {
      unsupported(
          "scope missing: a selection requirement needs 'In <adaptable>' (or "
          "'during', 'when in', 'if in')",
          r_.location);
    } else if (!is_selection_scope(*r_.scope)) {
      unsupported("scope '" + scope_text(*r_.scope) + "'" + kSubset +
                      "only 'in', 'during', 'when in' or 'if in' <adaptable>",
                  start_of(r_.scope->range, r_.location));
    }
    if (!equals_ignoring_case(r_.component, "Mission")) {
      unsupported("component '" + r_.component + "'" + kSubset + "only 'Mission'",
                  start_of(r_.component_range, r_.location));
    }
    if (!r_.timing.keyword.empty() && r_.timing.keyword != "immediately") {
      unsupported(
          "timing '" + timing_text(r_.timing) + "'" + kSubset + "only none or 'immediately'",
          start_of(r_.timing.range, r_.location));
    }
    if (alternative() == nullptr) {
      const std::string written = r_.response ? to_fretish(*r_.response) : std::string("?");
      unsupported("response '" + written + "'" + kSubset + "only 'selected_alt = <alternative>'",
                  start_of(r_.response_range, r_.location));
    }
    return ok_;
  }

  // `selected_alt` is the selection requirements' own word: a requirement that reads it was
  // meant to select an alternative (a property names `<adaptable>.selected` instead).
  bool mentions_selected_alt() const {
    if (!r_.response) return false;
    for (const std::string& name : identifiers_of(*r_.response))
      if (name == "selected_alt") return true;
    return false;
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
  return classify_requirements(requirements, findings).selections;
}

Classification classify_requirements(const std::vector<Requirement>& requirements,
                                     std::vector<Finding>& findings) {
  Classification out;
  std::vector<SelectionRequirement>& selections = out.selections;
  for (std::size_t i = 0; i < requirements.size(); ++i) {
    const Requirement& r = requirements[i];
    Classifier classifier(r, findings);
    const std::size_t before = findings.size();
    if (!classifier.check()) {
      if (findings.size() == before) out.properties.push_back(r);
      continue;
    }
    const Expr* alternative = classifier.alternative();
    SelectionRequirement s;
    s.id = r.id;
    s.adaptable = r.scope->mode;
    s.alternative = alternative->text;
    s.guard = r.folded_condition();
    s.location = r.location;
    s.guard_location =
        r.conditions.empty() ? r.location : start_of(r.conditions.front().range, r.location);
    s.alternative_location = start_of(alternative->range, r.location);
    s.source_index = static_cast<int>(i);
    selections.push_back(std::move(s));
  }
  return out;
}

}  // namespace uabt::fretish
