// AlwaysSuccess / AlwaysFailure: actions that complete at once.
#include "runtime/core.hpp"

namespace uabt::runtime::detail {

NodeStatus tick_always_success(Core&, NodeId) {
  return NodeStatus::success;
}
NodeStatus tick_always_failure(Core&, NodeId) {
  return NodeStatus::failure;
}

}  // namespace uabt::runtime::detail
