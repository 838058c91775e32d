// Replays a scenario on the runtime (what `uabt run` does, without the gate) and observes
// every selection with the state it was made in.
#include <functional>
#include <map>
#include <stdexcept>

#include "base/diagnostics.hpp"
#include "campaign/campaign.hpp"
#include "runtime/blackboard.hpp"
#include "runtime/runner.hpp"
#include "runtime/scenario_check.hpp"
#include "runtime/selection.hpp"
#include "runtime/source_map.hpp"

namespace uabt::campaign {

namespace {

// Reports a selection subtree (the root of the tree named like its adaptable node) that
// fails without having started an alternative that tick: a state in a gap, where the node
// is ticked and selects nothing.
class GapObserver : public runtime::Observer {
 public:
  GapObserver(const runtime::Engine& engine, std::set<std::string> adaptables,
              std::function<void(const std::string&)> on_gap)
      : engine_(engine), adaptables_(std::move(adaptables)), on_gap_(std::move(on_gap)) {}
  void on_status_change(runtime::NodeId, runtime::NodeStatus, runtime::NodeStatus) override {}
  void on_node_ticked(runtime::NodeId node, runtime::NodeStatus result) override {
    if (result != runtime::NodeStatus::failure) return;
    const runtime::NodeInfo& info = engine_.info(node);
    if (!adaptables_.count(info.tree_id)) return;
    if (info.parent != runtime::kNoNode && engine_.info(info.parent).tree_id == info.tree_id)
      return;
    on_gap_(info.tree_id);
  }

 private:
  const runtime::Engine& engine_;
  std::set<std::string> adaptables_;
  std::function<void(const std::string&)> on_gap_;
};

}  // namespace

struct Replayer::Impl {
  const load::Mission& mission;
  bt::Document document;
  std::vector<bt::NodeModel> robot_nodes;
  runtime::ScenarioVocabulary vocabulary;
  std::vector<compile::TraceEntry> trace;  // where each compiled node comes from
  // The tree, built for the first run and reset for each next one (Runner::restart: exactly a
  // fresh tree, without instantiating it again).
  std::unique_ptr<runtime::Runner> runner;
};

Replayer::Replayer(const load::Mission& mission, bt::Document compiled_tree,
                   std::vector<compile::TraceEntry> trace)
    : impl_(std::make_unique<Impl>(
          Impl{mission, std::move(compiled_tree), {}, {}, std::move(trace), {}})) {
  impl_->vocabulary.add(mission);
  if (mission.nodes) impl_->robot_nodes = *mission.nodes;
}

Replayer Replayer::compiling(const load::Mission& mission, const compile::Options& options) {
  compile::Result compiled = compile::compile_mission(mission, options);
  if (!compiled.ok)
    throw std::runtime_error("the mission does not compile:\n" + format_text(compiled.findings));
  // The tree as `uabt run` holds it: read back from the bytes the compiler writes.
  compile::ReadBack written = compile::read_back(compiled, options);
  if (!written.tree)
    throw std::runtime_error("the compiled tree does not read back:\n" +
                             format_text(written.findings));
  return Replayer(mission, std::move(*written.tree), std::move(compiled.trace));
}

Replayer::Replayer(Replayer&&) noexcept = default;
Replayer::~Replayer() = default;

runtime::Scenario Replayer::scenario(const std::string& json, const std::string& file) const {
  runtime::Scenario scenario = runtime::parse_scenario(json, file);
  runtime::type_numbers(scenario, impl_->vocabulary);
  return scenario;
}

runtime::Runner& Replayer::start(runtime::Scenario scenario) const {
  if (impl_->runner) {
    impl_->runner->restart(std::move(scenario));
  } else {
    runtime::RunOptions options;
    options.log_conditions = false;
    impl_->runner = std::make_unique<runtime::Runner>(impl_->document, std::move(scenario), options,
                                                      impl_->robot_nodes);
  }
  return *impl_->runner;
}

const bt::Document& Replayer::document() const {
  return impl_->document;
}

RunRecord Replayer::run(const std::string& json, const std::string& file,
                        const std::set<std::string>& stop_after) const {
  RunRecord record;
  record.source = file;
  runtime::Scenario scenario = this->scenario(json, file);
  // Names and values that do not fit the mission are refused, as `uabt run` refuses them.
  const std::vector<std::string> misfits = runtime::check_scenario(scenario, impl_->vocabulary);
  if (!misfits.empty()) {
    std::string text;
    for (const auto& m : misfits) text += (text.empty() ? "" : "\n") + m;
    throw runtime::ScenarioError(text);
  }
  runtime::Runner& runner = start(std::move(scenario));
  std::set<std::string> waiting = stop_after;
  std::map<std::string, std::uint64_t> selected_at;  // per node: the last tick it selected
  auto observe = [&](const std::string& adaptable, const std::string& alternative) {
    Observation o;
    o.adaptable = adaptable;
    o.tick = runner.ticks() + 1;  // the tick under way
    o.alternative = alternative;
    for (const auto& alt : impl_->mission.alternatives)
      if (alt.adaptable == adaptable && alt.tree_id == alternative) o.alternative = alt.name;
    // The domain's variables are what targets are about.
    for (const auto& [name, value] : runner.engine().blackboard().entries())
      if (value.kind != runtime::ScriptValue::Kind::empty &&
          impl_->mission.domain.find(name) != nullptr)
        o.state.emplace_back(name, runtime::to_value(value));
    waiting.erase(adaptable);
    record.observations.push_back(std::move(o));
  };
  runtime::SelectionObserver selections(runner.engine(), [&](const runtime::Selection& s) {
    selected_at[s.adaptable] = runner.ticks() + 1;
    observe(s.adaptable, s.alternative);
  });
  std::set<std::string> adaptables;
  for (const auto& site : impl_->mission.adaptables) adaptables.insert(site.id);
  GapObserver gaps(runner.engine(), adaptables, [&](const std::string& adaptable) {
    if (selected_at[adaptable] != runner.ticks() + 1) observe(adaptable, "");
  });
  {
    const runtime::Observing observing_selections(runner.engine(), selections);
    const runtime::Observing observing_gaps(runner.engine(), gaps);
    while (!runner.done() && static_cast<std::int64_t>(runner.ticks()) < runner.max_ticks()) {
      runner.step();
      runner.world().clear_log();
      if (!stop_after.empty() && waiting.empty()) break;
    }
  }
  record.ticks = runner.ticks();
  record.verdict = runner.verdict();
  if (runner.error())  // at the line the user wrote, as opened from where uabt runs
    record.error =
        with_user_path(runtime::with_source_places(runner.error()->message, impl_->document,
                                                   impl_->mission, impl_->trace),
                       path_prefix_for(impl_->mission.dir));
  return record;
}

}  // namespace uabt::campaign
