#pragma once
// The text format lives in base so that every stage (and its tests) can print findings.
#include "base/diagnostics.hpp"

namespace uabt::report {
using uabt::format_state;
using uabt::format_text;
}  // namespace uabt::report
