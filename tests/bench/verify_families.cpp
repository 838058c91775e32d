#include "verify_families.hpp"
#include "family_files.hpp"

#include <fstream>
#include <stdexcept>

namespace uabt::bench {

namespace {

std::string tree(const std::string& id, const std::string& body) {
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"" + id + "\">\n  <BehaviorTree ID=\"" +
         id + "\">\n" + body + "  </BehaviorTree>\n</root>\n";
}

// The node `navigation` and its default `hold`; `alternatives` are the other trees, by name.
void write_node(const std::filesystem::path& dir, const std::string& domain,
                const std::string& requirements,
                const std::map<std::string, std::string>& alternatives) {
  write_file(
      dir / "mission.xml",
      tree("MainTree", "    <Sequence>\n      <Adaptable ID=\"navigation\"/>\n    </Sequence>\n"));
  write_file(dir / "nodes.xml",
             "<root BTCPP_format=\"4\">\n  <TreeNodesModel>\n    <Condition ID=\"OnDust\"/>\n"
             "    <Action ID=\"Hop\">\n      <input_port name=\"distance\" type=\"int\"/>\n"
             "    </Action>\n    <Action ID=\"Stop\"/>\n  </TreeNodesModel>\n</root>\n");
  write_file(dir / "domain.fret", domain);
  write_file(dir / "requirements.fret",
             requirements + "Hold: In navigation Mission shall satisfy selected_alt = hold\n");
  write_file(dir / "alternatives/navigation/hold.xml", tree("hold", "    <Stop/>\n"));
  for (const auto& [name, body] : alternatives)
    write_file(dir / ("alternatives/navigation/" + name + ".xml"), tree(name, body));
}

}  // namespace

VerifyFamily generate_ported_sequence(const std::filesystem::path& dir, int actions) {
  if (actions < 1) throw std::invalid_argument("a Sequence has at least one action");
  std::string body = "    <Sequence>\n";
  for (int i = 0; i < actions; ++i) body += "      <Hop distance=\"1\"/>\n";
  body += "    </Sequence>\n";
  write_node(dir, "boolean OnDust\n",
             "Dusty: In navigation if OnDust Mission shall satisfy selected_alt = hop\n",
             {{"hop", body}});
  return {dir, {}};
}

VerifyFamily generate_disjunct_guard(const std::filesystem::path& dir, int disjuncts) {
  if (disjuncts < 1) throw std::invalid_argument("a guard has at least one disjunct");
  std::string guard = "depth = 0";
  for (int k = 1; k < disjuncts; ++k) guard += " | depth = " + std::to_string(k);
  write_node(dir, "integer depth in [0, 100000]\n",
             "Deep: In navigation if " + guard + " Mission shall satisfy selected_alt = hop\n",
             {{"hop", "    <Hop distance=\"1\"/>\n"}});
  VerifyFamily f{dir, {}};
  if (disjuncts > 1000) f.findings["verification-skipped"] = 1;
  return f;
}

VerifyFamily generate_real_grid(const std::filesystem::path& dir, int guards) {
  if (guards < 1) throw std::invalid_argument("a grid has at least one cell");
  constexpr int kColumns = 64;
  const int rows = (guards + kColumns - 1) / kColumns;
  std::string requirements;
  std::map<std::string, std::string> alternatives;
  for (int i = 0; i < guards; ++i) {
    const int column = i % kColumns, row = i / kColumns;
    // A bound the domain already gives would be a vacuous atom: left out.
    std::string guard;
    const auto conjoin = [&](const std::string& atom) {
      guard += (guard.empty() ? "" : " & ") + atom;
    };
    if (column > 0) conjoin("wind >= " + std::to_string(column));
    conjoin("wind < " + std::to_string(column + 1));
    if (row > 0) conjoin("battery >= " + std::to_string(row));
    conjoin("battery < " + std::to_string(row + 1));
    const std::string name = "a" + std::to_string(i);
    requirements += "R" + std::to_string(i) + ": In navigation if " + guard +
                    " Mission shall satisfy selected_alt = " + name + "\n";
    alternatives[name] = "    <Hop distance=\"" + std::to_string(i) + "\"/>\n";
  }
  write_node(dir,
             "real wind in [0, " + std::to_string(kColumns) + "]\nreal battery in [0, " +
                 std::to_string(rows) + "]\n",
             requirements, alternatives);
  return {dir, {}};
}

VerifyFamily generate_undeclared_guard(const std::filesystem::path& dir, int names) {
  if (names < 1) throw std::invalid_argument("a guard names at least one variable");
  std::string guard = "A0";
  for (int k = 1; k < names; ++k) guard += " & A" + std::to_string(k);
  write_node(dir, "",
             "Named: In navigation if " + guard + " Mission shall satisfy selected_alt = hop\n",
             {{"hop", "    <Hop distance=\"1\"/>\n"}});
  std::filesystem::remove(dir / "domain.fret");
  return {dir, {}};
}

VerifyFamily generate_noise_requirements(const std::filesystem::path& dir, int bytes) {
  if (bytes < 1) throw std::invalid_argument("noise has at least one byte");
  write_node(dir, "boolean OnDust\n", "", {{"hop", "    <Hop distance=\"1\"/>\n"}});
  std::string noise(static_cast<std::size_t>(bytes), '\0');
  std::uint64_t x = 0x9e3779b97f4a7c15ull;  // xorshift64: the same bytes on every machine
  for (char& c : noise) {
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    c = static_cast<char>(x >> 56);
  }
  write_file(dir / "requirements.fret", noise);
  return {dir, {}};
}

}  // namespace uabt::bench
