#pragma once
// Pieces shared by the report writers; not part of the public API (see reports.hpp).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "base/catalogue.hpp"
#include "base/finding.hpp"
#include "fretish/requirement.hpp"
#include "fretish/selection.hpp"
#include "report/model.hpp"

namespace uabt::report::detail {

// "25.0%" — one decimal, "0.0%" when `whole` is 0.
std::string percent(std::uint64_t part, std::uint64_t whole);

// "file:line:col", "file:line", "file" or "<mission>".
std::string location_text(const SourceLocation& location);

// "guard-overlap" → "GuardOverlap".
std::string camel_case(std::string_view id);

// 64-bit FNV-1a: a stable hash across runs and platforms.
std::uint64_t fnv1a(std::string_view text, std::uint64_t seed = 14695981039346656037ull);
std::string hex64(std::uint64_t value);

// Replaces invalid UTF-8 by U+FFFD and control characters other than tab and newline by a
// space, so that XML and HTML output stay well formed whatever a message holds.
std::string clean_text(std::string_view text);

// Escapes & < > " ' for HTML/XML text and attribute values (after clean_text).
std::string html_escape(std::string_view text);

// `text` escaped in an HTML <code> element.
std::string html_code(std::string_view text);

// Text safe inside a GFM table cell (after clean_text): Markdown punctuation is
// backslash-escaped (an intraword '_' is left alone: GFM never makes emphasis of it, and
// `selected_alt` stays readable), '&' cannot start an entity, '|' cannot end the cell and a
// newline cannot end the row.
std::string markdown_text(std::string_view text);

// A Markdown code span, or markdown_text when the content would break one.
std::string markdown_code(std::string_view text);
// An alternative as a report names it: "" (no alternative selected) is the node failing.
std::string alternative_text(const std::string& alternative);

// An SVG picture as inline HTML: without its namespace declaration, which HTML needs not, so
// that a page holds no URL.
std::string inline_svg(std::string svg);

// An element id from an id that may hold any character: "node-INDEX-ID" with every character
// but letters, digits, '-' and '_' as '_'; the index keeps two ids apart.
std::string anchor(std::size_t index, std::string_view id);

// The pipeline stage ("load", "verify", "compile", "conform", "runtime") that runs a check of
// the catalogue's stage (fretish and bt checks run while loading).
std::string pipeline_stage(std::string_view check_stage);

// Whether a check is reported once per adaptable node (verify, conform, compile and the ref-*
// load checks) rather than once per mission.
bool is_per_adaptable_check(const CheckInfo& check);

// The catalogue sorted by id.
std::vector<const CheckInfo*> sorted_catalogue();

struct SeverityCounts {
  std::size_t errors = 0, warnings = 0, notes = 0;
};
SeverityCounts count_severities(const std::vector<Finding>& findings);

// "2 errors, 1 warning, 0 notes"
std::string counts_text(const SeverityCounts& counts);

// Fill colour of the i-th alternative in priority order: the same in the bar, the legend and
// the map. Colour-blind-safe first (Okabe-Ito without its red, which means "gap").
const char* alternative_colour(std::size_t index);
inline constexpr const char* kGapColour = "#d62728";
inline constexpr const char* kOverlapColour = "#4d4d4d";

// The parsed requirement of an id, from the loaded mission.
const fretish::Requirement* find_requirement(const load::Mission& mission, const std::string& id);

// The adaptable nodes a report shows, in mission order, then ids that only findings or coverage
// name (a requirement for an unknown node), sorted.
std::vector<std::string> adaptables_shown(const ReportInput& input);

}  // namespace uabt::report::detail
