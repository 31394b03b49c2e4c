#pragma once

#include <vector>

#include "yarn_tearing/core/edge_set.hpp"
#include "yarn_tearing/core/vertex_set.hpp"
#include "yarn_tearing/core/yarn.hpp"
#include "yarn_tearing/core/yarn_spec.hpp"

namespace yarn_tearing {

/// The simulated world: vertices, edges and the yarns that own them.
struct Scene {
  VertexSet vertices;
  EdgeSet edges;
  std::vector<Yarn> yarns;

  /// Index of the yarn with this name, or -1.
  int findYarn(const std::string& name) const;
  /// Global vertex id of a yarn's vertex; `local` < 0 counts from the end. Throws
  /// std::out_of_range when the vertex does not exist.
  std::uint32_t globalVertex(std::size_t yarn, int local) const;
};

/// Builds a scene of straight yarns at rest. Throws std::invalid_argument on a bad spec
/// (the message names the yarn and the field) or duplicate yarn names.
Scene buildScene(const std::vector<YarnSpec>& specs);

}  // namespace yarn_tearing
