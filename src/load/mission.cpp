#include "load/mission.hpp"
#include "base/suggest.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "base/files.hpp"
#include "bt/node_kinds.hpp"
#include "bt/structure.hpp"
#include "bt/xml_io.hpp"
#include "fretish/durations.hpp"
#include "fretish/parse.hpp"
#include "load/layout.hpp"
#include "load/references.hpp"
#include "load/registered_nodes.hpp"
#include "load/unknowable.hpp"
#include "load/uplink.hpp"
#include "load/vocabulary.hpp"

namespace uabt::load {

namespace fs = std::filesystem;

const Alternative* Mission::find_alternative(const std::string& adaptable,
                                             const std::string& name) const {
  for (const auto& alt : alternatives)
    if (alt.adaptable == adaptable && alt.name == name) return &alt;
  return nullptr;
}

std::vector<const fretish::SelectionRequirement*> Mission::selections_for(
    const std::string& adaptable) const {
  std::vector<const fretish::SelectionRequirement*> guarded;
  const fretish::SelectionRequirement* fallback = nullptr;
  for (const auto& s : selections) {
    if (s.adaptable != adaptable) continue;
    if (s.guard)
      guarded.push_back(&s);
    else if (fallback == nullptr)  // a second default is ref-multiple-defaults
      fallback = &s;
  }
  if (fallback != nullptr) guarded.push_back(fallback);
  return guarded;
}

bool Mission::first_hit(const std::string& adaptable) const {
  for (const auto& site : adaptables)
    if (site.id == adaptable) return site.policy == "first";
  return false;
}

namespace {

// The folder a file comes from: the mission's, or an uplink package's.
struct Folder {
  fs::path path;
  std::string what;  // "the mission folder"
};

// A file of a folder is read only when it lies inside it, as an <include> must: one a symbolic
// link leads out of is refused unread, so that nothing of the outside file is shown.
bool inside_or_report(const fs::path& path, const Folder& folder, const std::string& shown,
                      std::vector<Finding>& findings) {
  if (lies_inside(path, folder.path)) return true;
  findings.push_back(make_finding("load-file", outside_folder_error(folder.what), {shown, 0, 0}));
  return false;
}

std::optional<std::string> read_or_report(const fs::path& path, const Folder& folder,
                                          const std::string& shown,
                                          std::vector<Finding>& findings) {
  if (!inside_or_report(path, folder, shown, findings)) return std::nullopt;
  std::string error;
  auto text = read_text_file(path, error);
  if (!text) findings.push_back(make_finding("load-file", shown + ": " + error, {shown, 0, 0}));
  return text;
}

// policy="unique|first" (ARCHITECTURE §11); one node id, one policy.
void check_policy(const bt::Node& node, AdaptableSite& site, const std::vector<AdaptableSite>& seen,
                  std::vector<Finding>& findings) {
  if (const std::string* policy = node.attribute("policy")) {
    if (*policy == "unique" || *policy == "first") {
      site.policy = *policy;
    } else {
      findings.push_back(make_finding("bt-structure",
                                      "<Adaptable> policy=\"" + *policy +
                                          "\" is not a hit policy: use \"unique\" (the default: "
                                          "an overlap is an error) or \"first\" (priority decides)",
                                      site.location));
    }
  }
  for (const auto& other : seen) {
    if (other.id != site.id || other.policy == site.policy) continue;
    Finding f = make_finding("bt-structure",
                             "<Adaptable ID=\"" + site.id + "\"> has policy \"" + site.policy +
                                 "\" here and \"" + other.policy +
                                 "\" elsewhere: one node has one hit policy",
                             site.location);
    f.adaptable = site.id;
    findings.push_back(std::move(f));
    break;
  }
}

// selection="sequence|reactive|optimized"; one node id, one selection style.
void check_selection(const bt::Node& node, AdaptableSite& site,
                     const std::vector<AdaptableSite>& seen, std::vector<Finding>& findings) {
  if (const std::string* style = node.attribute("selection")) {
    if (*style == "sequence" || *style == "reactive" || *style == "optimized") {
      site.selection = *style;
    } else {
      findings.push_back(make_finding(
          "bt-structure",
          "<Adaptable> selection=\"" + *style +
              "\" is not a selection style: use \"sequence\" (the paper's Fig. 4: a running "
              "alternative runs on), \"reactive\" (guards re-checked every tick) or "
              "\"optimized\"",
          site.location));
    }
  }
  for (const auto& other : seen) {
    if (other.id != site.id || other.selection == site.selection) continue;
    Finding f = make_finding("bt-structure",
                             "<Adaptable ID=\"" + site.id + "\"> has selection \"" +
                                 site.selection + "\" here and \"" + other.selection +
                                 "\" elsewhere: one node has one selection style",
                             site.location);
    f.adaptable = site.id;
    findings.push_back(std::move(f));
    break;
  }
}

void collect_adaptables(const bt::Node& node, const std::string& tree_id, const std::string& file,
                        std::vector<AdaptableSite>& out, std::vector<Finding>& findings) {
  // Iterative: trees may be deep, and the loader must not overflow the stack.
  std::vector<const bt::Node*> stack{&node};
  while (!stack.empty()) {
    const bt::Node* n = stack.back();
    stack.pop_back();
    if (n->tag == "Adaptable") {
      const std::string* id = n->attribute("ID");
      AdaptableSite site;
      site.id = id ? *id : std::string();
      site.tree_id = tree_id;
      site.location = {file, n->line, n->column};
      check_policy(*n, site, out, findings);
      check_selection(*n, site, out, findings);
      out.push_back(std::move(site));
    }
    for (auto it = n->children.rbegin(); it != n->children.rend(); ++it) stack.push_back(&*it);
  }
}

// The lines of `text`, indexed once: a file with a syntax error on every line must not be
// scanned again for each of them.
class Lines {
 public:
  explicit Lines(const std::string& text) : text_(text) {
    starts_.push_back(0);
    for (std::size_t k = 0; k < text.size(); ++k)
      if (text[k] == '\n') starts_.push_back(k + 1);
  }
  // Line `number` (1-based), "" when there is none.
  std::string operator()(int number) const {
    if (number < 1 || static_cast<std::size_t>(number) > starts_.size()) return {};
    const std::size_t begin = starts_[static_cast<std::size_t>(number) - 1];
    const std::size_t end = text_.find('\n', begin);
    return text_.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
  }

