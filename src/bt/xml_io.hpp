#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/finding.hpp"
#include "bt/tree.hpp"

namespace uabt::bt {

struct ReadOptions {
  // <include path=…> must resolve inside this directory (the mission directory).
  std::filesystem::path confine_to;
  // Shown in diagnostics instead of absolute paths: paths are made relative to it.
  std::filesystem::path display_base;
};

// Reads a BT.CPP v3 or v4 file (compact or explicit syntax, CRLF, <include>). Problems are
// findings (`bt-xml`, `bt-structure`) located at file:line:col; returns nullopt when the
// file cannot be used at all.
std::optional<Document> read_document(const std::filesystem::path& path, const ReadOptions& options,
                                      std::vector<Finding>& findings);

// Same, from text already in memory (`file` is the displayed name).
std::optional<Document> parse_document(const std::string& content, const std::string& file,
                                       std::vector<Finding>& findings);

struct WriteOptions {
  int format = 4;  // 4: <root BTCPP_format="4">; 3: v3 (no BTCPP_format)
  bool with_node_models = true;
};

// What tinyxml2 accepts as an element name (ASCII letters, digits, _ : . - and any byte of a
// multi-byte UTF-8 sequence; no digit, '.' or '-' first).
bool is_xml_name(std::string_view name);

// Text for an XML attribute value or element content: & < > " escaped, and newlines and tabs
// too (an XML parser turns raw ones in attributes into spaces).
std::string xml_escape(std::string_view text);

// Deterministic text: 2-space indentation, attributes in stored order, LF line ends, compact
// syntax, <TreeNodesModel> last.
std::string write_document(const Document& doc, const WriteOptions& options = {});

}  // namespace uabt::bt
