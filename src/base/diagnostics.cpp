#include "base/diagnostics.hpp"

namespace uabt {

namespace {

std::string location_prefix(const SourceLocation& loc) {
  std::string out = loc.file.empty() ? std::string("<mission>") : loc.file;
  if (loc.line > 0) {
    out += ":" + std::to_string(loc.line);
    if (loc.column > 0) out += ":" + std::to_string(loc.column);
  }
  return out;
}

}  // namespace

std::string format_state(const State& state) {
  std::string out;
  for (const auto& [name, value] : state) {
    if (!out.empty()) out += ", ";
    out += name + "=" + value.to_string();
  }
  return out;
}

std::string format_text(const std::vector<Finding>& findings) {
  std::string out;
  for (const auto& f : findings) {
    const std::string where = location_prefix(f.location);
    out += where + ": " + severity_name(f.severity) + ": " + f.message + " [" + f.check + "]\n";
    if (!f.node_path.empty()) out += where + ": note: at node " + f.node_path + "\n";
    if (!f.witness.empty()) out += where + ": note: witness: " + format_state(f.witness) + "\n";
    for (const auto& note : f.notes) out += where + ": note: " + note + "\n";
  }
  return out;
}

}  // namespace uabt