 private:
  const std::string& text_;
  std::vector<std::size_t> starts_;
};

// Parses a requirements file: the mission's own, or an uplink package's (then the caller
// merges it).
std::optional<std::vector<fretish::Requirement>> parse_requirements(Mission& m,
                                                                    const fs::path& path,
                                                                    const Folder& folder) {
  const std::string shown = display_path(path, m.dir);
  auto text = read_or_report(path, folder, shown, m.findings);
  if (!text) return std::nullopt;
  fretish::ParseResult parsed = path.extension() == ".json"
                                    ? fretish::parse_fret_json(*text, shown, m.domain)
                                    : fretish::parse_requirements_file(*text, shown);
  const Lines lines(*text);
  for (const auto& f : parsed.findings)
    if (f.check == "fretish-syntax")
      m.unparsed_requirements.emplace_back(f.location, lines(f.location.line));
  m.findings.insert(m.findings.end(), parsed.findings.begin(), parsed.findings.end());
  return std::move(parsed.requirements);
}

// What an uplink package's domain.fret redeclares differently: the merge would keep the
// mission's declaration and drop the package's in silence.
void redeclared(Mission& m, const std::string& what, const SourceLocation& here,
                const std::string& earlier_text, const SourceLocation& earlier) {
  Finding f = make_finding("domain-invalid",
                           what + ", but the mission has " + earlier_text +
                               ": an uplink adds to the domain, it cannot change it",
                           here);
  f.related.push_back({earlier, "the mission's declaration: " + earlier_text});
  f.notes.push_back("declare it as the mission does, or leave it out of the package");
  m.findings.push_back(std::move(f));
}

// The mission's domain.fret, or (`package`) an uplink package's, merged onto the domain: a
// package may repeat a declaration, an assumption or the tick period as the mission has them,
// and may add new ones; a different one is an error naming both.
void load_domain(Mission& m, const fs::path& path, const Folder& folder, bool package = false) {
  const std::string shown = display_path(path, m.dir);
  auto text = read_or_report(path, folder, shown, m.findings);
  if (!text) return;
  const std::size_t first = m.findings.size();
  fretish::Domain declared = fretish::parse_domain_file(*text, shown, m.findings);
  // A domain.fret declares the vocabulary when it declares a variable, or when a line of it
  // does not parse (that line may be a declaration); one with only assumptions does not.
  for (std::size_t k = first; k < m.findings.size(); ++k)
    m.has_domain_file |= m.findings[k].check == "fretish-syntax";
  m.has_domain_file |= !declared.variables.empty();
  // Declarations from a FRET export (already in m.domain) come first; domain.fret adds to them.
  for (auto& v : declared.variables) {
    const fretish::Variable* earlier = m.domain.find(v.name);
    if (earlier == nullptr) {
      m.domain.variables.push_back(std::move(v));
    } else if (package && v.invalid.empty() && earlier->invalid.empty() &&
               !fretish::same_declaration(*earlier, v)) {
      redeclared(m, "the package declares " + fretish::declaration_text(v), v.location,
                 fretish::declaration_text(*earlier), earlier->location);
    }
  }
  for (auto& a : declared.assumptions) {
    const auto same_name =
        std::find_if(m.domain.assumptions.begin(), m.domain.assumptions.end(),
                     [&](const fretish::Assumption& e) { return e.name == a.name; });
    if (!package || a.name.empty() || same_name == m.domain.assumptions.end()) {
      m.domain.assumptions.push_back(std::move(a));
      continue;
    }
    const std::string here = a.expr ? fretish::to_fretish(*a.expr) : std::string();
    const std::string there = same_name->expr ? fretish::to_fretish(*same_name->expr) : "";
    if (here != there)
      redeclared(m, "the package states assumption " + a.name + ": " + here, a.location,
                 "assumption " + a.name + ": " + there, same_name->location);
  }
  if (declared.tick_seconds && !m.domain.tick_seconds) {
    m.domain.tick_seconds = declared.tick_seconds;
    m.domain.tick_location = declared.tick_location;
  } else if (package && declared.tick_seconds &&
             // "100 ms" and "0.1 s" are one period, whatever the rounding of their product.
             std::abs(*declared.tick_seconds - *m.domain.tick_seconds) >
                 1e-9 * *m.domain.tick_seconds) {
    auto seconds = [](double s) {
      std::ostringstream out;
      out << s << " s";
      return out.str();
    };
    redeclared(m, "the package declares tick " + seconds(*declared.tick_seconds),
               declared.tick_location, "tick " + seconds(*m.domain.tick_seconds),
               m.domain.tick_location);
  }
}

// A --nodes file outside the mission is named relative to the mission directory too
// (display_path), like every finding's file, so that the mission's path in front of it opens it.
// nodes.xml lists what the robot registers with BehaviorTree.CPP's factory, which already holds
// every 4.x built-in: a built-in ID there is a second registration, refused on board (the v3
// spellings are not built into 4.x, so a robot may register them).
void load_nodes(Mission& m, const fs::path& path, const bt::ReadOptions& read_options) {
  auto doc = bt::read_document(path, read_options, m.findings);
  if (!doc) return;
  for (const auto& model : doc->node_models) {
    const bt::BuiltinNode* builtin = bt::find_builtin(model.id);
    if (builtin == nullptr || builtin->v3 || bt::family_named(model.family) == bt::Family::subtree)
      continue;
    Finding f = make_finding("ref-duplicate-id",
                             "node ID '" + model.id + "' is built into BehaviorTree.CPP 4.x, and " +
                                 model.file + " registers it again",
                             {model.file, model.line, model.column});
    f.notes.push_back(
        "BehaviorTree.CPP refuses to register an ID twice: remove the entry (the built-in needs "
        "none), or give the robot's own node another ID");
    m.findings.push_back(std::move(f));
  }
  m.nodes = doc->node_models;
}

void load_alternatives(Mission& m, const std::vector<AlternativeFile>& files,
                       const bt::ReadOptions& read_options, const Folder& folder) {
  for (const auto& file : files) {
    const std::string key = file.adaptable + "/" + file.name;
    std::optional<bt::Document> doc;
    if (inside_or_report(file.path, folder, display_path(file.path, m.dir), m.findings))
      doc = bt::read_document(file.path, read_options, m.findings);
    if (!doc) {
      m.unreadable_alternatives[key] = display_path(file.path, m.dir);
      continue;
    }
    m.unreadable_alternatives.erase(key);  // an uplink's readable version replaces it
    Alternative alt;
    alt.adaptable = file.adaptable;
    alt.name = file.name;
    alt.file = display_path(file.path, m.dir);
    alt.source = file.path;
    const bt::TreeDef* main = doc->find_tree(file.name);
    if (main == nullptr) main = doc->main();
    if (main == nullptr) {
      m.findings.push_back(make_finding(
          "bt-structure",
          "alternative '" + file.name + "' has no tree named '" + file.name +
              "', its main_tree_to_execute names no tree here, and it has more than one tree",
          {alt.file, doc->root_line, 1}));
      m.unreadable_alternatives[key] = alt.file;
      continue;
    }
    alt.tree_id = main->id;
    alt.document = std::move(*doc);
    // An uplinked alternative with the name of an existing one is its new version.
    auto same = std::find_if(
        m.alternatives.begin(), m.alternatives.end(),
        [&](const Alternative& a) { return a.adaptable == alt.adaptable && a.name == alt.name; });
    if (same != m.alternatives.end())
      *same = std::move(alt);
    else
      m.alternatives.push_back(std::move(alt));
  }
}

void check_all_structure(Mission& m) {
  std::vector<const bt::TreeDef*> trees;
  for (const auto& t : m.tree.trees) trees.push_back(&t);
  bt::StructureOptions options;
  if (m.nodes) {
    options.known_nodes_given = true;
    for (const auto& model : *m.nodes) options.known_nodes.push_back(model.id);
    options.node_models = *m.nodes;
  }
  // A custom control or decorator declared anywhere in the mission is known everywhere.
  options.node_models.insert(options.node_models.end(), m.tree.node_models.begin(),
                             m.tree.node_models.end());
  for (const auto& alt : m.alternatives)
    options.node_models.insert(options.node_models.end(), alt.document.node_models.begin(),
                               alt.document.node_models.end());
  auto mission_findings = bt::check_structure(trees, options);
  m.findings.insert(m.findings.end(), mission_findings.begin(), mission_findings.end());
  // Each alternative is checked on its own: its SubTrees resolve within its own file.
  for (const auto& alt : m.alternatives) {
    std::vector<const bt::TreeDef*> alt_trees;
    for (const auto& t : alt.document.trees) alt_trees.push_back(&t);
    auto alt_findings = bt::check_structure(alt_trees, options);
    m.findings.insert(m.findings.end(), alt_findings.begin(), alt_findings.end());
  }
}

// An alternative left directly in `root` (alternatives/) instead of alternatives/<adaptable>/.
void report_stray_alternatives(Mission& m, const fs::path& root) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) return;
  std::vector<fs::path> stray;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && it->path().extension() == ".xml") stray.push_back(it->path());
  std::sort(stray.begin(), stray.end());
  for (const auto& file : stray) {
    std::string example = "alternatives/<adaptable>/" + file.filename().string();
    if (!m.adaptables.empty() && !m.adaptables.front().id.empty())
      example = "alternatives/" + m.adaptables.front().id + "/" + file.filename().string();
    Finding f = make_finding("load-ignored-file",
                             "alternatives/" + file.filename().string() +
                                 " lies directly in alternatives/ and is not read: an alternative "
                                 "belongs to one adaptable node",
                             {display_path(file, m.dir), 0, 0});
    f.notes.push_back("move it to " + example);
    m.findings.push_back(std::move(f));
  }
}

