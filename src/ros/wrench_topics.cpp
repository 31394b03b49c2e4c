#include "yarn_tearing/ros/wrench_topics.hpp"

#include <geometry_msgs/WrenchStamped.h>

#include "yarn_tearing/ros/geometry_conversion.hpp"

namespace yarn_tearing {
namespace ros_layer {

ros::Publisher& WrenchTopics::publisherFor(const std::string& topic) {
  auto it = publishers_.find(topic);
  if (it == publishers_.end()) {
    it = publishers_.emplace(topic, nh_.advertise<geometry_msgs::WrenchStamped>(topic, kQueueSize))
             .first;
  }
  return it->second;
}

bool WrenchTopics::wanted(const std::string& topic) {
  return publisherFor(topic).getNumSubscribers() > 0;
}

void WrenchTopics::publish(const std::string& topic, const std::string& frame,
                           const ros::Time& stamp, const Eigen::Vector3d& force,
                           const Eigen::Vector3d& torque) {
  geometry_msgs::WrenchStamped wrench;
  wrench.header.stamp = stamp;
  wrench.header.frame_id = frame;
  wrench.wrench.force = toVector3(force);
  wrench.wrench.torque = toVector3(torque);
  publisherFor(topic).publish(wrench);
}

}  // namespace ros_layer
}  // namespace yarn_tearing
