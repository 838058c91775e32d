// FRET exports: a bare array of requirements or {"requirements": [...], "variables": [...]}.
#include <algorithm>
#include <cctype>
#include <exception>

#include <nlohmann/json.hpp>

#include "base/json_input.hpp"
#include "base/text.hpp"
#include "fretish/json_positions.hpp"
#include "fretish/parse.hpp"

namespace uabt::fretish {

namespace {

using nlohmann::json;

SourceLocation at(const std::string& file, const detail::JsonPosition& p) {
  return {file, p.line, p.column};
}

// FRET's realizability checking treats a requirement whose id mentions "assumption" and that
// reads "<component> shall always satisfy E" as an assumption E.
bool is_assumption_form(const Requirement& r) {
  return !r.freeform && !r.scope && r.conditions.empty() && !r.probability &&
         r.timing.keyword == "always" && r.response;
}

// dataType is a string, a one-element list (["boolean"]) or empty.
std::string data_type_of(const json& variable) {
  const auto it = variable.find("dataType");
  if (it == variable.end()) return {};
  if (it->is_string()) return it->get<std::string>();
  if (it->is_array())
    for (const json& t : *it)
      if (t.is_string() && !t.get<std::string>().empty()) return t.get<std::string>();
  return {};
}

void add_variables(const json& variables, const std::vector<detail::JsonPosition>& positions,
                   const std::string& file, Domain& domain, std::vector<Finding>& findings) {
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const json& v = variables[i];
    const SourceLocation loc =
        i < positions.size() ? at(file, positions[i]) : SourceLocation{file, 0, 0};
    if (!v.is_object() || !v.contains("variable_name") || !v["variable_name"].is_string()) continue;
    const std::string name = v["variable_name"].get<std::string>();
    const std::string type_text = data_type_of(v);
    if (name.empty() || type_text.empty()) continue;  // untyped: inferred from use later
    Variable var;
    var.name = name;
    var.location = loc;
    const std::string type = lower_case(type_text);
    if (type == "boolean") {
      var.type = VarType::boolean;
    } else if (type == "integer") {
      var.type = VarType::integer;
    } else if (type == "unsigned integer") {
      var.type = VarType::integer;
      var.lower = "0";
    } else if (type == "single" || type == "double") {
      var.type = VarType::real;
    } else {
      findings.push_back(make_finding(
          "domain-invalid",
          "variable '" + name + "' has dataType '" + type_text +
              "', which is not a FRET type (boolean, integer, unsigned integer, single, double)",
          loc));
      continue;
    }
    // FRET lists a variable once per component and model; the same type is the same variable.
    if (const Variable* known = domain.find(name)) {
      if (known->type != var.type || known->lower != var.lower)
        findings.push_back(make_finding(
            "domain-invalid",
            "variable '" + name +
                "' is declared again with another type: " + var_type_name(known->type) +
                (known->lower == "0" ? " (unsigned)" : "") + " before, '" + type_text + "' here",
            loc));
      continue;
    }
    domain.variables.push_back(std::move(var));
  }
}

void add_requirements(std::string_view json_text, const json& requirements,
                      const detail::JsonLayout& layout, const std::string& file,
                      ParseResult& result, Domain& domain) {
  for (std::size_t i = 0; i < requirements.size(); ++i) {
    const json& entry = requirements[i];
    const detail::JsonElement element =
        i < layout.requirements.size() ? layout.requirements[i] : detail::JsonElement{};
    const std::string position_id = "R" + std::to_string(i + 1);
    std::string reqid;
    if (entry.is_object() && entry.contains("reqid") && entry["reqid"].is_string())
      reqid = entry["reqid"].get<std::string>();
    const std::string id = reqid.empty() ? position_id : reqid;
    if (!entry.is_object() || !entry.contains("fulltext") || !entry["fulltext"].is_string()) {
      result.findings.push_back(make_finding("fretish-syntax",
                                             "requirement '" + id + "' has no \"fulltext\" string",
                                             at(file, element.start)));
      continue;
    }
    const std::string text = entry["fulltext"].get<std::string>();
    const detail::JsonPosition text_at = element.has_text ? element.text : element.start;
    const TextOrigin origin{file, text_at.line, text_at.column};
    const std::size_t before = result.findings.size();
    std::optional<Requirement> r = parse_requirement(text, origin, result.findings);
    // The parser counts in the decoded sentence: "\n" and "\u0041" are written otherwise.
    for (std::size_t k = before; element.has_text && k < result.findings.size(); ++k) {
      SourceLocation& l = result.findings[k].location;
      if (l.line < 1) continue;
      const detail::JsonPosition p = detail::position_of(
          json_text, json_string_source_offset(json_text, element.text_quote, text_at.line,
                                               text_at.column, l.line, l.column));
      l.line = p.line;
      l.column = p.column;
      l.end_line = 0;
    }
    if (!r) continue;
    r->id = id;
    if (lower_case(reqid).find("assumption") != std::string::npos && is_assumption_form(*r)) {
      domain.assumptions.push_back({id, r->response, r->location});
      continue;
    }
    result.requirements.push_back(std::move(*r));
  }
}

void parse_export(const std::string& content, const std::string& file, Domain& domain,
                  ParseResult& result) {
  const std::size_t bom = content.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  const std::string_view text = std::string_view(content).substr(bom);
  JsonInputError error;
  std::optional<json> parsed = parse_json_input(text, error);
  if (!parsed) {
    result.findings.push_back(make_finding("fretish-syntax",
                                           "not a valid FRET export: " + error.message,
                                           {file, error.line, error.column}));
    return;
  }
  json document = std::move(*parsed);
  const detail::JsonLayout layout = detail::scan_fret_export(text);
  const json* requirements = nullptr;
  if (document.is_array()) {
    requirements = &document;
  } else if (document.is_object() && document.contains("requirements") &&
             document["requirements"].is_array()) {
    requirements = &document["requirements"];
    if (document.contains("variables") && document["variables"].is_array())
      add_variables(document["variables"], layout.variables, file, domain, result.findings);
  } else {
    result.findings.push_back(
        make_finding("fretish-syntax",
                     "not a FRET export: expected an array of requirements or an object with "
                     "\"requirements\"",
                     {file, 1, 1}));
    return;
  }
  add_requirements(text, *requirements, layout, file, result, domain);
}

}  // namespace

ParseResult parse_fret_json(const std::string& content, const std::string& file, Domain& domain) {
  ParseResult result;
  try {
    parse_export(content, file, domain, result);
  } catch (const std::exception& e) {
    result.findings.push_back(
        make_finding("fretish-syntax", std::string("could not read the FRET export: ") + e.what(),
                     {file, 1, 1}));
  }
  return result;
}

}  // namespace uabt::fretish
