#pragma once

#include <string>

#include "yarn_tearing/ros/parameter_error.hpp"

namespace yarn_tearing {
namespace ros_layer {
namespace testing {

/// what() of the ParameterError that `load()` throws ("" when it throws none).
template <typename Load>
std::string parameterErrorOf(const Load& load) {
  try {
    load();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

}  // namespace testing
}  // namespace ros_layer
}  // namespace yarn_tearing
