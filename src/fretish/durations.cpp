#include "fretish/durations.hpp"

#include <cmath>
#include <cstdlib>

#include "fretish/domain.hpp"

namespace uabt::fretish {

namespace {

// Longest duration a requirement may count, in ticks.
constexpr double kMaxTicks = 1e12;

// The duration of `t` in whole ticks, or nullopt with `reason`.
std::optional<std::uint64_t> to_ticks(const Timing& t, std::optional<double> tick_seconds,
                                      std::string& reason) {
  const double value = std::strtod(t.duration.c_str(), nullptr);
  const std::string written = timing_text(t);
  const std::optional<double> per_unit = seconds_per_unit(t.unit);
  double ticks = value;
  if (per_unit) {
    if (!tick_seconds || *tick_seconds <= 0) {
      reason = "timing '" + written +
               "' is not in ticks and the domain declares no tick period (e.g. 'tick 100 ms' "
               "in domain.fret)";
      return std::nullopt;
    }
    // Rounded up to whole ticks; the small tolerance keeps 0.3 s / 100 ms at 3 ticks.
    ticks = std::ceil(value * *per_unit / *tick_seconds - 1e-9);
  } else if (value != std::floor(value)) {
    reason = "timing '" + written + "' is not a whole number of ticks";
    return std::nullopt;
  }
  if (!(ticks >= 0) || ticks > kMaxTicks) {
    reason = "timing '" + written + "' is out of range";
    return std::nullopt;
  }
  return static_cast<std::uint64_t>(ticks);
}

}  // namespace

std::string timing_text(const Timing& t) {
  std::string out = t.keyword;
  if (!t.duration.empty()) out += " " + t.duration;
  if (!t.unit.empty()) out += " " + t.unit;
  if (t.stop_condition) out += " " + to_fretish(*t.stop_condition);
  return out;
}

void lower_durations(std::vector<Requirement>& requirements, std::optional<double> tick_seconds,
                     std::vector<Finding>& findings) {
  for (Requirement& r : requirements) {
    Timing& t = r.timing;
    t.ticks.reset();
    t.unconverted.clear();
    if (t.duration.empty()) continue;
    t.ticks = to_ticks(t, tick_seconds, t.unconverted);
    if (t.ticks) continue;
    Finding f = make_finding("property-timing", r.id + ": " + t.unconverted,
                             start_of(t.duration_range, r.location));
    f.requirements = {r.id};
    findings.push_back(std::move(f));
  }
}

}  // namespace uabt::fretish
