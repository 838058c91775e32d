#include "report/coverage_view.hpp"

#include <cmath>
#include <cstdio>

namespace uabt::report::detail {

namespace {

std::string reduced(std::uint64_t part, std::uint64_t whole) {
  std::uint64_t a = part, b = whole;
  while (b != 0) {
    const std::uint64_t t = a % b;
    a = b;
    b = t;
  }
  if (a == 0) return "0";
  const std::uint64_t n = part / a, d = whole / a;
  return d == 1 ? std::to_string(n) : std::to_string(n) + "/" + std::to_string(d);
}

std::optional<ShownShare> from(const verify::Coverage& c, const verify::Exact& share,
                               std::uint64_t states) {
  if (c.measured) return ShownShare{share.value, share.text};
  if (c.counted && c.states > 0)
    return ShownShare{static_cast<double>(states) / static_cast<double>(c.states),
                      reduced(states, c.states)};
  return std::nullopt;
}

std::string percent_of(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f%%", value * 100);
  return buffer;
}

}  // namespace

std::optional<ShownShare> alternative_share(const verify::Coverage& c, std::size_t index) {
  const auto& a = c.alternatives.at(index);
  return from(c, a.share, a.states);
}
std::optional<ShownShare> gap_share(const verify::Coverage& c) {
  return from(c, c.gap_share, c.gap_states);
}
std::optional<ShownShare> overlap_share(const verify::Coverage& c) {
  return from(c, c.overlap_share, c.overlap_states);
}
bool has_shares(const verify::Coverage& c) {
  return c.measured || (c.counted && c.states > 0);
}

std::string share_text(const ShownShare& share) {
  if (share.exact == "0") return "0%";
  if (share.exact == "1") return "100%";
  std::string out = share.value > 0 && share.value < 0.0005 ? "<0.1%" : percent_of(share.value);
  // A share that one decimal of a percent states exactly needs nothing beside it.
  const double thousandths = share.value * 1000;
  if (std::fabs(thousandths - std::round(thousandths)) > 1e-9 || share.value < 0.0005)
    out += " (" + share.exact + ")";
  return out;
}

std::string bounds_text(const verify::Exact& lower, const verify::Exact& upper) {
  return "between " + share_text({lower.value, lower.text}) + " and " +
         share_text({upper.value, upper.text});
}

std::string not_measured_text(const verify::Coverage& c) {
  const std::string& why =
      !c.not_measured_reason.empty() ? c.not_measured_reason : c.not_counted_reason;
  return "not measured, because " + (why.empty() ? std::string("no reason was given") : why);
}

}  // namespace uabt::report::detail
