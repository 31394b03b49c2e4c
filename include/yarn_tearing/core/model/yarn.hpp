#pragma once

#include <cstdint>
#include <string>

#include "yarn_tearing/core/material/material.hpp"
#include "yarn_tearing/core/model/fabric_segment.hpp"

namespace yarn_tearing {

/// One yarn of a scene: a contiguous range of vertices and edges sharing a material. A fabric
/// (Fabric) has two: its warp and its weft group, which share the fabric's vertex range and each
/// hold one family's segments.
struct Yarn {
  std::string name;
  Material material;
  double radius = 0.0;             ///< radius used for drawing and reporting [m]
  std::uint32_t first_vertex = 0;  ///< global id of the yarn's vertex 0
  std::uint32_t num_vertices = 0;
  std::uint32_t first_edge = 0;  ///< global id of the yarn's edge 0
  std::uint32_t num_edges = 0;
  /// Index into Scene::fabrics when this is a fabric's warp or weft group, else -1.
  std::int32_t fabric = -1;
  FabricFamily family = FabricFamily::kWarp;  ///< which family of its fabric (when fabric >= 0)
};

}  // namespace yarn_tearing
