// requirements.fret: one requirement a line, `#` comments, optional `ID:` labels.
#include <exception>

#include "fretish/lines.hpp"
#include "fretish/parse.hpp"
#include "fretish/source_text.hpp"
#include "fretish/syntax_tree.hpp"

namespace uabt::fretish {

namespace {

namespace g = uabt::grammar;

struct Labelled {
  std::string id;              // empty: no label
  std::size_t sentence_start;  // offset of the text after "ID:"
};

Labelled split_label(std::string_view line) {
  const detail::ParseOutcome outcome = detail::run_parse<g::label>(line);
  if (!outcome.ok) return {{}, 0};
  const detail::SyntaxNode* name = outcome.root->child<g::label_name>();
  if (name == nullptr) return {{}, 0};
  const std::size_t colon = line.find(':', name->end);
  return {std::string(name->text(line)), colon + 1};
}

void parse_lines(const std::string& content, const std::string& file, ParseResult& result) {
  for (const detail::Line& line : detail::content_lines(content)) {
    if (detail::is_blank(line.text)) continue;
    const Labelled labelled = split_label(line.text);
    const std::string sentence(line.text.substr(labelled.sentence_start));
    const TextOrigin origin{file, line.number, static_cast<int>(labelled.sentence_start) + 1};
    if (!labelled.id.empty() && detail::is_blank(sentence)) {
      result.findings.push_back(make_finding(
          "fretish-syntax", "expected a requirement after label '" + labelled.id + ":'",
          {file, line.number, static_cast<int>(line.text.size()) + 1}));
      continue;
    }
    std::optional<Requirement> r = parse_requirement(sentence, origin, result.findings);
    if (!r) continue;
    r->id = labelled.id.empty() ? "R" + std::to_string(line.number) : labelled.id;
    result.requirements.push_back(std::move(*r));
  }
}

}  // namespace

ParseResult parse_requirements_file(const std::string& content, const std::string& file) {
  ParseResult result;
  try {
    parse_lines(content, file, result);
  } catch (const std::exception& e) {
    result.findings.push_back(
        make_finding("fretish-syntax", std::string("could not parse: ") + e.what(), {file, 1, 1}));
  }
  return result;
}

}  // namespace uabt::fretish
