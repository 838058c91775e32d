#include "load/unknowable.hpp"

#include <cctype>
#include <map>
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

// Variables an invalid declaration taints, each with the reason: the invalid ones and,
// through each assumption, every variable that shares an assumption with a tainted one.
std::map<std::string, std::string> tainted_variables(const Mission& m) {
  std::map<std::string, std::string> tainted;
  for (const auto& v : m.domain.variables)
    if (!v.invalid.empty())
      tainted.emplace(v.name, "the declaration of '" + v.name + "' is invalid (" +
                                  where(v.location) + ": " + v.invalid + ")");
  for (bool grew = !tainted.empty(); grew;) {
    grew = false;
    for (const auto& a : m.domain.assumptions) {
      if (!a.expr) continue;
      const auto names = fretish::identifiers_of(*a.expr);
      const std::string* reason = nullptr;
      for (const auto& n : names)
        if (auto it = tainted.find(n); it != tainted.end() && reason == nullptr)
          reason = &it->second;
      if (reason == nullptr) continue;
      const std::string why = *reason;
      for (const auto& n : names) grew |= tainted.emplace(n, why).second;
    }
  }
  return tainted;
}

void invalid_declarations(Mission& m) {
  const auto tainted = tainted_variables(m);
  if (tainted.empty()) return;
  for (const auto& s : m.selections) {
    if (!s.guard) continue;
    for (const auto& name : fretish::identifiers_of(*s.guard))
      if (auto it = tainted.find(name); it != tainted.end())
        m.not_verified.emplace(s.adaptable, it->second);
  }
}

}  // namespace

void mark_unknowable(Mission& m) {
  unparsed_requirements(m);
  invalid_declarations(m);
}

}  // namespace uabt::load
