#include "yarn_tearing/core/projection/edge_stretch_state.hpp"

#include <algorithm>
#include <limits>

namespace yarn_tearing {

void EdgeStretchState::reset(const EdgeSet& edges, const EdgeStretchLimits& limits,
                             double time_step) {
  const std::size_t q = edges.size();
  limits_ = &limits;
  time_step2_ = time_step * time_step;
  pieces_.clear();
  begin_.resize(q);
  end_.resize(q);
  pending_.resize(q);
  piece_.resize(q);
  shift_.resize(q);
  base_length_.resize(q);
  const bool flows = limits.flow_start.size() == q && limits.yarns != nullptr;
  for (std::size_t e = 0; e < q; ++e) {
    const double flow_start =
        flows ? limits.flow_start[e] * time_step2_ : std::numeric_limits<double>::infinity();
    const double s = limits.constraintCompliance(e) / time_step2_;
    if (flow_start <= 0.0) {
      expand(edges, e);  // flowing from the start: its spring alone is past its yield stress
      set(e, begin_[e]);
    } else if (flows && flow_start < limits.max_stretch[e] / s) {
      // Elastic up to where its flow starts; its pieces are built if a multiplier gets there.
      pending_[e] = 1;
      base_length_[e] = edges.rest_length[e];
      shift_[e] = s;
    } else {
      pending_[e] = 0;
      buildPieces(edges, e, {}, s);
      set(e, begin_[e]);
    }
  }
}

void EdgeStretchState::expand(const EdgeSet& edges, std::size_t e) {
  flowKnots(edges, *limits_->yarns, e, knots_, breakpoints_);
  buildPieces(edges, e, knots_, limits_->constraintCompliance(e) / time_step2_);
  pending_[e] = 0;
  piece_[e] = begin_[e];  // a pending edge is on its first piece, which this one repeats
}

void EdgeStretchState::buildPieces(const EdgeSet& edges, std::size_t e,
                                   const std::vector<FlowKnot>& knots, double elastic_shift) {
  // limit(m) = L + s m + X(m), X the plastic elongation of the flow kinks (force T_c = m / dt^2),
  // continuous and rising; held from where it reaches the breaking length L + s_max on.
  const EdgeStretchLimits& limits = *limits_;
  begin_[e] = static_cast<std::uint32_t>(pieces_.size());
  const double s = elastic_shift;
  const double rest = edges.rest_length[e];
  const double breaking_length = rest + limits.max_stretch[e];
  std::size_t knot = 0;
  Piece piece{0.0, rest, s};
  if (!knots.empty() && knots[0].force == 0.0) {
    piece.base += knots[0].elongation;
    piece.shift += knots[0].slope / time_step2_;
    ++knot;
  }
  for (;;) {
    const double next_start = knot < knots.size() ? knots[knot].force * time_step2_
                                                  : std::numeric_limits<double>::infinity();
    // Where this piece reaches the breaking length, the stop takes over.
    const double held_from = (breaking_length - piece.base) / piece.shift;
    if (held_from <= next_start) {
      // A piece that begins at the breaking length already is the stop's.
      if (held_from > piece.start) pieces_.push_back(piece);
      const double start = std::max(held_from, piece.start);
      const double shift = kStopCompliance * s;
      pieces_.push_back(Piece{start, breaking_length - shift * start, shift});
      break;
    }
    pieces_.push_back(piece);
    const FlowKnot& k = knots[knot];
    const double shift = s + k.slope / time_step2_;
    const double at_knot = rest + s * next_start + k.elongation;
    piece = Piece{next_start, at_knot - shift * next_start, shift};
    ++knot;
  }
  end_[e] = static_cast<std::uint32_t>(pieces_.size());
}

std::uint32_t EdgeStretchState::nextPieceToward(const EdgeSet& edges, std::size_t e, double m) {
  if (pending_[e]) {
    expand(edges, e);  // its first piece is the same: the next is begin_ + 1
    return m >= pieces_[begin_[e] + 1].start ? begin_[e] + 1 : begin_[e];
  }
  const std::uint32_t k = piece_[e];
  if (k + 1 < end_[e] && m >= pieces_[k + 1].start) return k + 1;
  if (k > begin_[e] && m < pieces_[k].start) return k - 1;
  return k;
}

bool EdgeStretchState::wouldSwitch(std::size_t e, double m) const {
  if (pending_[e]) return m > limits_->flow_start[e] * time_step2_ * (1.0 + kMargin);
  const std::uint32_t k = piece_[e];
  const bool below = k > begin_[e] && m < pieces_[k].start * (1.0 - kMargin);
  const bool above = k + 1 < end_[e] && m > pieces_[k + 1].start * (1.0 + kMargin);
  return below || above;
}

void EdgeStretchState::resumeFlow(const EdgeSet& edges, std::size_t e) {
  if (pending_[e]) expand(edges, e);
  if (piece_[e] != begin_[e] || begin_[e] + 2 > end_[e]) return;
  if (begin_[e] + 2 < end_[e]) set(e, begin_[e] + 1);  // else its second piece is the stop
}

double EdgeStretchState::settle(const EdgeSet& edges, std::size_t e, double m) {
  if (!(m > 0.0)) return release(edges, e);
  return wouldSwitch(e, m) ? set(e, nextPieceToward(edges, e, m)) : 0.0;
}

double EdgeStretchState::release(const EdgeSet& /*edges*/, std::size_t e) {
  return pending_[e] ? 0.0 : set(e, begin_[e]);
}

double EdgeStretchState::multiplierAtLength(const EdgeSet& edges, std::size_t e, double length) {
  if (pending_[e]) {
    if (!(length > base_length_[e])) return 0.0;  // on its first piece
    expand(edges, e);
  }
  if (!(length > pieces_[begin_[e]].base)) return 0.0;
  for (std::uint32_t k = begin_[e]; k < end_[e]; ++k) {
    const double m = (length - pieces_[k].base) / pieces_[k].shift;
    if (k + 1 == end_[e] || m < pieces_[k + 1].start) return std::max(m, pieces_[k].start);
  }
  return 0.0;
}

double EdgeStretchState::set(std::size_t e, std::uint32_t piece) {
  const double old_base = base_length_[e];
  piece_[e] = piece;
  base_length_[e] = pieces_[piece].base;
  shift_[e] = pieces_[piece].shift;
  return old_base - base_length_[e];
}

}  // namespace yarn_tearing
