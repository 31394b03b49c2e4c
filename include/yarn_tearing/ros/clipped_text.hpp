#pragma once

#include <cstddef>
#include <string>

namespace yarn_tearing {
namespace ros_layer {

/// Longest name (yarn, tf frame) quoted in a warning [characters].
constexpr std::size_t kMaxQuotedName = 40;

/// `text` if at most `max_length` characters, else its first `max_length` characters followed by
/// "...(N chars)", so a warning never carries a client's 200 kB name.
std::string clipped(const std::string& text, std::size_t max_length = kMaxQuotedName);

}  // namespace ros_layer
}  // namespace yarn_tearing
