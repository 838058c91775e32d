#include "bt/schema.hpp"

#include <map>
#include <set>
#include <string_view>

#include "bt/node_kinds.hpp"
#include "bt/port_types.hpp"
#include "bt/xml_io.hpp"

namespace uabt::bt {

namespace {

// The XSD type of a port's value: an output port takes a blackboard entry only; an input
// port a literal of its type or an entry. "" when the type does not map (any text).
std::string attribute_type(const Port& port) {
  if (port.direction == "output_port") return "blackboardType";
  switch (port_value(port.type)) {
    case PortValue::signed_integer:
    case PortValue::unsigned_integer: return "integerOrBlackboardType";
    case PortValue::real: return "doubleOrBlackboardType";
    case PortValue::boolean: return "booleanOrBlackboardType";
    case PortValue::node_status: return "nodeStatusOrBlackboardType";
    default: return "";
  }
}

const char* kCommon = R"(  <xs:simpleType name="blackboardType">
    <xs:restriction base="xs:string">
      <xs:pattern value="\{.*\}"/>
    </xs:restriction>
  </xs:simpleType>
  <xs:simpleType name="booleanOrBlackboardType">
    <xs:union memberTypes="booleanLiteralType blackboardType"/>
  </xs:simpleType>
  <xs:simpleType name="integerOrBlackboardType">
    <xs:union memberTypes="xs:integer blackboardType"/>
  </xs:simpleType>
  <xs:simpleType name="doubleOrBlackboardType">
    <xs:union memberTypes="xs:double blackboardType"/>
  </xs:simpleType>
  <xs:simpleType name="nodeStatusOrBlackboardType">
    <xs:union memberTypes="nodeStatusLiteralType blackboardType"/>
  </xs:simpleType>
  <xs:attributeGroup name="commonAttributeGroup">
    <xs:attribute name="name" type="xs:string"/>
    <xs:attribute name="_description" type="xs:string"/>
    <xs:attribute name="_skipIf" type="xs:string"/>
    <xs:attribute name="_failureIf" type="xs:string"/>
    <xs:attribute name="_successIf" type="xs:string"/>
    <xs:attribute name="_while" type="xs:string"/>
    <xs:attribute name="_onSuccess" type="xs:string"/>
    <xs:attribute name="_onFailure" type="xs:string"/>
    <xs:attribute name="_onHalted" type="xs:string"/>
    <xs:attribute name="_post" type="xs:string"/>
  </xs:attributeGroup>
  <xs:element name="root">
    <xs:complexType>
      <xs:choice minOccurs="0" maxOccurs="unbounded">
        <xs:element ref="include"/>
        <xs:element ref="BehaviorTree"/>
        <xs:element ref="TreeNodesModel"/>
      </xs:choice>
      <xs:attribute name="BTCPP_format" type="xs:string"/>
      <xs:attribute name="main_tree_to_execute" type="xs:string"/>
    </xs:complexType>
  </xs:element>
  <xs:element name="include">
    <xs:complexType>
      <xs:attribute name="path" type="xs:string" use="required"/>
      <xs:attribute name="ros_pkg" type="xs:string"/>
    </xs:complexType>
  </xs:element>
  <xs:element name="BehaviorTree">
    <xs:complexType>
      <xs:group ref="oneNodeGroup"/>
      <xs:attribute name="ID" type="xs:string" use="required"/>
      <xs:attribute name="_description" type="xs:string"/>
    </xs:complexType>
  </xs:element>
  <xs:complexType name="portModelType">
    <xs:simpleContent>
      <xs:extension base="xs:string">
        <xs:attribute name="name" type="xs:string" use="required"/>
        <xs:attribute name="type" type="xs:string"/>
        <xs:attribute name="default" type="xs:string"/>
      </xs:extension>
    </xs:simpleContent>
  </xs:complexType>
  <xs:complexType name="nodeModelType">
    <xs:choice minOccurs="0" maxOccurs="unbounded">
      <xs:element name="input_port" type="portModelType"/>
      <xs:element name="output_port" type="portModelType"/>
      <xs:element name="inout_port" type="portModelType"/>
      <xs:element name="description" type="xs:string"/>
      <xs:element name="metadata">
        <xs:complexType>
          <xs:anyAttribute processContents="skip"/>
        </xs:complexType>
      </xs:element>
    </xs:choice>
    <xs:attribute name="ID" type="xs:string" use="required"/>
    <xs:anyAttribute processContents="skip"/>
  </xs:complexType>
  <xs:element name="TreeNodesModel">
    <xs:complexType>
      <xs:choice minOccurs="0" maxOccurs="unbounded">
        <xs:element name="Action" type="nodeModelType"/>
        <xs:element name="Condition" type="nodeModelType"/>
        <xs:element name="Control" type="nodeModelType"/>
        <xs:element name="Decorator" type="nodeModelType"/>
        <xs:element name="SubTree" type="nodeModelType"/>
      </xs:choice>
    </xs:complexType>
  </xs:element>
  <xs:complexType name="SubTreeType">
    <xs:attribute name="ID" type="xs:string" use="required"/>
    <xs:anyAttribute processContents="skip"/>
  </xs:complexType>
)";

// A simple type whose values are `values`, indented `level` steps of two spaces.
std::string enumeration(const std::string& name, const std::vector<const char*>& values,
                        int level) {
  const std::string pad(static_cast<std::size_t>(level) * 2, ' ');
  std::string out = pad + "<xs:simpleType" + (name.empty() ? "" : " name=\"" + name + "\"") +
                    ">\n" + pad + "  <xs:restriction base=\"xs:string\">\n";
  for (const char* v : values) out += pad + "    <xs:enumeration value=\"" + v + "\"/>\n";
  return out + pad + "  </xs:restriction>\n" + pad + "</xs:simpleType>\n";
}

// uabt's <Adaptable ID="…" selection="…" policy="…"/> (ARCHITECTURE §11).
std::string adaptable_type() {
  return "  <xs:complexType name=\"AdaptableType\">\n"
         "    <xs:attribute name=\"ID\" type=\"xs:string\" use=\"required\"/>\n"
         "    <xs:attribute name=\"name\" type=\"xs:string\"/>\n"
         "    <xs:attribute name=\"selection\">\n" +
         enumeration("", {"sequence", "reactive", "optimized"}, 3) +
         "    </xs:attribute>\n    <xs:attribute name=\"policy\">\n" +
         enumeration("", {"unique", "first"}, 3) + "    </xs:attribute>\n  </xs:complexType>\n";
}

struct Entry {
  Family family = Family::action;
  int min_children = 0, max_children = 0;  // -1: unbounded
  std::vector<Port> ports;
};

// An ID that can be an element of its own: an XML name without ':' that is not one of the
// elements the schema defines otherwise.
bool element_name(const std::string& id) {
  static const std::set<std::string_view> kTaken = {"Action",    "Condition",    "Control",
                                                    "Decorator", "Adaptable",    "root",
                                                    "include",   "BehaviorTree", "TreeNodesModel"};
  return is_xml_name(id) && id.find(':') == std::string::npos && kTaken.count(id) == 0 &&
         !is_subtree(id);
}

// The children a node's content model allows.
std::string children_particle(const Entry& e) {
  if (e.max_children == 0) return "";
  const std::string max = e.max_children < 0 ? "unbounded" : std::to_string(e.max_children);
  return "    <xs:group ref=\"oneNodeGroup\" minOccurs=\"" + std::to_string(e.min_children) +
         "\" maxOccurs=\"" + max + "\"/>\n";
}

}  // namespace

