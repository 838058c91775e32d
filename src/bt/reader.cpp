// Reading BehaviorTree.CPP XML (v3 and v4) into bt::Document, with <include> resolution.
#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <map>
#include <set>
#include <string_view>

#include "base/files.hpp"
#include "base/suggest.hpp"
#include "bt/element_positions.hpp"
#include "bt/node_kinds.hpp"
#include "bt/structure.hpp"
#include "bt/xml_io.hpp"
#include "bt/xml_scan.hpp"

namespace uabt::bt {

namespace {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

constexpr int kMaxIncludeDepth = 32;

Finding xml_finding(std::string message, const std::string& file, int line, int column) {
  return make_finding("bt-xml", std::move(message), SourceLocation{file, line, column});
}

Finding structure_finding(std::string message, const std::string& file, int line, int column) {
  return make_finding("bt-structure", std::move(message), SourceLocation{file, line, column});
}

// What tinyxml2's error ids mean to someone who wrote the file.
std::string describe_xml_error(tinyxml2::XMLError error) {
  using namespace tinyxml2;
  switch (error) {
    case XML_ERROR_PARSING_ELEMENT: return "malformed element";
    case XML_ERROR_PARSING_ATTRIBUTE:
      return "malformed attribute (unquoted value, missing '=', or an attribute given twice)";
    case XML_ERROR_PARSING_TEXT:
      return "malformed text (a bare '<' or '&' must be written &lt; or &amp;)";
    case XML_ERROR_PARSING_CDATA: return "unterminated CDATA section";
    case XML_ERROR_PARSING_COMMENT: return "unterminated comment";
    case XML_ERROR_PARSING_DECLARATION: return "malformed <?...?> declaration";
    case XML_ERROR_PARSING_UNKNOWN: return "malformed <!...> markup";
    case XML_ERROR_EMPTY_DOCUMENT: return "no XML element found: expected a <root> element";
    case XML_ERROR_MISMATCHED_ELEMENT: return "closing tag does not match the open element";
    case XML_ELEMENT_DEPTH_EXCEEDED:
      return "elements nested deeper than " + std::to_string(TINYXML2_MAX_ELEMENT_DEPTH) +
             " levels: the XML parser uabt is built with (tinyxml2) refuses deeper files; "
             "split the tree into SubTrees";
    default: return "malformed XML";
  }
}

// tinyxml2's ErrorStr() ends with ": <detail>" after "Line number=N" (the element involved).
std::string xml_error_detail(const tinyxml2::XMLDocument& xml) {
  const std::string_view text = xml.ErrorStr() ? xml.ErrorStr() : "";
  const auto at = text.find("Line number=");
  if (at == std::string_view::npos) return "";
  const auto colon = text.find(": ", at);
  if (colon == std::string_view::npos) return "";
  return std::string(text.substr(colon + 2));
}

std::string attribute_or_empty(const XMLElement* element, const char* name) {
  const char* value = element->Attribute(name);
  return value ? value : "";
}

struct IncludeRequest {
  std::optional<std::string> path;  // nullopt: the attribute is missing
  bool ros_pkg = false;
  std::size_t tree_index = 0;  // where its trees go in the including document
  std::size_t model_index = 0;
  SourceLocation where;
};

struct ParsedText {
  Document doc;
  std::vector<IncludeRequest> includes;
};

class TextParser {
 public:
  TextParser(const std::string& text, const std::string& file, std::vector<Finding>& findings)
      : text_(text), file_(file), findings_(findings) {}

