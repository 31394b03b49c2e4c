#include "yarn_tearing/ros/input_handler.hpp"

#include <ros/console.h>
#include <ros/time.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "yarn_tearing/ros/clipped_text.hpp"
#include "yarn_tearing/ros/geometry_conversion.hpp"
#include "yarn_tearing/ros/input_bounds.hpp"
#include "yarn_tearing/ros/input_rejected.hpp"
#include "yarn_tearing/ros/vertex_lookup.hpp"
#include "yarn_tearing/ros/vertex_strength.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// Throws InputRejected unless `value` [s] is finite and in [0, input_bounds::kMaxDuration].
void requireDuration(double value, const char* what) {
  if (!std::isfinite(value)) {
    throw InputRejected(RefusalReason::kNotFinite, std::string(what) + " is not finite");
  }
  if (value < 0.0 || value > input_bounds::kMaxDuration) {
    throw InputRejected(RefusalReason::kOutOfBounds,
                        std::string(what) + " " + std::to_string(value) +
                            " s is invalid (allowed: [0, 1e9] s, 0 = until replaced)");
  }
}

/// The simulated time `span` [s] after `start` [s]; a zero span means never (infinity).
double endAfter(double start, double span) {
  return span > 0.0 ? start + span : std::numeric_limits<double>::infinity();
}

}  // namespace

InputHandler::InputHandler(const FrameTransformer& frames)
    : frames_(frames),
      target_warnings_(kWarnPeriod, static_cast<std::size_t>(RefusalReason::kCount)) {}

Eigen::Vector3d InputHandler::ActiveForce::at(double time) const {
  const Eigen::Vector3d value =
      rampedValue(force, rate, start, ramp_end, time, input_bounds::kMaxDuration);
  const double norm = value.norm();
  return norm > cap ? Eigen::Vector3d(value * (cap / norm)) : value;
}

void InputHandler::handleAppliedForce(const AppliedForce& msg, Simulator& simulator) {
  requireBoundedVector(toEigen(msg.force), input_bounds::kMaxForce, "force", "N");
  requireBoundedVector(toEigen(msg.force_rate), input_bounds::kMaxForceRate, "force_rate", "N/s");
  requireDuration(msg.duration, "duration");
  requireDuration(msg.ramp_duration, "ramp_duration");
  const std::uint32_t vertex = lookupVertex(simulator.scene(), msg.yarn, VertexAddress::of(msg));
  if (force_caps_.size() != simulator.scene().vertices.position.size()) {
    force_caps_ = vertexBreakingForces(simulator.scene());
    for (double& cap : force_caps_) {
      cap = std::min(input_bounds::kMaxForcePerStrength * cap, input_bounds::kMaxForce);
    }
  }
  ActiveForce applied;
  applied.cap = force_caps_[vertex];
  requireBoundedVector(
      toEigen(msg.force), applied.cap,
      "force on " + clipped(msg.yarn) + "'s vertex (100 x its segments' breaking forces)", "N");
  applied.force =
      frames_.rotateToFixedFrame(toEigen(msg.force), msg.header.frame_id, msg.header.stamp);
  applied.rate =
      frames_.rotateToFixedFrame(toEigen(msg.force_rate), msg.header.frame_id, msg.header.stamp);
  applied.start = simulator.time();
  applied.ramp_end = endAfter(applied.start, msg.ramp_duration);
  applied.expiry = endAfter(applied.start, msg.duration);
  simulator.setAppliedForce(vertex, applied.force);
  if (applied.force.isZero(0.0) && applied.rate.isZero(0.0)) {
    forces_.erase(vertex);
  } else {
    forces_[vertex] = applied;
  }
}

void InputHandler::handleGrasp(const Grasp& msg, Simulator& simulator) {
  const std::uint32_t vertex = lookupVertex(simulator.scene(), msg.yarn, VertexAddress::of(msg));
  if (msg.release) {
    if (grasps_.erase(vertex) == 0) {
      throw InputRejected(RefusalReason::kNotGrasped, VertexAddress::of(msg).describe() + " of '" +
                                                          clipped(msg.yarn) + "' is not grasped");
    }
    simulator.releaseVertex(vertex);
    return;
  }
  if (msg.target_frame.empty()) {
    throw InputRejected(RefusalReason::kUnknownFrame, "target_frame is empty");
  }
  requireBoundedVector(toEigen(msg.velocity), input_bounds::kMaxSpeed, "velocity", "m/s");
  requireDuration(msg.motion_duration, "motion_duration");
  GraspTarget target;
  target.label = VertexAddress::of(msg).describe() + " of '" + clipped(msg.yarn) + "'";
  target.follower = FrameFollower(msg.target_frame, frames_.motionOf(msg.target_frame));
  target.velocity =
      frames_.rotateToFixedFrame(toEigen(msg.velocity), msg.header.frame_id, msg.header.stamp);
  target.motion_start = simulator.time();
  target.motion_end = endAfter(target.motion_start, msg.motion_duration);
  const auto existing = grasps_.find(vertex);
  const Eigen::Vector3d& position = simulator.scene().vertices.position[vertex];
  const Eigen::Vector3d frame_origin = target.follower.pose().translation();
  if (existing != grasps_.end()) {
    // a re-grasp starts where the previous target was, the frame's motion then takes over
    target.start_offset = existing->second.last_target - frame_origin;
  } else if (position.norm() <= input_bounds::kMaxDistance) {
    target.start_offset = position - frame_origin;
  }  // else a fragment flown far away jumps, the blend stays bounded
  target.last_target = frame_origin + target.start_offset;
  grasps_[vertex] = target;
}

