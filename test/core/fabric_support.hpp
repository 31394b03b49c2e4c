#pragma once

#include "test_support.hpp"
#include "yarn_tearing/core/model/fabric_spec.hpp"

namespace yarn_tearing::test {

/// A cotton-like plain-weave patch hanging along -z from its first row (at the origin), the weft
/// along +x: `ends` x `picks` vertices, 0.1 mm yarns, no crimp, no scatter.
inline FabricSpec cottonPatch(int ends, int picks, double weft_length, double warp_length) {
  FabricSpec spec;
  spec.name = "cloth";
  spec.ends = ends;
  spec.picks = picks;
  spec.weft_length = weft_length;
  spec.warp_length = warp_length;
  spec.warp = hangingYarn();
  spec.weft = hangingYarn();
  spec.pinned_sides = {FabricSide::kFirstRow};
  return spec;
}

/// Global vertex ids of the scene's first fabric's last row (a strip's grips).
inline std::vector<std::uint32_t> lastRow(const Scene& scene) {
  const Fabric& fabric = scene.fabrics[0];
  std::vector<std::uint32_t> row;
  for (std::uint32_t c = 0; c < fabric.ends; ++c) row.push_back(fabric.vertex(fabric.picks - 1, c));
  return row;
}

/// Positions of the given vertices [m].
inline std::vector<Eigen::Vector3d> positionsOf(const Scene& scene,
                                                const std::vector<std::uint32_t>& vertices) {
  std::vector<Eigen::Vector3d> positions;
  for (std::uint32_t v : vertices) positions.push_back(scene.vertices.position[v]);
  return positions;
}

/// The breaking force sigma_b pi r^2 of a fabric family's yarn [N].
inline double breakingForce(const YarnSpec& yarn) {
  return yarn.material.curve.breakingStress() * yarn.area();
}

}  // namespace yarn_tearing::test