// Files uabt would otherwise pass over in silence: a second requirements file, and an
// alternative left directly in alternatives/ instead of alternatives/<adaptable>/.
void report_layout_mistakes(Mission& m, const MissionLayout& layout) {
  std::error_code ec;
  if (layout.kind != "uabt") return;
  if (fs::is_regular_file(m.dir / "requirements.fret", ec) &&
      fs::is_regular_file(m.dir / "requirements.json", ec)) {
    Finding f = make_finding("load-ignored-file",
                             "both requirements.fret and requirements.json exist: uabt reads "
                             "requirements.fret and ignores requirements.json",
                             {"requirements.json", 0, 0});
    f.notes.push_back("keep one of them, so that what is verified is what the team reads");
    m.findings.push_back(std::move(f));
  }
  report_stray_alternatives(m, m.dir / "alternatives");
}

// What an uplink package carries besides requirements.fret, domain.fret, alternatives/ and
// uplink.json: the merge reads nothing else, so a mission.xml (or a misspelt requirements
// file) would be dropped without a word. Hidden files and notes for people are left alone.
void report_package_strays(Mission& m, const fs::path& package) {
  static const std::vector<std::string> read = {"requirements.fret", "domain.fret", "alternatives",
                                                "uplink.json"};
  static const std::map<std::string, std::string> why = {
      {"mission.xml",
       "the fixed part of the tree changes with a new mission version, not an uplink"},
      {"requirements.json", "a package's requirements are read from requirements.fret only"},
      {"nodes.xml", "the robot's registered nodes do not change with an uplink"},
      {"world.json", "guarantees are proved in the mission's world model"},
      {"scenarios", "scenarios belong to the mission (an `uplink` event names the package)"},
      {"uplinks", "packages are not nested: gate each one against the mission"}};
  std::error_code ec;
  std::vector<fs::path> entries;
  for (fs::directory_iterator it(package, ec), end; !ec && it != end; it.increment(ec))
    entries.push_back(it->path());
  std::sort(entries.begin(), entries.end());
  for (const auto& entry : entries) {
    const std::string name = entry.filename().string();
    const std::string extension = entry.extension().string();
    const bool note_for_people =
        name.rfind("README", 0) == 0 || extension == ".md" || extension == ".txt";
    if (name.empty() || name[0] == '.' || note_for_people ||
        std::find(read.begin(), read.end(), name) != read.end())
      continue;
    const std::string shown = display_path(entry, m.dir);
    const bool folder = fs::is_directory(entry, ec);
    Finding f = make_finding("load-ignored-file",
                             name + (folder ? "/" : "") +
                                 " is not part of an uplink package and is not read: the merge "
                                 "reads requirements.fret, domain.fret, alternatives/ and "
                                 "uplink.json",
                             {shown, 0, 0});
    if (const auto reason = why.find(name); reason != why.end())
      f.notes.push_back(reason->second);
    else if (std::string hint = did_you_mean(name, read); !hint.empty())
      f.notes.push_back(std::move(hint));
    m.findings.push_back(std::move(f));
  }
  report_stray_alternatives(m, package / "alternatives");
}

