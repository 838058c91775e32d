#include "verify/tree/walk.hpp"

namespace uabt::verify::tree {

Registry::Registry(const load::Mission& mission) : mission_(mission) {
  if (mission.nodes)
    for (const auto& model : *mission.nodes) models_.emplace(model.id, &model);
  auto add_document = [&](const bt::Document& document) {
    for (const auto& model : document.node_models) models_.emplace(model.id, &model);
  };
  add_document(mission.tree);
  for (const auto& alternative : mission.alternatives) add_document(alternative.document);
  for (const auto& builtin : bt::builtin_nodes()) families_.emplace(builtin.name, builtin.family);
  for (const auto& [id, model] : models_) families_.emplace(id, bt::family_named(model->family));
  for (const auto& v : mission.domain.variables) domain_names_.insert(v.name);
}

const bt::NodeModel* Registry::model(const std::string& id) const {
  const auto it = models_.find(id);
  return it == models_.end() ? nullptr : it->second;
}

bt::Family Registry::family(const std::string& id) const {
  const auto it = families_.find(id);
  return it == families_.end() ? bt::Family::unknown : it->second;
}

SourceLocation Site::location() const {
  return location_of(*node);
}

SourceLocation Site::attribute_location(const std::string& name) const {
  const auto [line, column] = node->attribute_position(name);
  return {tree->file, line, column};
}

SourceLocation Site::location_of(const bt::Node& other) const {
  return {tree->file, other.line, other.column};
}

ControlRule control_rule(std::string_view kind, bt::Family family, std::size_t children) {
  ControlRule rule;
  if (children == 0 || family == bt::Family::action || family == bt::Family::condition) return rule;
  using K = bt::NodeKind;
  const K k = bt::node_kind(kind);
  if (is_sequence(kind)) {
    rule.combine = Combine::sequence;
  } else if (is_fallback(kind)) {
    rule.combine = Combine::fallback;
  } else if ((k == K::if_then_else || k == K::while_do_else) && children >= 2) {
    rule.combine = Combine::if_then_else;
  } else if (k == K::parallel || k == K::parallel_all) {
    rule.combine = Combine::parallel;
  } else if (family == bt::Family::decorator && children == 1) {
    rule.combine = k == K::inverter        ? Combine::invert
                   : k == K::force_success ? Combine::force_success
                   : k == K::force_failure ? Combine::force_failure
                                           : Combine::pass;
    rule.may_end_without_child = k == K::precondition || k == K::skip_unless_updated ||
                                 k == K::loop_int || k == K::loop_bool || k == K::loop_double ||
                                 k == K::loop_string || k == K::blackboard_check_int ||
                                 k == K::blackboard_check_double || k == K::blackboard_check_string;
    rule.may_run_alone = k == K::delay || k == K::timeout || k == K::wait_value_update;
  } else {
    rule.combine = Combine::any_child;
  }
  return rule;
}

std::string describe(const bt::Node& node) {
  std::string out = "<" + node.tag;
  for (const char* key : {"ID", "name"})
    if (const std::string* value = node.attribute(key))
      out += " " + std::string(key) + "=\"" + *value + "\"";
  return out + ">";
}

void add_path(Finding& finding, const Site& site, bool through_node) {
  finding.related.push_back({{site.tree->file, site.tree->line, site.tree->column},
                             "in <BehaviorTree ID=\"" + site.tree->id + "\">"});
  for (const bt::Node* ancestor : *site.path)
    finding.related.push_back({site.location_of(*ancestor), "in " + describe(*ancestor)});
  if (through_node) finding.related.push_back({site.location(), "in " + describe(*site.node)});
}

}  // namespace uabt::verify::tree
