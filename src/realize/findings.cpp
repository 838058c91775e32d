#include <algorithm>

#include "base/diagnostics.hpp"
#include "base/finding.hpp"
#include "realize/realize.hpp"

namespace uabt::realize {

namespace {

// Where a requirement or a domain assumption is written.
SourceLocation location_of(const load::Mission& m, const std::string& id) {
  for (const auto& r : m.properties)
    if (r.id == id) return r.location;
  for (const auto& a : m.domain.assumptions)
    if (a.name == id) return a.location;
  return {m.requirements_file, 0, 0};
}

std::string inputs_text(const std::vector<Choice>& choices) {
  std::string out;
  for (const auto& c : choices) {
    out += (out.empty() ? "" : "; ") + std::string("tick ") + std::to_string(c.tick) + ":" +
           (c.inputs.empty() ? "" : " " + format_state(c.inputs, " = "));
  }
  return out;
}

}  // namespace

std::vector<Finding> findings_of(const load::Mission& m, const Result& r,
                                 const std::set<std::string>& first) {
  std::vector<Finding> out;
  for (const auto& c : r.components) {
    if (!c.realizable) {
      out.push_back(make_finding("realizability-undecided",
                                 "whether a tree can meet " + listed_with_and(c.requirements) +
                                     " is not decided: " + c.reason,
                                 location_of(m, c.requirements.front())));
      continue;
    }
    if (*c.realizable) continue;
    for (std::vector<std::string> conflict : c.conflicts) {
      std::stable_partition(conflict.begin(), conflict.end(),
                            [&](const std::string& id) { return first.count(id) != 0; });
      Finding f = make_finding(
          "requirements-unrealizable",
          (conflict.size() == 1
               ? "no behavior tree meets " + conflict.front()
               : "no behavior tree meets " + listed_with_and(conflict) + " together") +
              (conflict.size() == 1
                   ? ": the environment can always bring about a state in which it fails"
                   : ": the environment can always bring about a state in which one of them "
                     "fails"),
          location_of(m, conflict.front()));
      f.requirements = conflict;
      if (!c.defeating_inputs.empty())
        f.notes.push_back("inputs that defeat every tree of this component: " +
                          inputs_text(c.defeating_inputs));
      if (!c.conflicts_complete)
        f.notes.push_back(
            "other minimal conflicts may exist: the component has too many guarantees to try "
            "every set");
      out.push_back(std::move(f));
    }
  }
  return out;
}

}  // namespace uabt::realize
