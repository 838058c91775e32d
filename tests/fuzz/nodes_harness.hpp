#pragma once
// The check behind fuzz_nodes, shared with test_hardening's replay of its inputs: a mission's
// nodes.xml read the two ways uabt reads it.
#include <tinyxml2.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "bt/node_kinds.hpp"
#include "bt/schema.hpp"
#include "bt/xml_io.hpp"
#include "fuzz/format_harnesses.hpp"
#include "load/mission.hpp"
#include "verify/verify.hpp"

namespace uabt::fuzz {

namespace detail {

// What makes an XSD 1.0 schema fail to compile that tinyxml2 does not see: a name declared
// twice in one symbol space, a reference to a type, group or attribute group nobody declares,
// an attribute declared twice on one complex type (its attribute groups included), an element
// declared twice in one choice, an attribute named xmlns. "" when there is none of these.
class SchemaCheck {
 public:
  std::string check(const std::string& xsd) {
    tinyxml2::XMLDocument doc;
    if (doc.Parse(xsd.c_str(), xsd.size()) != tinyxml2::XML_SUCCESS)
      return std::string("the schema is not XML: ") + doc.ErrorStr();
    const tinyxml2::XMLElement* schema = doc.RootElement();
    if (schema == nullptr || std::string_view(schema->Name()) != "xs:schema")
      return "the schema's root is not <xs:schema>";
    for (const auto* e = schema->FirstChildElement(); e; e = e->NextSiblingElement()) {
      const std::string kind = space(e->Name());
      const char* name = e->Attribute("name");
      if (name == nullptr) return std::string("a top-level <") + e->Name() + "> has no name";
      if (!declared_[kind].insert(name).second) return kind + " '" + name + "' is declared twice";
      if (kind == "attributeGroup") groups_[name] = e;
    }
    return walk(schema);
  }

 private:
  // XSD's symbol spaces: simple and complex types share one.
  static std::string space(std::string_view tag) {
    if (tag == "xs:simpleType" || tag == "xs:complexType") return "type";
    return std::string(tag.substr(tag.find(':') + 1));
  }

  std::string resolves(const std::string& kind, const std::string& name) const {
    if (name.rfind("xs:", 0) == 0) return {};
    const auto it = declared_.find(kind);
    if (it == declared_.end() || it->second.count(name) == 0)
      return "the schema refers to the " + kind + " '" + name + "', which it does not declare";
    return {};
  }

  std::string walk(const tinyxml2::XMLElement* element) const {
    const std::string_view tag = element->Name();
    if (const char* type = element->Attribute("type"))
      if (std::string p = resolves("type", type); !p.empty()) return p;
    if (const char* base = element->Attribute("base"))
      if (std::string p = resolves("type", base); !p.empty()) return p;
    if (const char* members = element->Attribute("memberTypes")) {
      std::istringstream in(members);
      for (std::string m; in >> m;)
        if (std::string p = resolves("type", m); !p.empty()) return p;
    }
    if (const char* ref = element->Attribute("ref")) {
      if (std::string p = resolves(space(tag), ref); !p.empty()) return p;
    }
    if (tag == "xs:attribute") {
      const char* name = element->Attribute("name");
      if (name && std::string_view(name) == "xmlns")
        return "the schema declares an attribute named xmlns";
    }
    if (tag == "xs:complexType") {
      std::set<std::string> attributes;
      std::string name = element->Attribute("name") ? element->Attribute("name") : "(anonymous)";
      for (const auto* a = element->FirstChildElement(); a; a = a->NextSiblingElement()) {
        std::vector<const tinyxml2::XMLElement*> declared;
        if (std::string_view(a->Name()) == "xs:attribute") declared.push_back(a);
        if (std::string_view(a->Name()) == "xs:attributeGroup" && a->Attribute("ref")) {
          const auto group = groups_.find(a->Attribute("ref"));
          if (group != groups_.end())
            for (const auto* g = group->second->FirstChildElement("xs:attribute"); g;
                 g = g->NextSiblingElement("xs:attribute"))
              declared.push_back(g);
        }
        for (const auto* d : declared)
          if (d->Attribute("name") && !attributes.insert(d->Attribute("name")).second)
            return "complex type " + name + " declares the attribute '" + d->Attribute("name") +
                   "' twice";
      }
    }
    if (tag == "xs:choice") {
      std::set<std::string> elements;
      for (const auto* e = element->FirstChildElement("xs:element"); e;
           e = e->NextSiblingElement("xs:element"))
        if (e->Attribute("name") && !elements.insert(e->Attribute("name")).second)
          return std::string("a choice declares the element '") + e->Attribute("name") + "' twice";
    }
    for (const auto* child = element->FirstChildElement(); child;
         child = child->NextSiblingElement())
      if (std::string p = walk(child); !p.empty()) return p;
    return {};
  }

