#include "yarn_tearing/core/projection/vertex_condensation.hpp"

namespace yarn_tearing {

std::size_t VertexCondensation::choose(const EdgeSet& edges, const EdgeIncidence& incidence,
                                       const std::vector<int>& vertex_row,
                                       const std::vector<int>& edge_row,
                                       const std::vector<std::uint8_t>& plain, int rows) {
  const std::size_t n = vertex_row.size();
  eliminated_.assign(n, 0);
  vertex_.clear();
  vertex_first_row_.clear();
  start_.assign(1, 0);
  edge_.clear();
  row_.clear();
  sign_.clear();
  for (std::uint32_t v = 0; v < n; ++v) {
    if (vertex_row[v] < 0) continue;
    bool stiffened = false;
    for (const std::uint32_t* e = incidence.begin(v); e != incidence.end(v) && !stiffened; ++e) {
      stiffened = edge_row[*e] >= 0 && !plain[*e];
    }
    if (stiffened) continue;
    eliminated_[v] = 1;
    vertex_.push_back(v);
    vertex_first_row_.push_back(vertex_row[v]);
    for (const std::uint32_t* e = incidence.begin(v); e != incidence.end(v); ++e) {
      if (edge_row[*e] < 0) continue;
      edge_.push_back(*e);
      row_.push_back(edge_row[*e]);
      sign_.push_back(edges.vertex_b[*e] == v ? 1.0 : -1.0);
    }
    start_.push_back(static_cast<std::uint32_t>(edge_.size()));
  }
  reduced_row_.assign(static_cast<std::size_t>(rows), 0);
  for (int first : vertex_first_row_) {
    for (int i = 0; i < 3; ++i) reduced_row_[static_cast<std::size_t>(first + i)] = -1;
  }
  reduced_rows_ = 0;
  for (int& r : reduced_row_) r = r < 0 ? -1 : reduced_rows_++;
  return vertex_.size();
}

void VertexCondensation::condense(const Eigen::VectorXd& full,
                                  const std::vector<double>& inverse_mass,
                                  const std::vector<Eigen::Vector3d>& direction,
                                  Eigen::VectorXd& reduced) const {
  reduced.resize(reduced_rows_);
  for (Eigen::Index r = 0; r < full.size(); ++r) {
    const int to = reduced_row_[static_cast<std::size_t>(r)];
    if (to >= 0) reduced[to] = full[r];
  }
  for (std::size_t k = 0; k < vertex_.size(); ++k) {
    const Eigen::Vector3d scaled = inverse_mass[vertex_[k]] * full.segment<3>(vertex_first_row_[k]);
    for (std::uint32_t i = start_[k]; i < start_[k + 1]; ++i) {
      reduced[reducedRow(row_[i])] -= sign_[i] * direction[edge_[i]].dot(scaled);
    }
  }
}

void VertexCondensation::expand(const Eigen::VectorXd& full_rhs, const Eigen::VectorXd& reduced,
                                const std::vector<double>& inverse_mass,
                                const std::vector<Eigen::Vector3d>& direction,
                                Eigen::VectorXd& full) const {
  full.resize(full_rhs.size());
  for (Eigen::Index r = 0; r < full.size(); ++r) {
    const int from = reduced_row_[static_cast<std::size_t>(r)];
    if (from >= 0) full[r] = reduced[from];
  }
  for (std::size_t k = 0; k < vertex_.size(); ++k) {
    Eigen::Vector3d force = full_rhs.segment<3>(vertex_first_row_[k]);
    for (std::uint32_t i = start_[k]; i < start_[k + 1]; ++i) {
      force -= (sign_[i] * reduced[reducedRow(row_[i])]) * direction[edge_[i]];
    }
    full.segment<3>(vertex_first_row_[k]) = inverse_mass[vertex_[k]] * force;
  }
}

}  // namespace yarn_tearing
