#pragma once

#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/projection/edge_stretch_limits.hpp"

namespace yarn_tearing {

/// Each edge's length limit during one projection as a piecewise-linear function of its
/// multiplier m [kg m] (the constraint force T_c times dt^2), and the piece each edge is on.
/// An elastic edge may be L + s m long (s = c / dt^2 [1/kg]); where the step's force takes it
/// past its current yield stress, its plastic flow adds L0 (eps_p - eps_p,n) on top
/// (EdgeStretchLimits::flow_knots), linear in m on each segment of the curve; at its breaking
/// length L0 (1 + eps_b) it is held, with a stop 10^6 times stiffer than the yarn for the force
/// beyond (so that the systems stay quasi-definite). Every piece is linear in m, so the
/// projection's linear complementarity problem keeps its form: limit = B + S m, with the base
/// length B [m] and the shift S [1/kg] of the edge's current piece given here.
class EdgeStretchState {
 public:
  /// Takes each edge's compliance term, where it starts to flow and its largest stretch from
  /// `limits` (kept by reference until the next reset); every edge on its first piece. The
  /// pieces past the start of an edge's flow are built when a multiplier first reaches it.
  void reset(const EdgeSet& edges, const EdgeStretchLimits& limits, double time_step);

  /// Moves edge e one piece toward the one multiplier `m` [kg m] lies on (nextPieceToward);
  /// returns B_old - B_new [m].
  double settle(const EdgeSet& edges, std::size_t e, double m);
  /// Puts edge e on its first piece (m = 0: a slack edge neither flows nor is held).
  double release(const EdgeSet& edges, std::size_t e);
  /// Whether edge e is on one of its flow pieces (past its first, short of the stop).
  bool flowing(std::size_t e) const {
    return !pending_[e] && piece_[e] > begin_[e] && piece_[e] + 1 < end_[e];
  }
  /// Puts edge e, on its first piece, on its first flow piece where it has one: for an edge that
  /// flowed in the last step, whose yield force is the one it ended that step with, so that its
  /// multiplier carried over lies at that piece's start to round-off and may fall on either
  /// side of it.
  void resumeFlow(const EdgeSet& edges, std::size_t e);
  /// True when multiplier `m` lies off edge e's current piece. A relative margin keeps an edge
  /// right at a kink (its largest stretch, say) from switching back and forth on round-off.
  bool wouldSwitch(std::size_t e, double m) const;

  /// S per edge [1/kg] on its current piece: s, s plus the flow's growth, or 10^-6 s when held.
  const std::vector<double>& shift() const { return shift_; }
  /// B per edge [m] on its current piece: L on the first elastic one.
  const std::vector<double>& baseLength() const { return base_length_; }
  /// The multiplier [kg m] at which edge e, `length` [m] long, is exactly at its limit: the
  /// force (times dt^2) of a stiff spring of the edge's compliance and flow stretched to that
  /// length, and of the stop past its largest stretch; 0 when the edge is not stretched past its
  /// limit at m = 0. For an edge whose vertices are all pinned or kinematic, which no projection
  /// can move: its length is given.
  double multiplierAtLength(const EdgeSet& edges, std::size_t e, double length);
  /// The limit B + S m [m] of edge e under multiplier `m` [kg m] on its current piece.
  double limit(std::size_t e, double m) const { return base_length_[e] + shift_[e] * m; }

 private:
  /// One linear piece of an edge's limit: from multiplier `start` [kg m] on, B + S m.
  struct Piece {
    double start = 0.0;  ///< [kg m]
    double base = 0.0;   ///< B [m]
    double shift = 0.0;  ///< S [1/kg]
  };
  /// Appends edge e's pieces to pieces_ from `knots` (its flow; none: elastic up to its
  /// breaking length) and points begin_[e], end_[e] at them; `elastic_shift` is its constraint's
  /// compliance over dt^2 [1/kg].
  void buildPieces(const EdgeSet& edges, std::size_t e, const std::vector<FlowKnot>& knots,
                   double elastic_shift);
  /// Builds edge e's flow pieces (flowKnots) the first time a multiplier reaches them.
  void expand(const EdgeSet& edges, std::size_t e);
  /// The piece (index into pieces_) next to edge e's current one on the side of multiplier m.
  /// One kink at a time: an edge's limit bends up where it starts to flow and down where it is
  /// held, and a linearization that jumped across both at once could return to where it started
  /// (a Newton iteration cycling around an S-shaped curve); kink by kink, each solve starts
  /// from the piece next to the answer.
  std::uint32_t nextPieceToward(const EdgeSet& edges, std::size_t e, double m);
  double set(std::size_t e, std::uint32_t piece);

  static constexpr double kMargin = 1e-9;  ///< relative, see wouldSwitch
  /// Compliance of the stop at the largest stretch, relative to the yarn's [-].
  static constexpr double kStopCompliance = 1e-6;
  const EdgeStretchLimits* limits_ = nullptr;  ///< of the last reset
  double time_step2_ = 1.0;                    ///< dt^2 [s^2]
  std::vector<Piece> pieces_;                  ///< every edge's pieces, by rising start
  /// Edge e's pieces: [begin_[e], end_[e]), none while it is pending.
  std::vector<std::uint32_t> begin_;
  std::vector<std::uint32_t> end_;  ///< see begin_
  /// Edge e's pieces are still to be built: it is on its first, elastic piece (B = L, S = s in
  /// base_length_ and shift_), and its flow starts at the multiplier
  /// limits_->flow_start[e] dt^2.
  std::vector<std::uint8_t> pending_;
  std::vector<std::uint32_t> piece_;  ///< each edge's current piece (into pieces_), if built
  std::vector<double> shift_;         ///< S [1/kg]
  std::vector<double> base_length_;   ///< B [m]
  std::vector<FlowKnot> knots_;       ///< scratch of expand()
  FlowBreakpoints breakpoints_;       ///< scratch of expand()
};

}  // namespace yarn_tearing
