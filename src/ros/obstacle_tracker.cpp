#include "yarn_tearing/ros/obstacle_tracker.hpp"

#include <ros/console.h>
#include <ros/time.h>

#include <algorithm>
#include <stdexcept>

#include "yarn_tearing/core/contact/deep_overlap.hpp"
#include "yarn_tearing/ros/input_bounds.hpp"
#include "yarn_tearing/ros/obstacle_move_limit.hpp"

namespace yarn_tearing {
namespace ros_layer {

ObstacleTracker::ObstacleTracker(const FrameTransformer& frames, std::vector<ObstacleSpec> specs,
                                 Simulator& simulator)
    : frames_(frames),
      max_step_travel_(obstacleStepLimit(simulator.scene())),
      warnings_(kWarnPeriod, static_cast<std::size_t>(RefusalReason::kCount)) {
  for (ObstacleSpec& spec : specs) {
    Tracked tracked;
    tracked.follower = FrameFollower(spec.attached_frame, FrameMotion::still(spec.obstacle.pose));
    tracked.placed = !spec.attached();
    tracked.spec = std::move(spec);
    tracked_.push_back(std::move(tracked));
  }
  try {
    placeInSimulator(simulator);
  } catch (const ObstacleThroughYarn& e) {  // a fixed one: the configuration's to change
    throw std::invalid_argument(std::string("obstacles: ") + e.what());
  }
}

std::optional<std::size_t> ObstacleTracker::simulatorIndex(std::size_t i) const {
  const int index = tracked_.at(i).index;
  if (index < 0) return std::nullopt;
  return static_cast<std::size_t>(index);
}

void ObstacleTracker::beginCycle(Simulator& simulator) {
  bool joined = false;
  for (Tracked& tracked : tracked_) {
    if (!tracked.spec.attached()) continue;
    if (lookUp(tracked) && !tracked.placed) {
      tracked.placed = true;
      joined = true;
    }
  }
  if (!joined) return;
  // A joining obstacle whose frame puts it through a yarn waits (warned) until its frame moves
  // it clear; each refusal takes one out, so this ends.
  for (;;) {
    try {
      placeInSimulator(simulator);
      return;
    } catch (const ObstacleThroughYarn& e) {
      Tracked& refused = byName(e.obstacle());
      refused.placed = false;
      warnLookupFailed(refused, InputRejected(RefusalReason::kThroughYarn, e.what()));
    }
  }
}

ObstacleTracker::Tracked& ObstacleTracker::byName(const std::string& name) {
  const auto named = [&name](const Tracked& tracked) { return tracked.spec.obstacle.name == name; };
  return *std::find_if(tracked_.begin(), tracked_.end(), named);  // names are unique (loader)
}

bool ObstacleTracker::lookUp(Tracked& tracked) {
  try {
    const FrameMotion motion = frames_.motionOf(tracked.spec.attached_frame);
    const Eigen::Isometry3d pose = motion.pose * tracked.spec.offset;
    requireBoundedVector(pose.translation(), input_bounds::kMaxDistance,
                         "obstacle '" + tracked.spec.obstacle.name + "' (frame + offset)", "m");
    Obstacle moved = tracked.spec.obstacle;
    moved.pose = pose;
    try {
      moved.validate();
    } catch (const std::invalid_argument& invalid) {
      throw InputRejected(RefusalReason::kOutOfBounds, invalid.what());
    }
    tracked.follower.follow(frames_, motion);
  } catch (const InputRejected& e) {
    tracked.follower.hold();  // where the frame was at the last step
    warnLookupFailed(tracked, e);
    return false;
  }
  if (tracked.lost) {
    ROS_INFO("obstacle '%s' follows frame '%s' (resolved)", tracked.spec.obstacle.name.c_str(),
             tracked.spec.attached_frame.c_str());
    tracked.lost = false;
  }
  return true;
}

void ObstacleTracker::warnLookupFailed(Tracked& tracked, const InputRejected& e) {
  tracked.lost = true;
  const auto key = static_cast<std::size_t>(e.reason());
  if (warnings_.shouldReport(key, ros::WallTime::now().toSec())) {
    ROS_WARN("obstacle '%s' %s (%s; %llu more held back): %s", tracked.spec.obstacle.name.c_str(),
             tracked.placed ? "keeps its last pose" : "waits for its frame", reasonName(e.reason()),
             static_cast<unsigned long long>(warnings_.heldBack(key)), e.what());
  }
}

void ObstacleTracker::placeInSimulator(Simulator& simulator) {
  std::vector<Obstacle> placed;
  for (Tracked& tracked : tracked_) {
    tracked.index = tracked.placed ? static_cast<int>(placed.size()) : -1;
    if (!tracked.placed) continue;
    placed.push_back(tracked.spec.obstacle);
    if (tracked.spec.attached()) placed.back().pose = tracked.follower.pose() * tracked.spec.offset;
  }
  simulator.setObstacles(placed);  // every pose was validated (lookUp) or loaded valid
}

bool ObstacleTracker::outrunsFrames(const ros::Time& step_end) const {
  return std::any_of(tracked_.begin(), tracked_.end(), [&](const Tracked& tracked) {
    return tracked.spec.attached() && tracked.placed && tracked.follower.outruns(frames_, step_end);
  });
}

void ObstacleTracker::beforeStep(Simulator& simulator, const ros::Time& step_end) {
  for (Tracked& tracked : tracked_) {
    if (!tracked.spec.attached() || !tracked.placed) continue;
    const auto index = static_cast<std::size_t>(tracked.index);
    try {
      const Eigen::Isometry3d target =
          tracked.follower.poseAt(frames_, step_end) * tracked.spec.offset;
      simulator.setObstaclePose(
          index, limitedObstacleMove(simulator.obstacles()[index].pose, target, max_step_travel_));
    } catch (const ObstacleThroughYarn& e) {  // a frame jumped into a yarn: it stays where it was
      warnLookupFailed(tracked, InputRejected(RefusalReason::kThroughYarn, e.what()));
    } catch (const std::exception& e) {  // past the core's bounds: an extrapolation run away
      ROS_ERROR_THROTTLE(kWarnPeriod, "obstacle '%s' not moved: %s",
                         tracked.spec.obstacle.name.c_str(), e.what());
    }
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
