#include "yarn_tearing/ros/service_thread.hpp"

namespace yarn_tearing {
namespace ros_layer {

ServiceThread::ServiceThread(const ros::NodeHandle& nh) : nh_(nh) { nh_.setCallbackQueue(&queue_); }

ServiceThread::~ServiceThread() { stop(); }

void ServiceThread::start() {
  if (!spinner_) {
    spinner_ = std::make_unique<ros::AsyncSpinner>(1, &queue_);
    spinner_->start();
  }
}

void ServiceThread::stop() {
  if (spinner_) {
    spinner_->stop();
    spinner_.reset();
  }
}

}  // namespace ros_layer
}  // namespace yarn_tearing
