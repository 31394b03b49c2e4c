#pragma once

#include <Eigen/Core>
#include <vector>

#include "yarn_tearing/core/contact/obstacle.hpp"
#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/simulation/recoil_region.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"
#include "yarn_tearing/core/simulation/step_health.hpp"
#include "yarn_tearing/core/simulation/step_workspace.hpp"
#include "yarn_tearing/core/tearing/tear_event.hpp"

namespace yarn_tearing {

/// Total force [N] and torque about the obstacle's origin [N m] that the yarns exert on an
/// obstacle through its contacts in the last step (world frame).
struct ContactWrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< [N]
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();  ///< [N m]
};

/// Simulates tearable, length-constrained yarns (the paper's method). Deterministic: the same
/// inputs give bitwise the same outputs. Not thread-safe; one thread drives it.
class Simulator {
 public:
  /// Throws std::invalid_argument (naming the parameter) on invalid parameters, yarn or fabric
  /// specs. Yarns come first in the scene, then fabrics (buildScene()).
  Simulator(const SimulationParameters& parameters, const std::vector<YarnSpec>& yarns,
            const std::vector<FabricSpec>& fabrics = {});
  /// Simulates a ready-made scene: any edge graph (a woven patch, a knot), not only straight
  /// yarns. Throws std::invalid_argument when an edge names a missing vertex or yarn, or a mass,
  /// length or area is not positive.
  Simulator(const SimulationParameters& parameters, Scene scene);

  /// Advances the simulation by parameters().time_step. The stages, in order:
  /// 1 accumulate forces, 2 predict (symplectic Euler), 3 project length constraints,
  /// 4 estimate tensions, 5 update material (strain limit, yield), 6 tear (collected, then
  /// applied). A step that leaves a non-finite value in a yarn (inputs past every documented
  /// bound) restores that yarn to its initial state (restoreYarn(): untorn, at rest, its forces
  /// and grasps cleared), drops that yarn's events of this step, and lists it in
  /// lastHealth().restored_yarns; the other yarns go on.
  void step();
  /// True when the next step() resolves the recoil of a tear in substeps of Δt / recoil_substeps
  /// while the torn pieces unload (the rest of that step in one). A step whose projection does
  /// not converge is taken again in substeps (a sudden load far beyond what one step can take
  /// back; advanceInSubsteps(); lastHealth().substeps says so).
  bool recoilPending() const { return recoil_pending_; }

  /// Replaces the parameters between steps (live tuning: air damping, regularization, breaking
  /// enabled, ...); the next step uses them. Throws std::invalid_argument like the constructor and
  /// then keeps the old ones.
  void setParameters(const SimulationParameters& parameters);

  /// Back to the initial scene and time 0; applied forces, grasps and pending events cleared.
  void reset();

  /// Sets the external force on a vertex (global id) [N]; replaces the previous one.
  void setAppliedForce(std::uint32_t vertex, const Eigen::Vector3d& force);
  /// Makes a vertex kinematic: from the next step it moves to `target` [m] (global id), by at
  /// most its yarn's snap-back speed c * eps_b per step (held_target_limit.hpp).
  void setKinematicTarget(std::uint32_t vertex, const Eigen::Vector3d& target);
  /// Sets the velocity of a free vertex [m/s] (initial conditions; global id).
  void setVelocity(std::uint32_t vertex, const Eigen::Vector3d& velocity);
  /// Frees a kinematic vertex (or restores the pin of an initially pinned one).
  void releaseVertex(std::uint32_t vertex);

