#include "yarn_tearing/core/model/vertex_set.hpp"

namespace yarn_tearing {

void VertexSet::add(const Eigen::Vector3d& x, double m, double damping_share,
                    std::uint32_t yarn_index) {
  position.push_back(x);
  velocity.push_back(Eigen::Vector3d::Zero());
  mass.push_back(m);
  damping_length.push_back(damping_share);
  motion.push_back(VertexMotion::kFree);
  applied_force.push_back(Eigen::Vector3d::Zero());
  kinematic_target.push_back(x);
  yarn.push_back(yarn_index);
}

}  // namespace yarn_tearing
