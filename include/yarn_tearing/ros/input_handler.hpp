#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>

#include "yarn_tearing/AppliedForce.h"
#include "yarn_tearing/Grasp.h"
#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/ros/frame_follower.hpp"
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
/// magnitude capped at input_bounds::kMaxForce. A grasped vertex is kinematic: its target at each
/// step is the origin of its target frame at the step's end (FrameTransformer::poseAt(): tf2's
/// interpolation between the frame's samples, extrapolated at most max_extrapolation past the
/// latest; a new sample that disagrees with the extrapolation taken up smoothly, FrameFollower),
/// plus the grasp's own motion, `velocity` for `motion_duration` simulated seconds from
/// the simulated instant the message is taken. A new grasp blends from where the vertex is to its
/// target over the first stepping cycle. Forces and targets past input_bounds.hpp are refused, so
/// a step never sees one.
class InputHandler {
 public:
  /// `frames` must outlive this object.
  explicit InputHandler(const FrameTransformer& frames);

  /// Applies an applied_force message; throws InputRejected (non-finite values, a force past
  /// input_bounds::kMaxForce or kMaxForcePerStrength x the breaking forces of the vertex's edges,
  /// a rate past kMaxForceRate, unknown yarn, vertex out of range, a
  /// duration or ramp duration outside [0, 1e9] s, unresolvable or stale frame), leaving
  /// everything unchanged.
  void handleAppliedForce(const AppliedForce& msg, Simulator& simulator);
  /// Grasps or releases a vertex; throws InputRejected (unknown yarn or vertex, empty or
  /// unresolvable or stale target frame, or one past input_bounds::kMaxDistance; a velocity past
  /// input_bounds::kMaxSpeed, a motion duration outside [0, 1e9] s; releasing a vertex that is not
  /// grasped).
  void handleGrasp(const Grasp& msg, Simulator& simulator);

  /// Before a cycle of steps: looks up how the grasps' frames move (FrameTransformer::motionOf()).
  /// A failing lookup holds each frame where it was at the last step (the grasp's own motion goes
  /// on):
  /// a stale frame (not updated for frame_timeout) is reported once per grasp until it is updated
  /// again, other failures are warned throttled per reason.
  void beginCycle();
  /// Before each step: clears lapsed forces, sets ramped forces to their value at the step's start
  /// and sets each grasped vertex's target for the step's end: its frame at `step_end` (the ROS
  /// time of the step's end) plus the grasp's motion at the step's end in simulated time; a new
  /// grasp is `fraction` (0..1] of the cycle's steps on from where the vertex was.
  void beforeStep(Simulator& simulator, double fraction, const ros::Time& step_end);

  /// True when a grasp's frame moves and `step_end` is past where its samples can be extrapolated
  /// (FrameFollower::outruns()).
  bool outrunsFrames(const ros::Time& step_end) const;

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
    double cap = 0.0;       ///< largest magnitude [N]: the vertex's force bound

    /// Force at simulated time `time` [s] [N], its magnitude capped at `cap`.
    Eigen::Vector3d at(double time) const;
  };

  struct GraspTarget {
    FrameFollower follower;  ///< the tf frame whose origin the vertex follows
    std::string label;       ///< "vertex <i> of yarn '<name>'", for warnings
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< grasp's own motion [m/s], fixed frame
    double motion_start = 0.0;                           ///< simulated time the grasp was taken [s]
    double motion_end = 0.0;  ///< simulated time its own motion stops [s] (inf)
    /// Vertex position minus frame origin when grasped [m]; blended away over the first cycle.
    Eigen::Vector3d start_offset = Eigen::Vector3d::Zero();
    Eigen::Vector3d last_target = Eigen::Vector3d::Zero();  ///< of the last step [m]
    bool fresh = true;   ///< grasped since the last cycle began: that cycle blends the offset
    bool stale = false;  ///< its frame's staleness has been reported
  };

  /// Warns that a grasp keeps its last target because its frame lookup failed with `e`.
  void reportHeldTarget(GraspTarget& target, const InputRejected& e);

  const FrameTransformer& frames_;
  std::map<std::uint32_t, ActiveForce> forces_;  ///< vertex -> its force
  /// Per vertex, the largest applied force it takes [N]: input_bounds::kMaxForcePerStrength x
  /// vertexBreakingForces, at most kMaxForce (built at the first force).
  std::vector<double> force_caps_;
  std::map<std::uint32_t, GraspTarget> grasps_;  ///< vertex -> holder
  WarningThrottle target_warnings_;              ///< per RefusalReason
};

}  // namespace ros_layer
}  // namespace yarn_tearing
