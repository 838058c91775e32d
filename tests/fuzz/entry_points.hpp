#pragma once
// The checks behind the libFuzzer targets (tests/fuzz/fuzz_*.cpp), shared with the GoogleTest
// suite that replays the corpora and every input a fuzzer ever found (tests/hardening/), so that
// CI replays them without clang.
//
// Each function runs one input through a real entry point of uabt and returns "" when every
// invariant holds, otherwise what went wrong. A crash, a hang or an escaping exception is a
// finding of its own: libFuzzer (or the test runner) reports it.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/finding.hpp"
#include "bt/structure.hpp"
#include "bt/xml_io.hpp"
#include "fretish/parse.hpp"
#include "fretish/selection.hpp"

namespace uabt::fuzz {

namespace detail {

inline std::string first_error(const std::vector<Finding>& findings) {
  for (const Finding& f : findings) {
    if (f.severity == Severity::error) {
      return f.location.file + ":" + std::to_string(f.location.line) + ":" +
             std::to_string(f.location.column) + ": " + f.message + " [" + f.check + "]";
    }
  }
  return "(no error)";
}

inline int line_count(std::string_view text) {
  int lines = 1;
  for (const char c : text) lines += c == '\n';
  return lines;
}

// Every finding names `file` and, when it has a line, one that exists in the text.
inline std::string check_locations(const std::vector<Finding>& findings, const std::string& file,
                                   std::string_view text, bool line_required) {
  const int lines = line_count(text);
  for (const Finding& f : findings) {
    if (f.location.file != file) {
      return "finding '" + f.message + "' [" + f.check + "] names the file '" + f.location.file +
             "', not '" + file + "'";
    }
    if (f.location.line < (line_required ? 1 : 0) || f.location.line > lines) {
      return "finding '" + f.message + "' [" + f.check + "] is at line " +
             std::to_string(f.location.line) + " of a text of " + std::to_string(lines) + " lines";
    }
    if (f.location.column < 0) return "finding '" + f.message + "' has a negative column";
  }
  return {};
}

// to_fretish(e) must parse back to the same tree, and print the same text again.
inline std::string round_trip(const fretish::Expr& e, const std::string& what) {
  const std::string text = fretish::to_fretish(e);
  std::vector<Finding> findings;
  const fretish::ExprPtr again =
      fretish::parse_expression(text, fretish::TextOrigin{"printed.fret", 1, 1}, findings);
  if (has_errors(findings) || !again) {
    return what + ": to_fretish printed '" + text +
           "', which does not parse: " + first_error(findings);
  }
  if (!fretish::same_expr(e, *again)) {
    return what + ": to_fretish printed '" + text + "', which parses to another tree, printed '" +
           fretish::to_fretish(*again) + "'";
  }
  if (const std::string twice = fretish::to_fretish(*again); twice != text) {
    return what + ": printing is not stable: '" + text + "' then '" + twice + "'";
  }
  for (const Finding& f : findings) {
    if (f.check == "fretish-precedence") {
      return what + ": to_fretish printed '" + text + "', which is ambiguous: " + f.message;
    }
  }
  return {};
}

inline std::string round_trip_requirement(const fretish::Requirement& r) {
  std::vector<std::pair<const fretish::Expr*, std::string>> parts;
  if (r.scope && r.scope->condition) parts.emplace_back(r.scope->condition.get(), "scope");
  for (const auto& c : r.conditions)
    if (c.expr) parts.emplace_back(c.expr.get(), "condition");
  if (r.response) parts.emplace_back(r.response.get(), "response");
  if (r.timing.stop_condition) parts.emplace_back(r.timing.stop_condition.get(), "timing");
  const fretish::ExprPtr guard = r.folded_condition();
  if (guard) parts.emplace_back(guard.get(), "folded guard");
  for (const auto& [e, what] : parts) {
    if (std::string problem = round_trip(*e, "requirement " + r.id + " " + what); !problem.empty())
      return problem;
  }
  return {};
}

inline std::string check_requirements(const fretish::ParseResult& parsed,
                                      std::vector<Finding> findings) {
  std::vector<Finding> selection_findings;
  const auto selections = fretish::classify_selection(parsed.requirements, selection_findings);
  for (const auto& s : selections) {
    if (s.adaptable.empty() || s.alternative.empty())
      return "selection requirement " + s.id + " without an adaptable or alternative";
  }
  for (const fretish::Requirement& r : parsed.requirements) {
    if (std::string problem = round_trip_requirement(r); !problem.empty()) return problem;
  }
  findings.insert(findings.end(), selection_findings.begin(), selection_findings.end());
  for (const Finding& f : findings) {
    if (f.message.empty()) return "a finding without a message [" + f.check + "]";
  }
  return {};
}

// Explicit syntax (<Action ID="X">) is written compact (<X>): compare what a node means.
inline bool same_meaning(const bt::Node& a, const bt::Node& b) {
  auto attributes = [](const bt::Node& n) {
    auto out = n.attributes;
    if (n.kind() != n.tag) std::erase_if(out, [](const auto& kv) { return kv.first == "ID"; });
    return out;
  };
  if (a.kind() != b.kind() || attributes(a) != attributes(b) ||
      a.children.size() != b.children.size())
    return false;
  for (std::size_t i = 0; i < a.children.size(); ++i)
    if (!same_meaning(a.children[i], b.children[i])) return false;
  return true;
}

}  // namespace detail

// requirements.fret text: parse_requirements_file + classify_selection; every expression of
// every requirement survives to_fretish → parse_expression unchanged.
inline std::string check_requirements_file(std::string_view data) {
  const std::string text(data);
  const fretish::ParseResult parsed = fretish::parse_requirements_file(text, "requirements.fret");
  if (std::string p = detail::check_locations(parsed.findings, "requirements.fret", text, true);
      !p.empty())
    return p;
  return detail::check_requirements(parsed, parsed.findings);
}

// domain.fret text: parse_domain_file; declarations are sane, assumptions round-trip.
inline std::string check_domain_file(std::string_view data) {
  const std::string text(data);
  std::vector<Finding> findings;
  const fretish::Domain domain = fretish::parse_domain_file(text, "domain.fret", findings);
  if (std::string p = detail::check_locations(findings, "domain.fret", text, true); !p.empty())
    return p;
  for (const auto& v : domain.variables) {
    if (v.name.empty()) return "a variable without a name";
    if (v.type == fretish::VarType::enumeration && v.enum_values.empty() && !has_errors(findings))
      return "enum " + v.name + " without literals and without an error";
    if (v.lower.empty() != v.upper.empty() && v.lower != "0")
      return "variable " + v.name + " has only one bound";
  }
  for (const auto& a : domain.assumptions) {
    if (!a.expr) return "assumption " + a.name + " without an expression";
    if (std::string p = detail::round_trip(*a.expr, "assumption " + a.name); !p.empty()) return p;
  }
  return {};
}

// A FRET export: parse_fret_json; findings name the file and an existing line; requirements
// as for requirements.fret.
inline std::string check_fret_json(std::string_view data) {
  const std::string text(data);
  fretish::Domain domain;
  const fretish::ParseResult parsed = fretish::parse_fret_json(text, "requirements.json", domain);
  if (std::string p = detail::check_locations(parsed.findings, "requirements.json", text, false);
      !p.empty())
    return p;
  for (const auto& a : domain.assumptions) {
    if (!a.expr) return "assumption " + a.name + " without an expression";
    if (std::string p = detail::round_trip(*a.expr, "assumption " + a.name); !p.empty()) return p;
  }
  return detail::check_requirements(parsed, parsed.findings);
}

// BehaviorTree.CPP XML: parse_document + check_structure; write_document's text parses again
// to the same trees, and writing that gives the same bytes.
inline std::string check_bt_xml(std::string_view data) {
  const std::string text(data);
  std::vector<Finding> findings;
  const std::optional<bt::Document> doc = bt::parse_document(text, "tree.xml", findings);
  if (std::string p = detail::check_locations(findings, "tree.xml", text, false); !p.empty())
    return p;
  if (!doc) {
    if (!has_errors(findings)) return "the document was refused without an error finding";
    return {};
  }
  std::vector<const bt::TreeDef*> trees;
  for (const auto& t : doc->trees) trees.push_back(&t);
  for (const bool allow_adaptable : {true, false}) {
    bt::StructureOptions options;
    options.allow_adaptable = allow_adaptable;
    options.node_models = doc->node_models;
    const auto structure = bt::check_structure(trees, options);
    if (std::string p = detail::check_locations(structure, "tree.xml", text, false); !p.empty())
      return p;
  }
  for (const int format : {4, 3}) {
    bt::WriteOptions options;
    options.format = format;
    const std::string written = bt::write_document(*doc, options);
    std::vector<Finding> again_findings;
    const std::optional<bt::Document> again =
        bt::parse_document(written, "written.xml", again_findings);
    const std::string v = "v" + std::to_string(format) + ": ";
    if (!again) {
      return v + "write_document's output does not parse: " + detail::first_error(again_findings) +
             "\n--- written:\n" + written;
    }
    for (const Finding& f : again_findings) {
      if (f.check == "bt-xml" && f.severity == Severity::error)
        return v + "write_document's output has an XML error: " + f.message;
    }
    if (again->trees.size() != doc->trees.size())
      return v + "the written document has another number of trees";
    for (std::size_t i = 0; i < doc->trees.size(); ++i) {
      if (again->trees[i].id != doc->trees[i].id)
        return v + "tree " + std::to_string(i) + " changed its ID";
      if (!detail::same_meaning(again->trees[i].root, doc->trees[i].root))
        return v + "tree '" + doc->trees[i].id + "' changed when written and read back";
    }
    const bt::TreeDef* main_before = doc->main();
    const bt::TreeDef* main_after = again->main();
    if ((main_before == nullptr) != (main_after == nullptr) ||
        (main_before && main_before->id != main_after->id))
      return v + "the main tree changed when written and read back";
    if (bt::write_document(*again, options) != written)
      return v + "write_document is not stable across a read-back";
  }
  return {};
}

}  // namespace uabt::fuzz