void InputHandler::beginCycle() {
  for (auto& entry : grasps_) {
    GraspTarget& target = entry.second;
    if (target.fresh) {
      target.fresh = false;  // this cycle blends from where the vertex was
    } else {
      target.start_offset.setZero();
    }
    try {
      target.follower.refresh(frames_);
      if (target.stale) {
        ROS_INFO("grasp of %s: frame '%s' is updated again", target.label.c_str(),
                 target.follower.frame().c_str());
        target.stale = false;
      }
    } catch (const InputRejected& e) {
      reportHeldTarget(target, e);  // the follower stands where the frame was at the last step
    }
  }
}

void InputHandler::reportHeldTarget(GraspTarget& target, const InputRejected& e) {
  if (e.reason() == RefusalReason::kStaleFrame) {
    if (!target.stale) {
      ROS_WARN("grasp of %s holds its last target: %s", target.label.c_str(), e.what());
      target.stale = true;
    }
    return;
  }
  const auto key = static_cast<std::size_t>(e.reason());
  if (target_warnings_.shouldReport(key, ros::WallTime::now().toSec())) {
    ROS_WARN("grasp of %s keeps its last target (%s; %llu more held back): %s",
             target.label.c_str(), reasonName(e.reason()),
             static_cast<unsigned long long>(target_warnings_.heldBack(key)), e.what());
  }
}

void InputHandler::beforeStep(Simulator& simulator, double fraction, const ros::Time& step_end) {
  const double now = simulator.time();
  const double end = now + simulator.parameters().time_step;
  for (auto it = forces_.begin(); it != forces_.end();) {
    if (now >= it->second.expiry) {
      simulator.setAppliedForce(it->first, Eigen::Vector3d::Zero());
      it = forces_.erase(it);
    } else {
      if (!it->second.rate.isZero(0.0)) simulator.setAppliedForce(it->first, it->second.at(now));
      ++it;
    }
  }
  for (auto& [vertex, target] : grasps_) {
    const Eigen::Vector3d scripted =
        rampedValue(Eigen::Vector3d::Zero(), target.velocity, target.motion_start,
                    target.motion_end, end, input_bounds::kMaxDuration);
    Eigen::Vector3d goal = target.follower.poseAt(frames_, step_end).translation() + scripted +
                           (1.0 - fraction) * target.start_offset;
    const double distance = goal.norm();
    if (distance > input_bounds::kMaxDistance) {
      goal *= input_bounds::kMaxDistance / distance;  // a scripted motion run past the bound
    }
    target.last_target = goal;
    simulator.setKinematicTarget(vertex, goal);
  }
}

bool InputHandler::outrunsFrames(const ros::Time& step_end) const {
  return std::any_of(grasps_.begin(), grasps_.end(), [&](const auto& entry) {
    return entry.second.follower.outruns(frames_, step_end);
  });
}

std::map<std::uint32_t, std::string> InputHandler::graspFrames() const {
  std::map<std::uint32_t, std::string> frames;
  for (const auto& [vertex, target] : grasps_) {
    frames.emplace(vertex, target.follower.frame());
  }
  return frames;
}

void InputHandler::clear() {
  forces_.clear();
  grasps_.clear();
}

void InputHandler::forgetYarn(const Scene& scene, std::uint32_t yarn) {
  const auto of_yarn = [&](std::uint32_t vertex) { return scene.vertices.yarn[vertex] == yarn; };
  for (auto it = forces_.begin(); it != forces_.end();) {
    it = of_yarn(it->first) ? forces_.erase(it) : std::next(it);
  }
  for (auto it = grasps_.begin(); it != grasps_.end();) {
    it = of_yarn(it->first) ? grasps_.erase(it) : std::next(it);
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
