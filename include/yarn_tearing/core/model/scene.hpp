#pragma once

#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/model/fabric.hpp"
#include "yarn_tearing/core/model/fabric_spec.hpp"
#include "yarn_tearing/core/model/vertex_set.hpp"
#include "yarn_tearing/core/model/yarn.hpp"
#include "yarn_tearing/core/model/yarn_spec.hpp"

namespace yarn_tearing {

/// The simulated world: vertices, edges, the yarns that own them and the fabrics woven of some.
struct Scene {
  VertexSet vertices;
  EdgeSet edges;
  std::vector<Yarn> yarns;
  std::vector<Fabric> fabrics;

  /// Index of the yarn with this name, or -1.
  int findYarn(const std::string& name) const;
  /// Global vertex id of a yarn's vertex; `local` < 0 counts from the end. Throws
  /// std::out_of_range when the vertex does not exist.
  std::uint32_t globalVertex(std::size_t yarn, int local) const;
  /// Index of the fabric with this name, or -1.
  int findFabric(const std::string& name) const;
  /// Global vertex id of a fabric's vertex (row, column); negative values count from the end.
  /// Throws std::out_of_range when the vertex does not exist.
  std::uint32_t fabricVertex(std::size_t fabric, int row, int column) const;
  /// Global edge id of a fabric's segment. Throws std::out_of_range when it does not exist.
  std::uint32_t fabricEdge(std::size_t fabric, const FabricSegment& segment) const;
  /// The fabric (index) edge `edge` belongs to, or -1 for a yarn's edge.
  int fabricOfEdge(std::size_t edge) const { return yarns[edges.yarn[edge]].fabric; }
  /// Which yarn and segment of its fabric edge `edge` is (it must be a fabric's edge).
  FabricSegment fabricSegmentOf(std::size_t edge) const;
};

/// Builds a scene of straight yarns and flat fabrics at rest (yarns first, then fabrics, each in
/// the order given). Throws std::invalid_argument on a bad spec (the message names the yarn or
/// fabric and the field) or a name used twice among yarns and fabrics.
Scene buildScene(const std::vector<YarnSpec>& specs, const std::vector<FabricSpec>& fabrics = {});

}  // namespace yarn_tearing