  std::optional<ParsedText> parse() {
    const detail::ScanResult scan = detail::scan_xml(text_, kMaxXmlDepth);
    if (scan.problem) {
      findings_.push_back(
          xml_finding(scan.problem->message, file_, scan.problem->line, scan.problem->column));
      return std::nullopt;
    }
    tinyxml2::XMLDocument xml(true, tinyxml2::PRESERVE_WHITESPACE);
    if (xml.Parse(text_.data(), text_.size()) != tinyxml2::XML_SUCCESS) {
      std::string message = describe_xml_error(xml.ErrorID());
      if (const std::string detail = xml_error_detail(xml); !detail.empty()) {
        message += " (" + detail + ")";
      }
      findings_.push_back(xml_finding(std::move(message), file_, xml.ErrorLineNum(), 0));
      return std::nullopt;
    }
    const detail::ElementPositions positions(xml, scan.elements, text_);
    positions_ = &positions;
    const XMLElement* root = xml.RootElement();
    if (root == nullptr) {
      findings_.push_back(
          xml_finding("no XML element found: expected a <root> element", file_, 1, 0));
      return std::nullopt;
    }
    if (std::string_view(root->Name()) != "root") {
      findings_.push_back(xml_finding(
          "the document element must be <root>, found <" + std::string(root->Name()) + ">", file_,
          where(root).line, where(root).column));
      return std::nullopt;
    }
    for (const XMLElement* extra = root->NextSiblingElement(); extra != nullptr;
         extra = extra->NextSiblingElement()) {
      findings_.push_back(xml_finding("only one document element is allowed; <" +
                                          std::string(extra->Name()) + "> follows </root>",
                                      file_, where(extra).line, where(extra).column));
    }
    ParsedText parsed;
    read_root(root, parsed);
    positions_ = nullptr;
    return parsed;
  }

 private:
  SourceLocation where(const XMLElement* e) const {
    const auto [line, column] = positions_->of(e);
    return SourceLocation{file_, line, column};
  }

  void read_root(const XMLElement* root, ParsedText& parsed) {
    Document& doc = parsed.doc;
    doc.file = file_;
    doc.root_line = where(root).line;
    doc.format = 3;
    if (const char* format = root->Attribute("BTCPP_format")) {
      const std::string value = format;
      if (value == "4" || value == "3") {
        doc.format = value == "4" ? 4 : 3;
      } else {
        doc.format = 4;
        const SourceLocation at = where(root);
        findings_.push_back(xml_finding("BTCPP_format must be 3 or 4, found '" + value + "'", file_,
                                        at.line, at.column));
      }
    }
    doc.main_tree = attribute_or_empty(root, "main_tree_to_execute");
    check_root_attributes(root, doc);
    bool seen_models = false;
    for (const XMLElement* child = root->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      const std::string_view name = child->Name();
      const SourceLocation at = where(child);
      if (name == "BehaviorTree") {
        doc.trees.push_back(read_tree(child));
      } else if (name == "TreeNodesModel") {
        if (seen_models) {
          findings_.push_back(structure_finding("only one <TreeNodesModel> is allowed per file",
                                                file_, at.line, at.column));
        }
        seen_models = true;
        read_models(child, doc.node_models);
      } else if (name == "include") {
        IncludeRequest request;
        request.where = at;
        request.tree_index = doc.trees.size();
        request.model_index = doc.node_models.size();
        request.ros_pkg = child->Attribute("ros_pkg") != nullptr;
        if (const char* path = child->Attribute("path")) request.path = path;
        parsed.includes.push_back(request);
      } else {
        Finding f = xml_finding(
            "<" + std::string(name) + "> is not a BehaviorTree.CPP element under <root>; ignored",
            file_, at.line, at.column);
        f.severity = Severity::warning;
        findings_.push_back(std::move(f));
      }
    }
  }

  // BT.CPP 4.10 reads BTCPP_format and main_tree_to_execute from <root> and ignores any other
  // attribute, so a misspelt one silently runs another tree (or none): an error at it.
  void check_root_attributes(const XMLElement* root, Document& doc) {
    static const std::vector<std::string> kKnown = {"BTCPP_format", "main_tree_to_execute"};
    for (const tinyxml2::XMLAttribute* a = root->FirstAttribute(); a != nullptr; a = a->Next()) {
      const std::string name = a->Name();
      const std::vector<std::string> close = closest_names(name, kKnown);
      if (close.empty() || root->Attribute(close.front().c_str()) != nullptr) continue;
      const SourceLocation at = attribute_location(root, name);
      findings_.push_back(structure_finding("unknown attribute '" + name +
                                                "' on <root>: BehaviorTree.CPP ignores it; " +
                                                did_you_mean(name, kKnown),
                                            file_, at.line, at.column));
      // Read as meant, so that the misspelling is the one finding it causes.
      if (close.front() == "main_tree_to_execute") doc.main_tree = a->Value();
    }
  }