// An uplink package (ARCHITECTURE §2): requirements.fret, domain.fret and alternatives/, each
// optional, merged onto the mission as it stands. Inside the mission (uplinks/<name>/) or
// anywhere else: its files are named relative to the mission directory like every other.
void merge_uplink(Mission& m, const fs::path& uplink, const bt::ReadOptions& read_options) {
  std::error_code ec;
  const std::string shown = display_path(uplink, m.dir);
  if (!fs::is_directory(uplink, ec)) {
    m.findings.push_back(
        make_finding("load-file", shown + ": uplink package is not a directory", {shown, 0, 0}));
    return;
  }
  m.uplinks.push_back(shown);
  const Folder package{uplink, "the uplink package"};
  report_package_strays(m, uplink);
  bool has_content = false;
  UplinkPlan plan;
  if (fs::exists(uplink / "uplink.json", ec)) {
    const std::string plan_shown = display_path(uplink / "uplink.json", m.dir);
    if (inside_or_report(uplink / "uplink.json", package, plan_shown, m.findings))
      plan = read_uplink_plan(uplink / "uplink.json", plan_shown, m.findings);
    has_content = true;
  }
  std::vector<fretish::Requirement> incoming;
  if (fs::is_regular_file(uplink / "requirements.fret", ec)) {
    if (auto parsed = parse_requirements(m, uplink / "requirements.fret", package))
      incoming = std::move(*parsed);
    has_content = true;
  }
  merge_requirements(m, std::move(incoming), plan, shown);
  for (GuaranteeConsent consent : plan.consent) {
    consent.package = shown;
    m.consents.push_back(std::move(consent));
  }
  if (fs::is_regular_file(uplink / "domain.fret", ec)) {
    load_domain(m, uplink / "domain.fret", package, /*package=*/true);
    has_content = true;
  }
  if (auto alternatives = discover_alternatives(uplink / "alternatives"); !alternatives.empty()) {
    load_alternatives(m, alternatives, read_options, package);
    has_content = true;
  }
  if (!has_content)
    m.findings.push_back(make_finding("load-file",
                                      shown + ": uplink package holds no requirements.fret, "
                                              "domain.fret, alternatives/ or uplink.json",
                                      {shown, 0, 0}));
}

}  // namespace

