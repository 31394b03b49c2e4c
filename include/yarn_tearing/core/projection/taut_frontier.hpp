#pragma once

#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// Speeds up the block principal pivoting of the length constraints where a pull runs along a
/// stretch of slack edges: an elastic wave front, or a yarn lifted from rest. Plain pivoting takes
/// in one edge per pass there, since a slack edge is stretched only once its neighbour holds, so a
/// front crossing a hundred edges in one step costs a hundred solves.
///
/// After each pass the frontier walks from every edge that has just joined, through its
/// vertices, along the slack edges beyond (and through taut ones, which pass a pull on), and takes
/// them in as long as their summed slack [m] stays below the stretch [m] the joining edge showed:
/// a pull that stretches an edge by d takes up d of slack beyond it. Where that overshoots, the
/// next solve shows the edges walked last as compressive; then only that batch leaves and later
/// walks get half the budget (a bisection of the front). The result is untouched: the pivoting
/// still ends only when no taut edge pushes and no slack edge is stretched.
class TautFrontier {
 public:
  /// Starts one complementarity solve over `num_edges` edges.
  void reset(std::size_t num_edges);

  /// Starts a pass, given the multipliers it solved [kg m] (negative = the edge would push).
  /// Picks the edges that may leave: the latest walked batch that has a pushing edge, or, when
  /// no walked edge pushes, every pushing edge.
  void beginPass(const std::vector<std::uint8_t>& candidate,
                 const std::vector<std::uint8_t>& active, const std::vector<double>& multiplier);
  /// True when a pushing edge `e` may leave the taut set in this pass.
  bool mayLeave(std::size_t e) const { return peel_batch_ == 0 || batch_[e] == peel_batch_; }
  /// Records that `e` left the taut set in this pass (no walk takes it back in this pass).
  void left(std::size_t e);
  /// Records that slack edge `e` joined because the pass's solution stretched it.
  void joined(std::size_t e);
  /// Walks from the edges that joined in this pass and takes slack edges into `active`.
  /// `stretch` is, per edge, how far the pass's solution would stretch it past its limit [m]
  /// (negative: its slack).
  void grow(const EdgeSet& edges, const EdgeIncidence& incidence,
            const std::vector<std::uint8_t>& candidate, const std::vector<double>& stretch,
            std::vector<std::uint8_t>& active);

 private:
  struct WalkStep {
    std::uint32_t edge;   ///< edge reached
    std::uint32_t entry;  ///< vertex it was reached through (kNoVertex: walk both ways)
    double slack_used;    ///< summed slack of the edges taken in on the way [m]
  };
  static constexpr std::uint32_t kNoVertex = 0xffffffffu;

  std::vector<int> batch_;             ///< walked batch an edge joined in (0: not walked)
  std::vector<std::uint32_t> seen_;    ///< pass stamp of the last walk that reached the edge
  std::vector<std::uint32_t> gone_;    ///< pass stamp of the last pass the edge left in
  std::vector<std::uint32_t> joined_;  ///< edges that joined in this pass
  std::vector<WalkStep> stack_;        ///< walk in progress
  std::uint32_t pass_ = 0;             ///< stamp of the current pass
  int batches_ = 0;                    ///< batches walked so far
  int peel_batch_ = 0;                 ///< batch that may leave in this pass (0: any edge)
  double budget_scale_ = 1.0;          ///< halves at each overshoot [-]
};

}  // namespace yarn_tearing
