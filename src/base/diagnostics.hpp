#pragma once
#include <string>
#include <vector>

#include "base/finding.hpp"

namespace uabt {

// GCC-style diagnostics: `file:line:col: severity: message [check]`, then notes and the
// witness as `note:` lines. Locations without a line print as `file: severity: …`.
std::string format_text(const std::vector<Finding>& findings);

// "OnDust=true, OnRocks=true"
std::string format_state(const State& state);

}  // namespace uabt