std::string write_schema(const std::vector<NodeModel>& models) {
  // Every node by ID: the built-ins, then the robot's (a registration of a built-in ID is
  // BehaviorTree.CPP's "already registered" error, so the built-in stays).
  std::map<std::string, Entry> nodes;
  for (const auto& b : builtin_nodes()) {
    if (b.family == Family::subtree) continue;
    nodes[b.name] = Entry{b.family, b.min_children, b.max_children, b.ports};
  }
  for (const auto& m : models) {
    if (family_named(m.family) == Family::subtree || nodes.count(m.id) != 0) continue;
    Entry e;
    e.family = family_named(m.family);
    if (e.family == Family::control) e.min_children = 1, e.max_children = -1;
    if (e.family == Family::decorator) e.min_children = 1, e.max_children = 1;
    e.ports = m.ports;
    nodes[m.id] = std::move(e);
  }

  std::string xsd =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<!-- Generated by uabt schema: the trees the robot can load (BehaviorTree.CPP 4.10). -->\n"
      "<xs:schema xmlns:xs=\"http://www.w3.org/2001/XMLSchema\" "
      "elementFormDefault=\"qualified\">\n";
  xsd += enumeration("booleanLiteralType", boolean_literals(), 1);
  xsd += enumeration("nodeStatusLiteralType", node_status_literals(), 1);
  xsd += kCommon;
  xsd += adaptable_type();

  // One node anywhere a node goes: compact by ID, explicit by family, SubTree, Adaptable.
  xsd += "  <xs:group name=\"oneNodeGroup\">\n    <xs:choice>\n";
  for (const auto& [id, e] : nodes)
    if (element_name(id))
      xsd += "      <xs:element name=\"" + id + "\" type=\"node_" + id + "\"/>\n";
  for (const char* f : {"Action", "Condition", "Control", "Decorator"})
    xsd += std::string("      <xs:element name=\"") + f + "\" type=\"explicit" + f + "\"/>\n";
  xsd += "      <xs:element name=\"SubTree\" type=\"SubTreeType\"/>\n";
  xsd += "      <xs:element name=\"SubTreePlus\" type=\"SubTreeType\"/>\n";
  xsd += "      <xs:element name=\"Adaptable\" type=\"AdaptableType\"/>\n";
  xsd += "    </xs:choice>\n  </xs:group>\n";

  // The explicit form: XSD 1.0 cannot make attributes depend on ID, so ID is one of the
  // family's IDs and any other attribute is allowed.
  for (const Family f : {Family::action, Family::condition, Family::control, Family::decorator}) {
    const std::string name = family_name(f);
    xsd += "  <xs:simpleType name=\"" + name + "ID\">\n    <xs:restriction base=\"xs:string\">\n";
    for (const auto& [id, e] : nodes)
      if (e.family == f) xsd += "      <xs:enumeration value=\"" + xml_escape(id) + "\"/>\n";
    xsd += "    </xs:restriction>\n  </xs:simpleType>\n";
    Entry shape;
    shape.min_children = f == Family::action || f == Family::condition ? 0 : 1;
    shape.max_children = f == Family::control ? -1 : shape.min_children;
    xsd += "  <xs:complexType name=\"explicit" + name + "\">\n";
    xsd += children_particle(shape);
    xsd += "    <xs:attribute name=\"ID\" type=\"" + name + "ID\" use=\"required\"/>\n";
    xsd += "    <xs:anyAttribute processContents=\"skip\"/>\n  </xs:complexType>\n";
  }

  for (const auto& [id, e] : nodes) {
    if (!element_name(id)) continue;
    xsd += "  <xs:complexType name=\"node_" + id + "\">\n";
    xsd += children_particle(e);
    std::map<std::string, const Port*> ports;
    for (const auto& p : e.ports) ports.emplace(p.name, &p);
    for (const auto& [name, p] : ports) {
      // Only a port BT.CPP sets from an attribute has one (`name`, `ID`, `_skipIf`, …: the
      // common attributes declare those BT.CPP reads itself), and never `xmlns`, which XML
      // Schema reserves for namespace declarations (allowed on every element anyway).
      if (!is_xml_name(name) || name.find(':') != std::string::npos || !is_port_attribute(name) ||
          name == "xmlns")
        continue;
      xsd += "    <xs:attribute name=\"" + name + "\"";
      if (const std::string type = attribute_type(*p); !type.empty())
        xsd += " type=\"" + type + "\"";
      else
        xsd += " type=\"xs:string\"";
      if (p->default_value.empty()) xsd += " use=\"required\"";
      xsd += "/>\n";
    }
    xsd += "    <xs:attributeGroup ref=\"commonAttributeGroup\"/>\n  </xs:complexType>\n";
  }
  xsd += "</xs:schema>\n";
  return xsd;
}

}  // namespace uabt::bt
