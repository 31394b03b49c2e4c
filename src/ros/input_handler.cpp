#include "yarn_tearing/ros/input_handler.hpp"

#include <ros/console.h>

#include <cmath>
#include <limits>

#include "yarn_tearing/ros/geometry_conversion.hpp"
#include "yarn_tearing/ros/input_rejected.hpp"
#include "yarn_tearing/ros/vertex_lookup.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr double kWarnPeriod = 2.0;  ///< [s] between repeated warnings

}  // namespace

InputHandler::InputHandler(const FrameTransformer& frames) : frames_(frames) {}

void InputHandler::handleAppliedForce(const AppliedForce& msg, Simulator& simulator) {
  const Eigen::Vector3d force = toEigen(msg.force);
  if (!force.allFinite()) {
    throw InputRejected("force is not finite");
  }
  if (!std::isfinite(msg.duration) || msg.duration < 0.0) {
    throw InputRejected("duration " + std::to_string(msg.duration) +
                        " is invalid (allowed: finite >= 0 [s], 0 = until replaced)");
  }
  const std::uint32_t vertex = lookupVertex(simulator.scene(), msg.yarn, msg.vertex);
  const Eigen::Vector3d fixed =
      frames_.rotateToFixedFrame(force, msg.header.frame_id, msg.header.stamp);
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
      throw InputRejected("vertex " + std::to_string(msg.vertex) + " of yarn '" + msg.yarn +
                          "' is not grasped");
    }
    simulator.releaseVertex(vertex);
    return;
  }
  if (msg.target_frame.empty()) {
    throw InputRejected("target_frame is empty");
  }
  GraspTarget target;
  target.frame = msg.target_frame;
  target.label = "vertex " + std::to_string(msg.vertex) + " of yarn '" + msg.yarn + "'";
  target.to = frames_.originInFixedFrame(msg.target_frame);
  const auto existing = grasps_.find(vertex);
  target.from =
      existing != grasps_.end() ? existing->second.to : simulator.scene().vertices.position[vertex];
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
    } catch (const InputRejected& e) {
      ROS_WARN_THROTTLE(kWarnPeriod, "grasp of %s keeps its last target: %s", target.label.c_str(),
                        e.what());
    }
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

}  // namespace ros_layer
}  // namespace yarn_tearing
