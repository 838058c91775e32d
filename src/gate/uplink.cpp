#include "gate/uplink.hpp"

#include <cctype>
#include <set>
#include <stdexcept>
#include <system_error>

#include "base/files.hpp"
#include "gate/contract.hpp"
#include "report/impact.hpp"
#include "verify/impact.hpp"

namespace uabt::gate {

namespace fs = std::filesystem;

Outcome run_uplink_gate(const load::Mission& running, load::Mission merged, const Options& options,
                        const std::string& tool_version) {
  // The last package merged is the one being gated (as the mission shows it).
  const std::string package = merged.uplinks.empty() ? std::string() : merged.uplinks.back();
  verify::Impact impact = verify::selection_impact(running, merged, options.verify);
  std::vector<Finding> notes = report::behaviour_change_findings(impact, merged);
  std::vector<load::UplinkMerge> merges = merged.merges;

  Outcome out = run_gate(std::move(merged), options, tool_version);
  auto& findings = out.report.findings;
  findings.insert(findings.end(), notes.begin(), notes.end());
  findings.insert(findings.end(), impact.findings.begin(), impact.findings.end());
  sort_findings(findings);
  out.report.uplink = report::UplinkChange{package, std::move(merges), std::move(impact), {}};
  check_contract(running, out, options);
  return out;
}

namespace {

std::string read_or_throw(const fs::path& path) {
  std::string error;
  auto text = read_text_file(path, error);
  if (!text) throw std::runtime_error(path.generic_string() + ": " + error);
  return *text;
}

bool is_label(const std::string& id) {
  if (id.empty() || !std::isalnum(static_cast<unsigned char>(id[0]))) return false;
  for (char c : id)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      return false;
  return true;
}

std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

std::string requirements_text(const load::Mission& m) {
  std::string out = "# " + m.name + " with its uplinks merged, in priority order";
  for (const auto& u : m.uplinks) out += "\n#   uplink: " + u;
  out += "\n";
  for (const auto& r : m.requirements)
    out += (is_label(r.id) ? r.id + ": " : std::string()) + one_line(r.text) + "\n";
  return out;
}

std::string domain_text(const load::Mission& m) {
  std::string out =
      "# The merged domain: declarations and assumptions of the mission and its uplinks\n";
  for (const auto& v : m.domain.variables)
    if (v.declared) out += fretish::declaration_text(v) + "\n";
  std::size_t unnamed = 0;
  for (const auto& a : m.domain.assumptions) {
    if (!a.expr) continue;
    const std::string name = is_label(a.name) ? a.name : "assumption_" + std::to_string(++unnamed);
    out += "assume " + name + ": " + fretish::to_fretish(*a.expr) + "\n";
  }
  return out;
}

}  // namespace

void write_merged_mission(const load::Mission& m, const fs::path& dir) {
  std::error_code ec;
  // Only what an earlier merge wrote goes away, never a directory of the user's.
  for (const char* name :
       {"mission.xml", "requirements.fret", "domain.fret", "nodes.xml", "world.json"})
    remove_output_file(dir / name);
  fs::remove_all(dir / "alternatives", ec);

  write_file_atomically(dir / "mission.xml", read_or_throw(m.mission_xml));
  // Included files keep their place relative to mission.xml (uabt layout only: the replication
  // package's mission.xml sits one folder lower).
  std::set<std::string> copied{m.tree.file};
  for (const auto& tree : m.tree.trees) {
    if (m.layout != "uabt" || !copied.insert(tree.file).second) continue;
    if (fs::path(tree.file).is_absolute() || tree.file.rfind("..", 0) == 0) continue;
    write_file_atomically(dir / tree.file, read_or_throw(m.dir / tree.file));
  }
  for (const auto& alt : m.alternatives)
    write_file_atomically(dir / "alternatives" / alt.adaptable / (alt.name + ".xml"),
                          read_or_throw(alt.source));
  write_file_atomically(dir / "requirements.fret", requirements_text(m));
  // A mission without declarations keeps inferring its conditions: no domain.fret for it.
  bool declares = !m.domain.assumptions.empty();
  for (const auto& v : m.domain.variables) declares |= v.declared;
  if (declares) write_file_atomically(dir / "domain.fret", domain_text(m));
  // Only the mission folder's own files: one a symlink leads out of was never read.
  if (m.nodes && fs::is_regular_file(m.dir / "nodes.xml", ec) &&
      lies_inside(m.dir / "nodes.xml", m.dir))
    write_file_atomically(dir / "nodes.xml", read_or_throw(m.dir / "nodes.xml"));
  // The world model the guarantees are proved in (an uplink does not change the world).
  if (fs::is_regular_file(m.dir / "world.json", ec) && lies_inside(m.dir / "world.json", m.dir))
    write_file_atomically(dir / "world.json", read_or_throw(m.dir / "world.json"));
}

}  // namespace uabt::gate