  /// Replaces the obstacles the yarns touch (kept through reset()). Throws
  /// std::invalid_argument naming the obstacle and field when one is invalid, or
  /// ObstacleThroughYarn naming the obstacle and the yarn when one not already in place (same
  /// geometry as a current one) lies through a yarn deeper than half a segment (findDeepOverlap,
  /// deep_overlap.hpp); the old ones then stay.
  /// When the new ones are the same solids at the same poses (Obstacle::sameGeometry, in the same
  /// order; only friction or names changed), the contacts keep their friction states.
  void setObstacles(const std::vector<Obstacle>& obstacles);
  /// Moves obstacle `index` to `pose` for the next step (a robot link, a finger); points that
  /// stick to it are carried along. Throws std::out_of_range / std::invalid_argument (non-finite,
  /// farther than 1e4 m; ObstacleThroughYarn through a yarn as setObstacles); the
  /// obstacle then stays where it was.
  void setObstaclePose(std::size_t index, const Eigen::Isometry3d& pose);
  const std::vector<Obstacle>& obstacles() const { return obstacles_; }
  /// What the yarns exerted on obstacle `index` in the last step (zero while untouched).
  ContactWrench contactWrench(std::size_t index) const { return contact_wrench_.at(index); }
  /// The contacts of the last step, with their impulses (force dt^2 [kg m]).
  const ContactSet& contacts() const { return work_.contacts; }

  /// Break events since the last call, in the order they happened; each is returned once.
  std::vector<TearEvent> takeTearEvents();

  /// Force the yarn (or fabric) exerts on the holder of a pinned or kinematic vertex [N] (zero if
  /// free).
  Eigen::Vector3d supportForce(std::uint32_t vertex) const { return support_force_[vertex]; }

  const Scene& scene() const { return scene_; }
  const SimulationParameters& parameters() const { return parameters_; }
  const StepHealth& lastHealth() const { return health_; }
  double time() const { return time_; }  ///< simulated time [s]
  std::uint64_t stepCount() const { return step_count_; }

