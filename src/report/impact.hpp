#pragma once
#include <string>

#include "verify/impact.hpp"

namespace uabt::report {

// `uabt diff` output: per adaptable node, which states change their selected alternative.
std::string impact_text(const verify::Impact& impact);
std::string impact_json(const verify::Impact& impact);

}  // namespace uabt::report
