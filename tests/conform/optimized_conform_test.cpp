// Conformance by meaning: optimized selection trees conform; hand-written decision trees are
// judged by what they select; and every mutant of an optimized tree that selects differently
// in some state is caught, every one that does not is accepted. The judge of "selects
// differently" is the runtime engine ticking the mutant in a sample of states, sharing no code
// with the conformance checker.
#include <gtest/gtest.h>

#include <cctype>
#include <functional>
#include <iostream>
#include <set>

#include "conform/equivalence.hpp"
#include "conform_test_util.hpp"
#include "guard_oracle.hpp"
#include "runtime/engine.hpp"
#include "runtime/selection_probe.hpp"
#include "selection_missions.hpp"
#include "smt/evaluate.hpp"
#include "temp_mission.hpp"
#include "test_support.hpp"

namespace uabt::testing {
namespace {

struct Subject {
  std::string name;
  std::map<std::string, std::string> files;  // empty: the shipped mission `name`
};

std::vector<Subject> subjects() {
  return {{"exploration", {}},
          {"battery_ladder_8", battery_ladder_files(8)},
          {"terrain_enum_8", terrain_enum_files(8)},
          {"assumed_cover", assumed_cover_files()}};
}

struct Loaded {
  std::optional<TempMission> temp;
  load::Mission mission;
};

void load_subject(const Subject& s, Loaded& out) {
  if (s.files.empty()) {
    out.mission = load_or_fail(mission_dir(s.name));
  } else {
    out.temp.emplace(s.files, s.name);
    out.mission = load_or_fail(out.temp->dir());
  }
}

TEST(ConformByMeaning, OptimizedTreesConform) {
  for (const Subject& s : subjects()) {
    SCOPED_TRACE(s.name);
    Loaded l;
    load_subject(s, l);
    compile::Options options;
    options.selection = compile::SelectionStyle::optimized;
    const compile::Result r = compile::compile_mission(l.mission, options);
    ASSERT_TRUE(r.ok);
    ASSERT_FALSE(r.selection_stats.empty());
    EXPECT_TRUE(r.selection_stats.front().optimized_used) << r.selection_stats.front().reason;
    const auto result = conform::conform_tree(l.mission, r.document);
    EXPECT_FALSE(has_errors(result.findings)) << describe(result.findings);
    // The shape is only a matter of style now.
    const auto shape = with_check(result.findings, "compiled-selector-shape");
    ASSERT_EQ(shape.size(), 1u) << describe(result.findings);
    EXPECT_EQ(shape[0]->severity, Severity::note);
  }
}

const char* const kPowerFiles[][2] = {
    {"mission.xml",
     "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
     "  <BehaviorTree ID=\"MainTree\"><Adaptable ID=\"power\"/></BehaviorTree>\n"
     "</root>\n"},
    {"domain.fret", "integer battery in [0, 100]\n"},
    {"requirements.fret",
     "Req1: In power if battery < 20 Mission shall satisfy selected_alt = recharge\n"
     "Default: In power Mission shall satisfy selected_alt = explore\n"},
};

std::string power_document(const std::string& test) {
  return "<root BTCPP_format=\"4\" main_tree_to_execute=\"MainTree\">\n"
         "  <BehaviorTree ID=\"MainTree\"><SubTree ID=\"power\" _autoremap=\"true\"/>"
         "</BehaviorTree>\n"
         "  <BehaviorTree ID=\"power\">\n"
         "    <IfThenElse name=\"power\">\n      " +
         test +
         "\n      <Sequence name=\"Req1\"><SubTree ID=\"recharge\" _autoremap=\"true\"/></Sequence>"
         "\n      <Sequence name=\"Default\"><SubTree ID=\"explore\" _autoremap=\"true\"/>"
         "</Sequence>\n    </IfThenElse>\n  </BehaviorTree>\n"
         "  <BehaviorTree ID=\"recharge\"><Stop/></BehaviorTree>\n"
         "  <BehaviorTree ID=\"explore\"><Stop/></BehaviorTree>\n"
         "</root>\n";
}

TEST(ConformByMeaning, HandWrittenDecisionIsJudgedByWhatItSelects) {
  std::map<std::string, std::string> files;
  for (const auto& f : kPowerFiles) files[f[0]] = f[1];
  files["alternatives/power/recharge.xml"] = alternative_tree("recharge");
  files["alternatives/power/explore.xml"] = alternative_tree("explore");
  TempMission t(files, "power");
  const load::Mission m = load_or_fail(t.dir());

  const auto good = conform::conform_tree(
      m, parse_or_fail(power_document("<ScriptCondition code=\"battery &lt; 20\"/>")));
  EXPECT_FALSE(has_errors(good.findings)) << describe(good.findings);
  // The same decision with the test turned around is as good.
  const auto inverted = conform::conform_tree(
      m, parse_or_fail(
             power_document("<Inverter><ScriptCondition code=\"battery &gt;= 20\"/></Inverter>")));
  EXPECT_FALSE(has_errors(inverted.findings)) << describe(inverted.findings);

  const auto off_by_one = conform::conform_tree(
      m, parse_or_fail(power_document("<ScriptCondition code=\"battery &lt;= 20\"/>")));
  const auto mismatch = with_check(off_by_one.findings, "compiled-selection-mismatch");
  ASSERT_EQ(mismatch.size(), 1u) << describe(off_by_one.findings);
  const Value* battery = find_value(mismatch[0]->witness, "battery");
  ASSERT_NE(battery, nullptr);
  EXPECT_EQ(battery->integer, 20);
  EXPECT_NE(mismatch[0]->message.find("it selects recharge where the requirements select "
                                      "explore (Default)"),
            std::string::npos)
      << mismatch[0]->message;
  EXPECT_EQ(mismatch[0]->requirements, std::vector<std::string>{"Default"});
}

// ---- mutants of optimized trees ----

struct Mutant {
  std::string op, where;
  bt::Document document;
};

std::vector<std::string> numbers_in(const std::string& code) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < code.size();) {
    if (std::isdigit(static_cast<unsigned char>(code[i])) &&
        (i == 0 || !std::isalnum(static_cast<unsigned char>(code[i - 1])) || code[i - 1] == ' ')) {
      std::size_t j = i;
      while (j < code.size() &&
             (std::isdigit(static_cast<unsigned char>(code[j])) || code[j] == '.'))
        ++j;
      out.push_back(code.substr(i, j - i));
      i = j;
    } else {
      ++i;
    }
  }
  return out;
}