  // Where `name="…"` stands in the start tag of `e` (the tag's own position if not found).
  SourceLocation attribute_location(const XMLElement* e, const std::string& name) const {
    const SourceLocation tag = where(e);
    std::size_t offset = 0;
    for (int line = 1; line < tag.line && offset < text_.size(); ++offset)
      if (text_[offset] == '\n') ++line;
    offset += static_cast<std::size_t>(std::max(tag.column, 1) - 1);
    for (std::size_t at = text_.find(name, offset); at != std::string::npos;
         at = text_.find(name, at + 1)) {
      const char before = at == 0 ? ' ' : text_[at - 1];
      std::size_t after = at + name.size();
      while (after < text_.size() && std::isspace(static_cast<unsigned char>(text_[after])))
        ++after;
      if (!std::isspace(static_cast<unsigned char>(before)) || after >= text_.size() ||
          text_[after] != '=')
        continue;
      int line = 1;
      std::size_t start = 0;
      for (std::size_t i = 0; i < at; ++i)
        if (text_[i] == '\n') {
          ++line;
          start = i + 1;
        }
      return {file_, line, static_cast<int>(at - start) + 1};
    }
    return tag;
  }

  // Where each attribute name of `node`'s start tag stands: a walk over that tag alone, from
  // the element's '<' (columns count characters, as the scanner's do).
  std::vector<std::pair<int, int>> attribute_positions(const Node& node) {
    std::vector<std::pair<int, int>> out;
    if (node.line <= 0 || node.column <= 0) return out;
    if (line_starts_.empty()) {
      line_starts_.push_back(0);
      for (std::size_t k = 0; k < text_.size(); ++k)
        if (text_[k] == '\n') line_starts_.push_back(k + 1);
    }
    if (static_cast<std::size_t>(node.line) > line_starts_.size()) return out;
    const std::size_t n = text_.size();
    std::size_t i = line_starts_[static_cast<std::size_t>(node.line) - 1];
    int line = node.line, column = 1;
    auto advance = [&] {
      if (text_[i] == '\n') {
        ++line;
        column = 1;
      } else if (i + 1 < n && (static_cast<unsigned char>(text_[i + 1]) & 0xC0) != 0x80) {
        ++column;
      }
      ++i;
    };
    auto space = [&] { return std::isspace(static_cast<unsigned char>(text_[i])) != 0; };
    while (i < n && column < node.column && text_[i] != '\n') advance();
    if (i >= n || text_[i] != '<') return out;
    advance();
    while (i < n && !space() && text_[i] != '/' && text_[i] != '>') advance();
    while (out.size() < node.attributes.size()) {
      while (i < n && space()) advance();
      if (i >= n || text_[i] == '/' || text_[i] == '>') break;
      out.emplace_back(line, column);
      while (i < n && !space() && text_[i] != '=') advance();
      while (i < n && text_[i] != '"' && text_[i] != '\'') advance();
      if (i >= n) break;
      const char quote = text_[i];
      advance();
      while (i < n && text_[i] != quote) advance();
      if (i < n) advance();
    }
    return out;
  }

  TreeDef read_tree(const XMLElement* element) {
    TreeDef tree;
    tree.id = attribute_or_empty(element, "ID");
    const SourceLocation at = where(element);
    tree.line = at.line;
    tree.column = at.column;
    tree.file = file_;
    int children = 0;
    for (const XMLElement* child = element->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      if (children++ == 0) tree.root = read_node(child);
    }
    if (children != 1) {
      findings_.push_back(structure_finding("<BehaviorTree ID=\"" + tree.id +
                                                "\"> must have exactly 1 child, has " +
                                                std::to_string(children),
                                            file_, at.line, at.column));
    }
    return tree;
  }

  // Recursion is bounded: the scanner refused anything nested deeper than kMaxXmlDepth.
  Node read_node(const XMLElement* element) {
    Node node;
    node.tag = element->Name();
    const SourceLocation at = where(element);
    node.line = at.line;
    node.column = at.column;
    for (const tinyxml2::XMLAttribute* a = element->FirstAttribute(); a != nullptr; a = a->Next()) {
      node.attributes.emplace_back(a->Name(), a->Value());
    }
    if (!node.attributes.empty()) node.attribute_positions = attribute_positions(node);
    for (const XMLElement* child = element->FirstChildElement(); child != nullptr;
         child = child->NextSiblingElement()) {
      node.children.push_back(read_node(child));
    }
    return node;
  }

