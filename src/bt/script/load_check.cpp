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

std::optional<std::string> script_refusal(const std::string& what, const std::string& code,
                                          bool empty_refused) {
  try {
    if (Script::parse(code).empty() && empty_refused)
      return what + " with an empty script has no result";
  } catch (const ScriptError& e) {
    return what + ": the script `" + excerpt_around(code, e.column()) +
           "` does not parse: " + e.what() + " (column " + std::to_string(e.column()) + ")";
  }
  return std::nullopt;
}

std::vector<std::pair<std::string, std::string>> node_script_refusals(const Node& node) {
  std::vector<std::pair<std::string, std::string>> out;
  const std::string kind = node.kind();
  for (const auto& [attr, value] : node.attributes)
    if (is_condition_attribute(attr))
      if (auto why = script_refusal(kind + " " + attr, value, false))
        out.emplace_back(attr, std::move(*why));
  const NodeKind k = node_kind(kind);
  if (k == NodeKind::script || k == NodeKind::script_condition) {
    const std::string* code = node.attribute("code");
    if (code == nullptr)
      out.emplace_back("", kind + " needs its port 'code'");
    else if (auto why = script_refusal(kind, *code, k == NodeKind::script_condition))
      out.emplace_back("code", std::move(*why));
  }
  return out;
}

}  // namespace uabt::bt::script