  std::map<std::string, std::set<std::string>> declared_;  // symbol space -> names
  std::map<std::string, const tinyxml2::XMLElement*> groups_;
};

}  // namespace detail

// nodes.xml of the drilling sample, read the two ways uabt reads it.
// - As `uabt verify` and the gate read it: load_mission, then verify. Every finding in
//   nodes.xml is at an existing line:col; a file that cannot be read has an error there; an
//   entry registering a BehaviorTree.CPP 4.x built-in again is refused (ref-duplicate-id, an
//   error at the entry).
// - As `uabt schema` reads it: read_document confined to the mission directory; its findings
//   are located the same way; an accepted file gives a schema that is XML and compiles as XSD
//   (detail::SchemaCheck), with the same bytes when the file is read and written again, from
//   the same models the loader read.
class NodesHarness {
 public:
  static constexpr const char* kFile = "nodes.xml";

  NodesHarness() { detail::write_drilling(dir_, detail::kDrillingRequirements); }
  const std::filesystem::path& dir() const { return dir_.dir(); }

  std::string check(std::string_view data, unsigned timeout_ms = 500) const {
    const std::string text(data);
    dir_.write(kFile, text);
    std::string error;
    auto mission = load::load_mission(dir_.dir(), {}, error);
    if (!mission) return "the mission did not load: " + error;
    if (std::string p = located(mission->findings, text); !p.empty()) return p;
    if (!mission->nodes && !errors_in_nodes(mission->findings))
      return "nodes.xml was not read, without an error in it";
    if (mission->nodes)
      if (std::string p = refused_builtins(*mission); !p.empty()) return p;
    verify::Options options;
    options.timeout_ms = timeout_ms;
    options.threads = 1;
    const verify::Result verified = verify::verify_mission(*mission, options);
    if (std::string p = located(verified.findings, text); !p.empty()) return "verify: " + p;
    return check_schema(text, mission->nodes);
  }

 private:
  // Every finding located in nodes.xml is at a line of the text, with a column; only the XML
  // parser's own errors (bt-xml) may give a line alone (column 0, printed "nodes.xml:4").
  static std::string located(const std::vector<Finding>& findings, const std::string& text) {
    for (const Finding& f : findings) {
      if (f.location.file != kFile) continue;
      if (f.location.line < 1 || f.location.line > detail::line_count(text) ||
          f.location.column < (f.check == "bt-xml" ? 0 : 1))
        return "finding '" + f.message + "' [" + f.check + "] is at " +
               detail::located(f.location) + " of a text of " +
               std::to_string(detail::line_count(text)) + " lines";
    }
    return {};
  }

  static bool errors_in_nodes(const std::vector<Finding>& findings) {
    return std::any_of(findings.begin(), findings.end(), [](const Finding& f) {
      return f.severity == Severity::error && f.location.file == kFile;
    });
  }

  // BehaviorTree.CPP's factory holds every 4.x built-in already: registering one again is
  // refused on board, so the loader must refuse it at the entry.
  static std::string refused_builtins(const load::Mission& m) {
    for (const bt::NodeModel& model : *m.nodes) {
      const bt::BuiltinNode* builtin = bt::find_builtin(model.id);
      if (builtin == nullptr || builtin->v3 ||
          bt::family_named(model.family) == bt::Family::subtree)
        continue;
      const bool refused = std::any_of(m.findings.begin(), m.findings.end(), [&](const Finding& f) {
        return f.check == "ref-duplicate-id" && f.severity == Severity::error &&
               f.location.file == model.file && f.location.line == model.line &&
               f.location.column == model.column;
      });
      if (!refused)
        return "the built-in '" + model.id + "' registered again at " + model.file + ":" +
               std::to_string(model.line) + " is not refused there";
    }
    return {};
  }

  // `uabt schema nodes.xml`.
  std::string check_schema(const std::string& text,
                           const std::optional<std::vector<bt::NodeModel>>& loaded) const {
    std::vector<Finding> findings;
    const auto doc = read(findings);
    if (std::string p = located(findings, text); !p.empty()) return "schema: " + p;
    if (!doc) return errors_in_nodes(findings) ? "" : "schema: refused without an error";
    if (has_errors(findings)) return {};  // no schema written
    if (!loaded || ids(*loaded) != ids(doc->node_models))
      return "schema: other node models than the loader read";
    const std::string xsd = bt::write_schema(doc->node_models);
    if (std::string p = detail::SchemaCheck().check(xsd); !p.empty()) return "schema: " + p;
    std::vector<Finding> again_findings;
    const auto again = read(again_findings);
    if (!again || bt::write_schema(again->node_models) != xsd)
      return "schema: the same nodes.xml gives another schema the second time";
    return {};
  }

  std::optional<bt::Document> read(std::vector<Finding>& findings) const {
    bt::ReadOptions options;
    options.confine_to = dir_.dir();
    options.display_base = dir_.dir();
    return bt::read_document(dir_.dir() / kFile, options, findings);
  }

  static std::vector<std::string> ids(const std::vector<bt::NodeModel>& models) {
    std::vector<std::string> out;
    for (const auto& m : models) out.push_back(m.family + " " + m.id);
    return out;
  }

  detail::TempMission dir_{"drilling"};
};

}  // namespace uabt::fuzz
