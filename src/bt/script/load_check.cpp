#include "bt/script/load_check.hpp"

#include <algorithm>

#include "bt/node_kinds.hpp"
#include "bt/script/ast.hpp"
#include "bt/tree.hpp"

namespace uabt::bt::script {

bool is_condition_attribute(std::string_view name) {
  static constexpr std::string_view kNames[] = {"_failureIf", "_successIf", "_skipIf",    "_while",
                                                "_onHalted",  "_onFailure", "_onSuccess", "_post"};
  for (std::string_view n : kNames)
    if (n == name) return true;
  return false;
}

namespace {

// The part of a long script around `column` (1-based), so that a refusal of a 60,000-character
// script is one readable line; cut at character boundaries, never inside a UTF-8 sequence.
std::string excerpt_around(const std::string& code, std::size_t column) {
  constexpr std::size_t kWhole = 100, kBefore = 40, kAfter = 40;
  if (code.size() <= kWhole) return code;
  auto boundary = [&](std::size_t at) {
    while (at > 0 && at < code.size() && (static_cast<unsigned char>(code[at]) & 0xC0) == 0x80)
      --at;
    return at;
  };
  const std::size_t at = std::min(column > 0 ? column - 1 : 0, code.size());
  const std::size_t from = boundary(at > kBefore ? at - kBefore : 0);
  const std::size_t to = boundary(std::min(code.size(), at + kAfter));
  return (from > 0 ? "…" : "") + code.substr(from, to - from) + (to < code.size() ? "…" : "");
}

}  // namespace

namespace {

// `code` parsed as BT.CPP's builder parses the script of `what`, or why it refuses it.
NodeScript parse_node_script(std::string attribute, const std::string& what,
                             const std::string& code, bool empty_refused) {
  NodeScript out;
  out.attribute = std::move(attribute);
  try {
    out.script = Script::parse(code);
    if (out.script->empty() && empty_refused) {
      out.script.reset();
      out.refusal = what + " with an empty script has no result";
    }
  } catch (const ScriptError& e) {
    out.refusal = what + ": the script `" + excerpt_around(code, e.column()) +
                  "` does not parse: " + e.what() + " (column " + std::to_string(e.column()) + ")";
  }
  return out;
}

}  // namespace

std::optional<std::string> script_refusal(const std::string& what, const std::string& code,
                                          bool empty_refused) {
  NodeScript parsed = parse_node_script("", what, code, empty_refused);
  if (parsed.refusal.empty()) return std::nullopt;
  return std::move(parsed.refusal);
}

std::vector<NodeScript> parse_node_scripts(const Node& node) {
  std::vector<NodeScript> out;
  const std::string kind = node.kind();
  for (const auto& [attr, value] : node.attributes)
    if (is_condition_attribute(attr))
      out.push_back(parse_node_script(attr, kind + " " + attr, value, false));
  const NodeKind k = node_kind(kind);
  if (k == NodeKind::script || k == NodeKind::script_condition) {
    const std::string* code = node.attribute("code");
    if (code == nullptr) {
      NodeScript missing;
      missing.refusal = kind + " needs its port 'code'";
      out.push_back(std::move(missing));
    } else {
      out.push_back(parse_node_script("code", kind, *code, k == NodeKind::script_condition));
    }
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> node_script_refusals(const Node& node) {
  std::vector<std::pair<std::string, std::string>> out;
  for (NodeScript& s : parse_node_scripts(node))
    if (!s.refusal.empty()) out.emplace_back(std::move(s.attribute), std::move(s.refusal));
  return out;
}

}  // namespace uabt::bt::script
