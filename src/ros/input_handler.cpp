#include "yarn_tearing/ros/input_handler.hpp"

#include <ros/console.h>
#include <ros/time.h>

#include <cmath>
#include <limits>

#include "yarn_tearing/ros/clipped_text.hpp"
#include "yarn_tearing/ros/geometry_conversion.hpp"
#include "yarn_tearing/ros/input_bounds.hpp"
#include "yarn_tearing/ros/input_rejected.hpp"
#include "yarn_tearing/ros/vertex_lookup.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kWarnPeriod = 2.0;  ///< [s] between repeated warnings of one reason

}  // namespace

InputHandler::InputHandler(const FrameTransformer& frames)
    : frames_(frames),
      target_warnings_(kWarnPeriod, static_cast<std::size_t>(RefusalReason::kCount)) {}

void InputHandler::handleAppliedForce(const AppliedForce& msg, Simulator& simulator) {
  requireBoundedVector(toEigen(msg.force), input_bounds::kMaxForce, "force", "N");
  if (!std::isfinite(msg.duration)) {
    throw InputRejected(RefusalReason::kNotFinite, "duration is not finite");
  }
  if (msg.duration < 0.0 || msg.duration > input_bounds::kMaxDuration) {
    throw InputRejected(RefusalReason::kOutOfBounds,
                        "duration " + std::to_string(msg.duration) +
                            " s is invalid (allowed: [0, 1e9] s, 0 = until replaced)");
  }
  const std::uint32_t vertex = lookupVertex(simulator.scene(), msg.yarn, msg.vertex);
  const Eigen::Vector3d fixed =
      frames_.rotateToFixedFrame(toEigen(msg.force), msg.header.frame_id, msg.header.stamp);
  simulator.setAppliedForce(vertex, fixed);
  if (fixed.isZero(0.0)) {
    force_expiry_.erase(vertex);
  } else {
    force_expiry_[vertex] = msg.duration > 0.0 ? simulator.time() + msg.duration
                                               : std::numeric_limits<double>::infinity();
  }
}

void InputHandler::handleGrasp(const Grasp& msg, Simulator& simulator) {
  const std::uint32_t vertex = lookupVertex(simulator.scene(), msg.yarn, msg.vertex);
  if (msg.release) {
    if (grasps_.erase(vertex) == 0) {
      throw InputRejected(RefusalReason::kNotGrasped,
                          "vertex " + std::to_string(msg.vertex) + " is not grasped");
    }
    simulator.releaseVertex(vertex);
    return;
  }
  if (msg.target_frame.empty()) {
    throw InputRejected(RefusalReason::kUnknownFrame, "target_frame is empty");
  }
  GraspTarget target;
  target.frame = msg.target_frame;
  target.label = "vertex " + std::to_string(msg.vertex) + " of '" + clipped(msg.yarn) + "'";
  target.to = frames_.originInFixedFrame(msg.target_frame);
  const auto existing = grasps_.find(vertex);
  const Eigen::Vector3d& position = simulator.scene().vertices.position[vertex];
  if (existing != grasps_.end()) {
    target.from = existing->second.to;
  } else if (position.norm() <= input_bounds::kMaxDistance) {
    target.from = position;
  } else {
    target.from = target.to;  // a fragment flown far away jumps, the interpolation stays bounded
  }
  grasps_[vertex] = target;
}

void InputHandler::beginCycle() {
  for (auto& entry : grasps_) {
    GraspTarget& target = entry.second;
    if (target.fresh) {
      target.fresh = false;
      continue;
    }
    target.from = target.to;
    try {
      target.to = frames_.originInFixedFrame(target.frame);
      if (target.stale) {
        ROS_INFO("grasp of %s: frame '%s' is updated again", target.label.c_str(),
                 target.frame.c_str());
        target.stale = false;
      }
    } catch (const InputRejected& e) {
      reportHeldTarget(target, e);
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

void InputHandler::beforeStep(Simulator& simulator, double fraction) {
  for (auto it = force_expiry_.begin(); it != force_expiry_.end();) {
    if (simulator.time() >= it->second) {
      simulator.setAppliedForce(it->first, Eigen::Vector3d::Zero());
      it = force_expiry_.erase(it);
    } else {
      ++it;
    }
  }
  for (const auto& [vertex, target] : grasps_) {
    simulator.setKinematicTarget(vertex, target.from + fraction * (target.to - target.from));
  }
}

std::map<std::uint32_t, std::string> InputHandler::graspFrames() const {
  std::map<std::uint32_t, std::string> frames;
  for (const auto& [vertex, target] : grasps_) {
    frames.emplace(vertex, target.frame);
  }
  return frames;
}

void InputHandler::clear() {
  force_expiry_.clear();
  grasps_.clear();
}

void InputHandler::forgetYarn(const Scene& scene, std::uint32_t yarn) {
  const auto of_yarn = [&](std::uint32_t vertex) { return scene.vertices.yarn[vertex] == yarn; };
  for (auto it = force_expiry_.begin(); it != force_expiry_.end();) {
    it = of_yarn(it->first) ? force_expiry_.erase(it) : std::next(it);
  }
  for (auto it = grasps_.begin(); it != grasps_.end();) {
    it = of_yarn(it->first) ? grasps_.erase(it) : std::next(it);
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
