#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/model/yarn_spec.hpp"

namespace yarn_tearing {

/// Ground truth for the tension estimate: the same yarn as a plain mass-spring chain with truly
/// stiff linear springs k = E A / L (E Young's modulus, A the area, L the segment length),
/// tension-only, integrated with symplectic Euler at a time step well inside its stability limit.
/// No strain limiting, no yield, no breaking: the tensions are those that really act.
class StiffReferenceYarn {
 public:
  /// `gravity` [m/s^2]; the step is `stability_fraction` of the explicit limit 2/omega_max.
  StiffReferenceYarn(const YarnSpec& spec, const Eigen::Vector3d& gravity,
                     double stability_fraction = 0.2);

  /// Sets the velocity of a vertex [m/s] (initial conditions).
  void setVelocity(std::size_t vertex, const Eigen::Vector3d& velocity) {
    velocity_[vertex] = velocity;
  }
  /// Changes the gravity [m/s^2] from now on.
  void setGravity(const Eigen::Vector3d& gravity) { gravity_ = gravity; }
  /// Advances by `duration` [s] in internal steps (the last one shortened to land on it).
  void advance(double duration);
  /// Moves the vertices to `positions` [m] (one per vertex), at rest.
  void setPositions(const std::vector<Eigen::Vector3d>& positions);
  /// Cuts edge e (between vertices e and e + 1): it carries no tension from now on.
  void cut(std::size_t e) { cut_[e] = true; }
  /// Kinetic energy of the free vertices [J].
  double kineticEnergy() const;

  const std::vector<Eigen::Vector3d>& positions() const { return position_; }   ///< [m]
  const std::vector<Eigen::Vector3d>& velocities() const { return velocity_; }  ///< [m/s]
  /// Spring tension of edge e [N] at the current positions (>= 0).
  double tension(std::size_t e) const;
  double internalTimeStep() const { return time_step_; }  ///< [s]
  double time() const { return time_; }                   ///< [s]

 private:
  void step(double dt);

  std::vector<Eigen::Vector3d> position_;
  std::vector<Eigen::Vector3d> velocity_;
  std::vector<Eigen::Vector3d> force_;
  std::vector<double> mass_;
  std::vector<bool> pinned_;
  std::vector<bool> cut_;  ///< per edge
  Eigen::Vector3d gravity_;
  double stiffness_ = 0.0;    ///< [N/m]
  double rest_length_ = 0.0;  ///< [m]
  double time_step_ = 0.0;    ///< [s]
  double time_ = 0.0;         ///< [s]
};

}  // namespace yarn_tearing
