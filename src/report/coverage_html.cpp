#include <set>

#include "report/common.hpp"
#include "report/coverage_view.hpp"
#include "report/reports.hpp"

namespace uabt::report::detail {

namespace {

// One row of the decision table.
struct Row {
  std::string kind;   // "rule", "gap", "overlap"
  std::string label;  // "1 Req1", "gap", "overlap"
  std::vector<std::string> requirements;
  std::vector<std::string> cells;  // per column; "-" for any value
  std::string other;
  std::string outcome;  // the alternative, "none: the node fails", "first in priority order"
  std::string share;
};

// A cell from a constraint: the constraint without its variable's name ("< 15", "= sand").
std::string cell_text(const verify::RegionConstraint& c) {
  if (c.text == c.variable) return "true";
  if (c.text == "!" + c.variable) return "false";
  if (c.text.rfind(c.variable + " ", 0) == 0) return c.text.substr(c.variable.size() + 1);
  return c.text;
}

std::string region_share(const verify::Coverage& coverage, const verify::Region& r) {
  if (!r.measured) return "not measured";
  if (r.share.text == "0") return "0 (a boundary)";
  std::string out = share_text({r.share.value, r.share.text});
  if (!r.exact || !coverage.measured) out = "at most " + out;
  return out;
}

struct Table {
  std::vector<std::string> columns;
  bool other = false;
  std::vector<Row> rows;
};

Table decision_table(const verify::Coverage& coverage) {
  Table t;
  std::set<std::string> used;
  for (const auto& a : coverage.alternatives)
    for (const auto& [v, c] : a.cells) used.insert(v);
  for (const auto* list : {&coverage.gap_regions, &coverage.overlap_regions})
    for (const auto& r : *list)
      for (const auto& c : r.constraints)
        if (c.kind != verify::RegionConstraint::Kind::linear) used.insert(c.variable);
  for (const auto& v : coverage.variables)
    if (used.count(v)) t.columns.push_back(v);
  auto column = [&](const std::string& v) -> std::ptrdiff_t {
    for (std::size_t k = 0; k < t.columns.size(); ++k)
      if (t.columns[k] == v) return static_cast<std::ptrdiff_t>(k);
    return -1;
  };
  for (std::size_t i = 0; i < coverage.alternatives.size(); ++i) {
    const auto& a = coverage.alternatives[i];
    Row row;
    row.kind = "rule";
    row.label = std::to_string(i + 1) + " " + a.requirement;
    row.cells.assign(t.columns.size(), "-");
    for (const auto& [v, c] : a.cells)
      if (auto k = column(v); k >= 0) row.cells[static_cast<std::size_t>(k)] = c;
    row.other = a.other_condition;
    bool is_default = a.cells.empty() && a.other_condition.empty();
    if (is_default) row.other = "(default: always)";
    t.other = t.other || !row.other.empty();
    row.outcome = a.name;
    if (const auto s = alternative_share(coverage, i))
      row.share = share_text(*s);
    else if (coverage.bounded)
      row.share = bounds_text(a.share_lower, a.share_upper);
    t.rows.push_back(std::move(row));
  }
  auto region_rows = [&](const std::vector<verify::Region>& regions, std::size_t omitted,
                         const char* kind, const std::string& outcome) {
    for (const auto& r : regions) {
      Row row;
      row.kind = kind;
      row.label = kind;
      row.requirements = r.requirements;
      row.cells.assign(t.columns.size(), "-");
      for (const auto& c : r.constraints) {
        const auto k = c.kind == verify::RegionConstraint::Kind::linear ? -1 : column(c.variable);
        if (k >= 0)
          row.cells[static_cast<std::size_t>(k)] = cell_text(c);
        else
          row.other += (row.other.empty() ? "" : " & ") + c.text;
      }
      t.other = t.other || !row.other.empty();
      row.outcome = outcome;
      row.share = region_share(coverage, r);
      t.rows.push_back(std::move(row));
    }
    if (omitted > 0) {
      Row row;
      row.kind = kind;
      row.label = kind;
      row.cells.assign(t.columns.size(), "");
      row.other = "… and " + std::to_string(omitted) + " more " + (omitted == 1 ? "row" : "rows");
      t.other = true;
      t.rows.push_back(std::move(row));
    }
  };
  region_rows(coverage.gap_regions, coverage.gap_regions_omitted, "gap", "none: the node fails");
  region_rows(coverage.overlap_regions, coverage.overlap_regions_omitted, "overlap",
              "the first in priority order");
  return t;
}

std::string shares_in_words(const verify::Coverage& c) {
  std::string out;
  if (c.counted) {
    out += "The domain has " + std::to_string(c.states) + (c.states == 1 ? " state" : " states") +
           ". ";
  } else if (c.measured) {
    out +=
        "The real variables are measured exactly (length, area or volume of their ranges, "
        "summed over the values of the discrete ones): the domain measures " +
        html_code(c.measure.text) + ". ";
  }
  std::string parts;
  for (std::size_t i = 0; i < c.alternatives.size(); ++i) {
    const auto& a = c.alternatives[i];
    const auto s = alternative_share(c, i);
    if (!s) continue;
    parts += (parts.empty() ? "" : "; ") + html_code(a.name) + " (" + html_code(a.requirement) +
             ") is selected in " + share_text(*s);
  }
  if (!parts.empty()) out += parts + ". ";
  const auto gap = gap_share(c);
  if (gap && gap->exact != "0")
    out +=
        "In " + share_text(*gap) + " of the domain no guard holds: the adaptable node fails there.";
  else if (!c.gap_regions.empty())
    out +=
        "No guard holds on a boundary of measure zero (listed below): the adaptable node "
        "fails there.";
  else
    out += "Every state selects an alternative.";
  const auto overlap = overlap_share(c);
  if (overlap && overlap->exact != "0")
    out += " In " + share_text(*overlap) +
           " two or more guards hold: the first in priority order is selected, and when its "
           "alternative fails the Fallback runs the next one.";
  else if (!c.overlap_regions.empty())
    out += " Two or more guards hold on a boundary of measure zero (listed below).";
  return out;
}

}  // namespace

std::string coverage_html(const verify::Coverage& coverage) {
  std::string out;
  if (has_shares(coverage)) {
    out += "<p>" + shares_in_words(coverage) + "</p>\n";
  } else if (coverage.bounded) {
    out += "<p class=\"callout info\">The shares are " + html_escape(not_measured_text(coverage)) +
           ". The table gives certified lower and upper bounds instead; the solver still decided "
           "which alternatives can be selected.</p>\n";
  } else {
    out += "<p class=\"callout info\">The state space was " +
           html_escape(not_measured_text(coverage)) +
           ". The solver still decided which alternatives can be selected.</p>\n";
  }
  out += inline_svg(coverage_svg(coverage)) + "\n";

  // The alternatives and their shares.
  out += "<table>\n<thead><tr><th>Alternative</th><th>Requirement</th>";
  if (coverage.counted) out += "<th>Selected in</th>";
  if (has_shares(coverage)) out += "<th>Share</th>";
  if (coverage.counted) out += "<th>Guard holds in</th>";
  if (coverage.bounded) out += "<th>Share (certified bounds)</th>";
  if (!has_shares(coverage)) out += "<th>Selected in some state</th>";
  out += "</tr></thead><tbody>\n";
  for (std::size_t i = 0; i < coverage.alternatives.size(); ++i) {
    const auto& a = coverage.alternatives[i];
    out += std::string("<tr><td><span class=\"swatch\" style=\"background:") +
           alternative_colour(i) + "\"></span>" + html_code(a.name) + "</td><td>" +
           html_code(a.requirement) + "</td>";
    if (coverage.counted) out += "<td class=\"num\">" + std::to_string(a.states) + "</td>";
    if (const auto s = alternative_share(coverage, i))
      out += "<td class=\"num\">" + share_text(*s) + "</td>";
    if (coverage.counted) out += "<td class=\"num\">" + std::to_string(a.enabled_states) + "</td>";
    if (coverage.bounded) out += "<td>" + bounds_text(a.share_lower, a.share_upper) + "</td>";
    if (!has_shares(coverage))
      out += std::string("<td>") + (a.reachable ? "yes" : "<strong>no, never</strong>") + "</td>";
    out += "</tr>\n";
  }
  auto extra = [&](const char* label, const char* swatch, std::uint64_t states,
                   const std::optional<ShownShare>& share, const verify::Exact& lo,
                   const verify::Exact& hi) {
    out += std::string("<tr><td>") + swatch + label + "</td><td></td>";
    if (coverage.counted) out += "<td class=\"num\">" + std::to_string(states) + "</td>";
    if (share) out += "<td class=\"num\">" + share_text(*share) + "</td>";
    if (coverage.counted) out += "<td></td>";
    if (coverage.bounded) out += "<td>" + bounds_text(lo, hi) + "</td>";
    if (!has_shares(coverage)) out += "<td></td>";
    out += "</tr>\n";
  };
  if (has_shares(coverage) || coverage.bounded) {
    extra("gap: no guard holds", "<span class=\"swatch gap\"></span>", coverage.gap_states,
          gap_share(coverage), coverage.gap_share_lower, coverage.gap_share_upper);
    extra("overlap: two or more guards hold", "", coverage.overlap_states, overlap_share(coverage),
          coverage.overlap_share_lower, coverage.overlap_share_upper);
  }
  out += "</tbody></table>\n";

  // The decision table.
  const Table t = decision_table(coverage);
  out +=
      "<table class=\"decision\">\n<caption>Decision table: the requirements in priority "
      "order (the first whose row matches is selected; - is any value), then the gap and "
      "overlap regions, each a box of the state space</caption>\n<thead><tr><th>#</th>";
  for (const auto& c : t.columns) out += "<th>" + html_code(c) + "</th>";
  if (t.other) out += "<th>other condition</th>";
  out += "<th>selects</th><th>share</th></tr></thead><tbody>\n";
  for (const auto& row : t.rows) {
    out += "<tr class=\"" + row.kind + "\"><td>";
    if (row.kind == "rule") {
      const auto space = row.label.find(' ');
      out += row.label.substr(0, space) + " " + html_code(row.label.substr(space + 1));
    } else {
      out += "<strong>" + row.kind + "</strong>";
      for (const auto& r : row.requirements) out += " " + html_code(r);
    }
    out += "</td>";
    for (const auto& c : row.cells) out += "<td>" + (c.empty() ? "" : html_code(c)) + "</td>";
    if (t.other) out += "<td>" + (row.other.empty() ? "" : html_code(row.other)) + "</td>";
    out += "<td>" + (row.kind == "rule" ? html_code(row.outcome) : html_escape(row.outcome)) +
           "</td><td class=\"num\">" + html_escape(row.share) + "</td></tr>\n";
  }
  out += "</tbody></table>\n";
  if (!coverage.gap_region.empty() && coverage.gap_regions.empty()) {
    out += "<p>The uncovered region, where the node fails:</p>\n<ul>\n";
    for (const auto& cube : coverage.gap_region) out += "<li>" + html_code(cube) + "</li>\n";
    out += "</ul>\n";
  }
  return out;
}

std::string decision_table_markdown(const verify::Coverage& coverage) {
  const Table t = decision_table(coverage);
  std::string out = "| # |";
  for (const auto& c : t.columns) out += " " + markdown_text(c) + " |";
  if (t.other) out += " other condition |";
  out += " selects | share |\n|---|";
  for (std::size_t k = 0; k < t.columns.size(); ++k) out += "---|";
  if (t.other) out += "---|";
  out += "---|---:|\n";
  for (const auto& row : t.rows) {
    std::string label = markdown_text(row.label);
    if (row.kind != "rule") {
      label = "**" + row.kind + "**";
      for (const auto& r : row.requirements) label += " " + markdown_text(r);
    }
    out += "| " + label + " |";
    for (const auto& c : row.cells) out += " " + markdown_text(c) + " |";
    if (t.other) out += " " + markdown_text(row.other) + " |";
    out += " " + markdown_text(row.outcome) + " | " + markdown_text(row.share) + " |\n";
  }
  return out;
}

}  // namespace uabt::report::detail
