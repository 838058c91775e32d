// The node catalogue: every node BehaviorTree.CPP 4.10's factory registers, with the family,
// children and ports its own code declares, and the only place in src/ that names them.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bt/node_kinds.hpp"

namespace uabt::bt {
namespace {

// One port as BT.CPP declares it: "in name type default" etc.
std::string show(const Port& p) {
  const std::string dir = p.direction == "input_port"    ? "in"
                          : p.direction == "output_port" ? "out"
                          : p.direction == "inout_port"  ? "inout"
                                                         : "?" + p.direction;
  return dir + " " + p.name + " " + (p.type.empty() ? "any" : p.type) +
         (p.default_value.empty() ? "" : " = " + p.default_value);
}

std::string show(const BuiltinNode& node) {
  std::string out = std::string(family_name(node.family)) + " " +
                    std::to_string(node.min_children) + ".." + std::to_string(node.max_children);
  for (const Port& p : node.ports) out += "; " + show(p);
  return out;
}

struct Expected {
  const char* name;
  const char* shape;  // family, children, ports
};

// From BT.CPP 4.10.0: BehaviorTreeFactory's constructor (src/bt_factory.cpp) and each node's
// providedPorts() (include/behaviortree_cpp/{controls,decorators,actions}/…).
const Expected kBtCpp410[] = {
    {"Fallback", "Control 1..-1"},
    {"AsyncFallback", "Control 1..-1"},
    {"Sequence", "Control 1..-1"},
    {"AsyncSequence", "Control 1..-1"},
    {"SequenceWithMemory", "Control 1..-1"},
    {"Parallel", "Control 1..-1; in success_count int = -1; in failure_count int = 1"},
    {"ParallelAll", "Control 1..-1; in max_failures int = 1"},
    {"ReactiveSequence", "Control 1..-1"},
    {"ReactiveFallback", "Control 1..-1"},
    {"IfThenElse", "Control 2..3"},
    {"WhileDoElse", "Control 2..3"},
    {"TryCatch", "Control 1..-1; in catch_on_halt bool = false"},
    {"Inverter", "Decorator 1..1"},
    {"RetryUntilSuccessful", "Decorator 1..1; in num_attempts int"},
    {"KeepRunningUntilFailure", "Decorator 1..1"},
    {"Repeat", "Decorator 1..1; in num_cycles int"},
    {"Timeout", "Decorator 1..1; in msec unsigned int"},
    {"Delay", "Decorator 1..1; in delay_msec unsigned int"},
    {"RunOnce", "Decorator 1..1; in then_skip bool = true"},
    {"ForceSuccess", "Decorator 1..1"},
    {"ForceFailure", "Decorator 1..1"},
    {"AlwaysSuccess", "Action 0..0"},
    {"AlwaysFailure", "Action 0..0"},
    {"Script", "Action 0..0; in code std::string"},
    {"ScriptCondition", "Condition 0..0; in code any"},
    {"SetBlackboard", "Action 0..0; in value any; inout output_key any"},
    {"Sleep", "Action 0..0; in msec unsigned int"},
    {"UnsetBlackboard", "Action 0..0; in key std::string"},
    {"SubTree", "SubTree 0..0"},
    {"Precondition", "Decorator 1..1; in if std::string; in else BT::NodeStatus = FAILURE"},
    {"Switch2",
     "Control 3..3; in variable std::string; in case_1 std::string; in case_2 "
     "std::string"},
    {"Switch3",
     "Control 4..4; in variable std::string; in case_1 std::string; in case_2 "
     "std::string; in case_3 std::string"},
    {"LoopInt",
     "Decorator 1..1; inout queue any; in if_empty BT::NodeStatus = SUCCESS; out "
     "value int"},
    {"LoopBool",
     "Decorator 1..1; inout queue any; in if_empty BT::NodeStatus = SUCCESS; out "
     "value bool"},
    {"LoopDouble",
     "Decorator 1..1; inout queue any; in if_empty BT::NodeStatus = SUCCESS; out "
     "value double"},
    {"LoopString",
     "Decorator 1..1; inout queue any; in if_empty BT::NodeStatus = SUCCESS; out "
     "value std::string"},
    {"WasEntryUpdated", "Action 0..0; in entry any"},
    {"SkipUnlessUpdated", "Decorator 1..1; in entry any"},
    {"WaitValueUpdate", "Decorator 1..1; in entry any"},
};

TEST(NodeCatalogue, HoldsEveryBuiltInOfBtCpp410WithItsFamilyChildrenAndPorts) {
  for (const Expected& e : kBtCpp410) {
    const BuiltinNode* node = find_builtin(e.name);
    ASSERT_NE(node, nullptr) << e.name;
    EXPECT_EQ(show(*node), e.shape) << e.name;
    EXPECT_FALSE(node->v3) << e.name;
    EXPECT_NE(node->kind, NodeKind::robot) << e.name;
    // The kind names it back: compiled trees write a kind by its BT.CPP 4.10 name.
    EXPECT_EQ(std::string(kind_name(node->kind)), e.name);
  }
  for (int n = 4; n <= 6; ++n)
    EXPECT_EQ(find_builtin("Switch" + std::to_string(n))->max_children, n + 1);
}

TEST(NodeCatalogue, EveryKindHasOneEntryUnderItsOwnName) {
  std::set<NodeKind> kinds;
  for (const BuiltinNode& node : builtin_nodes()) {
    if (!node.v3) {
      EXPECT_TRUE(kinds.insert(node.kind).second) << node.name;
    }
    EXPECT_EQ(find_builtin(node.name), &node);
    EXPECT_EQ(node_kind(node.name), node.kind);
  }
  for (auto k = 0; k < static_cast<int>(NodeKind::robot); ++k) {
    const auto kind = static_cast<NodeKind>(k);
    EXPECT_EQ(builtin(kind).kind, kind) << k;
  }
  EXPECT_EQ(node_kind("MoveForward"), NodeKind::robot);
  EXPECT_EQ(find_builtin("sequence"), nullptr);  // names are case-sensitive, as in BT.CPP
}

TEST(NodeCatalogue, V3SpellingsAreTheirV4Kinds) {
  EXPECT_EQ(node_kind("SequenceStar"), NodeKind::sequence_with_memory);
  EXPECT_EQ(node_kind("RetryUntilSuccesful"), NodeKind::retry_until_successful);
  EXPECT_EQ(node_kind("SubTreePlus"), NodeKind::subtree);
  EXPECT_TRUE(is_subtree("SubTreePlus"));
  EXPECT_TRUE(find_builtin("SequenceStar")->v3);
  EXPECT_EQ(std::string(kind_name(NodeKind::sequence_with_memory)), "SequenceWithMemory");
  // BT.CPP 3.8's Parallel read success_threshold / failure_threshold.
  EXPECT_EQ(find_builtin("Parallel")->v3_ports,
            (std::vector<std::string>{"success_threshold", "failure_threshold"}));
}

TEST(NodeCatalogue, ReactivityAndMemory) {
  auto reactive = [](const char* name) { return find_builtin(name)->reactive; };
  auto memory = [](const char* name) { return find_builtin(name)->memory; };
  EXPECT_TRUE(reactive("ReactiveSequence"));
  EXPECT_TRUE(reactive("ReactiveFallback"));
  EXPECT_TRUE(reactive("WhileDoElse"));
  EXPECT_FALSE(reactive("Sequence"));
  EXPECT_FALSE(reactive("IfThenElse"));
  EXPECT_TRUE(memory("Sequence"));
  EXPECT_TRUE(memory("SequenceWithMemory"));
  EXPECT_TRUE(memory("Fallback"));
  EXPECT_TRUE(memory("IfThenElse"));
  EXPECT_FALSE(memory("ReactiveSequence"));
  EXPECT_FALSE(memory("ReactiveFallback"));
  EXPECT_FALSE(memory("WhileDoElse"));
}

TEST(NodeCatalogue, FamiliesByTreeNodesModelName) {
  EXPECT_EQ(family_named("Control"), Family::control);
  EXPECT_EQ(family_named("SubTree"), Family::subtree);
  EXPECT_EQ(family_named("Sequence"), Family::unknown);
}

// The string literals of a C++ file, comments and raw strings (XML templates) left out.
std::vector<std::pair<int, std::string>> string_literals(const std::string& text) {
  std::vector<std::pair<int, std::string>> out;
  int line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
      while (i < text.size() && text[i] != '\n') ++i;
      ++line;
    } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
      const std::size_t end = text.find("*/", i + 2);
      for (std::size_t j = i; j < end && j < text.size(); ++j) line += text[j] == '\n';
      i = end == std::string::npos ? text.size() : end + 1;
    } else if (c == 'R' && i + 1 < text.size() && text[i + 1] == '"') {
      const std::size_t open = text.find('(', i);
      const std::string close = ")" + text.substr(i + 2, open - i - 2) + "\"";
      const std::size_t end = text.find(close, open);
      for (std::size_t j = i; j < end && j < text.size(); ++j) line += text[j] == '\n';
      i = end == std::string::npos ? text.size() : end + close.size() - 1;
    } else if (c == '\'' && i > 0 && std::isdigit(static_cast<unsigned char>(text[i - 1]))) {
      // a digit separator: 1'000
    } else if (c == '\'') {
      for (++i; i < text.size() && text[i] != '\''; ++i) i += text[i] == '\\';
    } else if (c == '"') {
      std::string literal;
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        if (text[i] == '\\') literal += text[i++];
        literal += text[i];
      }
      out.emplace_back(line, literal);
    }
  }
  return out;
}

