#pragma once
// What the coverage parts of every report share: the shares to show and how to say them.
#include <cstddef>
#include <optional>
#include <string>

#include "verify/verify.hpp"

namespace uabt::report::detail {

// A share to show: exact when the node was measured, from the counts when it was only counted.
struct ShownShare {
  double value = 0;
  std::string exact;  // "3/8"
};

std::optional<ShownShare> alternative_share(const verify::Coverage& coverage, std::size_t index);
std::optional<ShownShare> gap_share(const verify::Coverage& coverage);
std::optional<ShownShare> overlap_share(const verify::Coverage& coverage);
// Whether the node's shares are known (measured, or counted).
bool has_shares(const verify::Coverage& coverage);

// "37.5%", "33.3% (1/3)", "<0.1% (1/2000)", "0%": one decimal, and the exact fraction beside it
// whenever the percentage rounds it.
std::string share_text(const ShownShare& share);
// "between 12.5% and 50.0%" for a node that is bounded but not measured.
std::string bounds_text(const verify::Exact& lower, const verify::Exact& upper);

// Why the node was not measured, for a sentence: "not measured, because …".
std::string not_measured_text(const verify::Coverage& coverage);

}  // namespace uabt::report::detail

namespace uabt::report::detail {

// The coverage of one node in HTML: the shares in words, the bar, the alternatives table and
// the decision table (requirements in priority order, then the gap and overlap rows).
std::string coverage_html(const verify::Coverage& coverage);

// The same decision table in GitHub Markdown.
std::string decision_table_markdown(const verify::Coverage& coverage);

}  // namespace uabt::report::detail
