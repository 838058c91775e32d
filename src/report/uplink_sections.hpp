#pragma once
// The "uplink" part of the gate's reports (`gate --uplink`, ARCHITECTURE §11): where the merge put
// each requirement and the behaviour change, per adaptable node. Internal to the writers.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "report/model.hpp"

namespace uabt::report::detail {

// {"package", "merge": [{requirement, rule, relation, anchor, adaptable, priority, of,
// location}], "behaviour_change": [nodes as in `uabt diff --format json`]}
nlohmann::ordered_json uplink_json(const UplinkChange& uplink);

// The HTML id of the counterexample of `uplink.contract[index]` in uplink_html.
std::string uplink_counterexample_id(std::size_t index);

// A Markdown section (### Uplink …) and an HTML <section id="uplink">.
std::string uplink_markdown(const UplinkChange& uplink);
std::string uplink_html(const UplinkChange& uplink);

}  // namespace uabt::report::detail
