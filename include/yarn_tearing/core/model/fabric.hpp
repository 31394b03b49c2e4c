#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "yarn_tearing/core/model/fabric_segment.hpp"

namespace yarn_tearing {

/// One cell of a fabric (between rows r, r + 1 and columns c, c + 1) as an in-plane shear element:
/// two springs along its diagonals. It acts only while all four of its segments are intact, so it
/// never holds two torn pieces together.
struct FabricCell {
  /// Global vertex ids: (r, c), (r, c + 1), (r + 1, c), (r + 1, c + 1).
  std::array<std::uint32_t, 4> corner{};
  /// Global edge ids of its segments: weft (r, c), weft (r + 1, c), warp (c, r), warp (c + 1, r).
  std::array<std::uint32_t, 4> edge{};
  /// Rest lengths of the diagonals corner 0-3 and corner 1-2 [m].
  std::array<double, 2> diagonal_rest{};
};

/// One woven fabric of a scene: a grid of `picks` rows by `ends` columns of vertices, contiguous
/// from `first_vertex` (vertex (r, c) is first_vertex + r * ends + c), whose warp segments are
/// the edges of the scene yarn `warp_group` and whose weft segments those of `weft_group` (each a
/// contiguous edge range, yarn by yarn: segment s of yarn y is group.first_edge + y *
/// segments-per-yarn + s). The groups carry each family's material and radius, so the same
/// stages serve yarns and fabrics.
struct Fabric {
  std::string name;
  std::uint32_t ends = 0;          ///< warp yarns (columns) [-]
  std::uint32_t picks = 0;         ///< weft yarns (rows) [-]
  std::uint32_t first_vertex = 0;  ///< global id of vertex (0, 0)
  std::uint32_t warp_group = 0;    ///< index into Scene::yarns of the warp segments' group
  std::uint32_t weft_group = 0;    ///< index into Scene::yarns of the weft segments' group
  double shear_rigidity = 0.0;     ///< G [N/m] of each cell's diagonal springs (before the cap)
  std::vector<FabricCell> cells;   ///< (picks - 1) (ends - 1) shear elements, row by row

  std::uint32_t numVertices() const { return ends * picks; }
  /// Global id of vertex (row, column); no range check.
  std::uint32_t vertex(std::uint32_t row, std::uint32_t column) const {
    return first_vertex + row * ends + column;
  }
  /// Segments along one yarn of `family` [-].
  std::uint32_t segmentsPerYarn(FabricFamily family) const {
    return family == FabricFamily::kWarp ? picks - 1 : ends - 1;
  }
  /// The scene yarn (group) holding `family`'s segments.
  std::uint32_t group(FabricFamily family) const {
    return family == FabricFamily::kWarp ? warp_group : weft_group;
  }
  /// Which yarn and segment the `local`-th edge of `family`'s group is.
  FabricSegment segmentOf(FabricFamily family, std::uint32_t local) const {
    const std::uint32_t per_yarn = segmentsPerYarn(family);
    return FabricSegment{family, local / per_yarn, local % per_yarn};
  }
};

}  // namespace yarn_tearing
