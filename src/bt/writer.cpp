// Writing a bt::Document as BehaviorTree.CPP XML: deterministic bytes, compact syntax.
#include <algorithm>
#include <map>
#include <set>
#include <string_view>

#include "bt/node_kinds.hpp"
#include "bt/xml_io.hpp"

namespace uabt::bt {

std::string xml_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\n': out += "&#10;"; break;
      case '\r': out += "&#13;"; break;
      case '\t': out += "&#9;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

// Attributes BT.CPP interprets itself; they are not ports of the node.
bool is_reserved_attribute(const std::string& name) {
  static const std::set<std::string_view> kReserved = {
      "name",   "ID",         "_autoremap", "_failureIf", "_successIf", "_skipIf",
      "_while", "_onSuccess", "_onFailure", "_onHalted",  "_post"};
  return kReserved.contains(name) || name.starts_with("_");
}

void indent(std::string& out, int level) {
  out.append(static_cast<std::size_t>(level) * 2, ' ');
}

void write_attribute(std::string& out, const std::string& name, const std::string& value) {
  out += ' ';
  out += name;
  out += "=\"";
  out += xml_escape(value);
  out += '"';
}

// Explicit syntax (<Action ID="X">) is written compact (<X>): BT.CPP 4.10 rejects explicit
// children of a ReactiveSequence. An ID that is no XML name stays explicit, or the output
// would not parse.
void write_node(std::string& out, const Node& node, int level) {
  const bool compacted = is_explicit_family_tag(node.tag) && node.attribute("ID") != nullptr &&
                         is_xml_name(node.kind());
  const std::string& element = compacted ? node.kind() : node.tag;
  indent(out, level);
  out += '<';
  out += element;
  for (const auto& [name, value] : node.attributes) {
    if (compacted && name == "ID") continue;
    write_attribute(out, name, value);
  }
  if (node.children.empty()) {
    out += "/>\n";
    return;
  }
  out += ">\n";
  for (const Node& child : node.children) write_node(out, child, level + 1);
  indent(out, level);
  out += "</";
  out += element;
  out += ">\n";
}

bool looks_like_condition(const std::string& id) {
  for (const std::string_view prefix : {"Is", "Has", "On", "Can", "Check"}) {
    if (!id.starts_with(prefix)) continue;
    const char next = id.size() > prefix.size() ? id[prefix.size()] : '\0';
    if (next == '\0' || next == '_' || (next >= 'A' && next <= 'Z') ||
        (next >= '0' && next <= '9')) {
      return true;
    }
  }
  return false;
}

struct UsedNode {
  std::string explicit_family;  // from <Action|Condition|… ID=…>, if written so
  std::size_t max_children = 0;
  std::set<std::string> attributes;
};

// The <TreeNodesModel> entries: every node of the trees that BT.CPP does not register itself,
// plus the document's own models; sorted by ID.
std::vector<NodeModel> models_for(const Document& doc) {
  std::set<std::string> tree_ids;
  for (const TreeDef& tree : doc.trees) tree_ids.insert(tree.id);
  std::map<std::string, UsedNode> used;
  std::vector<const Node*> pending;
  for (const TreeDef& tree : doc.trees) pending.push_back(&tree.root);
  while (!pending.empty()) {
    const Node* node = pending.back();
    pending.pop_back();
    for (const Node& child : node->children) pending.push_back(&child);
    const std::string id = node->kind();
    if (id.empty() || id == "Adaptable" || find_builtin(id) || tree_ids.contains(id)) continue;
    UsedNode& entry = used[id];
    if (is_explicit_family_tag(node->tag)) entry.explicit_family = node->tag;
    entry.max_children = std::max(entry.max_children, node->children.size());
    for (const auto& [name, value] : node->attributes) {
      if (!is_reserved_attribute(name)) entry.attributes.insert(name);
    }
  }
  std::map<std::string, NodeModel> models;
  for (const NodeModel& model : doc.node_models) {
    if (!find_builtin(model.id) && !models.contains(model.id)) models.emplace(model.id, model);
  }
  for (const auto& [id, entry] : used) {
    NodeModel& model = models[id];
    if (model.id.empty()) {
      model.id = id;
      model.family = !entry.explicit_family.empty() ? entry.explicit_family
                     : entry.max_children > 1       ? "Control"
                     : entry.max_children == 1      ? "Decorator"
                     : looks_like_condition(id)     ? "Condition"
                                                    : "Action";
    }
    for (const std::string& name : entry.attributes) {
      const bool declared = std::any_of(model.ports.begin(), model.ports.end(),
                                        [&](const Port& p) { return p.name == name; });
      if (!declared) model.ports.push_back(Port{"input_port", name, "", "", ""});
    }
  }
  std::vector<NodeModel> sorted;
  for (auto& [id, model] : models) {
    std::stable_sort(model.ports.begin(), model.ports.end(),
                     [](const Port& a, const Port& b) { return a.name < b.name; });
    sorted.push_back(std::move(model));
  }
  return sorted;
}

void write_models(std::string& out, const std::vector<NodeModel>& models) {
  indent(out, 1);
  out += "<TreeNodesModel>\n";
  for (const NodeModel& model : models) {
    indent(out, 2);
    out += '<' + model.family;
    write_attribute(out, "ID", model.id);
    if (model.ports.empty()) {
      out += "/>\n";
      continue;
    }
    out += ">\n";
    for (const Port& port : model.ports) {
      indent(out, 3);
      out += '<' + port.direction;
      write_attribute(out, "name", port.name);
      if (!port.type.empty()) write_attribute(out, "type", port.type);
      if (!port.default_value.empty()) write_attribute(out, "default", port.default_value);
      if (port.description.empty()) {
        out += "/>\n";
      } else {
        out += '>' + xml_escape(port.description) + "</" + port.direction + ">\n";
      }
    }
    indent(out, 2);
    out += "</" + model.family + ">\n";
  }
  indent(out, 1);
  out += "</TreeNodesModel>\n";
}

}  // namespace

std::string write_document(const Document& doc, const WriteOptions& options) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<root";
  if (options.format != 3) write_attribute(out, "BTCPP_format", "4");
  // The tree that would run: a main_tree_to_execute naming no tree here is not repeated.
  const TreeDef* main = doc.main();
  const std::string main_tree = main ? main->id : doc.main_tree;
  if (!main_tree.empty()) write_attribute(out, "main_tree_to_execute", main_tree);
  out += ">\n";
  for (const TreeDef& tree : doc.trees) {
    indent(out, 1);
    out += "<BehaviorTree";
    write_attribute(out, "ID", tree.id);
    if (tree.root.tag.empty()) {
      out += "/>\n";
      continue;
    }
    out += ">\n";
    write_node(out, tree.root, 2);
    indent(out, 1);
    out += "</BehaviorTree>\n";
  }
  if (options.with_node_models) {
    const std::vector<NodeModel> models = models_for(doc);
    if (!models.empty()) write_models(out, models);
  }
  out += "</root>\n";
  return out;
}

}  // namespace uabt::bt
