#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"

namespace yarn_tearing {

/// What integrateRecoilWave() did.
struct RecoilWaveResult {
  /// False when an edge reached its breaking strain within the step: the scene is then left
  /// part-way and the step has to be taken otherwise.
  bool completed = false;
  int substeps = 0;  ///< explicit substeps taken [-]
};

/// The acceleration [m/s^2] each free vertex of `scene` starts its step with under gravity,
/// the applied forces, air damping and its intact edges as integrateRecoilWave()'s springs; zero
/// at pinned and kinematic vertices.
std::vector<Eigen::Vector3d> startAccelerations(const SimulationParameters& parameters,
                                                const Scene& scene);

/// Advances a yarn-only `scene` (a RecoilRegion's sub-scene) by `duration` [s] with its edges as
/// the material's elastic springs (doc/method.md, "Recoil wave"): tension-only, T = k (l - L),
/// k = E A f / L0 (f the edge's rate factor) and L its plastic rest length, the law the material
/// update reads lengths by. Free vertices move by symplectic Euler under gravity, applied forces,
/// air damping and those springs, in substeps of 0.97 of the explicit stability limit (the last
/// one what remains of `duration`); until
/// `arrival` [s from the step's start, per vertex; infinite: never] a free vertex moves on its
/// unaffected path x0 + v0 t + a0 t^2 / 2 (a0 = `start_acceleration` [m/s^2]), pinned vertices
/// stay and kinematic ones move linearly to their targets. An edge held at its breaking length
/// when the step begins is held there (an inelastic stop) until the wave unloads it.
/// `tension` [N] receives each edge's tension at the end (0 for torn edges).
RecoilWaveResult integrateRecoilWave(const SimulationParameters& parameters,
                                     const std::vector<double>& arrival,
                                     const std::vector<Eigen::Vector3d>& start_acceleration,
                                     double duration, Scene& scene, std::vector<double>& tension);

}  // namespace yarn_tearing
