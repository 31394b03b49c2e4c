#include "yarn_tearing/ros/input_rejected.hpp"

namespace yarn_tearing {
namespace ros_layer {

const char* reasonName(RefusalReason reason) {
  switch (reason) {
    case RefusalReason::kNotFinite:
      return "not finite";
    case RefusalReason::kOutOfBounds:
      return "out of bounds";
    case RefusalReason::kUnknownYarn:
      return "unknown yarn";
    case RefusalReason::kVertexOutOfRange:
      return "vertex out of range";
    case RefusalReason::kUnknownFrame:
      return "unknown frame";
    case RefusalReason::kStaleFrame:
      return "stale frame";
    case RefusalReason::kNotGrasped:
      return "not grasped";
    case RefusalReason::kTimeOutOfRange:
      return "time out of range";
    case RefusalReason::kThroughYarn:
      return "through a yarn";
    case RefusalReason::kUnexpected:
      return "unexpected error";
    case RefusalReason::kCount:
      break;
  }
  return "refused";
}

}  // namespace ros_layer
}  // namespace yarn_tearing