std::string replace_first(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// First-order mutants of the selection tree `adaptable`.
std::vector<Mutant> mutants_of(const bt::Document& doc, const std::string& adaptable,
                               const load::Mission& m) {
  std::vector<Mutant> out;
  std::size_t tree = 0;
  while (doc.trees[tree].id != adaptable) ++tree;
  std::vector<std::string> alternative_ids, literals;
  for (const auto& alt : m.alternatives)
    if (alt.adaptable == adaptable) alternative_ids.push_back(alt.tree_id);
  for (const auto& v : m.domain.variables)
    for (const auto& l : v.enum_values) literals.push_back(l);

  std::function<void(std::vector<std::size_t>&)> visit = [&](std::vector<std::size_t>& at) {
    auto mutate = [&](const std::string& op, const std::function<void(bt::Node&)>& change) {
      Mutant mu{op, "", doc};
      bt::Node* n = &mu.document.trees[tree].root;
      for (std::size_t i : at) {
        mu.where += "/" + std::to_string(i);
        n = &n->children[i];
      }
      change(*n);
      out.push_back(std::move(mu));
    };
    const bt::Node* node = &doc.trees[tree].root;
    for (std::size_t i : at) node = &node->children[i];
    const bt::Node& n = *node;
    if (n.tag == "IfThenElse") {
      mutate("swap-branches", [](bt::Node& x) { std::swap(x.children[1], x.children[2]); });
      mutate("drop-test-then", [](bt::Node& x) { x = bt::Node(x.children[1]); });
      mutate("drop-test-else", [](bt::Node& x) { x = bt::Node(x.children[2]); });
    }
    if ((n.tag == "IfThenElse" || n.tag == "Sequence") && n.children.size() >= 2) {
      mutate("negate-test", [](bt::Node& x) {
        bt::Node& test = x.children[0];
        if (test.tag == "Inverter") {
          test = bt::Node(test.children[0]);
        } else {
          bt::Node inv;
          inv.tag = "Inverter";
          inv.children.push_back(test);
          test = inv;
        }
      });
    }
    if (n.tag == "ScriptCondition") {
      const std::string code = *n.attribute("code");
      for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
               {"<=", "<"}, {"< ", "<= "}, {"==", "!="}})
        if (code.find(from) != std::string::npos)
          mutate("change-operator",
                 [&](bt::Node& x) { x.set_attribute("code", replace_first(code, from, to)); });
      for (const auto& number : numbers_in(code))
        mutate("change-constant", [&](bt::Node& x) {
          x.set_attribute("code",
                          replace_first(code, number, std::to_string(std::stoi(number) + 1)));
        });
      for (const auto& lit : literals)
        if (code.find("'" + lit + "'") != std::string::npos)
          for (const auto& other : literals)
            if (other != lit && code.find("'" + other + "'") == std::string::npos) {
              mutate("change-literal", [&](bt::Node& x) {
                x.set_attribute("code", replace_first(code, "'" + lit + "'", "'" + other + "'"));
              });
              break;
            }
    }
    if (n.tag == "SubTree") {
      const std::string id = *n.attribute("ID");
      for (const auto& other : alternative_ids)
        if (other != id) {
          mutate("retarget-leaf", [&](bt::Node& x) { x.set_attribute("ID", other); });
          break;
        }
      mutate("fail-leaf", [](bt::Node& x) {
        bt::Node f;
        f.tag = "AlwaysFailure";
        x = f;
      });
    }
    for (std::size_t i = 0; i < n.children.size(); ++i) {
      at.push_back(i);
      visit(at);
      at.pop_back();
    }
  };
  std::vector<std::size_t> at;
  visit(at);
  return out;
}

