#include "yarn_tearing/ros/tf_input.hpp"

#include <ros/console.h>
#include <ros/wall_timer.h>

#include <string>

#include "yarn_tearing/ros/clipped_text.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace {

constexpr std::size_t kMaxReason = 160;  ///< [characters] of the reason quoted
constexpr std::uint32_t kTfQueue = 100;  ///< as tf2_ros's listener
constexpr std::size_t kNumTfReasons = 2;
constexpr std::size_t kStampOutOfRange = 0;
constexpr std::size_t kRefusedByTf2 = 1;
const char* const kReasonNames[kNumTfReasons] = {"time out of range", "refused by tf2"};

}  // namespace

TfInput::TfInput(const ros::NodeHandle& nh, tf2_ros::Buffer& buffer)
    : buffer_(buffer), nh_(nh, ""), warnings_(kWarnPeriod, kNumTfReasons) {
  nh_.setCallbackQueue(&queue_);
  tf_sub_ = nh_.subscribe<tf2_msgs::TFMessage>(
      "/tf", kTfQueue,
      [this](const ros::MessageEvent<const tf2_msgs::TFMessage>& e) { onTf(e, false); });
  tf_static_sub_ = nh_.subscribe<tf2_msgs::TFMessage>(
      "/tf_static", kTfQueue,
      [this](const ros::MessageEvent<const tf2_msgs::TFMessage>& e) { onTf(e, true); });
  spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
  spinner_->start();
  buffer_.setUsingDedicatedThread(true);
}

TfInput::~TfInput() {
  spinner_->stop();
  tf_sub_.shutdown();
  tf_static_sub_.shutdown();
}

void TfInput::onTf(const ros::MessageEvent<const tf2_msgs::TFMessage>& event, bool is_static) {
  const ros::Time now = ros::Time::now();
  if (now < last_update_) {
    ROS_WARN("ROS time jumped back (%.3f s to %.3f s): tf buffer cleared", last_update_.toSec(),
             now.toSec());
    buffer_.clear();
  }
  last_update_ = now;
  const std::string& authority = event.getPublisherName();
  for (const geometry_msgs::TransformStamped& transform : event.getMessage()->transforms) {
    if (transform.header.stamp.toSec() > kMaxStamp) {
      warn(kStampOutOfRange, transform.child_frame_id,
           "stamped " + std::to_string(transform.header.stamp.sec) +
               " s, past the range tf2's cache can take");
      continue;
    }
    try {
      buffer_.setTransform(transform, authority, is_static);
    } catch (const std::exception& e) {
      warn(kRefusedByTf2, transform.child_frame_id, e.what());
    }
  }
}

void TfInput::warn(std::size_t reason, const std::string& child, const std::string& why) {
  if (warnings_.shouldReport(reason, ros::WallTime::now().toSec())) {
    ROS_WARN("tf refused (%s, frame '%s'; %llu more of this reason held back): %s",
             kReasonNames[reason], clipped(child).c_str(),
             static_cast<unsigned long long>(warnings_.heldBack(reason)),
             clipped(why, kMaxReason).c_str());
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
