#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/connected_pieces.hpp"
#include "yarn_tearing/core/model/scene.hpp"
#include "yarn_tearing/core/tearing/tear_event.hpp"

namespace yarn_tearing {

/// Stage 6: an edge tears when its strain reaches its breaking strain (EdgeSet::breaking_strain).
/// When one segment fails the load drops everywhere, so each step tears at most the most
/// over-strained edge of each connected piece, and in a piece a tear leaves an edge the elastic
/// wave from the tear has not reached yet (at c = sqrt(E / rho), straight from the torn edge) does
/// not tear until the wave has crossed the piece (its extent over c: the time the load takes to
/// drop). An edge the wave has reached that is still at its breaking point is loaded by more than
/// what the tear released, and tears. Breaks are collected first and applied after, so the
/// topology never changes while they are chosen.
class Tearing {
 public:
  /// Global ids of the edges to tear this step (ordered by edge id), at simulated `time` [s].
  const std::vector<std::uint32_t>& collect(const Scene& scene, double time);
  /// Tears the collected edges and appends one event each (time = `time` [s]; the state each
  /// reports follows tearEventOf(), `start_velocity` [m/s] the vertices' as the step began).
  void apply(Scene& scene, const std::vector<Eigen::Vector3d>& start_velocity, double time,
             std::vector<TearEvent>& events);
  /// When the last of the pieces torn so far has unloaded (its tear's time plus the elastic
  /// wave's crossing time, extent / c) [s]; -1 before any tear.
  double unloadingEnd() const { return unloading_end_; }
  /// This state for a sub-scene made of the vertices `vertices` (global ids, in the sub-scene's
  /// order): each vertex keeps the end of its piece's unloading [s], and the latest end stays.
  Tearing restrictedTo(const std::vector<std::uint32_t>& vertices) const;

 private:
  /// Whether edge e waits at `time` [s] for the unloading wave of an earlier tear in its piece:
  /// the piece is still unloading and the wave has not reached the edge yet.
  bool waiting(const Scene& scene, std::size_t e, double time) const;
  /// Marks the vertices of each piece a collected edge tears as unloading until the elastic
  /// wave from the tear has crossed the piece.
  void startUnloading(const Scene& scene, double time);

  double unloading_end_ = -1.0;               ///< latest end of an unloading [s]
  std::vector<double> unloaded_at_;           ///< per vertex: end of its piece's unloading [s]
  std::vector<double> torn_at_;               ///< per vertex: time of its piece's last tear [s]
  std::vector<Eigen::Vector3d> tear_point_;   ///< per vertex: midpoint of that torn edge [m]
  std::vector<double> wave_speed_;            ///< per vertex: c = sqrt(E / rho) of that edge [m/s]
  std::vector<double> unloading_until_;       ///< per piece root, scratch [s]
  std::vector<std::uint32_t> tear_of_piece_;  ///< per piece root: the edge torn in it, scratch
  std::vector<Eigen::Vector3d> box_min_;  ///< per piece root: lower corner of its box [m], scratch
  std::vector<Eigen::Vector3d> box_max_;  ///< per piece root: upper corner of its box [m], scratch
  ConnectedPieces pieces_;                ///< the pieces the edges join
  std::vector<std::int64_t> best_of_piece_;  ///< per root: most over-strained edge, or -1
  std::vector<double> best_ratio_;           ///< per root: its strain / breaking strain
  std::vector<std::uint32_t> collected_;
};

}  // namespace yarn_tearing
