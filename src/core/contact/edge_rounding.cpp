#include "yarn_tearing/core/contact/edge_rounding.hpp"

#include <algorithm>

namespace yarn_tearing {

double contactRounding(const Obstacle& obstacle, double yarn_radius, double segment_length) {
  if (obstacle.shape != ObstacleShape::kBox) return 0.0;
  return std::max(obstacle.edge_radius, kEdgeRoundingChords * segment_length - yarn_radius);
}

}  // namespace yarn_tearing
