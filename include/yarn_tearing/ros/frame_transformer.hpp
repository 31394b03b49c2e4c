#pragma once

#include <ros/time.h>
#include <tf2_ros/buffer.h>

#include <Eigen/Core>
#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// Expresses vectors and frame origins from tf2 in the simulation's frame.
class FrameTransformer {
 public:
  /// `buffer` must outlive this object; `fixed_frame` is the node's frame_id.
  FrameTransformer(const tf2_ros::Buffer& buffer, std::string fixed_frame);

  const std::string& fixedFrame() const { return fixed_frame_; }

  /// `vector` given in `frame` rotated into the fixed frame (rotation only, no translation) at
  /// `stamp` (zero = latest). An empty `frame` or the fixed frame itself returns `vector`.
  /// Throws InputRejected with tf2's reason when the frame cannot be resolved.
  Eigen::Vector3d rotateToFixedFrame(const Eigen::Vector3d& vector, const std::string& frame,
                                     const ros::Time& stamp) const;

  /// Origin of `frame` in the fixed frame [m] at the latest available time. Throws InputRejected.
  Eigen::Vector3d originInFixedFrame(const std::string& frame) const;

 private:
  const tf2_ros::Buffer& buffer_;
  std::string fixed_frame_;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
