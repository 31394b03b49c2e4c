#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>

#include "yarn_tearing/AppliedForce.h"
#include "yarn_tearing/Grasp.h"
#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/ros/frame_transformer.hpp"
#include "yarn_tearing/ros/input_rejected.hpp"
#include "yarn_tearing/ros/warning_throttle.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Applied forces and grasps received on topics: validated, expressed in the fixed frame and
/// handed to the simulator at the right steps.
///
/// Forces act until replaced for the same vertex, or for `duration` simulated seconds when > 0; a
/// zero force with a zero rate clears. A force with a `force_rate` changes at that rate in
/// simulated time (for `ramp_duration` when > 0, then stays), evaluated before each step, its
/// magnitude capped at input_bounds::kMaxForce. A grasped vertex is kinematic and follows the
/// origin of its target frame, looked up once per stepping cycle and interpolated linearly over the
/// cycle's steps. Forces and targets past input_bounds.hpp are refused, so a step never sees one.
class InputHandler {
 public:
  /// `frames` must outlive this object.
  explicit InputHandler(const FrameTransformer& frames);

  /// Applies an applied_force message; throws InputRejected (non-finite values, a force past
  /// input_bounds::kMaxForce or a rate past kMaxForceRate, unknown yarn, vertex out of range, a
  /// duration or ramp duration outside [0, 1e9] s, unresolvable or stale frame), leaving
  /// everything unchanged.
  void handleAppliedForce(const AppliedForce& msg, Simulator& simulator);
  /// Grasps or releases a vertex; throws InputRejected (unknown yarn or vertex, empty or
  /// unresolvable or stale target frame, or one past input_bounds::kMaxDistance; releasing a
  /// vertex that is not grasped).
  void handleGrasp(const Grasp& msg, Simulator& simulator);

  /// Before a cycle of steps: looks up the grasp targets. A failing lookup keeps the last target:
  /// a stale frame (not updated for frame_timeout) is reported once per grasp until it is updated
  /// again, other failures are warned throttled per reason.
  void beginCycle();
  /// Before each step: clears lapsed forces, sets ramped forces to their value at the step's start
  /// and moves grasped vertices `fraction` (0..1] of the way from the previous cycle's target to
  /// this cycle's.
  void beforeStep(Simulator& simulator, double fraction);

  /// Forgets all forces and grasps (the simulator has been reset).
  void clear();
  /// Forgets the forces and grasps on the vertices of yarn `yarn` (restored by the simulator).
  void forgetYarn(const Scene& scene, std::uint32_t yarn);

  std::size_t activeForces() const { return forces_.size(); }
  std::size_t activeGrasps() const { return grasps_.size(); }
  /// Grasped global vertex ids and the tf frame each follows.
  std::map<std::uint32_t, std::string> graspFrames() const;

 private:
  /// A force acting on one vertex, in the fixed frame.
  struct ActiveForce {
    Eigen::Vector3d force;  ///< force at `start` [N]
    Eigen::Vector3d rate;   ///< change per simulated second [N/s]
    double start = 0.0;     ///< simulated time the message was applied [s]
    double ramp_end = 0.0;  ///< simulated time the force stops changing [s] (inf)
    double expiry = 0.0;    ///< simulated time the force lapses [s] (inf)

    /// Force at simulated time `time` [s] [N], capped at input_bounds::kMaxForce.
    Eigen::Vector3d at(double time) const;
  };

  struct GraspTarget {
    std::string frame;     ///< tf frame whose origin the vertex follows
    std::string label;     ///< "vertex <i> of yarn '<name>'", for warnings
    Eigen::Vector3d from;  ///< target at the start of the cycle [m]
    Eigen::Vector3d to;    ///< target at the end of the cycle [m]
    bool fresh = true;     ///< grasped during the last cycle: `from` is the vertex position
    bool stale = false;    ///< its frame's staleness has been reported
  };

  /// Warns that a grasp keeps its last target because its frame lookup failed with `e`.
  void reportHeldTarget(GraspTarget& target, const InputRejected& e);

  const FrameTransformer& frames_;
  std::map<std::uint32_t, ActiveForce> forces_;  ///< vertex -> its force
  std::map<std::uint32_t, GraspTarget> grasps_;  ///< vertex -> holder
  WarningThrottle target_warnings_;              ///< per RefusalReason
};

}  // namespace ros_layer
}  // namespace yarn_tearing
