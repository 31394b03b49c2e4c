#include "yarn_tearing/ros/clipped_text.hpp"

namespace yarn_tearing {
namespace ros_layer {

std::string clipped(const std::string& text, std::size_t max_length) {
  if (text.size() <= max_length) {
    return text;
  }
  return text.substr(0, max_length) + "...(" + std::to_string(text.size()) + " chars)";
}

}  // namespace ros_layer
}  // namespace yarn_tearing