  void read_models(const XMLElement* element, std::vector<NodeModel>& models) {
    static const std::set<std::string_view> kPortKinds = {"input_port", "output_port",
                                                          "inout_port"};
    std::map<std::string, std::pair<SourceLocation, std::string>> registered;
    for (const XMLElement* entry = element->FirstChildElement(); entry != nullptr;
         entry = entry->NextSiblingElement()) {
      const SourceLocation at = where(entry);
      if (family_named(entry->Name()) == Family::unknown) {
        Finding f = xml_finding("<" + std::string(entry->Name()) +
                                    "> in <TreeNodesModel> is not Action, Condition, Control, "
                                    "Decorator or SubTree; ignored",
                                file_, at.line, at.column);
        f.severity = Severity::warning;
        findings_.push_back(std::move(f));
        continue;
      }
      NodeModel model;
      model.family = entry->Name();
      model.id = attribute_or_empty(entry, "ID");
      model.line = at.line;
      model.column = at.column;
      model.file = at.file;
      if (model.id.empty()) {
        findings_.push_back(structure_finding(
            "<" + model.family + "> in <TreeNodesModel> needs an ID", file_, at.line, at.column));
        continue;
      }
      for (const XMLElement* port = entry->FirstChildElement(); port != nullptr;
           port = port->NextSiblingElement()) {
        if (!kPortKinds.contains(port->Name())) continue;  // Groot2 adds <MetadataFields> etc.
        Port p;
        p.direction = port->Name();
        p.name = attribute_or_empty(port, "name");
        p.type = attribute_or_empty(port, "type");
        p.default_value = attribute_or_empty(port, "default");
        if (const char* text = port->GetText()) p.description = text;
        model.ports.push_back(std::move(p));
      }
      // BT.CPP refuses to register one ID twice: the second entry is the mistake.
      const auto [first, inserted] = registered.emplace(model.id, std::make_pair(at, model.family));
      if (!inserted) {
        const SourceLocation& earlier = first->second.first;
        Finding f = make_finding("ref-duplicate-id",
                                 "node ID '" + model.id + "' is registered twice in " + file_, at);
        f.notes.push_back("first registered at " + place_text(earlier) + " (as " +
                          first->second.second +
                          "): BehaviorTree.CPP refuses to register an ID twice");
        findings_.push_back(std::move(f));
        continue;
      }
      models.push_back(std::move(model));
    }
  }

  const std::string& text_;
  const std::string& file_;
  std::vector<Finding>& findings_;
  std::vector<std::size_t> line_starts_;  // byte offset of each line, built on first use
  const detail::ElementPositions* positions_ = nullptr;
};

std::optional<ParsedText> parse_text(const std::string& text, const std::string& file,
                                     std::vector<Finding>& findings) {
  try {
    return TextParser(text, file, findings).parse();
  } catch (const std::exception& e) {
    // Out of memory and the like: the API promises findings, not exceptions.
    findings.push_back(xml_finding(std::string("cannot read: ") + e.what(), file, 0, 0));
    return std::nullopt;
  }
}

// Reads a file and, depth first, the files it includes.
class FileReader {
 public:
  FileReader(const ReadOptions& options, std::vector<Finding>& findings)
      : options_(options), findings_(findings) {}

  std::optional<Document> read_top(const fs::path& path) {
    std::error_code ec;
    confine_ =
        options_.confine_to.empty() ? fs::absolute(path, ec).parent_path() : options_.confine_to;
    confine_ = fs::weakly_canonical(confine_, ec);
    return read(path);
  }

 private:
  std::string display(const fs::path& path) const {
    const fs::path& base =
        options_.display_base.empty() ? options_.confine_to : options_.display_base;
    if (base.empty()) return path.lexically_normal().generic_string();
    return display_path(path, base);
  }

