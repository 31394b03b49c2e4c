#include "yarn_tearing/ros/frame_transformer.hpp"

#include <tf2/exceptions.h>

#include <Eigen/Geometry>

#include "yarn_tearing/ros/input_rejected.hpp"

namespace yarn_tearing {
namespace ros_layer {

FrameTransformer::FrameTransformer(const tf2_ros::Buffer& buffer, std::string fixed_frame)
    : buffer_(buffer), fixed_frame_(std::move(fixed_frame)) {}

Eigen::Vector3d FrameTransformer::rotateToFixedFrame(const Eigen::Vector3d& vector,
                                                     const std::string& frame,
                                                     const ros::Time& stamp) const {
  if (frame.empty() || frame == fixed_frame_) {
    return vector;
  }
  try {
    const geometry_msgs::Quaternion q =
        buffer_.lookupTransform(fixed_frame_, frame, stamp).transform.rotation;
    return Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized() * vector;
  } catch (const tf2::TransformException& e) {
    throw InputRejected("cannot transform from frame '" + frame + "' to '" + fixed_frame_ +
                        "': " + e.what());
  }
}

Eigen::Vector3d FrameTransformer::originInFixedFrame(const std::string& frame) const {
  if (frame == fixed_frame_) {
    return Eigen::Vector3d::Zero();
  }
  try {
    const geometry_msgs::Vector3 t =
        buffer_.lookupTransform(fixed_frame_, frame, ros::Time(0)).transform.translation;
    return Eigen::Vector3d(t.x, t.y, t.z);
  } catch (const tf2::TransformException& e) {
    throw InputRejected("cannot look up frame '" + frame + "' in '" + fixed_frame_ +
                        "': " + e.what());
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
