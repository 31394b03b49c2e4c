#include "yarn_tearing/core/forces/fabric_shear.hpp"

#include <algorithm>

#include "yarn_tearing/core/projection/edge_stretch_limits.hpp"

namespace yarn_tearing {
namespace {

void addDiagonal(const Scene& scene, const SimulationParameters& parameters, double rigidity,
                 std::uint32_t a, std::uint32_t b, double rest,
                 std::vector<Eigen::Vector3d>& force) {
  const VertexSet& vertices = scene.vertices;
  const double k = std::min(rigidity, stabilitySpringConstant(vertices, a, b, parameters));
  if (!(k > 0.0)) return;
  const Eigen::Vector3d d = vertices.position[b] - vertices.position[a];
  const double length = d.norm();
  if (!(length > 0.0)) return;
  const Eigen::Vector3d f = (k * (length - rest) / length) * d;
  force[a] += f;
  force[b] -= f;
}

}  // namespace

std::size_t accumulateShearForces(const Scene& scene, const SimulationParameters& parameters,
                                  std::vector<Eigen::Vector3d>& force) {
  std::size_t acting = 0;
  for (const Fabric& fabric : scene.fabrics) {
    if (!(fabric.shear_rigidity > 0.0)) continue;
    for (const FabricCell& cell : fabric.cells) {
      const bool intact = std::all_of(cell.edge.begin(), cell.edge.end(),
                                      [&](std::uint32_t e) { return scene.edges.intact(e); });
      if (!intact) continue;
      ++acting;
      addDiagonal(scene, parameters, fabric.shear_rigidity, cell.corner[0], cell.corner[3],
                  cell.diagonal_rest[0], force);
      addDiagonal(scene, parameters, fabric.shear_rigidity, cell.corner[1], cell.corner[2],
                  cell.diagonal_rest[1], force);
    }
  }
  return acting;
}

}  // namespace yarn_tearing
