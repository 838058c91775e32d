#include "runtime/source_map.hpp"

#include <cctype>

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

// The Engine::tree_path of the node of `node`'s subtree that starts at line:column, "" if none.
std::string path_at(const bt::Node& node, const std::string& path, int line, int column) {
  if (node.line == line && node.column == column) return path;
  for (std::size_t i = 0; i < node.children.size(); ++i) {
    const bt::Node& child = node.children[i];
    std::string found = path_at(child, bt::child_path(path, child, i), line, column);
    if (!found.empty()) return found;
  }
  return "";
}

}  // namespace

std::string with_source_places(std::string text, const bt::Document& compiled,
                               const load::Mission& mission,
                               const std::vector<compile::TraceEntry>& trace) {
  const std::string file = compiled.file + ":";
  for (std::size_t at = text.find(file); at != std::string::npos; at = text.find(file, at + 1)) {
    // "compiled.xml:66:7", not the end of a longer name ("rejected.compiled.xml:…").
    if (at > 0 && text[at - 1] != ' ' && text[at - 1] != '(' && text[at - 1] != '\'') continue;
    std::size_t end = at + file.size();
    int place[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      const std::size_t digits = end;
      while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])) &&
             end - digits < 9)
        place[k] = place[k] * 10 + (text[end++] - '0');
      if (end == digits) break;
      if (k == 0 && (end >= text.size() || text[end++] != ':')) break;
    }
    if (place[0] == 0 || place[1] == 0) continue;
    std::optional<SourceLocation> source;
    for (const bt::TreeDef& def : compiled.trees) {
      const std::string path = path_at(def.root, def.id + "/" + def.root.tag, place[0], place[1]);
      if (!path.empty()) {
        source = source_of(path, mission, trace);
        break;
      }
    }
    if (!source) continue;
    const std::string named = place_text(source->file, source->line, source->column);
    text.replace(at, end - at, named);
  }
  return text;
}

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
