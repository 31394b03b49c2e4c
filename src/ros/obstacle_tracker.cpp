#include "yarn_tearing/ros/obstacle_tracker.hpp"

#include <ros/console.h>
#include <ros/time.h>

#include <stdexcept>

#include "yarn_tearing/ros/input_bounds.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kWarnPeriod = 2.0;  ///< [s] between repeated warnings of one reason

/// The pose `fraction` (0..1) of the way from `from` to `to`: position linear, rotation slerp.
Eigen::Isometry3d interpolate(const Eigen::Isometry3d& from, const Eigen::Isometry3d& to,
                              double fraction) {
  const Eigen::Quaterniond a(from.linear());
  const Eigen::Quaterniond b(to.linear());
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = a.slerp(fraction, b).normalized().toRotationMatrix();
  pose.translation() = from.translation() + fraction * (to.translation() - from.translation());
  return pose;
}

}  // namespace

ObstacleTracker::ObstacleTracker(const FrameTransformer& frames, std::vector<ObstacleSpec> specs,
                                 Simulator& simulator)
    : frames_(frames), warnings_(kWarnPeriod, static_cast<std::size_t>(RefusalReason::kCount)) {
  for (ObstacleSpec& spec : specs) {
    Tracked tracked;
    tracked.to = tracked.from = spec.obstacle.pose;
    tracked.placed = !spec.attached();
    tracked.spec = std::move(spec);
    tracked_.push_back(std::move(tracked));
  }
  placeInSimulator(simulator);
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
    tracked.from = tracked.to;
    if (lookUp(tracked) && !tracked.placed) {
      tracked.from = tracked.to;
      tracked.placed = true;
      joined = true;
    }
  }
  if (joined) placeInSimulator(simulator);
}

bool ObstacleTracker::lookUp(Tracked& tracked) {
  try {
    const Eigen::Isometry3d pose =
        frames_.poseInFixedFrame(tracked.spec.attached_frame) * tracked.spec.offset;
    requireBoundedVector(pose.translation(), input_bounds::kMaxDistance,
                         "obstacle '" + tracked.spec.obstacle.name + "' (frame + offset)", "m");
    Obstacle moved = tracked.spec.obstacle;
    moved.pose = pose;
    try {
      moved.validate();
    } catch (const std::invalid_argument& invalid) {
      throw InputRejected(RefusalReason::kOutOfBounds, invalid.what());
    }
    tracked.to = pose;
  } catch (const InputRejected& e) {
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
    placed.back().pose = tracked.to;
  }
  simulator.setObstacles(placed);  // every pose was validated (lookUp) or loaded valid
}

void ObstacleTracker::beforeStep(Simulator& simulator, double fraction) {
  for (const Tracked& tracked : tracked_) {
    if (!tracked.spec.attached() || !tracked.placed) continue;
    try {
      simulator.setObstaclePose(static_cast<std::size_t>(tracked.index),
                                interpolate(tracked.from, tracked.to, fraction));
    } catch (const std::exception& e) {  // bounded, finite poses only: not expected
      ROS_ERROR_THROTTLE(kWarnPeriod, "obstacle '%s' not moved: %s",
                         tracked.spec.obstacle.name.c_str(), e.what());
    }
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
