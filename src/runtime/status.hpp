#pragma once
#include <cstdint>

namespace uabt::runtime {

// BehaviorTree.CPP 4.x node statuses. SKIPPED is only ever returned to a parent: a node that
// is skipped keeps IDLE as its own status, as in BT.CPP's executeTick().
enum class NodeStatus : std::uint8_t { idle, running, success, failure, skipped };

// "IDLE", "RUNNING", "SUCCESS", "FAILURE", "SKIPPED" (BT.CPP's toStr spelling).
const char* status_name(NodeStatus status);

inline bool is_completed(NodeStatus s) {
  return s == NodeStatus::success || s == NodeStatus::failure;
}

}  // namespace uabt::runtime
