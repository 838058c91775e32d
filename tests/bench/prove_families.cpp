#include "prove_families.hpp"

#include <fstream>
#include <stdexcept>
#include <string>

namespace uabt::bench {

namespace {

void write(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string mission_xml(const std::string& body) {
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
         "  <BehaviorTree ID=\"MainTree\">\n    <KeepRunningUntilFailure>\n" +
         body + "    </KeepRunningUntilFailure>\n  </BehaviorTree>\n</root>\n";
}

std::string indent(int depth) {
  return std::string(static_cast<std::size_t>(2 * depth), ' ');
}

// The heap-shaped tree: node k has children 2k+1 and 2k+2 when they exist; leaves are
// numbered left to right.
struct BinaryTreeWriter {
  int nodes;
  int counters;
  int leaf = 0;
  std::string xml;

  void node(int k, int depth) {
    if (2 * k + 2 < nodes) {
      xml += indent(depth) + "<Fallback>\n";
      node(2 * k + 1, depth + 1);
      node(2 * k + 2, depth + 1);
      xml += indent(depth) + "</Fallback>\n";
      return;
    }
    const int i = leaf++;
    if (i % 2 == 0) {
      static constexpr int kThreshold[] = {8, 6, 4, 7, 5};
      const int check = i / 2;
      xml += indent(depth) + "<ScriptCondition code=\"vv_" + std::to_string(check % counters) +
             " &gt;= " + std::to_string(kThreshold[check % 5]) + "\"/>\n";
    } else {
      const int action = i / 2;
      const bool inc = (action / counters) % 2 == 0;
      xml +=
          indent(depth) + "<" + (inc ? "Inc" : "Dec") + std::to_string(action % counters) + "/>\n";
    }
  }
};

}  // namespace

FamilyMission generate_binary_tree(const std::filesystem::path& dir, int fallback_nodes,
                                   int counters) {
  if (fallback_nodes < 3 || fallback_nodes % 2 == 0)
    throw std::invalid_argument("a complete binary tree has an odd number of nodes, >= 3");
  if (counters < 1) throw std::invalid_argument("the binary tree needs at least one counter");
  BinaryTreeWriter tree{fallback_nodes, counters, 0, {}};
  tree.node(0, 3);
  write(dir / "mission.xml", mission_xml(tree.xml));
  std::string domain = "# Counters the checks read and the actions change.\n";
  std::string initial, actions;
  for (int j = 0; j < counters; ++j) {
    const std::string v = "vv_" + std::to_string(j);
    domain += "integer " + v + " in [0, 8]\n";
    initial += (j ? " & " : "") + v + " = 0";
    actions += std::string(j ? ",\n" : "") + "    \"Inc" + std::to_string(j) +
               "\": {\"ticks\": 1, \"results\": [\"success\", \"failure\"], \"on_success\": \"" +
               v + " = " + v + " < 8 ? " + v + " + 1 : " + v + "\"},\n    \"Dec" +
               std::to_string(j) +
               "\": {\"ticks\": 1, \"results\": [\"success\", \"failure\"], \"on_success\": \"" +
               v + " = " + v + " > 0 ? " + v + " - 1 : " + v + "\"}";
  }
  write(dir / "domain.fret", domain);
  write(dir / "world.json",
        "{\n  \"initial\": \"" + initial + "\",\n  \"actions\": {\n" + actions + "\n  }\n}\n");
  write(dir / "requirements.fret",
        "Bounded: Mission shall always satisfy vv_0 <= 8\n"
        "BelowMax: Mission shall always satisfy vv_0 < 8\n");
  FamilyMission m;
  m.dir = dir;
  m.tree_nodes = fallback_nodes + 1;
  m.verdicts = {{"Bounded", "proved"}, {"BelowMax", "violated"}};
  m.violation_ticks = {{"BelowMax", 8}};
  return m;
}

FamilyMission generate_checklist(const std::filesystem::path& dir, int checks) {
  if (checks < 1) throw std::invalid_argument("a checklist has at least one check");
  std::string body = "      <ForceSuccess>\n        <Sequence>\n";
  std::string domain = "# Whether each item of the checklist is in order.\n";
  std::string initial, actions, all_ok;
  for (int i = 0; i < checks; ++i) {
    const std::string ok = "IsOk_" + std::to_string(i), repair = "Repair" + std::to_string(i);
    body += "          <Fallback>\n            <" + ok + "/>\n            <" + repair +
            "/>\n          </Fallback>\n";
    domain += "boolean " + ok + "\n";
    initial += (i ? " & !" : "!") + ok;
    all_ok += (i ? " & " : "") + ok;
    actions += "    \"" + repair +
               "\": {\"ticks\": [2, 3], \"results\": [\"success\", \"failure\"], "
               "\"on_success\": \"" +
               ok + " = true\"},\n";
  }
  body += "          <Work/>\n        </Sequence>\n      </ForceSuccess>\n";
  write(dir / "mission.xml", mission_xml(body));
  write(dir / "domain.fret", domain);
  write(dir / "world.json",
        "{\n  \"initial\": \"" + initial + "\",\n  \"actions\": {\n" + actions +
            "    \"Work\": {\"ticks\": 2, \"results\": [\"success\"]}\n  }\n}\n");
  write(dir / "requirements.fret",
        "Ready: Mission shall always satisfy Work.running -> (" + all_ok +
            ")\nNeverWorks: Mission shall always satisfy !Work.running\n");
  FamilyMission m;
  m.dir = dir;
  m.tree_nodes = 3 * checks + 4;
  m.verdicts = {{"Ready", "proved"}, {"NeverWorks", "violated"}};
  m.violation_ticks = {{"NeverWorks", static_cast<std::uint64_t>(checks) + 1}};
  return m;
}

}  // namespace uabt::bench
