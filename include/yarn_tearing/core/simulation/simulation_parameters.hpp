#pragma once

#include <Eigen/Core>

namespace yarn_tearing {

/// How the length constraints are enforced (stage 3 of a step).
enum class ProjectionMethod {
  /// Fast projection (Goldenthal et al. 2007): Newton steps on the active constraints with a direct
  /// (banded for chains, sparse LDLT otherwise) solve. Converges at any mass ratio.
  kFastProjection,
  /// Gauss–Seidel sweeps over the edges (Provot / PBD). Cheaper, but does not converge at large
  /// mass ratios; stops after max_projection_iterations sweeps.
  kGaussSeidel,
};

/// How the rows of the tension least squares (stage 4) are weighted.
enum class TensionRowWeighting {
  /// Each free vertex's row is its force balance [N]: m (v'' - v) / dt - F - sum_e T_e u_ev.
  /// Every vertex counts alike whatever its mass, so a heavy weight on a light yarn still sets
  /// the tension it hangs from.
  kForceBalance,
  /// The paper's rows, velocities [m/s]: the force rows times dt / m. At large mass ratios the
  /// light vertices' rows outweigh the heavy ones' by (M/m)^2 and the estimate degrades.
  kVelocity,
};

/// Where each edge's tension (stage 4) comes from.
enum class TensionSource {
  /// The force of the compliant length constraint (doc/method.md, "Tension from the constraint
  /// force"): the tension of the stiff spring, compliance c = L0 / (E A), at the length the step
  /// ends with. This is the exact solution of the paper's least squares whenever the vertices'
  /// motion determines the tensions, and it stays right where the motion does not: a span
  /// between two holders, whose common tension moves no free vertex.
  kConstraintForce,
  /// The paper's §3.2 estimate: the regularized least squares over the free vertices' motion,
  /// anchored at the constraint force. Ill-posed for a span held at both ends (its common tension
  /// is then set by the vertices' tiny sideways motion).
  kLeastSquares,
};

/// Parameters of the whole simulation, shared by all yarns.
struct SimulationParameters {
  double time_step = 1.0e-3;                                   ///< physics step dt [s]
  Eigen::Vector3d gravity = Eigen::Vector3d(0.0, 0.0, -9.81);  ///< [m/s^2]
  /// Linear air damping c [N*s/m^2]: each vertex feels -c * (its share of yarn length) * velocity.
  double air_damping = 0.0;
  /// Dimensionless stiffness of the soft (non-stiff) springs: each edge's spring constant is
  /// ratio * m_min / dt^2 [N/m], m_min the lighter free vertex; stable for ratio < 1.
  double soft_spring_ratio = 0.05;
  /// Regularization lambda of the tension least squares [-], relative to the diagonal of the
  /// normal matrix (so it is independent of units and masses); paper §3.2 uses 1e-6.
  double regularization = 1.0e-6;
  /// Largest relative violation (|x_i - x_j| - limit) / limit accepted by the projection [-].
  double constraint_tolerance = 1.0e-6;
  int max_projection_iterations = 50;  ///< Newton steps (or Gauss–Seidel sweeps) per step
  ProjectionMethod projection_method = ProjectionMethod::kFastProjection;
  TensionSource tension_source = TensionSource::kConstraintForce;  ///< stage 4's tension
  /// Rows of the least squares (with TensionSource::kLeastSquares; its residual is reported in
  /// StepHealth either way).
  TensionRowWeighting tension_rows = TensionRowWeighting::kForceBalance;
  bool breaking_enabled = true;  ///< false: yarns never tear (yield still acts)
  /// Substeps per step while a tear's pieces unload [-] (1 = none): the released elastic energy
  /// runs through the pieces as a wave at sqrt(E / rho) (~2 km/s), far faster than a step
  /// resolves, so the step after a tear is taken in substeps of dt / recoil_substeps until the
  /// wave has crossed the torn pieces, the rest of it in one; a step whose projection does not
  /// converge is taken again in substeps no finer than dt / recoil_substeps (Simulator::step(),
  /// doc/method.md "Substeps for an unconverged step"). A fabric's tear whose release
  /// unloads the torn yarn's loaded run within two such substeps (a tear tip the crossing yarns
  /// hold) is followed by a whole step (substep_every_recoil).
  int recoil_substeps = 96;
  /// Substep the step after every fabric's tear, also where its release unloads the torn yarn's
  /// loaded run within two substeps (Simulator; for comparing the two).
  bool substep_every_recoil = false;
  /// Take only the neighbourhood of a yarn's tear (RecoilRegion: the yarn within the elastic
  /// wave's reach over the step, c dt of rest length, and a margin) through the step after it, as
  /// the release wave (integrateRecoilWave()), the rest of the scene in one step with the region's
  /// boundary moving on as it did; false substeps the whole scene. A tear in a fabric, a scene
  /// with obstacles, a region of most of the scene, an edge drawn to its breaking length within
  /// the wave, or a further tear or unconverged projection in the step take the whole scene's
  /// step either way.
  bool local_recoil = true;
  /// Use the general sparse solver even for chains (the banded O(N) path is otherwise chosen).
  bool force_general_solver = false;
  /// Solve the edge systems of graphs that are no chains by the sparse LDL^T only, never by
  /// conjugate gradients (EdgeGramSolver; for comparing the two).
  bool force_direct_solves = false;
  /// Newton steps solve the whole system, never eliminating the vertices no edge stiffens
  /// (StiffNewtonStep; for comparing the two).
  bool force_full_newton_systems = false;
  /// Newton steps factorize every system, never solving one by refinement with the last
  /// factorization of the same layout (StiffNewtonStep; for comparing the two).
  bool force_fresh_factorizations = false;
  /// Threads a large sparse factorization may use [-] (>= 1; it uses at most 2): the
  /// supernodal kernel's factorizations (fabrics of some 32 x 32 vertices up, while taut) then
  /// eliminate disjoint parts of the system on a second thread. Results do not depend on it.
  int threads = 1;

  /// Throws std::invalid_argument naming the parameter and the allowed range.
  void validate() const;
};

}  // namespace yarn_tearing
