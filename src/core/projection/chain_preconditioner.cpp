#include "yarn_tearing/core/projection/chain_preconditioner.hpp"

namespace yarn_tearing {

void ChainPreconditioner::factorize(const EdgeSet& edges, const EdgeChains& chains,
                                    const std::vector<Eigen::Vector3d>& direction,
                                    const std::vector<double>& vertex_weight,
                                    const std::vector<std::uint8_t>& included,
                                    const std::vector<double>& diagonal) {
  order_ = chains.order();
  const std::vector<std::uint32_t>& order = chains.order();
  const std::size_t q = order.size();
  chain_diagonal_.resize(q);
  chain_upper_.resize(q);
  chain_rhs_.resize(q);
  for (std::size_t i = 0; i < q; ++i) {
    const std::uint32_t e = order[i];
    chain_diagonal_[i] = diagonal[e];
    const std::uint32_t v = chains.joint()[i];
    chain_upper_[i] = 0.0;
    if (v == EdgeChains::kNoVertex) continue;
    const std::uint32_t f = order[i + 1];
    if (!included[e] || !included[f]) continue;
    // g_ev . g_fv = n_e . n_f where v is the same end (a or b) of both edges, else its negative.
    const double sign = (edges.vertex_b[e] == v) == (edges.vertex_b[f] == v) ? 1.0 : -1.0;
    chain_upper_[i] = vertex_weight[v] * sign * direction[e].dot(direction[f]);
  }
  tridiagonal_.factorize(chain_diagonal_, chain_upper_);
}

}  // namespace yarn_tearing