// The engine's verdict: in some sampled state, does the mutant start another alternative than
// the requirements select (or not fail where none is selected)?
std::string selects_differently(const load::Mission& m, const bt::Document& doc,
                                const std::string& adaptable, const std::vector<State>& states) {
  const auto reqs = m.selections_for(adaptable);
  for (const State& s : states) {
    std::string required;
    for (const auto* r : reqs)
      if (!r->guard || smt::evaluate(*r->guard, m.domain, s)) {
        required = m.find_alternative(adaptable, r->alternative)->tree_id;
        break;
      }
    runtime::SelectionProbe probe;
    try {
      probe = runtime::probe_selection(doc, adaptable, s);
    } catch (const std::exception& e) {
      return std::string("the engine refuses it: ") + e.what();
    }
    const bool differs = probe.first_call != required ||
                         (required.empty() && probe.status != runtime::NodeStatus::failure);
    if (differs) return "in " + conform::describe(s) + " it starts '" + probe.first_call + "'";
  }
  return "";
}

TEST(ConformByMeaning, MutantsOfOptimizedTreesAreCaughtExactlyWhenTheySelectDifferently) {
  int total = 0, must_catch = 0, caught = 0, must_accept = 0, accepted = 0;
  for (const Subject& s : subjects()) {
    SCOPED_TRACE(s.name);
    Loaded l;
    load_subject(s, l);
    const load::Mission& m = l.mission;
    const bt::Document compiled = compile_or_fail(m, compile::SelectionStyle::optimized);
    const std::string adaptable = m.adaptables.front().id;
    std::vector<double> constants;
    for (const auto& t : compiled.trees)
      if (t.id == adaptable) {
        std::function<void(const bt::Node&)> collect = [&](const bt::Node& n) {
          if (const std::string* code = n.attribute("code"))
            for (const auto& number : numbers_in(*code)) {
              const double v = std::stod(number);
              constants.push_back(v);
              constants.push_back(-v);
              constants.push_back(v + 1);
            }
          for (const auto& c : n.children) collect(c);
        };
        collect(t.root);
      }
    const auto states = oracle::sample_states(m.domain, {}, constants);
    ASSERT_FALSE(states.empty());
    ASSERT_EQ(selects_differently(m, compiled, adaptable, states), "");
    for (const Mutant& mu : mutants_of(compiled, adaptable, m)) {
      SCOPED_TRACE(mu.op + " at " + mu.where);
      ++total;
      const std::string difference = selects_differently(m, mu.document, adaptable, states);
      const auto result = conform::conform_tree(m, mu.document);
      const bool rejected = has_errors(result.findings);
      if (!difference.empty()) {
        ++must_catch;
        caught += rejected ? 1 : 0;
        EXPECT_TRUE(rejected) << difference << "\n" << describe(result.findings);
        EXPECT_TRUE(has_check(result.findings, "compiled-selection-mismatch") ||
                    has_check(result.findings, "bt-structure"))
            << describe(result.findings);
      } else {
        ++must_accept;
        accepted += rejected ? 0 : 1;
        EXPECT_FALSE(rejected) << describe(result.findings);
      }
    }
  }
  std::cout << "\nMutants of optimized trees: " << total << "; killed " << caught << "/"
            << must_catch << " that select differently; accepted " << accepted << "/" << must_accept
            << " that select the same\n";
  EXPECT_GT(must_catch, 20);
}

}  // namespace
}  // namespace uabt::testing
