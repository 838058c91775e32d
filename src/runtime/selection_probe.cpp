// Counts what one tick of a selection tree really ticks (cross-checks the compiler's counts).
#include "runtime/selection_probe.hpp"

#include "bt/node_kinds.hpp"
#include "runtime/runner.hpp"

namespace uabt::runtime {

namespace {

ScriptValue script_value(const Value& v) {
  switch (v.kind) {
    case Value::Kind::boolean: return ScriptValue::of_bool(v.boolean);
    case Value::Kind::integer: return ScriptValue::of_int(v.integer);
    case Value::Kind::real: return ScriptValue::of_real(v.real);
    case Value::Kind::enumeration: return ScriptValue::of_string(v.text);
  }
  return {};
}

class Counter : public Observer {
 public:
  Counter(const Engine& engine, const std::string& tree_id, SelectionProbe& out)
      : engine_(engine), tree_id_(tree_id), out_(out) {}

  void on_status_change(NodeId node, NodeStatus previous, NodeStatus next) override {
    if (previous != NodeStatus::idle) return;
    const NodeInfo& info = engine_.info(node);
    if (info.tree_id != tree_id_) return;
    const bt::NodeKind kind = bt::node_kind(info.kind);
    if (kind == bt::NodeKind::subtree) {
      if (next == NodeStatus::running && out_.first_call.empty())
        if (const std::string* id = info.element->attribute("ID")) out_.first_call = *id;
      return;
    }
    const bool done = next == NodeStatus::success || next == NodeStatus::failure;
    const bool leaf = engine_.children(node).empty();
    if (done && leaf && kind != bt::NodeKind::always_success &&
        kind != bt::NodeKind::always_failure && kind != bt::NodeKind::script)
      ++out_.conditions;
  }

 private:
  const Engine& engine_;
  const std::string& tree_id_;
  SelectionProbe& out_;
};

}  // namespace

SelectionProbe probe_selection(const bt::Document& doc, const std::string& tree_id,
                               const State& state) {
  Scenario scenario;
  scenario.max_ticks = 1;
  for (const auto& [name, value] : state) scenario.initial.emplace_back(name, script_value(value));
  RunOptions options;
  options.main_tree = tree_id;
  options.log_conditions = false;
  Runner runner(doc, std::move(scenario), options);
  SelectionProbe probe;
  Counter counter(runner.engine(), tree_id, probe);
  runner.engine().add_observer(&counter);
  probe.status = runner.step();
  runner.engine().remove_observer(&counter);
  return probe;
}

}  // namespace uabt::runtime
