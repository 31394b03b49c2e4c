#pragma once

#include <stdexcept>
#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// An invalid or missing ROS parameter; what() names the parameter, its value and what is allowed.
class ParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
