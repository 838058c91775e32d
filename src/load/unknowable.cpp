#include "load/unknowable.hpp"

#include <algorithm>
#include <cctype>
#include <set>

namespace uabt::load {

namespace {

std::set<std::string> words_of(const std::string& text) {
  std::set<std::string> out;
  std::string word;
  for (const char c : text + " ") {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
      word += c;
    } else if (!word.empty()) {
      out.insert(word);
      word.clear();
    }
  }
  return out;
}

std::string where(const SourceLocation& l) {
  return l.line > 0 ? l.file + ":" + std::to_string(l.line) : l.file;
}

void unparsed_requirements(Mission& m) {
  for (const auto& [location, line] : m.unparsed_requirements) {
    const std::string why = "the requirement at " + where(location) + " does not parse";
    const std::set<std::string> words = words_of(line);
    bool named = false;
    for (const auto& site : m.adaptables) {
      if (site.id.empty() || !words.count(site.id)) continue;
      m.not_verified.emplace(site.id, why);
      m.requirements_incomplete.insert(site.id);
      named = true;
    }
    if (named) continue;
    for (const auto& site : m.adaptables)  // its scope is unknown: it may belong to any node
      if (!site.id.empty()) {
        m.not_verified.emplace(site.id, why);
        m.requirements_incomplete.insert(site.id);
      }
  }
}

// A declaration that cannot be used as written (an empty range, a refused enum) leaves the
// domain unknown: a range [4, 2] has no state at all, and an unbounded stand-in would give
// witnesses outside what was declared. No guard is checked until it is fixed, as with an
// inconsistent domain.
void invalid_declarations(Mission& m) {
  const auto invalid = std::find_if(m.domain.variables.begin(), m.domain.variables.end(),
                                    [](const fretish::Variable& v) { return !v.invalid.empty(); });
  if (invalid == m.domain.variables.end()) return;
  const std::string why = "the declaration of '" + invalid->name + "' is invalid (" +
                          where(invalid->location) + ": " + invalid->invalid + ")";
  for (const auto& site : m.adaptables)
    if (!site.id.empty()) m.not_verified.emplace(site.id, why);
}

}  // namespace

void mark_unknowable(Mission& m) {
  unparsed_requirements(m);
  invalid_declarations(m);
}

}  // namespace uabt::load
