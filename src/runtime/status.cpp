#include "runtime/status.hpp"

namespace uabt::runtime {

const char* status_name(NodeStatus status) {
  switch (status) {
    case NodeStatus::idle: return "IDLE";
    case NodeStatus::running: return "RUNNING";
    case NodeStatus::success: return "SUCCESS";
    case NodeStatus::failure: return "FAILURE";
    case NodeStatus::skipped: return "SKIPPED";
  }
  return "?";
}

}  // namespace uabt::runtime
