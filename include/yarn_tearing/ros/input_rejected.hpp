#pragma once

#include <stdexcept>

namespace yarn_tearing {
namespace ros_layer {

/// An applied_force or grasp message that was refused; what() says what was wrong with it.
class InputRejected : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
