#include "yarn_tearing/core/simulation/step_health.hpp"

#include <algorithm>

namespace yarn_tearing {

void accumulateHealth(const StepHealth& substep, StepHealth& whole) {
  whole.max_constraint_violation =
      std::max(whole.max_constraint_violation, substep.max_constraint_violation);
  whole.projection_iterations += substep.projection_iterations;
  whole.factorizations += substep.factorizations;
  whole.analyses += substep.analyses;
  whole.projection_converged = whole.projection_converged && substep.projection_converged;
  whole.force_mismatch = std::max(whole.force_mismatch, substep.force_mismatch);
  whole.max_penetration = std::max(whole.max_penetration, substep.max_penetration);
  whole.tension_residual = std::max(whole.tension_residual, substep.tension_residual);
  whole.breaks += substep.breaks;
  whole.restored_yarns.insert(whole.restored_yarns.end(), substep.restored_yarns.begin(),
                              substep.restored_yarns.end());
}

}  // namespace yarn_tearing
