#include "yarn_tearing/ros/unknown_parameters.hpp"

#include <algorithm>
#include <cstddef>

namespace yarn_tearing {
namespace ros_layer {
namespace {

/// Levenshtein distance between `a` and `b`.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) {
    row[j] = j;
  }
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

}  // namespace

std::string nearestName(const std::string& word, const std::set<std::string>& candidates) {
  const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
  std::string nearest;
  std::size_t best = limit + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = editDistance(word, candidate);
    if (distance < best) {
      best = distance;
      nearest = candidate;
    }
  }
  return nearest;
}

std::vector<std::string> unknownParameterWarnings(const std::vector<std::string>& names,
                                                  const std::string& ns,
                                                  const std::set<std::string>& known) {
  const std::string prefix = ns + "/";
  std::set<std::string> unknown;
  for (const std::string& name : names) {
    if (name.compare(0, prefix.size(), prefix) != 0) {
      continue;
    }
    const std::string key =
        name.substr(prefix.size(), name.find('/', prefix.size()) - prefix.size());
    if (known.count(key) == 0) {
      unknown.insert(key);
    }
  }
  std::vector<std::string> warnings;
  for (const std::string& key : unknown) {
    std::string text = "unknown parameter " + prefix + key + " (ignored)";
    const std::string nearest = nearestName(key, known);
    if (!nearest.empty()) {
      text += "; did you mean '" + nearest + "'?";
    }
    warnings.push_back(text);
  }
  return warnings;
}

}  // namespace ros_layer
}  // namespace yarn_tearing
