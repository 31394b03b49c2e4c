#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "yarn_tearing/core/contact/contact_set.hpp"
#include "yarn_tearing/core/model/edge_set.hpp"
#include "yarn_tearing/core/projection/edge_gram_solver.hpp"

namespace yarn_tearing {

/// A few contact points as rows of the projection's fast iterations (a yarn over a peg): the
/// same rows the Newton steps carry (ContactSet), each of gradient -((1 - t) d, t d) on the
/// point's vertices (d the normal or a friction tangent) and multiplier mu [kg m], but solved in
/// the fast iterations' linear complementarity problem in the multipliers, beside the edges:
///   [K_ee + S  K_ec] [m ]   [t_e]
///   [K_ce  K_cc + s] [mu] = [t_c],   K = G W G^T,
/// by a Schur complement over the contact rows on the edges' banded (chains) or sparse solve:
/// one edge solve per active contact row and a small dense solve, so a chain stays O(N).
/// A point's normal row pushes and never pulls (pivoted with the edges); a point with friction
/// has two tangent rows holding it where it stuck, valid while |mu_k| <= mu mu_n (checked by
/// frictionHolds(); sliding is left to the Newton steps). Only points whose states allow it
/// (frictionless, or stuck along both tangents in the last step) and at most kMaxPoints of them.
class FastContactRows {
 public:
  /// Most contact points the fast iterations take as rows (each a dense Schur column).
  static constexpr std::size_t kMaxPoints = 8;

  /// Takes every contact of `contacts` not marked in `skip` (by contact index) as rows; false
  /// when there are too many or one may slide or has unknown friction states.
  bool select(const ContactSet& contacts, const std::vector<std::uint8_t>& skip,
              const std::vector<double>& inverse_mass);
  /// No rows selected.
  bool empty() const { return row_.empty(); }
  /// Some row moves a vertex marked in `vertex_mask` (per vertex).
  bool touches(const std::vector<std::uint8_t>& vertex_mask) const;
  /// Updates each row's direction and constraint value C [m] from `contacts`, linearized at
  /// `position` [m].
  void linearize(const ContactSet& contacts, const std::vector<Eigen::Vector3d>& position);
  /// sum += G^T `value` per vertex (value per row; total multipliers or a pass's).
  void addGradients(const std::vector<double>& value, std::vector<Eigen::Vector3d>& sum) const;
  /// product_j = G_j . W sum [m] for every row.
  void multiply(const std::vector<double>& inverse_mass, const std::vector<Eigen::Vector3d>& sum,
                std::vector<double>& product) const;
  /// Sets target_ = C + K mu_total (`product` = K mu_total per row).
  void setTargets(const std::vector<double>& product);
  /// One pivoting pass's solve: `step` holds the edges' targets (0 where inactive) and returns
  /// their multipliers; the rows' multipliers go to pass_multiplier(). `system` is the edges'.
  void solve(const EdgeSet& edges, EdgeGramSolver& gram, const GramSystem& system,
             const std::vector<double>& inverse_mass, std::vector<double>& step);
  /// After a pass, with `product` = K (the pass's multipliers) per row: releases normal rows
  /// that would pull and takes in those the step would push in (with their tangent rows); true
  /// when any changed. `tolerance` [-] relative to each point's length scale.
  bool pivot(const std::vector<double>& product, double tolerance);
  /// Moves `position` by the change of the rows' multipliers to the pass's, and takes them.
  void accept(const std::vector<double>& inverse_mass, std::vector<Eigen::Vector3d>& position);
  /// Writes each row point's impulse (normal multiplier, friction impulse) into `contacts`.
  void store(ContactSet& contacts) const;
  /// Every stuck point's friction within its pyramid, |mu_k| <= mu mu_n.
  bool frictionHolds(const ContactSet& contacts) const;
  /// The rows' total multipliers [kg m].
  const std::vector<double>& multiplier() const { return multiplier_; }
  /// The rows' multipliers of the last pass [kg m].
  const std::vector<double>& passMultiplier() const { return pass_multiplier_; }
  /// Starts the rows' multipliers at zero (the projection starts from the prediction).
  void reset();

 private:
  /// One row: a point's normal or one of its friction tangents.
  struct Row {
    std::uint32_t contact = 0;  ///< index in the ContactSet
    int tangent = -1;           ///< -1 the normal row, else the friction tangent
    std::uint32_t normal = 0;   ///< index of the point's normal row (itself for a normal row)
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< d: normal or tangent
    double value = 0.0;                                   ///< C at the current linearization [m]
    double shift = 0.0;     ///< compliance s (kContactCompliance times the mobility) [1/kg]
    double scale = 0.0;     ///< the point's length scale [m]
    std::uint32_t a = 0;    ///< first vertex
    std::uint32_t b = 0;    ///< second vertex (= a for a vertex contact)
    double weight_a = 1.0;  ///< 1 - t
    double weight_b = 0.0;  ///< t (0 for a vertex contact)
    bool active = false;    ///< in the equality set
    /// The vertices the row moves [-]: 1 for a vertex contact (b = a), else 2.
    int ends() const { return b == a ? 1 : 2; }
  };
  /// K_ij over the vertices the two rows share [m/kg].
  double coupling(const Row& i, const Row& j, const std::vector<double>& inverse_mass) const;

  /// As StiffNewtonStep's: keeps the system definite where rows are nearly dependent.
  static constexpr double kContactCompliance = 1e-12;
  std::vector<Row> row_;
  std::vector<double> multiplier_;       ///< total multipliers per row [kg m]
  std::vector<double> pass_multiplier_;  ///< a pass's multipliers per row [kg m]
  std::vector<double> target_;           ///< right-hand side per row [m]
  std::vector<std::uint32_t> active_rows_;
  std::vector<std::vector<double>> column_;  ///< per active row: K_e,row over the edges
  std::vector<std::vector<double>> solved_;  ///< per active row: K_ee^-1 column
  Eigen::MatrixXd schur_;
  Eigen::VectorXd schur_rhs_;
};

}  // namespace yarn_tearing
