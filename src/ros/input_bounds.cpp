#include "yarn_tearing/ros/input_bounds.hpp"

#include <sstream>

#include "yarn_tearing/ros/input_rejected.hpp"

namespace yarn_tearing {
namespace ros_layer {

void requireBoundedVector(const Eigen::Vector3d& value, double bound, const std::string& what,
                          const std::string& unit) {
  if (!value.allFinite()) {
    throw InputRejected(RefusalReason::kNotFinite, what + " is not finite");
  }
  const double norm = value.norm();
  if (!(norm <= bound)) {
    std::ostringstream text;
    text << what << " of magnitude " << norm << " " << unit << " is past the bound " << bound << " "
         << unit;
    throw InputRejected(RefusalReason::kOutOfBounds, text.str());
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
