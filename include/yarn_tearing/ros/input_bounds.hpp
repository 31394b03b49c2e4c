#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// Physical bounds on what clients send on topics (doc/node.md, "Bad input"): past them a message
/// is refused, so nothing from outside can overflow the simulation.
namespace input_bounds {

constexpr double kMaxForce = 1.0e6;  ///< |applied force| [N]
/// |applied force| / the breaking forces of the vertex's edges summed (vertexBreakingForces) [-]:
/// past it a force only flings a vertex that tears out anyway, and a fabric's step to take it
/// grows from milliseconds to seconds (1e4 x at a 16 x 12 patch's corner: 15 s).
constexpr double kMaxForcePerStrength = 100.0;
constexpr double kMaxDistance = 1.0e4;      ///< distance of a grasp target from the origin [m]
constexpr double kMaxDuration = 1.0e9;      ///< applied force duration and ramp duration [s]
constexpr double kMaxForceRate = 1.0e9;     ///< |applied force rate| [N/s]
constexpr double kMaxSpeed = 1.0e3;         ///< |grasp velocity| [m/s]
constexpr std::size_t kMaxFrameName = 256;  ///< tf frame name [characters]

}  // namespace input_bounds

/// Throws InputRejected (kNotFinite or kOutOfBounds) unless `value` is finite and its norm is at
/// most `bound`; `what` names the quantity and `unit` its unit in the message, e.g. "force", "N".
void requireBoundedVector(const Eigen::Vector3d& value, double bound, const std::string& what,
                          const std::string& unit);

}  // namespace ros_layer
}  // namespace yarn_tearing
