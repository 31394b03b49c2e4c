#pragma once

#include <cstdint>
#include <vector>

#include "yarn_tearing/core/model/edge_incidence.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"

namespace yarn_tearing {

/// The edges of a scene laid out yarn by yarn: an order in which the segments of each yarn follow
/// each other along it. Two edges continue each other where they are the only two edges of their
/// yarn (EdgeSet::yarn: a yarn, or a fabric's warp or weft) at a vertex they share; a vertex where
/// one yarn has more than two edges ends the chains there. A closed loop is cut at its lowest
/// edge. Each yarn of a woven fabric is then one chain, and so is a free yarn.
class EdgeChains {
 public:
  /// Rebuilds from the edge graph; call whenever edges are added (breaking does not change it).
  void build(const EdgeSet& edges, const EdgeIncidence& incidence);

  /// Edges in chain order: each chain's edges consecutive, along it.
  const std::vector<std::uint32_t>& order() const { return order_; }
  /// Per position i of order(): the vertex that edge order()[i] shares with order()[i + 1] when
  /// the chain goes on there, else kNoVertex.
  const std::vector<std::uint32_t>& joint() const { return joint_; }

  static constexpr std::uint32_t kNoVertex = 0xffffffffu;  ///< see joint()

 private:
  std::vector<std::uint32_t> order_;
  std::vector<std::uint32_t> joint_;
  /// Per edge, its continuation at vertex a and at vertex b (kNoVertex where the chain ends).
  std::vector<std::uint32_t> next_at_a_;
  std::vector<std::uint32_t> next_at_b_;
  std::vector<std::uint8_t> placed_;  ///< per edge: already in order_
};

}  // namespace yarn_tearing
