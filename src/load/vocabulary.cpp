#include "load/vocabulary.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "base/suggest.hpp"

namespace uabt::load {

using fretish::Expr;
using fretish::ExprKind;

namespace {

// Every identifier occurrence with its position (identifiers_of gives names only).
void identifier_nodes(const Expr& root, std::vector<const Expr*>& out) {
  std::vector<const Expr*> stack{&root};
  while (!stack.empty()) {
    const Expr* e = stack.back();
    stack.pop_back();
    if (e->kind == ExprKind::identifier) out.push_back(e);
    for (auto it = e->args.rbegin(); it != e->args.rend(); ++it) stack.push_back(it->get());
  }
}

std::string fs_name(const std::string& file) {
  const auto slash = file.rfind('/');
  return slash == std::string::npos ? file : file.substr(slash + 1);
}

std::string source_of(const VocabularyUse& use) {
  return use.requirement.empty() ? "assumption '" + use.assumption + "'"
                                 : "requirement " + use.requirement;
}

// Names the mission declares: domain.fret's variables and enum literals (and a FRET export's
// variables), and the conditions of nodes.xml.
std::vector<std::string> declared_names(const Mission& m) {
  std::vector<std::string> names;
  for (const auto& v : m.domain.variables) {
    if (!v.declared) continue;
    names.push_back(v.name);
    for (const auto& literal : v.enum_values) names.push_back(literal);
  }
  if (m.nodes)
    for (const auto& model : *m.nodes)
      if (model.family == "Condition") names.push_back(model.id);
  return names;
}

void add_words(const std::string& text, std::set<std::string>& out) {
  std::string word;
  for (const char c : text + " ") {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '%') {
      word += c;
    } else if (!word.empty()) {
      out.insert(word);
      word.clear();
    }
  }
}

void tree_words(const bt::Node& root, std::set<std::string>& out) {
  std::vector<const bt::Node*> stack{&root};
  while (!stack.empty()) {
    const bt::Node* n = stack.back();
    stack.pop_back();
    out.insert(n->kind());
    for (const auto& [name, value] : n->attributes) add_words(value, out);
    for (const auto& child : n->children) stack.push_back(&child);
  }
}

// What reads a variable: any requirement (selection or not), assumption, or the trees
// (a condition leaf of that name, a script or port that mentions it).
std::set<std::string> read_names(const Mission& m) {
  std::set<std::string> out;
  auto add = [&](const fretish::ExprPtr& e) {
    if (!e) return;
    for (const auto& name : fretish::identifiers_of(*e)) out.insert(name);
  };
  for (const auto& r : m.requirements) {
    for (const auto& c : r.conditions) add(c.expr);
    if (r.scope) add(r.scope->condition);
    add(r.timing.stop_condition);
    add(r.response);
  }
  for (const auto& a : m.domain.assumptions) add(a.expr);
  for (const auto& t : m.tree.trees) tree_words(t.root, out);
  for (const auto& alt : m.alternatives)
    for (const auto& t : alt.document.trees) tree_words(t.root, out);
  return out;
}

std::string vocabulary_files(const Mission& m) {
  if (m.has_domain_file && m.nodes) return "domain.fret or nodes.xml";
  return m.has_domain_file ? "domain.fret" : "nodes.xml";
}

// A line of domain.fret that does not parse may declare any name, and so may an enum whose
// literals were refused (too many of them): "" when there is neither, else what it is and where.
std::string unknown_declaration(const Mission& m) {
  for (const auto& f : m.findings)
    if (f.check == "fretish-syntax" && fs_name(f.location.file) == "domain.fret")
      return "the line of domain.fret that does not parse (" + f.location.file + ":" +
             std::to_string(f.location.line) + ")";
  for (const auto& v : m.domain.variables)
    if (v.type == fretish::VarType::enumeration && !v.invalid.empty() && v.enum_values.empty())
      return "the refused declaration of '" + v.name + "' (" + v.location.file + ":" +
             std::to_string(v.location.line) + ")";
  return {};
}

void report_undeclared(Mission& m, const std::vector<VocabularyUse>& uses) {
  const std::string unknown = unknown_declaration(m);
  const std::vector<std::string> declared = declared_names(m);
  const std::set<std::string> known(declared.begin(), declared.end());
  const NameIndex suggestions(declared);
  const std::string files = vocabulary_files(m);
  std::set<std::string> broken_assumptions;
  for (const auto& use : uses) {
    std::vector<const Expr*> ids;
    identifier_nodes(*use.expr, ids);
    std::set<std::string> reported;  // once per name and expression
    for (const Expr* id : ids) {
      if (known.count(id->text) || !reported.insert(id->text).second) continue;
      if (id->text == "FTP") continue;  // FRET's own name: report_first_time_point
      m.undeclared.insert(id->text);
      if (!unknown.empty()) {  // unknowable: the broken declaration may declare it
        const std::string why =
            source_of(use) + " reads '" + id->text + "', which " + unknown + " may declare";
        for (const auto& site : m.adaptables)
          if (!site.id.empty() && (use.adaptable.empty() || use.adaptable == site.id))
            m.not_verified.emplace(site.id, why);
        if (use.requirement.empty()) broken_assumptions.insert(use.assumption);
        continue;
      }
      Finding f =
          make_finding("ref-undeclared",
                       "'" + id->text + "' in " + source_of(use) + " is not declared in " + files,
                       start_of(id->range, use.owner));
      f.adaptable = use.adaptable;
      if (!use.requirement.empty()) f.requirements = {use.requirement};
      if (const std::string hint = suggestions.did_you_mean(id->text); !hint.empty())
        f.notes.push_back(hint);
      f.notes.push_back("declare it in " + files +
                        ": with a declared vocabulary a new name is a typo until it is declared");
      m.findings.push_back(std::move(f));
      const std::string why = source_of(use) + " reads the undeclared '" + id->text + "'";
      if (!use.adaptable.empty()) {
        m.not_verified.emplace(use.adaptable, why);
      } else if (use.requirement.empty()) {
        broken_assumptions.insert(use.assumption);
        for (const auto& site : m.adaptables)
          if (!site.id.empty()) m.not_verified.emplace(site.id, why);
      }
    }
  }
  // Every verdict over a broken assumption would be meaningless and it cannot be typed: it
  // leaves the domain (the nodes it concerns are reported as not verified).
  std::erase_if(m.domain.assumptions,
                [&](const fretish::Assumption& a) { return broken_assumptions.count(a.name) > 0; });
}

void report_unused(Mission& m) {
  const std::set<std::string> reads = read_names(m);
  for (const auto& v : m.domain.variables) {
    if (!v.declared || v.location.file.empty() || reads.count(v.name)) continue;
    bool literal_read = false;
    for (const auto& literal : v.enum_values) literal_read |= reads.count(literal) > 0;
    if (literal_read) continue;
    Finding f = make_finding("domain-unused-variable",
                             "variable '" + v.name +
                                 "' is declared but no guard, assumption, requirement or tree "
                                 "reads it",
                             v.location);
    f.notes.push_back("remove the declaration, or check the guards for a misspelt use of it");
    m.findings.push_back(std::move(f));
  }
}

std::string without_digits(const std::string& name) {
  std::string out;
  for (const char c : name)
    if (!std::isdigit(static_cast<unsigned char>(c))) out += c;
  return out;
}

// Without a declared vocabulary every new name is a fresh condition: a name within two edits
// of another one is most likely a typo of it.
void report_similar(Mission& m, const std::vector<VocabularyUse>& uses) {
  struct Seen {
    const Expr* first = nullptr;
    const VocabularyUse* use = nullptr;
    int count = 0;
    std::size_t order = 0;
  };
  std::map<std::string, Seen> seen;
  std::vector<std::string> names;  // first-use order
  for (const auto& use : uses) {
    std::vector<const Expr*> ids;
    identifier_nodes(*use.expr, ids);
    for (const Expr* id : ids) {
      if (id->text == "FTP") continue;  // FRET's own name: report_first_time_point
      Seen& s = seen[id->text];
      if (s.count++ == 0) {
        s.first = id;
        s.use = &use;
        s.order = names.size();
        names.push_back(id->text);
      }
    }
  }
  std::vector<std::string> candidates = names;
  for (const auto& v : m.domain.variables)
    if (v.declared) candidates.push_back(v.name);
  // Names of one numbered series (Zone1, Zone2: equal once digits are dropped) are never each
  // other's typos. Two names within two edits have series within two edits (dropping the
  // digits of both drops edits, never adds one), so only the members of the series near a
  // name's own are compared, from an index of the series; the comparisons are bounded so that
  // a generated mission with thousands of unrelated names stays fast.
  std::map<std::string, std::vector<std::string>> series;
  for (const auto& c : candidates) series[without_digits(c)].push_back(c);
  std::vector<std::string> skeletons;
  for (const auto& [skeleton, members] : series) skeletons.push_back(skeleton);
  const NameIndex series_index(skeletons);
  constexpr std::size_t kMaxComparisons = 4'000'000;
  std::size_t comparisons = 0;
  std::set<std::pair<std::string, std::string>> reported;
  for (const auto& name : names) {
    std::vector<std::string> others;
    for (const auto& [d, skeleton] : series_index.within_two_edits(without_digits(name)))
      for (const auto& c : series.at(skeleton))
        if (comparisons++ < kMaxComparisons) others.push_back(c);
    for (const auto& other : closest_names(name, others)) {
      const auto pair = std::minmax(name, other);
      if (!reported.insert(pair).second) continue;
      // Reported at the likelier typo: the rarer name, else the one used later.
      const Seen& a = seen[name];
      const auto b_it = seen.find(other);
      std::string typo = name, meant = other;
      if (b_it != seen.end()) {
        const Seen& b = b_it->second;
        if (b.count < a.count || (b.count == a.count && b.order > a.order)) std::swap(typo, meant);
      }
      const Seen& t = seen[typo];
      const int edits = edit_distance(typo, meant);
      Finding f = make_finding(
          "ref-similar-name",
          "'" + typo + "' in " + source_of(*t.use) + " is " + std::to_string(edits) +
              (edits == 1 ? " edit" : " edits") + " away from '" + meant +
              "': without domain.fret or nodes.xml it becomes a new condition of its own",
          start_of(t.first->range, t.use->owner));
      f.adaptable = t.use->adaptable;
      if (!t.use->requirement.empty()) f.requirements = {t.use->requirement};
      f.notes.push_back("if it is a typo, write '" + meant + "'; if both are meant, declare them " +
                        "in domain.fret (boolean " + std::min(typo, meant) + ", " +
                        std::max(typo, meant) + ")");
      m.findings.push_back(std::move(f));
    }
  }
}

// FRET's predefined FTP (true at the first tick only) is FRET's, not a typo: a mission property
// reads it as FRET does (uabt monitor, uabt run). A selection guard or an assumption is a
// condition of one state, where the first tick has no meaning: refused by name, never a
// condition of its own.
// Returns the assumptions that read it (they leave the domain once every use is checked).
std::set<std::string> report_first_time_point(Mission& m, const std::vector<VocabularyUse>& uses) {
  std::set<std::string> assumptions;
  for (const auto& v : m.domain.variables)
    if (v.declared && v.name == "FTP") return assumptions;  // a variable of that name is it
  for (const auto& use : uses) {
    std::vector<const Expr*> ids;
    identifier_nodes(*use.expr, ids);
    const auto ftp =
        std::find_if(ids.begin(), ids.end(), [](const Expr* id) { return id->text == "FTP"; });
    if (ftp == ids.end()) continue;
    m.undeclared.insert("FTP");
    Finding f = make_finding(
        "fretish-unsupported",
        "FRET's first time point 'FTP' in " + source_of(use) + " has no meaning here: " +
            (use.requirement.empty() ? "an assumption holds in every state"
                                     : "a selection guard is a condition of the state the tree "
                                       "ticks in"),
        start_of((*ftp)->range, use.owner));
    f.adaptable = use.adaptable;
    if (!use.requirement.empty()) f.requirements = {use.requirement};
    f.notes.push_back(
        "state what holds at the first tick in a mission property, e.g. 'the rover shall always "
        "satisfy FTP -> battery = 100', which uabt monitor and uabt run check");
    m.findings.push_back(std::move(f));
    const std::string why = source_of(use) + " reads FRET's first time point 'FTP'";
    if (!use.adaptable.empty()) {
      m.not_verified.emplace(use.adaptable, why);
    } else if (use.requirement.empty()) {
      assumptions.insert(use.assumption);
      for (const auto& site : m.adaptables)
        if (!site.id.empty()) m.not_verified.emplace(site.id, why);
    }
  }
  return assumptions;
}

}  // namespace

std::vector<VocabularyUse> vocabulary_uses(const Mission& m) {
  std::vector<VocabularyUse> uses;
  for (const auto& s : m.selections)
    if (s.guard) uses.push_back({s.guard.get(), s.location, s.id, "", s.adaptable});
  for (const auto& a : m.domain.assumptions)
    if (a.expr) uses.push_back({a.expr.get(), a.location, "", a.name, ""});
  return uses;
}

void check_vocabulary(Mission& m, const std::vector<VocabularyUse>& uses) {
  const std::set<std::string> first_tick = report_first_time_point(m, uses);
  if (m.has_domain_file || m.nodes) {
    report_undeclared(m, uses);
    report_unused(m);
  } else {
    report_similar(m, uses);
  }
  std::erase_if(m.domain.assumptions,
                [&](const fretish::Assumption& a) { return first_tick.count(a.name) > 0; });
}

}  // namespace uabt::load
