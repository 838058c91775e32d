// tree-output-literal, tree-output-unbound: BehaviorTree.CPP 4.10's setOutput writes only
// through a blackboard pointer ("{key}", or "{=}" for the entry named like the port); a port
// bound to a literal or to "" returns "setOutput requires a blackboard pointer. Use {}", and an
// output port with no attribute and no "{key}" default is missing from the node's output
// ports ("NodeConfig::output_ports does not contain the key"). Either way the value is lost.
#include "verify/tree/checks.hpp"

namespace uabt::verify::tree {

namespace {

bool is_blackboard_pointer(const std::string& value) {
  return value.size() >= 3 && value.front() == '{' && value.back() == '}';
}

bool writes_entry(const std::string& value) {
  return value == "=" || is_blackboard_pointer(value);
}

}  // namespace

void check_output_ports(const Site& site, const Registry& registry, std::vector<Finding>& out) {
  const bt::Node& node = *site.node;
  const std::string kind = node.kind();
  const bt::NodeModel* model = registry.model(kind);
  if (model == nullptr || bt::family_named(model->family) == bt::Family::subtree ||
      bt::find_builtin(kind) != nullptr)
    return;
  for (const auto& port : model->ports) {
    if (port.direction != "output_port" && port.direction != "inout_port") continue;
    const std::string* value = node.attribute(port.name);
    const std::string what = (port.direction == "inout_port" ? "in/out port '" : "output port '") +
                             port.name + "' of " + kind;
    if (value != nullptr) {
      if (writes_entry(*value)) continue;
      Finding f = make_finding(
          "tree-output-literal",
          what +
              (value->empty() ? " is bound to nothing (" + port.name + "=\"\")"
                              : " is bound to the literal \"" + *value + "\"") +
              ": BehaviorTree.CPP's setOutput fails at run time (\"setOutput requires a "
              "blackboard pointer. Use {}\") and the value is lost",
          site.attribute_location(port.name));
      f.notes.push_back("write it to a blackboard entry: " + port.name + "=\"{" + port.name +
                        "}\" (or \"{=}\", the entry named like the port)");
      add_path(f, site);
      out.push_back(std::move(f));
      continue;
    }
    // An in/out port without a value is ref-missing-port's (its input side) unless defaulted.
    if (port.direction != "output_port" || is_blackboard_pointer(port.default_value)) continue;
    Finding f = make_finding(
        "tree-output-unbound",
        what + " is not bound" +
            (port.default_value.empty()
                 ? std::string()
                 : " (its default \"" + port.default_value + "\" is not a blackboard entry)") +
            ": BehaviorTree.CPP's setOutput fails at run time (\"NodeConfig::output_ports does "
            "not contain the key\") and the value is lost",
        site.location());
    f.notes.push_back("bind it to a blackboard entry: " + port.name + "=\"{" + port.name + "}\"");
    add_path(f, site);
    out.push_back(std::move(f));
  }
}

}  // namespace uabt::verify::tree
