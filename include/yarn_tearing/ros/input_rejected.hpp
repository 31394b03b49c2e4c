#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// Why an input was refused: a fixed set, so that warnings can be throttled per reason with
/// bounded memory however many different bad messages arrive.
enum class RefusalReason : std::size_t {
  kNotFinite,         ///< NaN or infinity in a number
  kOutOfBounds,       ///< finite but past a documented physical bound (input_bounds.hpp)
  kUnknownYarn,       ///< no yarn of that name
  kVertexOutOfRange,  ///< no such vertex in the yarn
  kUnknownFrame,      ///< empty, too long, unknown or unresolvable tf frame
  kStaleFrame,        ///< tf frame not updated for longer than frame_timeout
  kNotGrasped,        ///< release of a vertex that is not grasped
  kTimeOutOfRange,    ///< a stamp or a time difference past the range of ROS time
  kThroughYarn,       ///< an obstacle's pose through a yarn (ObstacleThroughYarn)
  kUnexpected,        ///< any other exception while a message was taken
  kCount              ///< number of reasons (not a reason)
};

/// Short name of a reason, e.g. "not finite".
const char* reasonName(RefusalReason reason);

/// An applied_force or grasp message that was refused; what() says what was wrong with it (names
/// in it are clipped, see clipped()).
class InputRejected : public std::runtime_error {
 public:
  InputRejected(RefusalReason reason, const std::string& what)
      : std::runtime_error(what), reason_(reason) {}

  RefusalReason reason() const { return reason_; }

 private:
  RefusalReason reason_;
};

}  // namespace ros_layer
}  // namespace yarn_tearing
