#include "yarn_tearing/ros/support_wrench_publisher.hpp"

#include <ros/names.h>
#include <tf2/exceptions.h>

#include <Eigen/Geometry>

#include "yarn_tearing/ros/warning_throttle.hpp"

namespace yarn_tearing {
namespace ros_layer {

SupportWrenchPublisher::SupportWrenchPublisher(ros::NodeHandle private_nh,
                                               const tf2_ros::Buffer& buffer,
                                               std::string fixed_frame)
    : topics_(std::move(private_nh)), buffer_(buffer), fixed_frame_(std::move(fixed_frame)) {}

void SupportWrenchPublisher::publish(const Simulator& simulator,
                                     const std::map<std::uint32_t, std::string>& grasp_frames,
                                     const ros::Time& stamp) {
  const Scene& scene = simulator.scene();
  for (const Yarn& yarn : scene.yarns) {
    // A fabric's vertices are listed once, under the fabric's name (its weft shares them).
    if (yarn.fabric >= 0 && yarn.family == FabricFamily::kWeft) continue;
    const std::string& name =
        yarn.fabric >= 0 ? scene.fabrics[static_cast<std::size_t>(yarn.fabric)].name : yarn.name;
    std::string error;
    if (!ros::names::validate(name, error)) {
      if (invalid_names_.insert(name).second) {
        ROS_WARN("no wrench topics for '%s': not a valid ROS name (%s)", name.c_str(),
                 error.c_str());
      }
      continue;
    }
    for (std::uint32_t i = 0; i < yarn.num_vertices; ++i) {
      const std::uint32_t v = yarn.first_vertex + i;
      if (!scene.vertices.isSupport(v)) {
        continue;
      }
      const auto grasp = grasp_frames.find(v);
      const bool grasped = grasp != grasp_frames.end();
      const std::string topic =
          (grasped ? "grasp_wrench/" : "pin_wrench/") + name + "/vertex_" + std::to_string(i);
      if (!topics_.wanted(topic)) {
        continue;
      }
      const std::string& frame = grasped ? grasp->second : fixed_frame_;
      Eigen::Vector3d force = simulator.supportForce(v);  // [N] in the fixed frame
      if (frame != fixed_frame_) {
        try {
          const geometry_msgs::Quaternion q =
              buffer_.lookupTransform(frame, fixed_frame_, ros::Time(0)).transform.rotation;
          force = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized() * force;
        } catch (const tf2::TransformException& e) {
          ROS_WARN_THROTTLE(kWarnPeriod, "no grasp wrench in frame '%s': %s", frame.c_str(),
                            e.what());
          continue;
        }
      }
      // the holder holds the vertex at its frame's origin: no torque about it
      topics_.publish(topic, frame, stamp, force, Eigen::Vector3d::Zero());
    }
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
