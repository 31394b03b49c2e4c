#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/scene.hpp"

namespace yarn_tearing {

/// The neighbourhood of a tear in which the step after it resolves the recoil in fine substeps
/// (doc/method.md, "Recoil substeps"): the vertices within `reach` of a torn edge along its yarn,
/// and the intact edges that touch them. The elastic wave the tear releases runs at
/// c = sqrt(E / rho) through the unstrained material; within one step Δt it crosses c Δt of rest
/// length, so the yarn beyond that still carries its load and keeps the motion it had.
struct RecoilRegion {
  /// Global ids of the region's vertices, ascending (a sub-scene's local ids follow this order).
  std::vector<std::uint32_t> vertices;
  /// Per region vertex: 1 where the walk stopped at a free vertex, which the recoil leaves on
  /// its unaffected path (the rest of the scene's step), 0 for the region's own vertices.
  std::vector<std::uint8_t> boundary;
  /// Per region vertex: its rest-length (L0) distance from the nearest end of a torn edge along
  /// the walk [m].
  std::vector<double> distance;
  /// Global ids of the intact edges with at least one end among the region's own vertices,
  /// ascending; both their ends are region vertices.
  std::vector<std::uint32_t> edges;
  /// False when the region cannot be substepped on its own: it reaches a fabric's edge (a
  /// fabric's cells couple it sideways) or holds no edge.
  bool usable = false;

  /// Builds the region around the edges `torn` (global ids): a walk along intact edges from
  /// each torn edge's ends that goes on through free vertices until `reach` [m] of rest length
  /// (L0) from the tear and stops at held (pinned or kinematic) vertices, which stay the
  /// region's own. Each vertex where the walk stops past `reach` is a boundary vertex.
  static RecoilRegion around(const Scene& scene, const std::vector<std::uint32_t>& torn,
                             double reach);

  /// The region as a scene of its own (the scene's yarns and materials, no fabrics): its
  /// vertices and edges with all their state.
  Scene subScene(const Scene& scene) const;

  /// Copies the state of the region's own vertices and of its edges from `sub` (a subScene()
  /// after its step) back into `scene`.
  void writeBack(const Scene& sub, Scene& scene) const;
};

}  // namespace yarn_tearing
