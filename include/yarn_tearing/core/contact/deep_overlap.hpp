#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "yarn_tearing/core/contact/obstacle.hpp"
#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {

/// A yarn point deeper inside an obstacle than one step's contact resolves. The contact rows
/// push a point out within the step in which it is found inside; a point found half a segment
/// deep or more is a solid placed through the yarn, not a touch: pushing it out in one step
/// throws its vertices at depth / dt and tears its segments, and each Newton step of the
/// projection then starts far from the solution (doc/contact.md, "Obstacles through a yarn").
struct DeepOverlap {
  std::uint32_t edge = 0;    ///< the segment (global edge id) whose point is deepest [-]
  std::uint32_t vertex = 0;  ///< its vertex nearer the deepest point (global id) [-]
  double depth = 0.0;        ///< how far the yarn's surface lies inside the solid [m]
  double allowed = 0.0;  ///< the depth a step resolves there: half the segment's rest length [m]
};

/// Fraction of a segment's rest length a yarn point may lie inside an obstacle [-].
constexpr double kAllowedOverlapFraction = 0.5;

/// The deepest point of `scene`'s yarns inside `obstacle` past its allowed depth (points of
/// intact segments with a free end, and free ends of torn ones), or none. Held vertices are left
/// out: a grasp or pin inside a solid is the user's to place, and no contact acts on it.
std::optional<DeepOverlap> findDeepOverlap(const Obstacle& obstacle, const Scene& scene);

/// Thrown where an obstacle is set or moved through a yarn (Simulator::setObstacles,
/// setObstaclePose); what() is describeDeepOverlap's sentence.
class ObstacleThroughYarn : public std::invalid_argument {
 public:
  ObstacleThroughYarn(std::string obstacle, const std::string& what)
      : std::invalid_argument(what), obstacle_(std::move(obstacle)) {}
  /// The obstacle's name.
  const std::string& obstacle() const { return obstacle_; }

 private:
  std::string obstacle_;
};

/// One sentence naming the obstacle, the yarn, the segment and both depths [mm].
std::string describeDeepOverlap(const DeepOverlap& overlap, const Obstacle& obstacle,
                                const Scene& scene);

}  // namespace yarn_tearing
