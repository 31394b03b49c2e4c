#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace yarn_tearing {

/// Numerical health of one step.
struct StepHealth {
  double max_constraint_violation = 0.0;  ///< max (length - limit) / limit after projection [-]
  int projection_iterations = 0;          ///< Newton steps or sweeps used
  /// Newton systems factorized; the others were solved with the last factors [-].
  int factorizations = 0;
  /// Symbolic analyses of those systems' factors, each for a pattern the last factorization did
  /// not have (the taut edges, the eliminated vertices or the contacts changed) [-].
  int analyses = 0;
  bool projection_converged = true;  ///< violation and force mismatch within tolerance
  /// Largest distance [-, per edge length] between a vertex's correction and the one the final
  /// constraint forces along the final edge directions give (ProjectionResult::force_mismatch).
  double force_mismatch = 0.0;
  /// Largest penetration of a yarn into an obstacle after the projection, relative to the
  /// touching edge's length [-] (ProjectionResult::max_penetration).
  double max_penetration = 0.0;
  double tension_residual = 0.0;  ///< |A T - b| / |b| of the tension least squares [-]
  int breaks = 0;                 ///< edges torn in this step
  /// Yarns (scene indices) this step left with a non-finite value, restored to their initial
  /// state (Simulator::step); empty in a healthy step.
  std::vector<std::uint32_t> restored_yarns;
  /// Substeps the step was taken in [-]: 1; after a tear, the fine substeps of the unloading plus
  /// those growing to the step's end, or the explicit substeps of a local recoil's wave
  /// (integrateRecoilWave()); the retry's substeps when the whole step's projection did not
  /// converge (recoil_substeps of them with obstacles; the other fields are then the worst
  /// substep's, breaks and restored_yarns their union).
  int substeps = 1;
  /// Vertices those substeps moved [-]: the scene's, or a local recoil's region
  /// (SimulationParameters::local_recoil); 0 for a step taken in one.
  std::size_t substepped_vertices = 0;
};

/// Folds one substep's health into the whole step's `whole`: the worst of each measure, the
/// sum of iterations and breaks, the union of restored yarns.
void accumulateHealth(const StepHealth& substep, StepHealth& whole);

}  // namespace yarn_tearing