 private:
  /// Throws ObstacleThroughYarn when `obstacle` lies through a yarn deeper than a step's
  /// contact resolves (findDeepOverlap).
  void requireClearOfYarns(const Obstacle& obstacle) const;
  /// Stages 1-6 over parameters_.time_step; advances time_. With `undo_if_unconverged`, a
  /// projection that does not converge undoes the step instead (undoPrediction()) and returns
  /// false (stages 4-6 not run, time_ unchanged).
  bool advance(bool undo_if_unconverged);
  /// Puts the vertices back where the step started and forgets the solvers' warm starts.
  void undoPrediction();
  /// One step of `time_step` in substeps (the fine ones time_step / recoil_substeps), kinematic
  /// vertices moved linearly to their targets; lastHealth() is the worst of the substeps'. With
  /// `recoil` (the step after a tear) only while a torn piece is still unloading
  /// (Tearing::unloadingEnd()); the rest of the step is then taken in substeps growing in length,
  /// or in fine substeps again if one of those does not converge (doc/method.md, "Recoil
  /// substeps"). Without `recoil` (an unconverged step) and without obstacles, in substeps from a
  /// quarter of the step, each that does not converge retried at a quarter of itself, each that
  /// does followed by one up to twice as long (doc/method.md, "Substeps for an unconverged step").
  void advanceInSubsteps(bool recoil);
  /// The step after the tears of `torn` (global edge ids) with only their RecoilRegion taken
  /// through the release wave, the rest of the scene in one step with the region's boundary
  /// vertices moving on their unaffected paths (stepAroundRegion(), propagateRecoilWave()).
  /// Returns false, with nothing changed, when the whole scene has to be substepped instead
  /// (SimulationParameters::local_recoil).
  bool recoilLocally(const std::vector<std::uint32_t>& torn);
  /// False when every tear of `torn` (global edge ids) is in a fabric and its release wave
  /// unloads the torn yarn's loaded run (releaseCrossingTime()) within kResolvedReleaseSubsteps
  /// fine substeps: the step after the tear is then taken whole, else in recoil substeps.
  bool releaseResolvedBySubsteps(const std::vector<std::uint32_t>& torn) const;
  /// How far along its yarn a tear of `torn` is substepped `duration` [s] after it [m]: the
  /// elastic wave's travel in the fastest torn material and a margin for the implicit
  /// projection's spread of its front.
  double recoilReach(const std::vector<std::uint32_t>& torn, double duration) const;
  /// The whole scene's step (from `start`, the scene as it began) with the boundary vertices of
  /// `region` held on their unaffectedPosition(); false when it did not converge or tore.
  bool stepAroundRegion(const RecoilRegion& region, const Scene& start,
                        const std::vector<Eigen::Vector3d>& acceleration);
  /// Where vertex `v` of `start` is `elapsed` [s] into the step if the recoil does not reach it
  /// [m]: on at its velocity and start `acceleration` [m/s^2, per vertex], or led (kinematic) or
  /// pinned.
  Eigen::Vector3d unaffectedPosition(const Scene& start,
                                     const std::vector<Eigen::Vector3d>& acceleration,
                                     std::uint32_t v, double elapsed) const;
  /// When each vertex of `region` comes within the recoil's reach of a tear of `torn`
  /// (recoilReach()) [s from the step's start]; infinite at the boundary.
  std::vector<double> waveArrival(const RecoilRegion& region,
                                  const std::vector<std::uint32_t>& torn) const;
  /// Takes `region` from `start` (tearing state `start_tearing`, start accelerations
  /// `acceleration` [m/s^2, per scene vertex]) through the step as the recoil wave
  /// (advanceWave()) and writes it over the step stepAroundRegion() took; false when it tore or
  /// left a non-finite value.
  bool propagateRecoilWave(const RecoilRegion& region, const std::vector<std::uint32_t>& torn,
                           const Scene& start, const std::vector<Eigen::Vector3d>& acceleration,
                           const Tearing& start_tearing);
  /// Stages 1 and 4-6 over parameters_.time_step with stages 2-3 replaced by
  /// integrateRecoilWave() (free vertices on their unaffected paths, from `start_acceleration`
  /// [m/s^2], until `arrival` [s]); false, with the scene part-way, when an edge reached its
  /// breaking strain within the step.
  bool advanceWave(const std::vector<double>& arrival,
                   const std::vector<Eigen::Vector3d>& start_acceleration);
  /// Moves the kinematic vertices' targets to `fraction` [-] of the way from the step's start.
  void setSubstepTargets(double fraction);
  void accumulateForces();
  void predictPositions();
  void projectLengthConstraints();
  void estimateTensions();
  void updateMaterial();
  void tear();
  /// Restores the yarns this step left non-finite; `first_event_of_step` indexes pending_events_.
  void restoreNonFiniteYarns(std::size_t first_event_of_step);
  /// Sizes the scratch arrays for scene_ and forgets the solvers' warm starts.
  void resetWorkspace();
  /// Passes parameters_' solver switches (force_general_solver and the like) to the solvers.
  void applySolverSwitches();

  SimulationParameters parameters_;
  Scene initial_scene_;
  Scene scene_;
  StepWorkspace work_;
  std::vector<Eigen::Vector3d> support_force_;
  std::vector<TearEvent> pending_events_;
  StepHealth health_;
  double time_ = 0.0;
  std::uint64_t step_count_ = 0;
  bool recoil_pending_ = false;                   ///< the last step tore: substep the next one
  std::vector<std::uint32_t> torn_edges_;         ///< edges the last step tore (global ids)
  std::vector<Eigen::Vector3d> step_target_;      ///< kinematic targets of the current step [m]
  std::vector<Eigen::Vector3d> step_start_;       ///< kinematic vertices' start positions [m]
  std::vector<Obstacle> obstacles_;               ///< what the yarns touch
  std::vector<Eigen::Isometry3d> previous_pose_;  ///< each obstacle's pose in the last step
  std::vector<ContactWrench> contact_wrench_;     ///< per obstacle, from the last step
  std::vector<double> inverse_mass_;              ///< per vertex, for contact detection [1/kg]
  /// Adds the contacts' forces to work_.force and sums each obstacle's wrench.
  void applyContactForces();
};

}  // namespace yarn_tearing
