#pragma once
#include <cstdint>
#include <vector>

#include "runtime/engine.hpp"

namespace uabt::runtime {

// Counts condition ticks: every tick of a ScriptCondition or of a robot leaf the World answers
// as a condition (one that names what it reads). On a rover each of those can be a sensor
// query; this is the cost smart re-selection (EngineOptions::smart_selection) saves.
class ConditionCounter : public Observer {
 public:
  explicit ConditionCounter(const Engine& engine) : engine_(engine) {}
  void on_status_change(NodeId, NodeStatus, NodeStatus) override {}
  void on_node_ticked(NodeId node, NodeStatus result) override;
  std::uint64_t count() const { return count_; }

 private:
  const Engine& engine_;
  std::vector<std::uint8_t> kind_;  // per node: 0 unknown, 1 condition, 2 not
  std::uint64_t count_ = 0;
};

}  // namespace uabt::runtime