std::optional<Mission> load_mission(const fs::path& dir, const LoadOptions& options,
                                    std::string& error) {
  auto layout = discover_layout(dir, error);
  if (!layout) return std::nullopt;

  Mission m;
  m.dir = dir;
  m.name = fs::weakly_canonical(dir).filename().string();
  m.layout = layout->kind;
  m.mission_xml = layout->mission_xml;

  bt::ReadOptions read_options;
  read_options.confine_to = dir;
  read_options.display_base = dir;

  const Folder folder{dir, "the mission folder"};
  if (inside_or_report(layout->mission_xml, folder, display_path(layout->mission_xml, dir),
                       m.findings)) {
    if (auto doc = bt::read_document(layout->mission_xml, read_options, m.findings)) {
      m.tree = std::move(*doc);
      for (const auto& t : m.tree.trees)
        collect_adaptables(t.root, t.id, t.file, m.adaptables, m.findings);
    }
  }

  if (layout->requirements.empty())
    m.findings.push_back(
        make_finding("load-file", "no requirements file (requirements.fret or requirements.json)",
                     {display_path(dir, dir), 0, 0}));
  else if (auto parsed = parse_requirements(m, layout->requirements, folder))
    m.requirements = std::move(*parsed);
  if (!layout->requirements.empty()) m.requirements_file = display_path(layout->requirements, dir);

  if (layout->domain) load_domain(m, *layout->domain, folder);
  if (options.nodes_file)
    load_nodes(m, *options.nodes_file, read_options);
  else if (layout->nodes &&
           inside_or_report(*layout->nodes, folder, display_path(*layout->nodes, dir), m.findings))
    load_nodes(m, *layout->nodes, read_options);

  load_alternatives(m, layout->alternatives, read_options, folder);
  report_layout_mistakes(m, *layout);
  for (const auto& uplink : options.uplinks) merge_uplink(m, uplink, read_options);
  fretish::Classification classified = fretish::classify_requirements(m.requirements, m.findings);
  m.selections = std::move(classified.selections);
  m.properties = std::move(classified.properties);
  // Durations become ticks here, once, with the merged domain's tick period.
  fretish::lower_durations(m.properties, m.domain.tick_seconds, m.findings);
  describe_merges(m);
  check_vocabulary(m, vocabulary_uses(m));
  infer_condition_variables(m);
  mark_unknowable(m);
  check_references(m);
  check_all_structure(m);
  check_registered_nodes(m);
  sort_findings(m.findings);
  return m;
}

}  // namespace uabt::load
