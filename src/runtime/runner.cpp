#include "runtime/runner.hpp"

namespace uabt::runtime {

Runner::Runner(const bt::Document& doc, Scenario scenario, RunOptions options,
               std::vector<bt::NodeModel> robot_nodes)
    : options_(std::move(options)) {
  // The document's own models first, then what the robot declares (nodes.xml).
  models_ = doc.node_models;
  models_.insert(models_.end(), robot_nodes.begin(), robot_nodes.end());
  world_ = new_world(std::move(scenario));
  engine_ =
      std::make_unique<Engine>(Engine::build(doc, options_.main_tree, *world_, options_.engine));
  built_ = EngineState::save(*engine_);
  start();
}

void Runner::restart(Scenario scenario) {
  // The old world goes only once the engine no longer points at it.
  auto world = new_world(std::move(scenario));
  engine_->reset(*world, built_);
  world_ = std::move(world);
  next_event_ = 0;
  last_ = NodeStatus::idle;
  error_.reset();
  unhandled_.clear();
  start();
}

std::unique_ptr<SimWorld> Runner::new_world(Scenario scenario) const {
  auto world = std::make_unique<SimWorld>(std::move(scenario), models_);
  world->log_conditions(options_.log_conditions);
  return world;
}

void Runner::start() {
  max_ticks_ = options_.max_ticks > 0 ? options_.max_ticks : world_->scenario().max_ticks;
  world_->apply_initial(engine_->blackboard());
}

NodeStatus Runner::step() {
  if (error_) return last_;
  const auto next_tick = static_cast<std::int64_t>(engine_->tick_count() + 1);
  const auto& events = world_->scenario().events;
  try {
    while (next_event_ < events.size() && events[next_event_].at <= next_tick) {
      const ScenarioEvent& event = events[next_event_++];
      world_->apply_event(event, engine_->blackboard());
      if (event.uplink.empty()) continue;
      if (on_uplink) {
        on_uplink(event, *this);
      } else {
        unhandled_.push_back(event);
      }
    }
    last_ = engine_->tick();
  } catch (const TickException& e) {
    error_ = e.error;
  }
  return last_;
}

bool Runner::done() const {
  return error_ || last_ == NodeStatus::success || last_ == NodeStatus::failure ||
         last_ == NodeStatus::skipped;
}

std::string Runner::verdict() const {
  if (error_) return "error";
  switch (last_) {
    case NodeStatus::success: return "success";
    case NodeStatus::failure: return "failure";
    case NodeStatus::skipped: return "skipped";
    default: return "timeout";
  }
}

RunResult Runner::run() {
  while (!done() && static_cast<std::int64_t>(engine_->tick_count()) < max_ticks_) step();
  RunResult result;
  result.status = last_;
  result.ticks = engine_->tick_count();
  result.finished = done() && !error_;
  result.verdict = verdict();
  result.error = error_;
  result.log = world_->log();
  result.errors = engine_->errors();
  result.unhandled_uplinks = unhandled_;
  result.stats = engine_->stats();
  return result;
}

}  // namespace uabt::runtime
