#pragma once

#include <ros/callback_queue.h>
#include <ros/node_handle.h>
#include <ros/spinner.h>
#include <ros/subscriber.h>
#include <ros/time.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

#include <memory>

#include "yarn_tearing/ros/warning_throttle.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Fills a tf2 buffer from /tf and /tf_static in a thread of its own (as tf2_ros's
/// TransformListener), refusing what tf2 cannot hold: a transform stamped so late that tf2's
/// cache arithmetic leaves ROS time's range (past kMaxStamp), or one tf2 throws on, is dropped with
/// a warning throttled per reason, so nothing from /tf can end the node. When ROS time jumps
/// back (a bag looped, a simulated clock restarted) the buffer is cleared, as tf2_ros does.
class TfInput {
 public:
  /// Latest stamp taken [s]: ROS time's range less a day, far more than tf2's cache span.
  static constexpr double kMaxStamp = 4294967295.0 - 86400.0;

  /// `buffer` must outlive this object; subscribes through a node handle of `nh`'s namespace.
  TfInput(const ros::NodeHandle& nh, tf2_ros::Buffer& buffer);
  ~TfInput();
  TfInput(const TfInput&) = delete;
  TfInput& operator=(const TfInput&) = delete;

 private:
  void onTf(const ros::MessageEvent<const tf2_msgs::TFMessage>& event, bool is_static);
  /// Warns, throttled per reason (0: stamp out of range, 1: refused by tf2), about `child`.
  void warn(std::size_t reason, const std::string& child, const std::string& why);

  tf2_ros::Buffer& buffer_;
  ros::CallbackQueue queue_;
  ros::NodeHandle nh_;
  ros::Subscriber tf_sub_;
  ros::Subscriber tf_static_sub_;
  std::unique_ptr<ros::AsyncSpinner> spinner_;
  WarningThrottle warnings_;
  ros::Time last_update_;  ///< ROS time of the last message (a jump back clears the buffer)
};

}  // namespace ros_layer
}  // namespace yarn_tearing
