#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "yarn_tearing/core/model/fabric_segment.hpp"
#include "yarn_tearing/core/model/yarn_spec.hpp"

namespace yarn_tearing {

/// How warp and weft interlace. The crossings are shared vertices (yarns do not slide), so the
/// weave sets nothing mechanical beyond the crimp; only the plain weave is offered.
enum class Weave {
  kPlain,
};

/// A vertex of a fabric by its place in the grid: row = weft yarn (pick), column = warp yarn
/// (end). Negative values count from the last row or column.
struct FabricVertexIndex {
  int row = 0;
  int column = 0;
};

/// A whole side of the fabric's grid.
enum class FabricSide {
  kFirstRow,     ///< row 0 (at `origin`, across the warp)
  kLastRow,      ///< the last row
  kFirstColumn,  ///< column 0 (at `origin`, along the warp)
  kLastColumn,   ///< the last column
};

/// A cut made before the simulation starts: segment `segment` of the yarns `first_yarn` ..
/// `last_yarn` (inclusive) of one family, i.e. a straight slit across those yarns.
struct FabricSlit {
  FabricFamily family = FabricFamily::kWeft;
  int first_yarn = 0;  ///< first yarn cut [-]
  int last_yarn = 0;   ///< last yarn cut [-]
  int segment = 0;     ///< the segment cut on each [-]
};

/// Everything needed to build one flat woven fabric: a grid of `picks` rows by `ends` columns of
/// vertices, where each warp yarn (a column) crosses each weft yarn (a row). Each warp and weft
/// segment is a length-constrained, tearable edge of its yarn's material, exactly as a yarn's.
struct FabricSpec {
  std::string name;  ///< unique among yarns and fabrics
  Weave weave = Weave::kPlain;
  double warp_length = 0.1;                          ///< size of the fabric along the warp [m]
  double weft_length = 0.1;                          ///< size of the fabric along the weft [m]
  int ends = 16;                                     ///< warp yarns simulated (columns), >= 2
  int picks = 16;                                    ///< weft yarns simulated (rows), >= 2
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< vertex (row 0, column 0) [m]
  /// Direction the warp yarns run in, from row 0 to the last row (normalized) [-].
  Eigen::Vector3d warp_direction = Eigen::Vector3d(0.0, 0.0, -1.0);
  /// Direction the weft yarns run in, from column 0 to the last column (normalized) [-]; not
  /// parallel to the warp.
  Eigen::Vector3d weft_direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  /// The warp yarn: its material, radius (or tex and packing_fraction) and strength_scatter are
  /// used; length, num_vertices, start, direction, pinned and end_mass are not.
  YarnSpec warp;
  YarnSpec weft;  ///< the weft yarn, as `warp`
  /// Warp crimp [-]: a warp segment's rest length is (1 + crimp) times the distance between its
  /// rows, so the fabric stretches by the crimp before the warp yarns carry load. >= 0.
  double warp_crimp = 0.0;
  double weft_crimp = 0.0;  ///< weft crimp [-], as warp_crimp
  /// In-plane shear rigidity G [N/m] (shear force per unit width per radian; KES-F "G" of
  /// 1 gf/(cm deg) is 56 N/m): two diagonal springs of stiffness G per cell, dropped once a
  /// segment of the cell is cut; capped for stability like the soft springs
  /// (SimulationParameters::soft_spring_ratio). 0 = none.
  double shear_rigidity = 50.0;
  std::vector<FabricVertexIndex> pinned;  ///< pinned vertices
  std::vector<FabricSide> pinned_sides;   ///< whole sides pinned
  std::vector<FabricSlit> slits;          ///< segments cut at the start

  /// Throws std::invalid_argument naming the fabric, the field and what is allowed.
  void validate() const;
  /// Number of segments along one yarn of `family` [-].
  int segmentsPerYarn(FabricFamily family) const;
  /// Number of yarns of `family` [-].
  int yarnCount(FabricFamily family) const;
};

}  // namespace yarn_tearing
