#include "mission_generator.hpp"
#include "family_files.hpp"

#include <algorithm>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>

namespace uabt::bench {
namespace {

// Concatenation by append: GCC 12 warns (-Wrestrict, a false positive) on "literal" + string.
std::string cat(std::initializer_list<std::string> parts) {
  std::string s;
  for (const auto& p : parts) s += p;
  return s;
}

std::string node_name(int i) {
  return cat({"node", std::to_string(i)});
}
std::string alt_name(int i, int j) {
  return cat({"n", std::to_string(i), "_alt", std::to_string(j)});
}
std::string req_id(int i, int j) {
  return cat({"N", std::to_string(i), "A", std::to_string(j)});
}

// Guard of alternative j (j < K-1) of node i: pairwise disjoint over the node's variable.
// `kind` is the layout (i mod 4 for mixed missions; 2 or 4 for the real-valued ones).
std::string guard(int i, int j, int kind) {
  const std::string n = std::to_string(i);
  const std::string a = std::to_string(j);
  switch (kind) {
    case 4:
      return "r_" + n + " + s_" + n + " >= " + a + " & r_" + n + " + s_" + n + " < " +
             std::to_string(j + 1);
    case 0: return "mode_" + n + " = m" + n + "_l" + a;
    case 1:
      return "x_" + n + " >= " + std::to_string(10 * j) + " & x_" + n + " < " +
             std::to_string(10 * j + 10);
    case 2: return "r_" + n + " >= " + a + " & r_" + n + " < " + std::to_string(j + 1);
    default: return "mode_" + n + " = m" + n + "_l" + a + " & ok_" + n;
  }
}

// Domain declarations of node i; each leaves room for the default (a literal, or values
// outside every interval).
std::string declarations(int i, int k, int kind) {
  const std::string n = std::to_string(i);
  switch (kind) {
    case 4:
      return "real r_" + n + " in [-1, " + std::to_string(k) + "]\nreal s_" + n + " in [0, " +
             std::to_string(k) + "]\n";
    case 1: return "integer x_" + n + " in [-1, " + std::to_string(10 * k) + "]\n";
    case 2: return "real r_" + n + " in [-1, " + std::to_string(k) + "]\n";
    default: {
      std::string s = "enum mode_" + n + " in {";
      for (int j = 0; j < k; ++j) s += (j ? ", m" : "m") + n + "_l" + std::to_string(j);
      s += "}\n";
      if (kind == 3) s += "boolean ok_" + n + "\n";
      return s;
    }
  }
}

std::string alternative_xml(const std::string& id, int tree_nodes) {
  std::string body;
  if (tree_nodes <= 1) {
    body = "    <AlwaysSuccess/>\n";
  } else {
    body = "    <Sequence>\n";
    for (int k = 1; k < tree_nodes; ++k)
      body += k % 2 ? "      <AlwaysSuccess/>\n" : "      <AlwaysSuccess name=\"step\"/>\n";
    body += "    </Sequence>\n";
  }
  return cat({"<root BTCPP_format=\"4\" main_tree_to_execute=\"", id, "\">\n  <BehaviorTree ID=\"",
              id, "\">\n", body, "  </BehaviorTree>\n</root>\n"});
}

}  // namespace

GeneratedMission generate_mission(const std::filesystem::path& parent, int nodes, int alternatives,
                                  GeneratorMode mode, int tree_nodes) {
  const int k = alternatives;
  const bool planted = mode == GeneratorMode::planted;
  if (nodes < 1 || k < 2) throw std::invalid_argument("need nodes >= 1 and alternatives >= 2");
  if (planted && (nodes < 3 || k < 4))
    throw std::invalid_argument("planted missions need nodes >= 3 and alternatives >= 4");

  GeneratedMission result;
  const int fixed_kind = mode == GeneratorMode::real ? 2 : mode == GeneratorMode::real_sum ? 4 : -1;
  const char* const label = planted                           ? "planted_"
                            : mode == GeneratorMode::real     ? "real_"
                            : mode == GeneratorMode::real_sum ? "realsum_"
                                                              : "partition_";
  result.dir = parent / cat({"gen_", label, std::to_string(nodes), "x", std::to_string(k), "x",
                             std::to_string(tree_nodes)});
  std::filesystem::remove_all(result.dir);

  std::ostringstream mission, requirements, domain;
  mission << "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
          << "  <BehaviorTree ID=\"MainTree\">\n    <Sequence>\n";
  for (int i = 0; i < nodes; ++i) {
    mission << "      <Adaptable ID=\"" << node_name(i) << "\"/>\n";
    const int kind = fixed_kind >= 0 ? fixed_kind : i % 4;
    domain << declarations(i, k, kind);
    const bool overlap_node = planted && i == 0;
    const bool gap_node = planted && i == 1;
    const bool shadow_node = planted && i == 2;
    for (int j = 0; j < k; ++j) {
      const bool is_default = j == k - 1;
      if (is_default && gap_node) continue;  // no default: the last literal/interval is a gap
      std::string g;
      if (!is_default) g = guard(i, j, kind);
      if (overlap_node && j == 1)
        g = cat({"(", guard(i, 1, kind), ") | (", guard(i, 0, kind), ")"});
      if (shadow_node && j == k - 2) g = guard(i, 0, kind);  // hidden by alternative 0
      requirements << req_id(i, j) << ": In " << node_name(i);
      if (!g.empty()) requirements << " if " << g;
      requirements << " Mission shall satisfy selected_alt = " << alt_name(i, j) << "\n";
      write_file(result.dir / "alternatives" / node_name(i) / (alt_name(i, j) + ".xml"),
                 alternative_xml(alt_name(i, j), tree_nodes));
    }
  }
  mission << "    </Sequence>\n  </BehaviorTree>\n</root>\n";
  write_file(result.dir / "mission.xml", mission.str());
  write_file(result.dir / "requirements.fret", requirements.str());
  write_file(result.dir / "domain.fret", domain.str());

  if (planted) {
    result.expected = {
        {"guard-overlap", node_name(0), {req_id(0, 0), req_id(0, 1)}},
        {"guard-gap", node_name(1), {}},
        {"guard-overlap", node_name(2), {req_id(2, 0), req_id(2, k - 2)}},
        {"guard-shadowed", node_name(2), {req_id(2, 0), req_id(2, k - 2)}},
    };
    for (auto& e : result.expected) std::sort(e.requirements.begin(), e.requirements.end());
  }
  return result;
}

}  // namespace uabt::bench
