#pragma once

#include <ros/ros.h>
#include <tf2_ros/buffer.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/ros/wrench_topics.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// A simulated force–torque sensor in every holder: publishes geometry_msgs/WrenchStamped with the
/// force the yarn exerts on each grasped vertex's gripper, in the grasp's target_frame, on
/// `~grasp_wrench/<yarn>/vertex_<i>`, and on each pinned vertex's holder, in the fixed frame, on
/// `~pin_wrench/<yarn>/vertex_<i>` (i the vertex index within the yarn, from 0). The holder holds
/// the vertex at its frame's origin, so the torque about that origin is zero.
class SupportWrenchPublisher {
 public:
  /// `private_nh` advertises the topics; `buffer` (outliving this object) rotates into grasp
  /// frames; `fixed_frame` is the node's frame_id.
  SupportWrenchPublisher(ros::NodeHandle private_nh, const tf2_ros::Buffer& buffer,
                         std::string fixed_frame);

  /// Publishes the wrench of every supported vertex of `simulator`, stamped `stamp`;
  /// `grasp_frames` maps grasped global vertex ids to their target frames (the others are pins).
  /// A grasp frame tf cannot rotate into is skipped (warned, throttled).
  void publish(const Simulator& simulator, const std::map<std::uint32_t, std::string>& grasp_frames,
               const ros::Time& stamp);

 private:
  WrenchTopics topics_;  ///< in the private namespace
  const tf2_ros::Buffer& buffer_;
  std::string fixed_frame_;
  std::set<std::string> invalid_names_;  ///< yarn names no topic can carry (warned)
};

}  // namespace ros_layer
}  // namespace yarn_tearing
