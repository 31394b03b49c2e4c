#pragma once

#include <ros/ros.h>

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// geometry_msgs/WrenchStamped topics under one node handle, one publisher per topic, advertised
/// on first use (a holder or an obstacle appears), each with queue size kQueueSize.
class WrenchTopics {
 public:
  /// Outgoing queue of every wrench topic [messages]; a consumer needs no more than 1 (each
  /// message is the latest value, sent at publish_rate).
  static constexpr std::uint32_t kQueueSize = 10;

  explicit WrenchTopics(ros::NodeHandle nh) : nh_(std::move(nh)) {}

  /// True when `topic` (advertised now if new) has a subscriber: only then is a wrench built.
  bool wanted(const std::string& topic);
  /// Publishes `force` [N] and `torque` [N m], expressed in `frame`, stamped `stamp`, on `topic`.
  void publish(const std::string& topic, const std::string& frame, const ros::Time& stamp,
               const Eigen::Vector3d& force, const Eigen::Vector3d& torque);

 private:
  ros::Publisher& publisherFor(const std::string& topic);

  ros::NodeHandle nh_;
  std::map<std::string, ros::Publisher> publishers_;  ///< topic -> publisher
};

}  // namespace ros_layer
}  // namespace yarn_tearing
