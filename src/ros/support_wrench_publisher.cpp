#include "yarn_tearing/ros/support_wrench_publisher.hpp"

#include <geometry_msgs/WrenchStamped.h>
#include <ros/names.h>
#include <tf2/exceptions.h>

#include <Eigen/Geometry>

#include "yarn_tearing/ros/geometry_conversion.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr std::uint32_t kWrenchQueue = 10;
constexpr double kWarnPeriod = 2.0;  ///< [s] between repeats of a rotation failure warning

}  // namespace

SupportWrenchPublisher::SupportWrenchPublisher(ros::NodeHandle private_nh,
                                               const tf2_ros::Buffer& buffer,
                                               std::string fixed_frame)
    : private_nh_(private_nh), buffer_(buffer), fixed_frame_(std::move(fixed_frame)) {}

ros::Publisher& SupportWrenchPublisher::publisherFor(const std::string& topic) {
  auto it = publishers_.find(topic);
  if (it == publishers_.end()) {
    it = publishers_
             .emplace(topic,
                      private_nh_.advertise<geometry_msgs::WrenchStamped>(topic, kWrenchQueue))
             .first;
  }
  return it->second;
}

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
      ros::Publisher& publisher = publisherFor((grasped ? "grasp_wrench/" : "pin_wrench/") + name +
                                               "/vertex_" + std::to_string(i));
      if (publisher.getNumSubscribers() == 0) {
        continue;
      }
      geometry_msgs::WrenchStamped wrench;
      wrench.header.stamp = stamp;
      wrench.header.frame_id = grasped ? grasp->second : fixed_frame_;
      Eigen::Vector3d force = simulator.supportForce(v);  // [N] in the fixed frame
      if (wrench.header.frame_id != fixed_frame_) {
        try {
          const geometry_msgs::Quaternion q =
              buffer_.lookupTransform(wrench.header.frame_id, fixed_frame_, ros::Time(0))
                  .transform.rotation;
          force = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized() * force;
        } catch (const tf2::TransformException& e) {
          ROS_WARN_THROTTLE(kWarnPeriod, "no grasp wrench in frame '%s': %s",
                            wrench.header.frame_id.c_str(), e.what());
          continue;
        }
      }
      wrench.wrench.force = toVector3(force);  // torque about the holder's origin: zero
      publisher.publish(wrench);
    }
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
