#pragma once
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/finding.hpp"
#include "bt/tree.hpp"
#include "fretish/domain.hpp"
#include "fretish/requirement.hpp"
#include "fretish/selection.hpp"

namespace uabt::load {

// An <Adaptable ID="…"/> leaf of the mission tree.
struct AdaptableSite {
  std::string id;
  std::string tree_id;  // the <BehaviorTree> that holds it
  SourceLocation location;
  // DMN hit policy (ARCHITECTURE §11): "unique" (default: an overlap is an error) or "first" (an
  // overlap is a note, priority decides). Never written to the compiled tree.
  std::string policy = "unique";
  // selection="sequence|reactive|optimized": how this node's selection is compiled (the
  // mission's own choice; an explicit --selection overrides it). Empty: not declared.
  std::string selection;
};

// Where an uplink put one requirement (or what it removed), and by which rule (ARCHITECTURE §11).
struct UplinkMerge {
  std::string package;      // displayed path of the uplink package
  std::string requirement;  // requirement id
  // "appended" (new id, no placement: last before the default), "replaced" (existing id, in
  // place), "placed" (uplink.json before/after), "removed" (uplink.json remove)
  std::string rule;
  std::string relation, anchor;  // placed: "before"/"after" and the requirement it names
  SourceLocation location;       // the requirement's line, or its entry in uplink.json
  // Filled once the merged set is classified: its adaptable node and 1-based priority there
  // (0 when it is not a selection requirement or was removed), out of `of`.
  std::string adaptable;
  int priority = 0, of = 0;
};

// uplink.json's consent that a guarantee of the mission may stop holding (ARCHITECTURE §11):
// "retire": {"HammerPower": "reason"} or "weaken": {"LandSoon": "reason"}.
struct GuaranteeConsent {
  std::string package;      // displayed path of the uplink package
  std::string requirement;  // the guarantee's id
  std::string kind;         // "retire" | "weaken"
  std::string reason;
  SourceLocation location;  // its key in uplink.json
};

// One alternative behaviour: alternatives/<adaptable>/<name>.xml (or the replication
// package's resource/<adaptable>/<name>/<name>.xml).
struct Alternative {
  std::string adaptable;
  std::string name;              // as the requirements name it (file or folder name)
  std::string tree_id;           // its main tree inside the file (may differ from `name`)
  std::string file;              // displayed path
  std::filesystem::path source;  // the file it was read from
  bt::Document document;
};

struct Mission {
  std::filesystem::path dir;
  std::string name;                   // the directory's name
  std::string layout;                 // "uabt" or "replication"
  std::filesystem::path mission_xml;  // the file mission.xml was read from

  bt::Document tree;                      // mission.xml (includes resolved)
  std::vector<AdaptableSite> adaptables;  // document order
  std::vector<Alternative> alternatives;  // by adaptable, then name

  std::string requirements_file;                          // displayed path
  std::vector<fretish::Requirement> requirements;         // every parsed requirement
  std::vector<fretish::SelectionRequirement> selections;  // the selection subset, file order
  // Mission properties (ARCHITECTURE §10), in file order.
  std::vector<fretish::Requirement> properties;
  fretish::Domain domain;  // declared + inferred booleans

  std::optional<std::vector<bt::NodeModel>> nodes;  // nodes.xml, when present
  std::vector<std::string> uplinks;        // uplink packages merged on top, in order (displayed)
  std::vector<UplinkMerge> merges;         // what each uplink did to the requirements, in order
  std::vector<GuaranteeConsent> consents;  // guarantees the uplinks may retire or weaken

  // Everything the loader found wrong (syntax, references, structure, types).
  std::vector<Finding> findings;

  // A domain.fret (the mission's or an uplink's) declares variables, or has a line that does
  // not parse: the mission declares its vocabulary.
  bool has_domain_file = false;
  std::set<std::string> undeclared;  // names reported as ref-undeclared: never inferred
  // Adaptable nodes whose guard checks a broken input makes meaningless, each with the reason
  // ("requirements.fret:3 does not parse"): verify reports each once as not verified instead
  // of findings that would pretend to know (ARCHITECTURE §7: one mistake, one finding).
  std::map<std::string, std::string> not_verified;
  // Alternatives whose file exists but could not be read ("adaptable/name" → displayed path).
  std::map<std::string, std::string> unreadable_alternatives;
  // Adaptable nodes that a requirement which does not parse may belong to: which
  // alternatives they select, and whether they have a requirement at all, is unknown.
  std::set<std::string> requirements_incomplete;
  // Requirements that do not parse: where, and the text of their line.
  std::vector<std::pair<SourceLocation, std::string>> unparsed_requirements;

  const Alternative* find_alternative(const std::string& adaptable, const std::string& name) const;
  // The selection requirements of one adaptable node in priority order (default last).
  std::vector<const fretish::SelectionRequirement*> selections_for(
      const std::string& adaptable) const;
  // Whether the node's hit policy is "first" (priority decides an overlap).
  bool first_hit(const std::string& adaptable) const;
};

struct LoadOptions {
  std::optional<std::filesystem::path> nodes_file;  // --nodes
  // Uplink packages merged onto the mission in order (ARCHITECTURE §11). This is the one merge that
  // `gate --uplink`, `diff --uplink` and `run` share: requirements go where the package's
  // uplink.json places them, else a new id goes last before the default and an existing id
  // is replaced in place; uplink.json may remove requirements; domain declarations and
  // assumptions are added; alternatives are added (an existing name is replaced). Each path
  // is used as given (relative to the current directory).
  std::vector<std::filesystem::path> uplinks;
};

// Loads a mission directory (ARCHITECTURE §2, or the replication package's layout). Never throws
// for bad content: problems become findings. Returns nullopt only when `dir` is not a directory.
std::optional<Mission> load_mission(const std::filesystem::path& dir, const LoadOptions& options,
                                    std::string& error);

}  // namespace uabt::load