TEST(NodeCatalogue, NoFileUnderSrcOutsideTheCatalogueNamesABuiltIn) {
  namespace fs = std::filesystem;
  const fs::path src = fs::path(UABT_SOURCE_DIR) / "src";
  // The catalogue itself, and the XML writer, which writes tags.
  const std::set<fs::path> excepted = {src / "bt" / "node_kinds.cpp", src / "bt" / "writer.cpp"};
  std::set<std::string> names;
  for (const BuiltinNode& node : builtin_nodes()) names.insert(node.name);
  std::string found;
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(src)) {
    const fs::path& path = entry.path();
    if (!entry.is_regular_file() || excepted.contains(path)) continue;
    if (path.extension() != ".cpp" && path.extension() != ".hpp") continue;
    ++files;
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    for (const auto& [line, literal] : string_literals(text.str()))
      if (names.contains(literal))
        found += fs::relative(path, src).string() + ":" + std::to_string(line) + ": \"" + literal +
                 "\"\n";
  }
  EXPECT_GT(files, 100u);
  EXPECT_EQ(found, "") << "use bt::NodeKind / bt::node_kind / bt::kind_name instead";
}

TEST(NodeCatalogue, TheLiteralScanSeesWhatItShould) {
  const auto literals = string_literals(
      "a == \"Sequence\"; // \"Fallback\"\n/* \"Inverter\" */ R\"(\"Repeat\")\" '\"' \"x\\\"y\"");
  ASSERT_EQ(literals.size(), 2u);
  EXPECT_EQ(literals[0], (std::pair<int, std::string>{1, "Sequence"}));
  EXPECT_EQ(literals[1], (std::pair<int, std::string>{2, "x\\\"y"}));
}

}  // namespace
}  // namespace uabt::bt
