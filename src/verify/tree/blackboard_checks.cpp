#include "verify/tree/blackboard_checks.hpp"

#include "verify/tree/domain_questions.hpp"

namespace uabt::verify::tree {

std::vector<Finding> check_blackboard_and_scripts(const load::Mission& mission,
                                                  const Options& options) {
  const FlowGraph graph = build_flow_graph(mission);
  std::vector<Finding> out = check_read_before_write(graph);
  for (auto& f : check_type_conflicts(graph)) out.push_back(std::move(f));
  for (auto& f : check_literal_types(graph)) out.push_back(std::move(f));
  if (!graph.scripts.empty()) {
    DomainQuestions questions(mission, options);
    for (auto& f : check_script_decided(graph, mission, questions)) out.push_back(std::move(f));
    for (auto& f : check_script_range(graph, mission, questions)) out.push_back(std::move(f));
    for (auto& f : check_script_divisions(graph, mission, questions, options))
      out.push_back(std::move(f));
  }
  return out;
}

}  // namespace uabt::verify::tree
