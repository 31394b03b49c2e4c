#pragma once

#include <ros/time.h>

#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/ros/frame_follower.hpp"
#include "yarn_tearing/ros/frame_transformer.hpp"
#include "yarn_tearing/ros/input_rejected.hpp"
#include "yarn_tearing/ros/obstacle_spec_loader.hpp"
#include "yarn_tearing/ros/warning_throttle.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// The obstacles of ~obstacles in the simulator. A fixed one is there from the start. One attached
/// to a tf frame joins the simulator in the first stepping cycle its frame resolves and then
/// follows it as grasp targets do: how the frame moves is looked up once per cycle
/// (FrameTransformer::motionOf()) and the obstacle put, before each step, where the frame is at
/// the step's end (FrameTransformer::poseAt(): interpolated between the frame's tf samples,
/// extrapolated at most max_extrapolation past the latest; FrameFollower). A lookup that fails
/// (unknown, unresolvable or stale frame, an origin past input_bounds::kMaxDistance), and a pose
/// through a yarn (ObstacleThroughYarn: a frame jumping into the fabric), holds the obstacle
/// where it was at the last step (or keeps it out of the simulator until its frame is clear),
/// warned throttled per reason; nothing here throws into the step loop.
class ObstacleTracker {
 public:
  /// `frames` must outlive this object. Gives `simulator` the fixed obstacles of `specs`; throws
  /// std::invalid_argument starting "obstacles: " when one lies through a yarn.
  ObstacleTracker(const FrameTransformer& frames, std::vector<ObstacleSpec> specs,
                  Simulator& simulator);

  /// Before a cycle of steps: looks up the attached obstacles' frames; those resolved for the
  /// first time join the simulator.
  void beginCycle(Simulator& simulator);
  /// Before each step: moves each attached obstacle towards where its frame is at `step_end` (the
  /// ROS time of the step's end), at most obstacleStepLimit() a step (limitedObstacleMove).
  void beforeStep(Simulator& simulator, const ros::Time& step_end);

  /// True when an attached obstacle's frame moves and `step_end` is past where its samples can be
  /// extrapolated (FrameFollower::outruns()).
  bool outrunsFrames(const ros::Time& step_end) const;

  /// Number of obstacles of ~obstacles.
  std::size_t size() const { return tracked_.size(); }
  /// Obstacle `i` of ~obstacles as configured (its pose: the fixed pose, or the offset's frame).
  const ObstacleSpec& spec(std::size_t i) const { return tracked_.at(i).spec; }
  /// Index of obstacle `i` of ~obstacles in the simulator's obstacles(), or none while an
  /// attached obstacle's frame has never resolved.
  std::optional<std::size_t> simulatorIndex(std::size_t i) const;

 private:
  struct Tracked {
    ObstacleSpec spec;
    FrameFollower follower;  ///< its tf frame (attached ones)
    int index = -1;          ///< in the simulator's obstacles(); -1 = not (yet) there
    bool placed = false;     ///< fixed, or attached and its frame resolved at least once
    bool lost = false;       ///< its last lookup failed (logged when it resolves again)
  };

  /// The tracked obstacle of that name (one exists: the simulator's obstacles are ours).
  Tracked& byName(const std::string& name);
  /// Looks up where attached obstacle `tracked` is now; false (warned) when it cannot be found.
  bool lookUp(Tracked& tracked);
  /// Warns, throttled per reason, that `tracked`'s frame lookup failed with `e`.
  void warnLookupFailed(Tracked& tracked, const InputRejected& e);
  /// Gives the simulator every obstacle that is placed (fixed, or attached and resolved once).
  void placeInSimulator(Simulator& simulator);

  const FrameTransformer& frames_;
  double max_step_travel_;        ///< [m] an attached obstacle's longest move in one step
  std::vector<Tracked> tracked_;  ///< in ~obstacles order
  WarningThrottle warnings_;      ///< per RefusalReason
};

}  // namespace ros_layer
}  // namespace yarn_tearing
