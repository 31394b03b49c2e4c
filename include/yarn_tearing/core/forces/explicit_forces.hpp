#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/model/vertex_set.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"

namespace yarn_tearing {

/// The forces on each vertex [N] into `force` (sized to the vertices) that no edge exerts: gravity
/// m g, the applied force and linear air damping -c l v (c = air_damping [N s/m^2], l the
/// vertex's share of yarn length [m]).
void accumulateExternalForces(const SimulationParameters& parameters, const VertexSet& vertices,
                              std::vector<Eigen::Vector3d>& force);

/// Stage 1: the non-constraint force on each vertex [N] into `force` (sized to the vertices):
/// gravity m g, the applied force, linear air damping -c l v (c = air_damping [N s/m^2], l the
/// vertex's share of yarn length [m]) and the tension-only soft springs along the intact edges,
/// `spring_constant` [N/m] per edge (EdgeStretchLimits::soft_spring). Writes each edge's spring
/// tension [N] (0 when slack or broken) to edges.spring_tension.
void accumulateExplicitForces(const SimulationParameters& parameters, const VertexSet& vertices,
                              const std::vector<double>& spring_constant, EdgeSet& edges,
                              std::vector<Eigen::Vector3d>& force);

/// Stage 2: symplectic Euler over one time step. Free vertices take v += dt F / m, x += dt v;
/// pinned ones stay at rest; kinematic ones jump to their target with the velocity that takes
/// them there [m/s].
void predictPositions(const std::vector<Eigen::Vector3d>& force, double time_step,
                      VertexSet& vertices);

}  // namespace yarn_tearing
