#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/edge_gram_solver.hpp"
#include "yarn_tearing/core/edge_set.hpp"
#include "yarn_tearing/core/simulation_parameters.hpp"
#include "yarn_tearing/core/vertex_set.hpp"

namespace yarn_tearing {

/// Outcome of one projection.
struct ProjectionResult {
  int iterations = 0;            ///< Newton steps or Gauss–Seidel sweeps
  double max_violation = 0.0;    ///< max (length - limit) / limit over intact edges [-]
  bool converged = false;        ///< max_violation <= tolerance
};

/// Stage 3: limits every intact edge to |x_a - x_b| <= rest_length (1 + strain_limit), stretch
/// only, by a mass-weighted projection of the predicted positions (Goldenthal et al. 2007).
/// Edges whose vertices are all pinned or kinematic cannot be corrected and are not counted.
class LengthConstraintProjection {
 public:
  /// Projects `position` in place; masses and supports come from `vertices`.
  ProjectionResult project(std::vector<Eigen::Vector3d>& position, const VertexSet& vertices,
                           const EdgeSet& edges, const SimulationParameters& parameters,
                           EdgeGramSolver& gram);

 private:
  /// Fills directions, violations and the active set; returns the max relative violation.
  double evaluate(const std::vector<Eigen::Vector3d>& position, const EdgeSet& edges);
  ProjectionResult projectFast(std::vector<Eigen::Vector3d>& position, const EdgeSet& edges,
                               const SimulationParameters& parameters, EdgeGramSolver& gram);
  ProjectionResult projectGaussSeidel(std::vector<Eigen::Vector3d>& position,
                                      const EdgeSet& edges,
                                      const SimulationParameters& parameters);

  std::vector<double> inverse_mass_;            ///< [1/kg]
  std::vector<Eigen::Vector3d> direction_;      ///< unit edge directions
  std::vector<double> violation_;               ///< length - limit [m]
  std::vector<double> multiplier_;              ///< accumulated Newton multipliers [kg*m]
  std::vector<double> step_;                    ///< Newton step of the multipliers [kg*m]
  std::vector<std::uint8_t> active_;            ///< edges in the active set
};

}  // namespace yarn_tearing
