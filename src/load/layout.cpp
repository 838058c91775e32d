#include "load/layout.hpp"

#include <algorithm>
#include <system_error>

namespace uabt::load {

namespace fs = std::filesystem;

namespace {

bool is_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

std::vector<fs::path> sorted_entries(const fs::path& dir) {
  std::vector<fs::path> entries;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    entries.push_back(it->path());
  std::sort(entries.begin(), entries.end());
  return entries;
}

}  // namespace

// alternatives/<adaptable>/<alt>.xml
std::vector<AlternativeFile> discover_alternatives(const fs::path& root) {
  std::vector<AlternativeFile> out;
  if (!is_dir(root)) return out;
  for (const auto& adaptable_dir : sorted_entries(root)) {
    if (!is_dir(adaptable_dir)) continue;
    for (const auto& file : sorted_entries(adaptable_dir)) {
      if (!is_file(file) || file.extension() != ".xml") continue;
      out.push_back({adaptable_dir.filename().string(), file.stem().string(), file});
    }
  }
  return out;
}

namespace {

// resource/<adaptable>/<alt>/<alt>.xml — the folder names the alternative; the generator's
// <alt>_conditions.xml beside it is its own output, not an alternative.
std::vector<AlternativeFile> replication_alternatives(const fs::path& root) {
  std::vector<AlternativeFile> out;
  for (const auto& adaptable_dir : sorted_entries(root)) {
    if (!is_dir(adaptable_dir)) continue;
    for (const auto& alt_dir : sorted_entries(adaptable_dir)) {
      if (!is_dir(alt_dir)) continue;
      const fs::path file = alt_dir / (alt_dir.filename().string() + ".xml");
      if (is_file(file))
        out.push_back({adaptable_dir.filename().string(), alt_dir.filename().string(), file});
    }
  }
  return out;
}

// Present in any form: a directory where a file belongs must be reported, not ignored.
std::optional<fs::path> optional_file(const fs::path& p) {
  std::error_code ec;
  if (fs::exists(p, ec)) return p;
  return std::nullopt;
}

}  // namespace

std::optional<MissionLayout> discover_layout(const fs::path& dir, std::string& error) {
  if (!is_dir(dir)) {
    error = "not a mission directory";
    return std::nullopt;
  }
  MissionLayout layout;
  if (is_file(dir / "mission.xml")) {
    layout.kind = "uabt";
    layout.mission_xml = dir / "mission.xml";
    if (is_file(dir / "requirements.fret"))
      layout.requirements = dir / "requirements.fret";
    else if (is_file(dir / "requirements.json"))
      layout.requirements = dir / "requirements.json";
    layout.domain = optional_file(dir / "domain.fret");
    layout.nodes = optional_file(dir / "nodes.xml");
    layout.alternatives = discover_alternatives(dir / "alternatives");
    return layout;
  }
  if (is_file(dir / "mission" / "mission.xml") && is_dir(dir / "resource")) {
    layout.kind = "replication";
    layout.mission_xml = dir / "mission" / "mission.xml";
    if (is_file(dir / "mission" / "fretRequirements.json"))
      layout.requirements = dir / "mission" / "fretRequirements.json";
    layout.domain = optional_file(dir / "mission" / "domain.fret");
    layout.nodes = optional_file(dir / "mission" / "nodes.xml");
    layout.alternatives = replication_alternatives(dir / "resource");
    return layout;
  }
  error =
      "no mission.xml (uabt layout) and no mission/mission.xml with resource/ (the "
      "replication package's layout)";
  // An uplink package given where its mission belongs: say how to gate it.
  auto without_slash = [](fs::path p) { return p.filename().empty() ? p.parent_path() : p; };
  const fs::path parent = without_slash(fs::absolute(dir).lexically_normal()).parent_path();
  if (is_file(dir / "uplink.json") || parent.filename() == "uplinks") {
    const fs::path mission = without_slash((dir / ".." / "..").lexically_normal());
    error += "; this looks like an uplink package: gate it against its mission with `uabt gate " +
             mission.generic_string() + " --uplink " + dir.generic_string() + "`";
  }
  return std::nullopt;
}

}  // namespace uabt::load
