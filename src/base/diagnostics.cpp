#include "base/diagnostics.hpp"

#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace uabt {

namespace fs = std::filesystem;

namespace {

std::string location_prefix(const SourceLocation& loc, const std::string& path_prefix) {
  std::string out = loc.file.empty() && path_prefix.empty() ? std::string("<mission>")
                                                            : user_path(loc.file, path_prefix);
  if (loc.line > 0) {
    out += ":" + std::to_string(loc.line);
    if (loc.column > 0) out += ":" + std::to_string(loc.column);
  }
  return out;
}

// Source lines of the files findings point into, read once each.
class SourceLines {
 public:
  explicit SourceLines(fs::path dir) : dir_(std::move(dir)) {}

  // Line `number` of `file`, without its line end; nullptr when there is none.
  const std::string* line(const std::string& file, int number) {
    auto [it, inserted] = files_.try_emplace(file);
    if (inserted) {
      const fs::path path = fs::path(file).is_absolute() ? fs::path(file) : dir_ / file;
      std::ifstream in(path, std::ios::binary);
      std::string text;
      while (in && std::getline(in, text)) {
        if (!text.empty() && text.back() == '\r') text.pop_back();
        it->second.push_back(text);
      }
    }
    if (number < 1 || static_cast<std::size_t>(number) > it->second.size()) return nullptr;
    return &it->second[static_cast<std::size_t>(number) - 1];
  }

 private:
  fs::path dir_;
  std::map<std::string, std::vector<std::string>> files_;
};

// "    3 | text\n      |     ^\n": the caret under `column` (characters, tabs kept).
std::string source_excerpt(const std::string& text, int line, int column) {
  const std::string number = std::to_string(line);
  const std::string gutter(std::max<std::size_t>(number.size(), 4), ' ');
  std::string out = gutter.substr(number.size()) + number + " | " + text + "\n";
  out += gutter + " | ";
  int character = 1;
  for (std::size_t k = 0; k < text.size() && character < column; ++k) {
    const unsigned char c = static_cast<unsigned char>(text[k]);
    if ((c & 0xC0) == 0x80) continue;  // continuation byte of a UTF-8 character
    out += c == '\t' ? '\t' : ' ';
    ++character;
  }
  return out + "^\n";
}

}  // namespace

namespace {

// How many ".." a relative path starts with.
int climbs(const fs::path& path) {
  int n = 0;
  for (const auto& part : path) {
    if (part != "..") break;
    ++n;
  }
  return n;
}

}  // namespace

std::string user_path(const std::string& file, const std::string& prefix) {
  if (fs::path(file).is_absolute()) return file;
  if (prefix.empty() && climbs(file) == 0) return file.empty() ? "." : file;
  fs::path joined = fs::path(prefix + file).lexically_normal();
  // A file further up than the mission itself (a package in /tmp for a mission below the
  // current directory) reads better, and as surely, by its absolute path.
  if (climbs(joined) > climbs(fs::path(prefix).lexically_normal())) {
    std::error_code ec;
    const fs::path here = fs::current_path(ec);
    if (!ec) joined = (here / joined).lexically_normal();
  }
  std::string text = joined.generic_string();
  while (text.size() > 1 && text.back() == '/') text.pop_back();
  return text.empty() ? "." : text;
}

std::string with_user_path(const std::string& message, const std::string& prefix) {
  if (prefix.empty()) return message;
  // "file.ext:line:col" at the start, or after a space, a parenthesis or a quote.
  static const std::regex located(
      R"((^|[\s('"`])([A-Za-z0-9_.][^\s:()'"`]*\.[A-Za-z0-9]+)(:\d+:\d+))");
  std::string out;
  auto from = message.cbegin();
  for (std::sregex_iterator it(message.begin(), message.end(), located), end; it != end; ++it) {
    const std::smatch& m = *it;
    out.append(from, m[2].first);
    out += user_path(m[2], prefix) + m[3].str();
    from = m[0].second;
  }
  out.append(from, message.cend());
  return out;
}

std::string path_prefix_for(const fs::path& mission_dir) {
  fs::path p = mission_dir.lexically_normal();
  if (p.is_absolute()) {
    std::error_code ec;
    const fs::path cwd = fs::current_path(ec);
    const fs::path rel = ec ? fs::path() : p.lexically_relative(cwd);
    if (!rel.empty() && *rel.begin() != "..") p = rel;
  }
  std::string text = p.generic_string();
  while (text.size() > 1 && text.back() == '/') text.pop_back();
  if (text.empty() || text == ".") return {};
  return text + "/";
}

std::string format_state(const State& state, std::string_view equals) {
  std::string out;
  for (const auto& [name, value] : state) {
    if (!out.empty()) out += ", ";
    out += name + std::string(equals) + value.to_string();
  }
  return out;
}

std::string format_text(const std::vector<Finding>& findings, const TextOptions& options) {
  SourceLines sources(options.source_dir);
  std::string out;
  for (const auto& f : findings) {
    const std::string where = location_prefix(f.location, options.path_prefix);
    out += where + ": " + severity_name(f.severity) + ": " + f.message + " [" + f.check + "]\n";
    if (options.show_source && f.location.line > 0 && f.location.column > 0)
      if (const std::string* text = sources.line(f.location.file, f.location.line))
        out += source_excerpt(*text, f.location.line, f.location.column);
    if (!f.node_path.empty()) out += where + ": note: at node " + f.node_path + "\n";
    if (!f.witness.empty()) out += where + ": note: witness: " + format_state(f.witness) + "\n";
    for (const auto& note : f.notes) out += where + ": note: " + note + "\n";
    for (const auto& r : f.related)
      out += location_prefix(r.location, options.path_prefix) + ": note: " + r.message + "\n";
  }
  return out;
}

}  // namespace uabt
