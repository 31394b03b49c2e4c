#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/contact/contact_set.hpp"
#include "yarn_tearing/core/projection/edge_gram_solver.hpp"
#include "yarn_tearing/core/projection/edge_stretch_limits.hpp"
#include "yarn_tearing/core/projection/length_constraint_projection.hpp"
#include "yarn_tearing/core/projection/tension_estimator.hpp"
#include "yarn_tearing/core/tearing/tearing.hpp"

namespace yarn_tearing {

/// The stage objects and scratch arrays that every step reuses, so a step does not allocate
/// after the first one.
struct StepWorkspace {
  std::vector<Eigen::Vector3d> force;           ///< non-constraint force per vertex [N]
  std::vector<Eigen::Vector3d> start_position;  ///< x at the start of the step [m]
  std::vector<Eigen::Vector3d> start_velocity;  ///< v at the start of the step [m/s]
  EdgeStretchLimits stretch_limits;             ///< compliance and largest stretch per edge
  std::vector<double> constraint_tension;       ///< constraint part of the tension [N]
  EdgeGramSolver gram;                          ///< J W J^T solver shared by stages 3 and 4
  LengthConstraintProjection projection;        ///< stage 3
  ContactSet contacts;                          ///< stage 3's contacts with obstacles
  std::vector<double> vertex_radius;            ///< yarn radius at each vertex [m]
  TensionEstimator estimator;                   ///< stage 4
  Tearing tearing;                              ///< stage 6
};

}  // namespace yarn_tearing