  std::optional<Document> read(const fs::path& path) {
    const std::string file = display(path);
    std::string error;
    const std::optional<std::string> text = read_text_file(path, error);
    if (!text) {
      findings_.push_back(xml_finding("cannot read: " + error, file, 0, 0));
      return std::nullopt;
    }
    std::optional<ParsedText> parsed = parse_text(*text, file, findings_);
    if (!parsed) return std::nullopt;
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(path, ec);
    stack_.push_back(canonical);
    done_.insert(canonical);
    // In document order, so the first include of a file shared by two (a diamond) reads it.
    Shift shift;
    for (const IncludeRequest& request : parsed->includes) {
      resolve(request, canonical.parent_path(), parsed->doc, shift);
    }
    stack_.pop_back();
    return std::move(parsed->doc);
  }

  // How many trees and models earlier includes inserted: later insertion points move by it.
  struct Shift {
    std::size_t trees = 0;
    std::size_t models = 0;
  };

  void resolve(const IncludeRequest& request, const fs::path& dir, Document& into, Shift& shift) {
    const SourceLocation& at = request.where;
    auto fail = [&](std::string message) {
      findings_.push_back(structure_finding(std::move(message), at.file, at.line, at.column));
    };
    if (request.ros_pkg) {
      return fail(
          "<include ros_pkg=…> is not supported: paths are resolved relative to the "
          "including file");
    }
    if (!request.path || request.path->empty()) return fail("<include> needs a path attribute");
    const std::string& written = *request.path;
    const fs::path relative(written);
    if (relative.is_absolute()) {
      return fail("include path '" + written +
                  "' is absolute; write it relative to the including file");
    }
    std::error_code ec;
    const fs::path target = fs::weakly_canonical(dir / relative, ec);
    if (ec || !lies_inside(target, confine_)) {
      return fail("include path '" + written + "' leaves the mission directory");
    }
    if (!fs::is_regular_file(target, ec)) {
      return fail("included file '" + written + "' does not exist");
    }
    if (const auto cycle = std::find(stack_.begin(), stack_.end(), target); cycle != stack_.end()) {
      std::string chain;
      for (auto it = cycle; it != stack_.end(); ++it) chain += display(*it) + " → ";
      return fail("include cycle: " + chain + display(target));
    }
    if (done_.contains(target)) return;  // included twice (a diamond): its trees are here already
    if (static_cast<int>(stack_.size()) >= kMaxIncludeDepth) {
      return fail("includes nested deeper than " + std::to_string(kMaxIncludeDepth) + " files");
    }
    std::optional<Document> included = read(target);
    if (!included) return;
    const auto tree_at = static_cast<std::ptrdiff_t>(request.tree_index + shift.trees);
    const auto model_at = static_cast<std::ptrdiff_t>(request.model_index + shift.models);
    shift.trees += included->trees.size();
    shift.models += included->node_models.size();
    into.trees.insert(into.trees.begin() + tree_at,
                      std::make_move_iterator(included->trees.begin()),
                      std::make_move_iterator(included->trees.end()));
    into.node_models.insert(into.node_models.begin() + model_at,
                            std::make_move_iterator(included->node_models.begin()),
                            std::make_move_iterator(included->node_models.end()));
  }

  const ReadOptions& options_;
  std::vector<Finding>& findings_;
  fs::path confine_;
  std::vector<fs::path> stack_;  // canonical paths of the files being read
  std::set<fs::path> done_;
};

}  // namespace

std::optional<Document> read_document(const fs::path& path, const ReadOptions& options,
                                      std::vector<Finding>& findings) {
  try {
    return FileReader(options, findings).read_top(path);
  } catch (const std::exception& e) {
    findings.push_back(
        xml_finding(std::string("cannot read: ") + e.what(), path.filename().string(), 0, 0));
    return std::nullopt;
  }
}

std::optional<Document> parse_document(const std::string& content, const std::string& file,
                                       std::vector<Finding>& findings) {
  std::optional<ParsedText> parsed = parse_text(content, file, findings);
  if (!parsed) return std::nullopt;
  for (const IncludeRequest& request : parsed->includes) {
    findings.push_back(
        structure_finding("<include> cannot be resolved in text that was not read from a file",
                          request.where.file, request.where.line, request.where.column));
  }
  return std::move(parsed->doc);
}

}  // namespace uabt::bt
