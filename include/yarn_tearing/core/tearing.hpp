#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/connected_pieces.hpp"
#include "yarn_tearing/core/scene.hpp"
#include "yarn_tearing/core/tear_event.hpp"

namespace yarn_tearing {

/// Stage 6: an edge tears when its strain reaches its breaking strain (the material's, times the
/// edge's strength factor). When one segment fails the load drops everywhere, so each step tears
/// at most the most over-strained edge of each connected piece. Breaks are collected first and
/// applied after, so the topology never changes while they are chosen.
class Tearing {
 public:
  /// Global ids of the edges to tear this step (ordered by edge id).
  const std::vector<std::uint32_t>& collect(const Scene& scene);
  /// Tears the collected edges and appends one event each (time = `time` [s]; the state each
  /// reports follows tearEventOf(), `time_step` [s] the step's Δt).
  void apply(Scene& scene, double time, double time_step, std::vector<TearEvent>& events);

 private:
  ConnectedPieces pieces_;                   ///< the pieces the edges join
  std::vector<std::int64_t> best_of_piece_;  ///< per root: most over-strained edge, or -1
  std::vector<double> best_ratio_;           ///< per root: its strain / breaking strain
  std::vector<std::uint32_t> collected_;
};

}  // namespace yarn_tearing
