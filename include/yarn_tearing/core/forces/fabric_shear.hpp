#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"

namespace yarn_tearing {

/// Stage 1 (fabrics): adds each fabric cell's in-plane shear force [N] to `force`. A cell whose
/// four segments are intact pulls and pushes along both diagonals with k (l - l_rest), k = min(G,
/// stabilitySpringConstant of the diagonal's ends) [N/m] (G = Fabric::shear_rigidity): soft and
/// explicit, so it never over-constrains the length constraints, and a cell with a cut segment
/// exerts nothing, so no shear element holds two torn pieces together. Returns the number of
/// cells acting.
std::size_t accumulateShearForces(const Scene& scene, const SimulationParameters& parameters,
                                  std::vector<Eigen::Vector3d>& force);

}  // namespace yarn_tearing
