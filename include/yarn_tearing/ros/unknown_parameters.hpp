#pragma once

#include <set>
#include <string>
#include <vector>

namespace yarn_tearing {
namespace ros_layer {

/// The candidate closest to `word` by edit distance (insertions, deletions, substitutions), or ""
/// when none is within max(2, |word| / 3) edits (a typo, not another word).
std::string nearestName(const std::string& word, const std::set<std::string>& candidates);

/// One warning per parameter under `ns` (e.g. "/yarn_tearing") whose first name segment after
/// `ns` is not in `known`, from the full parameter names `names` (ros::param::getParamNames):
/// "unknown parameter /yarn_tearing/air_dampin (ignored); did you mean 'air_damping'?". A
/// misspelled map or list is reported once.
std::vector<std::string> unknownParameterWarnings(const std::vector<std::string>& names,
                                                  const std::string& ns,
                                                  const std::set<std::string>& known);

}  // namespace ros_layer
}  // namespace yarn_tearing
