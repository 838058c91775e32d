#include "runtime/source_map.hpp"

namespace uabt::runtime {

namespace {

// "Tag[3]" → 3; the root segment has no index.
std::optional<std::size_t> child_index(const std::string& segment) {
  const auto open = segment.rfind('[');
  if (open == std::string::npos || segment.back() != ']') return std::nullopt;
  try {
    return std::stoul(segment.substr(open + 1, segment.size() - open - 2));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::vector<std::string> split(const std::string& path) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t slash; (slash = path.find('/', start)) != std::string::npos; start = slash + 1)
    out.push_back(path.substr(start, slash - start));
  out.push_back(path.substr(start));
  return out;
}

const bt::TreeDef* find_source_tree(const std::string& id, const load::Mission& mission) {
  if (const bt::TreeDef* def = mission.tree.find_tree(id)) return def;
  for (const load::Alternative& alt : mission.alternatives)
    if (const bt::TreeDef* def = alt.document.find_tree(id)) return def;
  return nullptr;
}

}  // namespace

std::optional<SourceLocation> source_of(const std::string& tree_path, const load::Mission& mission,
                                        const std::vector<compile::TraceEntry>& trace) {
  const std::vector<std::string> segments = split(tree_path);
  if (segments.size() < 2) return std::nullopt;
  // A generated node: the compiler's trace map (same path notation).
  for (const compile::TraceEntry& entry : trace)
    if (entry.node_path == tree_path && entry.source.line > 0) return entry.source;
  // A copied node: the same place in its source tree.
  const bt::TreeDef* def = find_source_tree(segments[0], mission);
  if (def == nullptr || def->root.tag != segments[1]) return std::nullopt;
  const bt::Node* node = &def->root;
  for (std::size_t i = 2; i < segments.size(); ++i) {
    const auto index = child_index(segments[i]);
    if (!index || *index >= node->children.size()) return std::nullopt;
    node = &node->children[*index];
    if (segments[i].rfind(node->tag + "[", 0) != 0) return std::nullopt;
  }
  return SourceLocation{def->file.empty() ? mission.tree.file : def->file, node->line,
                        node->column};
}

}  // namespace uabt::runtime
